"""pencore.workflowconfig.registry: one record per Section 4 study, from which the
configuration dispatch, the job parts and the plot table are derived."""

from pathlib import Path

import pytest
import xarray as xr
import yaml

from pencore import plotting
from pencore.errors import InputError
from pencore.studies.config import StudySettings, from_config, gather
from pencore.workflowconfig import registry
from pencore.workflowconfig.parts import parts_of
from pencore.workflowconfig.registry import SHARED_KEYS, STUDIES, Study

REPO = Path(__file__).resolve().parents[2]


def test_every_record_names_a_run_and_a_plot_function():
    for s in STUDIES.values():
        assert callable(registry.resolve(s.run)), s.id
        assert plotting.PLOTS[s.id] is getattr(plotting, s.plot), s.id


def test_records_match_the_shipped_configuration():
    section4 = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["section4"]
    assert set(SHARED_KEYS) <= set(section4)
    for s in STUDIES.values():
        assert s.entry in section4, s.id
        if s.split_by:
            assert "projectiles" in section4[s.entry], s.id


def test_datasets_figures_and_parts_folders_are_unique():
    """Report downloads and job outputs must not clash: a figure's file name alone is
    unique, and no two studies write one dataset or share a parts folder."""
    records = list(STUDIES.values())
    names = [s.figure.rsplit("/", 1)[1] for s in records] + ["table2", "fig5", "verification"]
    assert len(set(names)) == len(names)
    assert len({s.dataset for s in records}) == len(records)
    split = [s.parts_dir for s in records if s.split_by]
    assert len(set(split)) == len(split)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"shared": ("target", "tolerance")}, "unknown shared keys"),
        ({"split_by": ("obliquity",)}, "must be a start of"),
        ({"dataset": "out/toy.csv"}, "is not results/"),
    ],
)
def test_a_malformed_record_is_refused(change, message):
    fields = dict(
        id="toy", entry="toy", shared=("target",), run=len, dataset="results/toy/toy.nc",
        figure="results/toy/toy", title="toy", plot="plot_fig7",
    )  # fmt: skip
    with pytest.raises(InputError, match=message):
        Study(**{**fields, **change})


def test_unknown_study_names_the_known_ones():
    with pytest.raises(InputError, match="unknown Section 4 study 'fig99'; known: fig7"):
        registry.study("fig99")


# ----------------------------------------------------------------------------- a toy study


def _toy_run(entry, settings: StudySettings) -> xr.Dataset:
    """A study that runs nothing: its configuration entry and settings as a dataset."""
    return xr.Dataset(
        {"speed": ("projectile", [float(entry["speed_m_s"])], {"units": "m s-1"})},
        coords={"projectile": [settings.projectile]},
        attrs={"target": settings.target, "n_time": settings.n_time},
    )


def _toy_plot(ds):
    return ("toy figure", ds)


@pytest.fixture
def toy(monkeypatch):
    """One record added to the registry, and nothing else edited."""
    record = Study(
        id="toy",
        entry="toy",
        shared=("target", "trajectory_samples"),
        run=_toy_run,
        dataset="results/toy/speeds.nc",
        figure="results/toy/toy_speeds",
        title="Toy speeds",
        plot=_toy_plot,
        split_by=("projectile",),
    )
    monkeypatch.setitem(STUDIES, "toy", record)
    return record


def test_a_registered_study_is_dispatched_split_gathered_and_plotted(toy):
    entry = {"projectiles": ["p1", "p3"], "speed_m_s": 250.0}
    shared = {"target": "concrete", "trajectory_samples": 40}
    assert parts_of("toy", entry) == [{"projectile": "p1"}, {"projectile": "p3"}]
    parts = [from_config("toy", entry, shared, **part) for part in parts_of("toy", entry)]
    assert [p.attrs["target"] for p in parts] == ["concrete", "concrete"]
    assert parts[0].attrs["n_time"] == 40
    ds = gather("toy", parts[::-1])
    assert ds["projectile"].values.tolist() == ["p3", "p1"]
    assert ds["speed"].values.tolist() == [250.0, 250.0]
    with pytest.raises(InputError, match="runs per projectile"):
        from_config("toy", entry, shared)
    assert "toy" in plotting.PLOTS and len(plotting.PLOTS) == len(set(plotting.PLOTS))
    assert plotting.PLOTS["toy"](ds) == ("toy figure", ds)


def test_the_toy_study_is_gone_without_its_record():
    assert "toy" not in STUDIES and "toy" not in plotting.PLOTS
    with pytest.raises(InputError, match="unknown Section 4 study 'toy'"):
        parts_of("toy", {"projectiles": ["p1"]})
