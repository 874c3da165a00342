"""pencore.studies.trajectories.spin: Figs 16-17 and the start-height study: no spin goes
straight, a spin deviates; a spinning body turns in free flight, so the angle at contact
and alpha grow with the start height."""

from pencore.studies.trajectories.spin import spin_trajectories, start_height_study


def test_spin_deviates_the_path():
    ds = spin_trajectories(omegas=(0.0, 20.0), n_time=40)
    assert ds["tip_y"].dims == ("omega", "time") and ds["omega"].attrs["units"] == "rad s-1"
    dev = ds["final_deviation"].values
    assert abs(dev[0]) < 1e-9 < dev[1]


def test_the_start_height_turns_the_body_before_contact():
    ds = start_height_study(omegas=(20.0,), heights=(0.0, 0.5))
    assert ds["alpha"].dims == ("start_height", "omega")
    assert ds["start_height"].attrs["units"] == "m"
    theta = ds["theta_at_contact"].sel(omega=20.0).values
    assert theta[0] == 0.0 < theta[1]  # touching: no free flight to turn in
    alpha = ds["alpha"].sel(omega=20.0).values
    assert alpha[1] > alpha[0] > 0
