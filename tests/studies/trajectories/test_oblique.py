"""pencore.studies.trajectories.oblique: Fig. 7, #2 at 45 deg on either side of Vcr: the
slower run stays in the target, the faster turns back; the turning angle with units."""

import numpy as np

from pencore.studies.trajectories.oblique import oblique_trajectories


def test_either_side_of_vcr():
    ds = oblique_trajectories(velocities=(1000.0, 2000.0), n_time=60)
    assert ds["tip_y"].dims == ("velocity", "time")
    assert ds["reversed"].values.tolist() == [0, 1]  # Vcr of #2 at 45 deg is near 1574 m/s
    assert ds["x_linear"].attrs["units"] == "m" and ds["delta_theta"].attrs["units"] == "degree"
    assert np.all(ds["delta_theta"].values > 0)
