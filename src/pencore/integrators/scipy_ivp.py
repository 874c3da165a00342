"""Reference integration with :func:`scipy.integrate.solve_ivp` on the same right-hand side.

pencore's default integrator is the compiled Rosenbrock pair of
:mod:`pencore.integrators.rosenbrock`.
This module integrates the same equations (:func:`pencore.kernels.forces.rhs_model`) with one of
scipy's implicit methods (``Radau``, ``BDF``), a well-kept independent implementation that
the tests use to check the compiled one. Select it with ``numerics.method``:
``pencore.simulate(..., method="Radau")``. It is 10-100 times slower.

Differences from the compiled integrator, all below the error tolerance:

* the stopping events (speed below ``v_stop``, the body leaving the target, the first
  reversal) are located by scipy's root finder instead of being taken at step ends;
* the attitude quaternion is normalised inside the right-hand side rather than after each
  step;
* the step bound ``max_travel`` (m) becomes a time bound ``max_travel / V0``; near a thin
  layer the bound of :func:`pencore.kernels.state.layer_step_bound` is set as scipy's
  ``max_step`` before every step (a subclass of the method that sets it; scipy reads it
  at every step);
* the step budget ``max_steps`` counts right-hand-side calls, :data:`CALLS_PER_STEP` to a
  step, and is enforced inside the right-hand side; the same subclass records every
  accepted step, so a run that ends on a budget reports where it got to.

The shank ``"factor"`` model and the panel surface work here too; the cavity model does
not (its nose-tip path grows at accepted steps, which ``solve_ivp`` does not expose).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.integrate import BDF, OdeSolver, Radau, solve_ivp

from pencore.integrators.driver import RunGuard, RunResult
from pencore.integrators.problem import Problem
from pencore.kernels.forces import rhs_model
from pencore.kernels.state import body_top, layer_step_bound

__all__ = ["CALLS_PER_STEP", "integrate_scipy"]

#: Right-hand-side calls allowed per step of the budget ``numerics.max_steps``.
CALLS_PER_STEP = 20


def integrate_scipy(
    problem: Problem, y0: np.ndarray, velocity: float, *, stop_at_reversal: bool = False
) -> RunResult:
    """Integrate one trajectory with ``solve_ivp(method=...)``.

    Parameters are those of :func:`pencore.integrators.rosenbrock.integrate`; the method
    is ``problem.numerics.method`` (``"Radau"`` or ``"BDF"``); ``numerics.max_steps`` and
    ``numerics.max_wall`` bound the number of right-hand-side calls / :data:`CALLS_PER_STEP`
    and the wall time (looked at before every call); a run that ends on one of them
    (outcome ``step_limit`` or ``wall_limit``) returns its accepted steps up to the last
    one. Every compiled call holds SIGINT and is followed by a look at the run's stop
    flag (:class:`~pencore.integrators.driver.RunGuard`), so Ctrl-C raises
    ``KeyboardInterrupt`` after the call in progress.

    Returns
    -------
    pencore.integrators.driver.RunResult
    """
    num = problem.numerics
    method, t_max, rtol, v_stop = num.method, num.t_max, num.rtol, num.v_stop
    max_steps, max_wall = num.max_steps, num.max_wall
    atol = problem.atol(velocity)
    max_travel = num.max_travel
    thin, reach = problem.thin_layers, problem.reach
    args = problem.load_args()
    mass, rings, bounds = problem.mass, args[3], problem.bounds
    # the 14th component is the work of the contact stresses (J): 1 % of rtol x KE0
    atol14 = np.append(atol, 1e-2 * rtol * 0.5 * mass * float(y0[7:10] @ y0[7:10]))
    calls = [0]
    guard = RunGuard(max_wall)
    # the accepted steps (t, y), recorded by the solver: a budget ends the run inside the
    # right-hand side, where solve_ivp's own record of them is lost
    accepted: list[tuple[float, np.ndarray]] = []

    class _Budget(Exception):
        pass

    def compiled(fun: Any, *fargs: Any) -> Any:
        out = fun(*fargs)
        guard.check_interrupt()
        return out

    def state(y: np.ndarray) -> np.ndarray:
        yn = np.array(y, dtype=float)
        yn[3:7] /= math.sqrt(float(yn[3:7] @ yn[3:7]))
        return yn

    def f(t: float, y: np.ndarray) -> np.ndarray:
        calls[0] += 1
        if calls[0] > CALLS_PER_STEP * max_steps:
            raise _Budget("step_limit")
        if guard.out_of_time:
            raise _Budget("wall_limit")
        return compiled(rhs_model, state(y), *args)[0]

    def clearance(t: float, y: np.ndarray) -> float:
        return float(compiled(rhs_model, state(y), *args)[1])

    def slow(t: float, y: np.ndarray) -> float:
        return math.sqrt(float(y[7:10] @ y[7:10])) - v_stop

    def rising(t: float, y: np.ndarray) -> float:
        return float(y[8])

    rear = float(bounds[-1, 1])

    def cleared(t: float, y: np.ndarray) -> float:
        # > 0 once every ring is below the rear face of a finite target
        return rear - float(compiled(body_top, state(y), rings))

    contact = _event(clearance, terminal=False, direction=-1.0)
    left = _event(clearance, terminal=True, direction=1.0)
    stopped = _event(slow, terminal=True, direction=-1.0)
    reversal = _event(rising, terminal=stop_at_reversal, direction=1.0)
    speed0 = math.sqrt(float(y0[7:10] @ y0[7:10]))
    max_step = max_travel / max(speed0, 1e-3)

    def step_bound(y: np.ndarray) -> float:
        # the time bound of the next step: max_step, and near a thin layer that of
        # pencore.kernels.state.layer_step_bound
        return min(max_step, float(compiled(layer_step_bound, state(y), rings, thin, reach)))

    try:
        with guard, np.errstate(over="ignore"):  # scipy's numerical Jacobian probes wide steps
            sol = solve_ivp(
                f,
                (0.0, t_max),
                state(y0),
                method=_solver(method, step_bound if thin.shape[0] else None, accepted.append),
                rtol=rtol,
                atol=atol14,
                max_step=max_step,
                events=(contact, left, stopped, reversal)
                + ((_event(cleared, terminal=True, direction=1.0),) if math.isfinite(rear) else ()),
            )
            t_contact = 0.0 if clearance(0.0, y0) <= 0.0 else math.nan
    except _Budget as exc:
        ts = np.array([0.0] + [t for t, _ in accepted])
        ys = np.array([state(y0)] + [state(y) for _, y in accepted])
        return RunResult(ts, ys, str(exc), False, math.nan, calls[0], 0, math.nan)
    if sol.status == -1:
        return RunResult(sol.t, sol.y.T, "step_underflow", False, math.nan, calls[0], 0, math.inf)
    if sol.t_events[0].size:
        t_contact = float(sol.t_events[0][0]) if math.isnan(t_contact) else t_contact
    outcome = "time_limit"
    if sol.t_events[1].size:
        outcome = "exited"
    elif len(sol.t_events) > 4 and sol.t_events[4].size:
        outcome = "perforated"
    elif sol.t_events[2].size:
        outcome = "stopped"
    elif stop_at_reversal and sol.t_events[3].size:
        outcome = "reversed"
    ys = np.array([state(y) for y in sol.y.T])
    return RunResult(
        sol.t, ys, outcome, bool(sol.t_events[3].size), t_contact, calls[0], 0, math.nan
    )


def _event(fun: Any, *, terminal: bool, direction: float) -> Any:
    fun_ = lambda t, y: fun(t, y)  # noqa: E731 - solve_ivp reads attributes off the callable
    fun_.terminal = terminal
    fun_.direction = direction
    return fun_


def _solver(method: str, bound: Any, record: Any) -> type[OdeSolver]:
    """scipy's ``method`` (``"Radau"`` or ``"BDF"``) that calls ``record((t, y))`` after
    every accepted step and, when ``bound`` is not None, sets ``max_step`` to
    ``bound(y)`` (s) before every step. Recording reads the solver's state and changes
    no number of the solution."""
    base = {"Radau": Radau, "BDF": BDF}[method]

    class Solver(base):  # type: ignore[misc, valid-type]
        def _step_impl(self) -> tuple[bool, str | None]:
            if bound is not None:
                self.max_step = bound(self.y)
            success, message = super()._step_impl()
            if success:
                record((self.t, np.array(self.y)))
            return success, message

    Solver.__name__ = f"{'Bounded' if bound is not None else 'Recorded'}{method}"
    return Solver
