"""pencore.studies.critical.omega_c: omega_c on (projectile, velocity); no turn-back up to
the top of the range is reported as above_range, not as a number."""

import numpy as np

from pencore.studies.critical.omega_c import omega_c_study


def test_no_turn_back_within_the_range_is_above_range():
    # #2 at 1000 m/s does not turn back with a spin of 30 rad/s (the archived study: not
    # up to 500 rad/s)
    ds = omega_c_study(["p2"], [1000.0], lo=0.0, hi=30.0, tol=10.0, scan=None)
    assert ds["omega_c"].dims == ("projectile", "velocity")
    assert ds["omega_c"].attrs["units"] == "rad s-1" and ds["velocity"].attrs["units"] == "m s-1"
    cell = ds.sel(projectile="p2", velocity=1000.0)
    assert str(cell["status"].values) == "above_range"
    assert np.isnan(float(cell["omega_c"])) and float(cell["omega_c_lo"]) == 30.0
