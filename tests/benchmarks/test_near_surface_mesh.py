"""``benchmarks/near_surface_mesh.py`` calls a map cell converged only when twice the rings
move its ballistic limit by at most the search tolerance, and never when a search failed."""

from __future__ import annotations

import math

import pandas as pd
import pytest


@pytest.fixture(scope="module")
def mesh(load_benchmark):
    return load_benchmark("near_surface_mesh")


def test_converged_is_within_the_tolerance_and_both_found(mesh):
    table = pd.DataFrame(
        {
            "v_bl_mesh1": [539.0, 539.0, 539.0, math.nan, 300.0],
            "v_bl_mesh2": [541.0, 541.5, 536.9, 300.0, math.nan],
        }
    )
    # |diff| = 2.0 (at the tolerance), 2.5, 2.1 (below), and the two failed searches
    assert mesh.converged(table, 2.0).tolist() == [True, False, False, False, False]


def test_the_labels_name_the_mesh_columns(mesh):
    assert [mesh.label(f) for f in (0.5, 1.0, 2.0)] == ["mesh0p5", "mesh1", "mesh2"]
