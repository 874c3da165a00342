"""pencore.studies.trajectories.stack: runs on one shared time axis, exact at each run's
own last sample and NaN after it, scalars from the full runs."""

import numpy as np
import pytest

import pencore
from pencore.studies.trajectories.stack import stack_trajectories


def test_stack_trajectories_shared_axis():
    pr = pencore.prepare("p2", "soil")
    runs = {
        (i,): pencore.simulate("p2", "soil", v, 45.0, prepared=pr)
        for i, v in enumerate((300.0, 600.0))
    }
    ds = stack_trajectories(
        runs, {"velocity": (np.array([300.0, 600.0]), {"units": "m s-1"})}, n_time=80
    )
    assert ds["tip_x"].dims == ("velocity", "time")
    assert 80 <= ds.sizes["time"] <= 82  # + each run's last time
    for name, var in ds.data_vars.items():
        assert "long_name" in var.attrs and "units" in var.attrs, name
    for i, run in runs.items():
        t_end = float(run["time"][-1])
        row = ds.isel(velocity=i[0])
        # exact at the run's own last sample, NaN after it
        assert float(row["tip_y"].sel(time=t_end)) == pytest.approx(float(run["tip_y"][-1]))
        assert np.isnan(row["tip_y"].where(ds["time"] > t_end, drop=True)).all()
        assert float(row["penetration_depth"]) == float(run["penetration_depth"])
        assert float(row["final_deviation"]) == pytest.approx(pencore.analysis.final_deviation(run))
