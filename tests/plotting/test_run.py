"""plot_run draws the Dataset's own numbers, with labelled axes and units."""

import numpy as np
import pytest

import pencore
from pencore.errors import InputError
from pencore.plotting.run import plot_run


@pytest.fixture(scope="module")
def oblique():
    return pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)


def test_lines_are_the_datasets_data(oblique):
    fig = pencore.plot_run(oblique)
    path, dev, speed, decel = fig.axes[:4]
    x, y = path.lines[0].get_data()
    np.testing.assert_array_equal(x, oblique.tip_x.values)
    np.testing.assert_array_equal(y, oblique.tip_y.values)
    t = oblique.time.values * 1e3
    for ax, name in [(dev, "deviation"), (speed, "speed"), (decel, "deceleration_g")]:
        xs, ys = ax.lines[0].get_data()
        np.testing.assert_array_equal(xs, t)
        np.testing.assert_array_equal(ys, oblique[name].values)
    assert [ax.get_xlabel() for ax in fig.axes[1:4]] == ["Time (ms)"] * 3
    assert path.get_xlabel() == "Nose tip x (m)"
    assert decel.get_ylabel() == "Deceleration (g)"
    # the right axis is m/s^2
    (right,) = decel.child_axes
    assert right.get_ylabel() == "Deceleration (m/s²)"


def test_against_depth(oblique):
    fig = plot_run(oblique, against="depth")
    xs, ys = fig.axes[2].lines[0].get_data()
    np.testing.assert_array_equal(xs, -oblique.tip_y.values)
    assert fig.axes[2].get_xlabel() == "Nose tip depth below the surface (m)"


def test_without_loads_says_so():
    ds = pencore.simulate("p2", "soil", 300.0, loads=False)
    fig = plot_run(ds)
    assert "deceleration" not in ds
    assert not fig.axes[3].lines
    assert "no loads" in fig.axes[3].texts[0].get_text()


def test_a_study_dataset_is_refused_in_one_line():
    import xarray as xr

    with pytest.raises(InputError, match="one trajectory"):
        plot_run(xr.Dataset({"velocity": ("velocity", [1.0])}))
    with pytest.raises(InputError, match="against"):
        plot_run(pencore.simulate("p2", "soil", 300.0), against="speed")


def test_a_layered_targets_path_shows_each_interface():
    """Concrete 0.3 m, an air gap of 0.1 m, soil 0.5 m: the interfaces and the rear face
    dashed at y = -0.3, -0.4 and -0.9 m, the gap shaded, each layer named; a half-space of
    one medium has its surface only (the first test: two lines)."""
    import warnings

    concrete, soil = pencore.get_target("concrete").medium, pencore.get_target("soil").medium
    target = pencore.Target(
        "stack",
        (pencore.Layer(concrete, 0.3), pencore.Layer.gap(0.1), pencore.Layer(soil, 0.5)),
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pencore.PlausibilityWarning)  # thin plates
        ds = pencore.simulate("p2", target, 400.0, loads=False)
    path = plot_run(ds).axes[0]
    dashed = [ln for ln in path.lines if ln.get_linestyle() == "--"]
    heights = sorted(float(ln.get_ydata()[0]) for ln in dashed)
    assert heights == pytest.approx([-0.9, -0.4, -0.3], abs=1e-12)
    assert all(np.ptp(ln.get_ydata()) == 0 for ln in dashed)  # horizontal
    (gap,) = path.patches  # the shaded gap spans y = -0.4 to -0.3 m
    ys = gap.get_transform().transform(gap.get_path().vertices)[:, 1]
    data_ys = path.transData.inverted().transform(np.c_[np.zeros_like(ys), ys])[:, 1]
    assert sorted({round(y, 9) for y in data_ys}) == [-0.4, -0.3]
    names = [t.get_text().strip() for t in path.texts]
    assert names == ["concrete", "air gap", "soil"]
    half_space = plot_run(pencore.simulate("p2", "soil", 300.0, loads=False)).axes[0]
    assert len(half_space.lines) == 2 and not half_space.texts and not half_space.patches
