"""Fixed-step explicit integration: the central-difference scheme of explicit dynamics.

Selected with ``emulation={"integrator": "explicit", "dt": ...}`` (:mod:`pencore.inputs.models`).
It emulates what an explicit finite-element code computes for the paper's model (paper
Sect. 3: ABAQUS/Explicit with a VDLOAD pressure on a rigid body), as opposed to
pencore's converged default (:mod:`pencore.integrators.rosenbrock`):

* central difference (leapfrog): velocities live at half steps, positions and attitude
  at whole steps (the textbook scheme of explicit dynamics, e.g. Belytschko, Liu & Moran,
  *Nonlinear Finite Elements for Continua and Structures*, 2000, Sect. 6.2)::

      v(n+1/2) = v(n-1/2) + dt a(n)           (first step: v(1/2) = v(0) + dt/2 a(0))
      x(n+1)   = x(n) + dt v(n+1/2)
      w(n+1/2) = w(n-1/2) + dt I^-1 (M(n) - w(n-1/2) x I w(n-1/2))     (body frame)
      q(n+1)   = q(n) (x) exp(dt w(n+1/2) / 2)                          (exact rotation)

* the loads at step ``n`` use the positions at ``n`` and the latest velocities,
  ``v(n-1/2)``, ``w(n-1/2)`` (velocity-dependent loads lag half a step);
* the contact step is the pure Heaviside of Eq. 7 (``H(0) = 1``): ``numerics.eps`` is
  not used, as a VDLOAD that tests ``Vn >= 0`` does not smooth it;
* no error control: ``dt`` is fixed. The scheme is second order for smooth loads; with
  the discontinuous shank law the lateral force chatters from step to step and the
  error falls like ``dt`` (``benchmarks/emulation_convergence.py``).

Saved states hold ``x(n)``, ``q(n)`` and the half-step velocities ``v(n-1/2)``,
``w(n-1/2)``, every ``stride`` steps (about every :data:`RECORD_INTERVAL` s), and the
last state; stopping is tested at every step (:func:`pencore.kernels.state.stop_code`). The
work of the contact stresses over a kick is ``F(n) . dt (v(n-1/2) + v(n+1/2)) / 2`` (and
likewise for the moment), so that it balances the kinetic energy of the saved
(half-step) velocities.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.inputs.models import SHANK_CAVITY
from pencore.integrators.driver import (
    CHUNK_STEPS,
    RunGuard,
    RunResult,
    path_of,
    reserve_path,
    start_path,
)
from pencore.integrators.problem import Problem
from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP, push_path
from pencore.kernels.dynamics import quat_to_matrix
from pencore.kernels.forces import model_loads
from pencore.kernels.state import (
    NY,
    OUTCOMES,
    PERFORATED,
    RUNNING,
    SF_CLEAR,
    SF_T,
    SF_T_CONTACT,
    SI_ENTERED,
    SI_N_RHS,
    SI_REV,
    normalise_quaternion,
    perforated,
    speed_of,
    stop_code,
)

__all__ = ["integrate_explicit", "explicit_chunk", "RECORD_INTERVAL"]

#: Time (s) between saved states (at least every step).
RECORD_INTERVAL = 2e-6
#: Index into ``si`` of the "first step taken" flag (the half kick).
SI_STARTED = 4


@nb.njit(cache=True)
def _step(y, dt, first, mass, inertia, gravity, rings, bounds, coef, fric, n_gauss, model):
    """One central-difference step of ``y`` in place; returns the clearance at the start."""
    fb, mb, clear = model_loads(y, rings, bounds, coef, fric, 0.0, n_gauss, model)
    rot = quat_to_matrix(y[3:7])
    kick = 0.5 * dt if first else dt
    fx = rot[0, 0] * fb[0] + rot[0, 1] * fb[1] + rot[0, 2] * fb[2]
    fy = rot[1, 0] * fb[0] + rot[1, 1] * fb[1] + rot[1, 2] * fb[2]
    fz = rot[2, 0] * fb[0] + rot[2, 1] * fb[1] + rot[2, 2] * fb[2]
    v0x, v0y, v0z = y[7], y[8], y[9]
    w1, w2, w3 = y[10], y[11], y[12]
    y[7] += kick * (fx / mass + gravity[0])
    y[8] += kick * (fy / mass + gravity[1])
    y[9] += kick * (fz / mass + gravity[2])
    i1, i2, i3 = inertia[0], inertia[1], inertia[2]
    y[10] += kick * (mb[0] + (i2 - i3) * w2 * w3) / i1
    y[11] += kick * (mb[1] + (i3 - i1) * w3 * w1) / i2
    y[12] += kick * (mb[2] + (i1 - i2) * w1 * w2) / i3
    # work of the loads over the kick, with the mean of the old and new velocities: the
    # translational kinetic energy of the half-step velocities then balances it exactly
    y[13] += 0.5 * kick * (fx * (v0x + y[7]) + fy * (v0y + y[8]) + fz * (v0z + y[9]))
    y[13] += 0.5 * kick * (mb[0] * (w1 + y[10]) + mb[1] * (w2 + y[11]) + mb[2] * (w3 + y[12]))
    # drift
    y[0] += dt * y[7]
    y[1] += dt * y[8]
    y[2] += dt * y[9]
    # attitude: q <- q (x) (cos(|th|/2), sin(|th|/2) th/|th|), th = dt w (body frame)
    t1, t2, t3 = dt * y[10], dt * y[11], dt * y[12]
    ang = math.sqrt(t1 * t1 + t2 * t2 + t3 * t3)
    if ang > 0.0:
        c = math.cos(0.5 * ang)
        s = math.sin(0.5 * ang) / ang
        b0, b1, b2, b3 = c, s * t1, s * t2, s * t3
        a0, a1, a2, a3 = y[3], y[4], y[5], y[6]
        y[3] = a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3
        y[4] = a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2
        y[5] = a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1
        y[6] = a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0
        normalise_quaternion(y)
    return clear


@nb.njit(cache=True, nogil=True)
def explicit_chunk(
    y,
    sf,
    si,
    n_max,
    stride,
    max_steps,
    dt,
    t_max,
    v_stop,
    stop_at_reversal,
    mass,
    inertia,
    gravity,
    rings,
    bounds,
    coef,
    fric,
    n_gauss,
    model,
    stop=None,
):
    """Advance by at most ``n_max`` saved states (``stride`` steps each) or until
    ``max_steps`` steps in all. ``y``, ``sf``, ``si`` are updated in place (indices as
    :func:`pencore.integrators.rosenbrock.integrate_chunk`; ``si[SI_N_RHS]`` counts steps).

    Returns ``ts, ys, code`` as :func:`pencore.integrators.rosenbrock.integrate_chunk`;
    ``stop`` as there (read before every step).
    """
    ts = np.empty(n_max)
    ys = np.empty((n_max, NY))
    t = sf[SF_T]
    clear = sf[SF_CLEAR]
    cavity = model[0][0] == SHANK_CAVITY
    path, npath = model[3], model[4]
    lc, spacing = model[1][2], model[1][3]
    yold = y.copy()
    k = 0
    n = 0
    code = RUNNING
    halt = np.zeros(1, dtype=np.int64) if stop is None else stop
    while k < n_max:
        code = stop_code(y, t, t_max, si[SI_ENTERED] == 1, clear, v_stop)
        if code != RUNNING or si[SI_N_RHS] >= max_steps or halt[0] != 0:
            break
        if cavity and path.shape[0] - npath[0] <= MAX_SAMPLES_PER_STEP:
            break
        yold[:] = y
        clear = _step(
            y, dt, si[SI_STARTED] == 0, mass, inertia, gravity, rings, bounds, coef, fric,
            n_gauss, model,
        )  # fmt: skip
        si[SI_STARTED] = 1
        si[SI_N_RHS] += 1
        t += dt
        n += 1
        finite = True
        for i in range(NY):
            if not math.isfinite(y[i]):
                finite = False
        if not finite:
            code = 6
            break
        if cavity:
            push_path(path, npath, yold, y, dt, lc, spacing)
        if si[SI_ENTERED] == 0 and clear <= 0.0:
            si[SI_ENTERED] = 1
            sf[SF_T_CONTACT] = t
        stop = False
        if si[SI_ENTERED] == 1 and clear <= 0.0 and y[8] >= 0.0 and si[SI_REV] == 0:
            if speed_of(y) >= v_stop:
                si[SI_REV] = 1
                if stop_at_reversal:
                    code = 3
                    stop = True
        if not stop and si[SI_ENTERED] == 1 and perforated(y, rings, bounds):
            code = PERFORATED
            stop = True
        if (
            stop
            or n % stride == 0
            or stop_code(y, t, t_max, si[SI_ENTERED] == 1, clear, v_stop) != RUNNING
        ):
            ts[k] = t
            ys[k] = y
            k += 1
        if stop:
            break
    sf[SF_T] = t
    sf[SF_CLEAR] = clear
    return ts[:k], ys[:k], code


def integrate_explicit(
    problem: Problem, y0: np.ndarray, velocity: float, *, stop_at_reversal: bool = False
) -> RunResult:
    """Integrate one trajectory from ``y0`` (SI units) with fixed steps
    ``problem.emulation.dt`` (s); ``velocity`` (m/s, the impact speed) is not used by a
    fixed-step scheme and is taken for a common signature.

    Same stopping rules and budgets as :func:`pencore.integrators.rosenbrock.integrate`, except that
    ``max_steps`` counts fixed steps (saved or not) and there is no chatter test (a fixed
    step cannot stall). ``RunResult.n_rhs`` is the number of steps (one load
    evaluation each); ``n_rejected`` is 0.
    """
    with RunGuard(problem.numerics.max_wall) as guard:
        return _integrate(problem, y0, stop_at_reversal, guard)


def _integrate(
    problem: Problem, y0: np.ndarray, stop_at_reversal: bool, guard: RunGuard
) -> RunResult:
    """The body of :func:`integrate_explicit`, under ``guard``."""
    num = problem.numerics
    dt, t_max, v_stop = problem.emulation.dt, num.t_max, num.v_stop
    max_steps = num.max_steps
    mass, inertia, gravity, rings, bounds, coef, fric, _, n_gauss, model = problem.load_args()
    y = np.array(y0, dtype=float)
    normalise_quaternion(y)
    model = start_path(model, y)
    fb, mb, clear = model_loads(y, rings, bounds, coef, fric, 0.0, n_gauss, model)
    entered = clear <= 0.0
    sf = np.array([0.0, dt, 0.0 if entered else math.nan, clear, 0.0])
    si = np.array([int(entered), 0, 0, 0, 0], dtype=np.int64)
    stride = max(1, int(round(RECORD_INTERVAL / dt)))
    ts_parts = [np.zeros(1)]
    ys_parts = [y[None, :].copy()]
    while True:
        model = reserve_path(model, 8192)  # the chunk returns early if it fills
        ts, ys, code = explicit_chunk(
            y, sf, si, CHUNK_STEPS, stride, max_steps, dt, t_max, v_stop,
            stop_at_reversal, mass, inertia, gravity, rings, bounds, coef, fric,
            n_gauss, model, guard.stop,
        )  # fmt: skip
        guard.check_interrupt()
        ts_parts.append(ts)
        ys_parts.append(ys)
        if code != RUNNING:
            outcome = OUTCOMES[code]
            break
        if si[SI_N_RHS] >= max_steps:
            outcome = "step_limit"
            break
        if guard.out_of_time:
            outcome = "wall_limit"
            break
    ts_all = np.concatenate(ts_parts)
    ys_all = np.concatenate(ys_parts)
    if ts_all[-1] < sf[SF_T]:  # the last state, if the stride skipped it
        ts_all = np.append(ts_all, sf[SF_T])
        ys_all = np.vstack([ys_all, y[None, :]])
    return RunResult(
        ts_all,
        ys_all,
        outcome,
        bool(si[SI_REV]),
        float(sf[SF_T_CONTACT]),
        int(si[SI_N_RHS]),
        0,
        math.nan,
        path_of(model),
    )


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
