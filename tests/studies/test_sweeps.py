"""The sweeps are the single runs and searches they gather, point by point."""

import numpy as np
import pytest

import pencore
from pencore.errors import InputError
from pencore.studies.sweeps import ballistic_table, depth_curve, residual_curve

PLATE = {"name": "plate", "layers": [{"medium": "aluminium", "thickness": 0.02}]}


def test_depth_curve_is_simulate_per_speed():
    seen = []
    ds = depth_curve("p2", "soil", [250.0, 500.0], obliquity=10.0, progress=seen.append)
    assert len(seen) == 2 and seen[0].startswith("250 m/s")
    for k, v in enumerate((250.0, 500.0)):
        run = pencore.simulate("p2", "soil", v, 10.0)
        assert ds.penetration_depth.values[k] == float(run.penetration_depth)
        assert ds.peak_deceleration.values[k] == run.attrs["peak_deceleration_m_s2"]
        assert ds.peak_lateral_force.values[k] == run.attrs["peak_lateral_force_N"]
    for name in ds.variables:
        assert ds[name].attrs["units"] is not None and ds[name].attrs["long_name"]


def test_residual_curve_fits_recht_ipson_to_its_runs():
    ds = residual_curve("p2", PLATE, [150.0, 250.0, 350.0, 450.0])
    vr = ds.residual_velocity.values
    assert (vr > 0).all() and np.all(np.diff(vr) > 0)
    v_bl = ds.attrs["v_bl_m_s"]
    assert 0.0 < v_bl < 150.0
    # the recorded RMS is that of the curve written beside the runs
    rms = np.sqrt(np.mean((ds.recht_ipson.values - vr) ** 2))
    assert ds.attrs["recht_ipson_rms_m_s"] == pytest.approx(rms, rel=1e-9)
    with pytest.raises(InputError, match="no rear face"):
        residual_curve("p2", "soil", [300.0])


def test_ballistic_table_cells_are_ballistic_limit_searches():
    ds = ballistic_table("p2", "aluminium", [0.01], [0.0, 30.0], tol=20.0)
    slab = {"name": "s", "layers": [{"medium": "aluminium", "thickness": 0.01}]}
    r = pencore.ballistic_limit("p2", slab, 30.0, tol=20.0, scan=5)
    assert float(ds.v_bl.sel(thickness=0.01, obliquity=30.0)) == r.value
