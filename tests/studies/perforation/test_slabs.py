"""pencore.studies.perforation.slabs: a slab slows the projectile (residual below impact,
rising with it), and a thicker slab has a higher ballistic limit."""

import numpy as np

from pencore.studies.perforation.slabs import (
    ballistic_limit_map,
    residual_velocity_curve,
    slab_target,
)


def test_slab_target_is_one_layer_of_the_medium():
    t = slab_target("concrete", 0.5)
    assert len(t.layers) == 1 and t.layers[0].thickness == 0.5


def test_residual_velocity_is_below_the_impact_and_rises_with_it():
    v = np.array([300.0, 600.0, 900.0])
    ds = residual_velocity_curve("p2", "concrete", 0.5, v, tol=20.0)
    vr = ds["residual_velocity"].values
    assert ds["residual_velocity"].attrs["units"] == "m s-1"
    assert np.all(vr < v) and np.all(np.diff(vr) > 0)


def test_the_ballistic_limit_rises_with_thickness():
    ds = ballistic_limit_map("p2", "concrete", [0.25, 0.5], [0.0], tol=50.0, scan=None)
    assert ds["v_bl"].dims == ("thickness", "obliquity")
    assert ds["v_bl"].attrs["units"] == "m s-1" and ds["thickness"].attrs["units"] == "m"
    v_bl = ds["v_bl"].sel(obliquity=0.0).values
    assert (ds["status"] == "ok").all() and v_bl[1] > v_bl[0]
