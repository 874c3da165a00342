"""pencore.studies.turning: Fig. 9, the total turning angle against Lc/L, by the bracket
and the sign-change definitions, with units."""

import numpy as np

from pencore.studies.turning import turning_angle_study


def test_turning_angle_per_projectile_and_fraction():
    ds = turning_angle_study(["p1", "p4"], fractions=(0.05, 0.1), n_time=40)
    assert ds["delta_theta"].dims == ("projectile", "bracket_fraction")
    assert ds["delta_theta"].attrs["units"] == "degree"
    assert ds["lc_over_l"].values[0] < ds["lc_over_l"].values[1]
    assert np.all(ds["delta_theta"].values > 0)
    assert ds["delta_theta_sign_change"].dims == ("projectile",)
