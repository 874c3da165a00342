"""The compiled integrator against references: scipy's solve_ivp on the same right-hand
side, and itself in another process (bit-for-bit)."""

import json
import re
import subprocess
import sys

import numpy as np
import pytest

import pencore
from pencore.integrators.scipy_ivp import CALLS_PER_STEP

# trajectories under scipy's reference integrator, ~4-7 s each (~37 s in all)
pytestmark = pytest.mark.slow

CASES = [
    ("p2", dict(velocity=280.0)),
    ("p2", dict(velocity=1000.0, obliquity=45.0)),
    ("p4", dict(velocity=500.0, yaw=2.0)),
    ("p2", dict(velocity=1000.0, omega=20.0)),
    ("p2", dict(velocity=1700.0, obliquity=45.0, start=(-1.0, 1.0, 0.0))),
]
TIGHT = dict(rtol=1e-8, max_travel=0.01)


def _ids(case):
    return "-".join([case[0]] + [f"{k}{v}" for k, v in case[1].items()])


@pytest.mark.parametrize("case", CASES, ids=[_ids(c) for c in CASES])
def test_compiled_equals_solve_ivp_at_tight_tolerance(case):
    """Both integrators solve the same equations: at rtol 1e-8 each one's global error on
    depth and path is ~1e-5 (measured: <= 1.1e-5 between them), so they must agree to
    1e-4; the deviation angle to 1e-3 deg; and on the outcome and the reversal."""
    projectile, kw = case
    a = pencore.simulate(projectile, "soil", **TIGHT, **kw)
    b = pencore.simulate(projectile, "soil", method="BDF", **TIGHT, **kw)
    assert a.attrs["outcome"] == b.attrs["outcome"]
    assert a.attrs["reversed"] == b.attrs["reversed"]
    for name in ("penetration_depth", "path_length"):
        assert float(a[name]) == pytest.approx(float(b[name]), rel=1e-4)
    assert float(a.final_deviation) == pytest.approx(float(b.final_deviation), abs=1e-3)


@pytest.mark.parametrize("case", CASES[:3], ids=[_ids(c) for c in CASES[:3]])
def test_default_numerics_within_the_convergence_bound_of_solve_ivp(case):
    """The defaults' depth and path lie within 2e-3 of a tight solve_ivp solution: the
    convergence study (benchmarks/results/convergence.csv) bounds the default numerics'
    effect on both at 0.15 %."""
    projectile, kw = case
    a = pencore.simulate(projectile, "soil", **kw)
    b = pencore.simulate(projectile, "soil", method="Radau", **TIGHT, **kw)
    for name in ("penetration_depth", "path_length"):
        assert float(a[name]) == pytest.approx(float(b[name]), rel=2e-3)


_CHILD = """
import hashlib, json, sys
import pencore
ds = pencore.simulate("p4", "soil", 700.0, yaw=1.0, omega=-10.0)
h = hashlib.sha256()
for name in sorted(ds.data_vars):
    h.update(name.encode()); h.update(ds[name].values.tobytes())
h.update(ds.time.values.tobytes())
print(json.dumps({"sha": h.hexdigest(), "n": ds.sizes["time"]}))
"""


def test_two_processes_give_identical_arrays():
    """Same code, same machine, same inputs: the same bits, in two fresh processes."""
    out = [
        json.loads(
            subprocess.run(
                [sys.executable, "-c", _CHILD],
                capture_output=True,
                text=True,
                check=True,
                timeout=300,
            )
            .stdout.strip()
            .splitlines()[-1]
        )
        for _ in range(2)
    ]
    assert out[0] == out[1]
    assert out[0]["n"] > 100


def test_method_is_checked():
    with pytest.raises(pencore.InputError, match="did you mean 'Radau'"):
        pencore.simulate("p2", "soil", 300.0, method="radau")


def test_reference_reports_the_same_fields():
    a = pencore.simulate("p2", "soil", 300.0)
    b = pencore.simulate("p2", "soil", 300.0, method="BDF")
    assert set(a.variables) == set(b.variables)
    assert b.attrs["t_first_contact_s"] >= 0.0
    assert np.all(np.diff(b.time.values) > 0)


def test_budget_failure_reports_the_last_accepted_step():
    """The step budget is enforced inside the right-hand side; the message reports the
    last step accepted before it ran out (time, count, position, speed), which is the
    same step of the same run without the budget, and no more steps than the calls allow."""
    full = pencore.simulate("p2", "soil", 300.0, method="Radau")
    max_steps = 10
    with pytest.raises(pencore.SolverError) as info:
        pencore.simulate("p2", "soil", 300.0, method="Radau", max_steps=max_steps)
    msg = str(info.value)
    assert f"step budget of {max_steps} steps ({CALLS_PER_STEP * max_steps} right-hand" in msg
    m = re.search(
        r"at t = (\S+) s after (\d+) steps the centre of mass was at "
        r"\((\S+), (\S+), (\S+)\) m moving at (\S+) m/s$",
        msg,
    )
    assert m is not None, msg
    t, n, cm_y, speed = float(m[1]), int(m[2]), float(m[4]), float(m[6])
    assert 0 < n <= CALLS_PER_STEP * max_steps
    assert n < full.sizes["time"] - 1
    # printed to 4 significant digits
    assert t == pytest.approx(float(full.time[n]), rel=1e-3)
    assert cm_y == pytest.approx(float(full.cm_y[n]), rel=1e-3)
    assert speed == pytest.approx(float(full.speed[n]), rel=1e-3)
