"""The public surface: every entry point a user calls is a name of ``pencore``, each topic
subpackage lists its own public names, ``dir`` shows only those, the old import paths keep
working, and a process that only reads, analyses and plots results does not load the solver."""

from __future__ import annotations

import importlib
import subprocess
import sys

import pytest

import pencore

SUBPACKAGES = ["run", "search", "io", "analysis", "inputs", "integrators", "kernels", "cli"]

#: What a user is told to call (README, user guide, examples): each must be at the top.
ENTRY_POINTS = [
    "simulate",
    "prepare",
    "vcr",
    "vci",
    "omega_c",
    "ballistic_limit",
    "residual_velocity",
    "read_netcdf",
    "plot_run",
    "final_deviation",
    "turning_angle",
    "inflection_points_ds",
    "signed_curvature",
    "get_projectile",
    "get_target",
    "Projectile",
    "Target",
    "concrete_law",
    "metal_law",
    "soil_law",
    "Numerics",
    "InputError",
    "SolverError",
    "PlausibilityWarning",
    "RigidRegimeWarning",
]


@pytest.mark.parametrize("name", pencore.__all__)
def test_every_public_name_resolves(name):
    value = getattr(pencore, name)
    if name != "__version__":
        # documented where it is defined, and reachable by the same object at the top
        assert value.__module__.startswith("pencore."), name


def test_the_entry_points_are_public_names():
    assert set(ENTRY_POINTS) <= set(pencore.__all__)


def test_dir_shows_only_the_public_names():
    import pencore.run  # noqa: F401  (an imported submodule is not listed either)

    assert dir(pencore) == sorted(pencore.__all__)
    assert len(set(pencore.__all__)) == len(pencore.__all__)
    for helper in ("Any", "TYPE_CHECKING", "annotations", "importlib", "attach"):
        assert helper not in dir(pencore)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'simulat'"):
        pencore.simulat  # noqa: B018
    with pytest.raises(AttributeError, match="no attribute 'vcrr'"):
        pencore.search.vcrr  # noqa: B018


@pytest.mark.parametrize("sub", SUBPACKAGES)
def test_each_subpackage_lists_its_public_names(sub):
    module = importlib.import_module(f"pencore.{sub}")
    assert isinstance(module.__all__, list)
    for name in module.__all__:
        assert not name.startswith("_"), name
        assert getattr(module, name) is not None


@pytest.mark.parametrize("name", [n for n in pencore.__all__ if n != "__version__"])
def test_a_top_level_name_is_the_object_of_its_topic_subpackage(name):
    value = getattr(pencore, name)
    parts = value.__module__.split(".")
    if len(parts) > 2:  # pencore.<topic>.<module>: the topic package holds it too
        topic = importlib.import_module(".".join(parts[:2]))
        assert name in topic.__all__, (name, topic.__name__)
        assert getattr(topic, name) is value
    # the module that defines it is an import path that keeps working
    assert getattr(importlib.import_module(value.__module__), name) is value


def test_the_old_import_paths_keep_working():
    from pencore.analysis.turning import turning_angle
    from pencore.io.netcdf import read_netcdf
    from pencore.run.impact import simulate
    from pencore.search.critical import vcr
    from pencore.search.perforation import ballistic_limit

    assert (simulate, vcr, ballistic_limit, read_netcdf, turning_angle) == (
        pencore.simulate,
        pencore.vcr,
        pencore.ballistic_limit,
        pencore.read_netcdf,
        pencore.turning_angle,
    )


def test_a_figure_job_does_not_load_the_solver():
    """Reading, analysing and plotting results (the workflow's figure jobs) through the
    public names imports neither numba nor the solver: the names are imported on first
    use, from the submodule that defines each."""
    code = (
        "import sys, pencore, pencore.io, pencore.plotting, pencore.analysis\n"
        "from pencore import read_netcdf, final_deviation, turning_angle, InputError\n"
        "from pencore.io import read_netcdf\n"
        "dir(pencore)\n"
        "print(sorted(m for m in ('numba', 'pencore.run.impact', 'pencore.kernels')"
        " if m in sys.modules))\n"
        "pencore.simulate\n"
        "print('numba' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["[]", "True"]
