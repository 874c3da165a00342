"""pencore.search.critical: threshold search on synthetic verdicts, plus one cheap solver check."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pencore
from pencore.errors import InputError
from pencore.inputs import conventions
from pencore.search import critical as C
from pencore.search import threshold as T


class Counter:
    """Verdict wrapper counting calls."""

    def __init__(self, f):
        self.f = f
        self.calls: list[float] = []

    def __call__(self, v: float) -> bool:
        self.calls.append(v)
        return self.f(v)


@pytest.mark.parametrize("tol", [5.0, 0.5, 1e-3])
def test_step_verdict_found_within_tol(tol):
    thr = 1234.567
    v = Counter(lambda x: x >= thr)
    r = T.find_threshold(v, 100.0, 4000.0, tol)
    assert r.status == "ok" and r.monotone and r.converged
    assert r.hi - r.lo <= tol
    assert r.lo < thr <= r.hi
    assert abs(r.value - thr) <= tol / 2
    assert r.value == pytest.approx(0.5 * (r.lo + r.hi))
    n_bisect = math.ceil(math.log2((4000.0 - 100.0) / tol))
    assert r.n_evals == n_bisect + 2 == len(v.calls)  # two ends + bisections
    assert len(r.history) == r.n_evals
    assert r.history[0] == (100.0, False) and r.history[1] == (4000.0, True)
    assert all(b == (x >= thr) for x, b in r.history)
    assert r.tol == tol


def test_scan_on_monotone_verdict():
    r = T.find_threshold(lambda x: x > 7.3, 0.0, 10.0, 0.01, scan=5)
    assert r.status == "ok" and r.monotone and "monotone" in r.message
    assert 7.5 >= r.hi >= r.lo >= 5.0 and r.lo < 7.3 <= r.hi
    # each value evaluated once even when scan and bisection meet
    xs = [x for x, _ in r.history]
    assert len(xs) == len(set(xs)) == r.n_evals


def test_below_range():
    v = Counter(lambda x: x > 50.0)
    r = T.find_threshold(v, 100.0, 200.0, 1.0, scan=5)
    assert r.status == "below_range" and math.isnan(r.value)
    assert r.hi == 100.0 and math.isnan(r.lo)
    assert r.n_evals == 1 and v.calls == [100.0]
    assert "lower end" in r.message and not r.converged


def test_above_range():
    r = T.find_threshold(lambda x: x > 500.0, 100.0, 200.0, 1.0)
    assert r.status == "above_range" and math.isnan(r.value)
    assert r.lo == 200.0 and math.isnan(r.hi)
    assert r.n_evals == 2 and r.history == ((100.0, False), (200.0, False))
    assert "upper end" in r.message


def _wavy(x: float) -> bool:
    """False below 3, True on [3, 5), False on [5, 7), True from 7."""
    return (3.0 <= x < 5.0) or x >= 7.0


def test_non_monotone_flagged_and_lowest_threshold_found():
    r = T.find_threshold(_wavy, 0.0, 10.0, 0.05, scan=11)
    assert r.status == "non_monotone" and not r.monotone and r.converged
    assert r.lo < 3.0 <= r.hi and r.hi - r.lo <= 0.05  # the FIRST transition
    # the message names where the verdict flips: up near 3, down near 5, up near 7
    assert "True->False between 4 and 5" in r.message
    assert "False->True between 2 and 3" in r.message
    assert "False->True between 6 and 7" in r.message
    assert "lowest threshold" in r.message


def test_non_monotone_missed_without_scan():
    # documented limitation: without a scan, bisection may land on any transition
    r = T.find_threshold(_wavy, 0.0, 10.0, 0.05)
    assert r.monotone and r.status == "ok" and "not checked" in r.message
    assert any(abs(r.value - c) < 0.05 for c in (3.0, 5.0, 7.0))


def test_max_iter():
    r = T.find_threshold(lambda x: x > 0.123, 0.0, 1.0, 1e-9, max_iter=5)
    assert r.status == "max_iter" and not r.converged
    assert r.hi - r.lo == pytest.approx(1.0 / 32) and r.lo < 0.123 <= r.hi


def test_bad_arguments():
    with pytest.raises(InputError):
        T.find_threshold(lambda x: True, 2.0, 1.0, 0.1)
    with pytest.raises(InputError):
        T.find_threshold(lambda x: True, 1.0, 2.0, 0.0)
    with pytest.raises(InputError):
        T.find_threshold(lambda x: True, 1.0, 2.0, 0.1, scan=1)
    with pytest.raises(InputError, match="set by the search"):
        C.vcr("p2", "soil", 60.0, velocity=100.0)
    with pytest.raises(InputError, match="unknown"):
        C.vcr("p2", "soil", 60.0, colour="red")
    with pytest.raises(InputError, match="threshold_deg"):
        C.vci("p4", "soil", 0.1, 200.0, 3000.0, threshold_deg=0.0)


def test_constants_and_to_dict():
    assert T.VELOCITY_TOL == 5.0 and T.OMEGA_TOL == 0.5
    d = T.find_threshold(lambda x: x > 1.0, 0.0, 2.0, 0.1).to_dict()
    assert d["status"] == "ok" and isinstance(d["history"], list)
    assert d["history"][0] == [0.0, False]


@pytest.mark.slow
def test_vcr_bracket_is_real():
    """Coarse Vcr search on a cheap case; both bracket ends re-simulated."""
    import pencore

    r = C.vcr("p2", "soil", 60.0, lo=300.0, hi=3000.0, tol=50.0, scan=None)
    assert r.converged, r.message
    assert r.hi - r.lo <= 50.0
    lo_run = pencore.simulate("p2", "soil", r.lo, 60.0, stop_at_reversal=True)
    hi_run = pencore.simulate("p2", "soil", r.hi, 60.0, stop_at_reversal=True)
    assert lo_run.attrs["reversed"] == 0
    assert hi_run.attrs["reversed"] == 1


def test_normal_impact_angles():
    assert conventions.YAW_CONVENTIONS == ("axis_tilted", "velocity_tilted")
    assert conventions.normal_impact_angles(0.1, "axis_tilted") == (0.1, -0.1)
    assert conventions.normal_impact_angles(0.1, "velocity_tilted") == (0.0, 0.1)
    # axis_tilted: velocity angle obliquity + yaw is exactly normal
    obl, yaw = conventions.normal_impact_angles(0.7)
    assert obl + yaw == 0.0 and obl == 0.7
    with pytest.raises(InputError, match="convention"):
        conventions.normal_impact_angles(0.1, "sideways")
    with pytest.raises(InputError, match="convention"):
        C.vci("p4", "soil", 0.1, 200.0, 3000.0, threshold_deg=5.0, convention="x")


def test_vci_shared_runs_identical_to_separate_searches():
    # a run does not depend on the threshold, so searches for several thresholds that
    # share their runs must return exactly what separate searches return (same values,
    # same evaluation histories), while running each speed once
    kw = dict(scan=3, max_iter=3)
    shared: dict[float, tuple[bool, float]] = {}
    for thr in (0.2, 1.0):
        alone = C.vci("p4", "soil", 0.1, 500.0, 3000.0, thr, 50.0, **kw)
        together = C.vci("p4", "soil", 0.1, 500.0, 3000.0, thr, 50.0, shared_runs=shared, **kw)
        assert together.to_dict() == alone.to_dict()
    speeds = [
        v
        for thr in (0.2, 1.0)
        for v, _ in C.vci("p4", "soil", 0.1, 500.0, 3000.0, thr, 50.0, **kw).history
    ]
    assert set(shared) == set(speeds)


def test_run_impact_is_simulate_without_the_dataset():
    # the searches judge the raw run: it must be the very run simulate() stores
    from pencore.run.impact import run_impact

    kw = dict(obliquity=45.0, start=(-1.0, 1.0, 0.0), stop_at_reversal=True)
    ds = pencore.simulate("p2", "soil", 1700.0, **kw)
    run = run_impact("p2", "soil", 1700.0, **kw)
    assert int(run.reversed) == ds.attrs["reversed"] == 1
    assert run.outcome == ds.attrs["outcome"]
    assert np.array_equal(run.ts, ds["time"].values)
    assert np.array_equal(run.ys[:, 7], ds["vel_x"].values)
