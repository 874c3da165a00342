"""pencore.studies.trajectories.yaw: Figs 13-14, normal impact with a small yaw: zero yaw
goes straight (symmetry) under both conventions, a yaw deviates the path."""

import numpy as np
import pytest

from pencore.inputs.conventions import YAW_CONVENTIONS
from pencore.studies.trajectories.yaw import yaw_trajectories


def test_zero_yaw_goes_straight_and_a_yaw_deviates():
    straight = yaw_trajectories(yaw=0.0, velocities=(280.0,), n_time=40)
    assert straight["final_deviation"].dims == ("convention", "velocity")
    assert straight["convention"].values.tolist() == list(YAW_CONVENTIONS)
    assert straight["final_deviation"].attrs["units"] == "degree"
    np.testing.assert_allclose(straight["final_deviation"], 0.0, atol=1e-9)
    yawed = yaw_trajectories(yaw=0.5, velocities=(280.0,), n_time=40)
    assert (yawed["final_deviation"] > 0.1).all()


def test_repeated_velocities_are_refused():
    from pencore.errors import InputError

    with pytest.raises(InputError, match="repeated"):
        yaw_trajectories(velocities=(280.0, 280.0))
