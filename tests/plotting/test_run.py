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
