"""``benchmarks/near_surface_mesh.py`` calls a map cell converged as the workflow's ring-mesh
check does: only when twice the rings move its ballistic limit by at most the search
tolerance, and never when a search failed."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def mesh(load_benchmark):
    return load_benchmark("near_surface_mesh")


def test_the_verdict_is_the_workflows_check(mesh):
    # the benchmark's converged/reason columns come from the function the workflow's
    # rule near_surface_mesh archives (tested in tests/studies/perforation/test_mesh_check.py)
    from pencore.studies.perforation import mesh_check

    assert mesh.mesh_check is mesh_check.mesh_check
    assert mesh.finer_rings is mesh_check.finer_rings


def test_the_labels_name_the_mesh_columns(mesh):
    assert [mesh.label(f) for f in (0.5, 1.0, 2.0)] == ["mesh0p5", "mesh1", "mesh2"]
