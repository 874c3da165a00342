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


def _stalls_at(monkeypatch, module, stalls):
    """Make ``module``'s runs raise the SolverError of a stalled run where
    ``stalls(velocity, obliquity)`` is true (as a chattering contact does)."""
    from pencore.errors import SolverError

    real = module.simulate if hasattr(module, "simulate") else module.run_impact
    name = "simulate" if hasattr(module, "simulate") else "run_impact"

    def run(projectile, target, velocity, obliquity=0.0, *args, **kwargs):
        if stalls(float(velocity), float(obliquity)):
            raise SolverError(f"step size fell below h_min at {velocity:g} m/s (stalled)")
        return real(projectile, target, velocity, obliquity, *args, **kwargs)

    monkeypatch.setattr(module, name, run)


def test_a_stalled_cell_is_a_verdict_and_the_table_keeps_the_others(monkeypatch):
    import pencore.search.perforation as perforation

    _stalls_at(monkeypatch, perforation, lambda v, o: o == 7.0 and v > 400.0)
    ds = ballistic_table("p2", "aluminium", [0.01], [6.0, 7.0], tol=20.0)
    cell6 = ds.sel(thickness=0.01, obliquity=6.0)
    cell7 = ds.sel(thickness=0.01, obliquity=7.0)
    monkeypatch.undo()
    slab = {"name": "s", "layers": [{"medium": "aluminium", "thickness": 0.01}]}
    assert float(cell6.v_bl) == pencore.ballistic_limit("p2", slab, 6.0, tol=20.0).value
    assert str(cell7.status.values) == "solver_error" and np.isnan(float(cell7.v_bl))
    assert "stalled" in str(cell7.message.values)
    assert int(cell7.n_evals) >= 1  # the verdicts found before it are counted


def test_a_run_that_cannot_finish_is_a_row_of_its_own(monkeypatch):
    import pencore.studies.perforation.slabs as slabs
    import pencore.studies.sweeps as sweeps

    _stalls_at(monkeypatch, sweeps, lambda v, o: v == 300.0)
    ds = depth_curve("p2", "soil", [250.0, 300.0, 500.0])
    assert list(ds.outcome.values) == ["stopped", "solver_error", "stopped"]
    assert np.isnan(ds.penetration_depth.values[1]) and "stalled" in ds.message.values[1]
    assert ds.penetration_depth.values[2] == float(pencore.simulate("p2", "soil", 500.0)
                                                    .penetration_depth)  # fmt: skip
    _stalls_at(monkeypatch, slabs, lambda v, o: v == 250.0)
    ds = residual_curve("p2", PLATE, [150.0, 250.0, 350.0, 450.0])
    assert ds.outcome.values[1] == "solver_error" and np.isnan(ds.residual_velocity.values[1])
    assert ds.attrs["recht_ipson_status"] == "fitted"  # on the three runs that finished
    assert np.all(np.isfinite(ds.recht_ipson.values))


def test_a_fit_that_cannot_be_made_is_nan_with_a_status():
    # two perforating runs: both are run and kept; the fit is NaN and says why
    ds = residual_curve("p2", PLATE, [500.0, 900.0])
    assert (ds.residual_velocity.values > 0).all()
    assert np.isnan(ds.attrs["v_bl_m_s"]) and np.isnan(ds.attrs["recht_ipson_a"])
    assert np.isnan(ds.recht_ipson.values).all()
    assert ds.attrs["recht_ipson_status"] == "not fitted: 2 of 2 runs perforate, 3 are needed"
    assert "message" not in ds  # every run finished


def test_a_grid_of_searches_is_bounded_before_any_run():
    from pencore.studies.common import MAX_AXIS_POINTS, MAX_SEARCHES

    obliquities = np.linspace(-44.0, 44.0, 89)
    with pytest.raises(InputError, match=f"200 x 89 = 17800 searches; at most {MAX_SEARCHES}"):
        ballistic_table("p2", "aluminium", np.linspace(0.001, 0.2, 200), obliquities)
    with pytest.raises(InputError, match=f"at most {MAX_AXIS_POINTS} are allowed"):
        depth_curve("p2", "soil", np.linspace(100.0, 900.0, MAX_AXIS_POINTS + 1))


def test_the_axis_bound_is_the_workflow_grid_bound():
    from pencore.studies.common import MAX_AXIS_POINTS
    from pencore.workflowconfig.config_check import MAX_GRID

    assert MAX_AXIS_POINTS == MAX_GRID


def test_a_fit_that_fails_after_the_runs_is_nan_with_its_reason(monkeypatch):
    import pencore.studies.sweeps as sweeps

    def fails(v, vr, v_bl=None):
        raise ValueError("x0 is infeasible")

    monkeypatch.setattr(sweeps, "fit_recht_ipson", fails)
    ds = residual_curve("p2", PLATE, [150.0, 250.0, 350.0, 450.0])
    assert (ds.residual_velocity.values > 0).all()  # the runs are kept
    assert ds.attrs["recht_ipson_status"] == "not fitted: x0 is infeasible"
    assert np.isnan(ds.recht_ipson.values).all() and np.isnan(ds.attrs["v_bl_m_s"])
