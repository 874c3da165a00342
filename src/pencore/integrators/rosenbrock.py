"""Time integration of a penetration trajectory.

Scheme: the linearly implicit Rosenbrock (2,3) pair of Shampine & Reichelt (1997), the
formula behind MATLAB's ``ode23s``: second order, L-stable, with a third-order error
estimate and adaptive steps. It is used because the smoothed contact step of
:mod:`pencore.kernels.dynamics` is stiff: on a shank moving almost straight, the lateral force
changes by ``~a0 * area`` over a normal-velocity band of ``2 eps``, an eigenvalue of
order ``1e6-1e8 1/s`` that would force an explicit scheme to sub-microsecond steps. The
implicit stages hold the shank in that band (the sliding mode of the discontinuous law)
at the cost of a Jacobian per step.

Jacobian: the kinematic rows are exact; the force and moment derivatives with respect to
the velocities are closed form (:mod:`pencore.kernels.jacobian`) where the model allows it, else
finite differences; the derivatives with respect to position and attitude are left out
(they are not stiff), which the error control absorbs.

Held Jacobian (``jacobian_age`` > 1): the Jacobian may be kept for several accepted steps.
The pair stays consistent because its second-order solution is a W-method (Shampine &
Reichelt 1997, Sec. 3; Hairer & Wanner IV.7): the order conditions of the propagated
solution ``y + h k2`` up to order 2 do not involve the matrix in ``I - h d J``, so the
step keeps order 2 for any ``J`` (only its stability depends on ``J`` being close to the
true one; the omitted position derivatives above already make every ``J`` inexact). The
third-order companion is third order only with the exact Jacobian; with a held one the
estimate ``h/6 (k1 - 2 k2 + k3)`` is still a difference of a second-order solution and
a solution at least second order, so it stays an asymptotically correct, if
conservative, measure of the local error of the second-order step. What keeps it honest
in practice is that a rejected step rebuilds a held Jacobian before it is retried, and
the body entering or leaving the target rebuilds it (:func:`integrate_chunk`); the
default age is chosen by ``benchmarks/bench_jacobian.py``.

Structure (as scipy's ``_ivp`` separates them): ``_jacobian`` builds the Jacobian,
``_attempt`` takes one Rosenbrock step and returns its error norm,
``_next_step`` is the step-size controller, :func:`~pencore.kernels.state.stop_code` holds
the stopping
events, and :func:`integrate_chunk` records accepted steps. ``integrate_chunk`` returns
to Python every ``n_max`` steps with its state in two small arrays, so that a run can be
interrupted (Ctrl-C), bounded in wall time, and its results grown as needed instead of
preallocated (:func:`pencore.run.impact.simulate` drives it).

Stopping: the run ends when, after first contact, the speed falls below ``v_stop``
(``stopped``), no part of the body is below the surface any more (``exited``), the
centre-of-mass velocity turns towards the surface while in the target and
``stop_at_reversal`` is set (``reversed``), the whole body is below the rear face of a
finite target and moving away from it (``perforated``, :func:`pencore.kernels.state.perforated`),
or ``t_max`` is reached (``time_limit``).
It fails with ``step_underflow`` when the step needed for the error tolerance falls below
``h_min`` (a stiff or chattering right-hand side, e.g. ``eps = 0``) and with
``non_finite`` when the state stops being finite (a runaway).
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
    leaving,
    path_of,
    reserve_path,
    stalled,
    start_path,
)
from pencore.integrators.problem import Problem
from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP, push_path
from pencore.kernels.forces import rhs_model
from pencore.kernels.jacobian import analytic_jacobian_applies, velocity_jacobian
from pencore.kernels.state import (
    NON_FINITE,
    NY,
    OUTCOMES,
    PERFORATED,
    RUNNING,
    SF_CLEAR,
    SF_ERR,
    SF_H,
    SF_T,
    SF_T_CONTACT,
    SI_ENTERED,
    SI_N_JAC,
    SI_N_REJ,
    SI_N_RHS,
    SI_REV,
    STEP_UNDERFLOW,
    body_extent,
    layer_step_bound,
    lu_factor,
    lu_solve,
    normalise_quaternion,
    perforated,
    speed_of,
    stop_code,
)

_D = 1.0 / (2.0 + math.sqrt(2.0))
_E32 = 6.0 + math.sqrt(2.0)


@nb.njit(cache=True)
def _jacobian(
    jac, si, y, f0, clear, reach, mass, inertia, gravity, rings, bounds, coef, fric, eps,
    n_gauss, model, analytic=False,
):  # fmt: skip
    """Fill ``jac`` (14 x 14) at state ``y``, and count it and the right-hand-side calls
    it makes in ``si`` (``SI_N_JAC``, ``SI_N_RHS``).

    The velocity columns of the force rows are closed form (:mod:`pencore.kernels.jacobian`)
    when ``analytic`` is set (the caller checks that the model allows it), else one-sided
    finite differences (six right-hand-side calls)."""
    for i in range(NY):
        for j in range(NY):
            jac[i, j] = 0.0
    jac[0, 7] = 1.0
    jac[1, 8] = 1.0
    jac[2, 9] = 1.0
    qw, qx, qy, qz = y[3], y[4], y[5], y[6]
    w1, w2, w3 = y[10], y[11], y[12]
    # d(qdot)/dq
    jac[3, 4] = -0.5 * w1
    jac[3, 5] = -0.5 * w2
    jac[3, 6] = -0.5 * w3
    jac[4, 3] = 0.5 * w1
    jac[4, 5] = 0.5 * w3
    jac[4, 6] = -0.5 * w2
    jac[5, 3] = 0.5 * w2
    jac[5, 4] = -0.5 * w3
    jac[5, 6] = 0.5 * w1
    jac[6, 3] = 0.5 * w3
    jac[6, 4] = 0.5 * w2
    jac[6, 5] = -0.5 * w1
    # d(qdot)/dw
    jac[3, 10] = -0.5 * qx
    jac[3, 11] = -0.5 * qy
    jac[3, 12] = -0.5 * qz
    jac[4, 10] = 0.5 * qw
    jac[4, 11] = -0.5 * qz
    jac[4, 12] = 0.5 * qy
    jac[5, 10] = 0.5 * qz
    jac[5, 11] = 0.5 * qw
    jac[5, 12] = -0.5 * qx
    jac[6, 10] = -0.5 * qy
    jac[6, 11] = 0.5 * qx
    jac[6, 12] = 0.5 * qw
    si[SI_N_JAC] += 1
    if clear > 0.0:
        return
    if analytic:
        velocity_jacobian(jac, y, f0, mass, inertia, gravity, rings, bounds, coef, fric, eps, model)
        return
    speed = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
    wmag = math.sqrt(w1**2 + w2**2 + w3**2)
    for c in range(7, 13):
        yp = y.copy()
        scale = speed if c < 10 else max(wmag, speed / max(reach, 1e-9))
        dlt = 1e-7 * max(scale, 1.0)
        if eps > 0.0:
            dlt = min(dlt, 0.05 * eps) if c < 10 else min(dlt, 0.05 * eps / reach)
        yp[c] += dlt
        fp, _ = rhs_model(
            yp, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model
        )
        for r in range(7, 14):
            jac[r, c] = (fp[r] - f0[r]) / dlt
    si[SI_N_RHS] += 6


@nb.njit(cache=True)
def _attempt(
    h,
    y,
    f0,
    jac,
    wmat,
    piv,
    rtol,
    atol,
    mass,
    inertia,
    gravity,
    rings,
    bounds,
    coef,
    fric,
    eps,
    n_gauss,
    model,
):
    """One Rosenbrock (2,3) step of size ``h``: ``(ynew, f(ynew), clearance, err)``, with
    ``err`` the RMS of the third-order error estimate scaled by ``atol + rtol |y|``."""
    for i in range(NY):
        for j in range(NY):
            wmat[i, j] = -h * _D * jac[i, j]
        wmat[i, i] += 1.0
    lu_factor(wmat, piv)
    k1 = lu_solve(wmat, piv, f0)
    y1 = y + 0.5 * h * k1
    f1, _ = rhs_model(y1, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model)
    k2 = lu_solve(wmat, piv, f1 - k1) + k1
    ynew = y + h * k2
    f2, clear_new = rhs_model(
        ynew, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model
    )
    k3 = lu_solve(wmat, piv, f2 - _E32 * (k2 - f1) - 2.0 * (k1 - f0))
    err = 0.0
    for i in range(13):
        sc = atol[i] + rtol * max(abs(y[i]), abs(ynew[i]))
        e = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]) / sc
        err += e * e
    err = math.sqrt(err / 13.0)
    return ynew, f2, clear_new, err


@nb.njit(cache=True)
def _next_step(h, err):
    """Step-size controller after an accepted step (third-order error estimate)."""
    if err == 0.0:
        return 5.0 * h
    return h * min(5.0, max(0.2, 0.8 * err ** (-1.0 / 3.0)))


@nb.njit(cache=True, nogil=True)
def integrate_chunk(
    y,
    f0,
    sf,
    si,
    n_max,
    t_max,
    rtol,
    atol,
    h_min,
    max_travel,
    v_stop,
    stop_at_reversal,
    mass,
    inertia,
    gravity,
    rings,
    bounds,
    coef,
    fric,
    eps,
    n_gauss,
    reach,
    thin,
    model,
    jacobian_age=1,
    analytic=False,
    stop=None,
    fs=None,
):
    """Advance a trajectory by at most ``n_max`` accepted steps.

    ``y`` (14,) and ``f0`` (its derivative) are updated in place, and so are the float
    state ``sf`` (time, next step, time of first contact, clearance, last error norm;
    indices ``SF_*``) and the integer state ``si`` (entered, reversed, right-hand-side
    calls, rejected steps, Jacobians; indices ``SI_*``). ``reach`` (m) is the body's
    largest distance from its centre of mass to a surface ring; ``thin`` (k, 2) holds
    the top and bottom heights (m) of the target's thin layers and gaps, near which a step
    is bounded so that it cannot carry the body over one
    (:func:`pencore.kernels.state.layer_step_bound`). ``model`` is the kernel tuple of
    :mod:`pencore.kernels.forces`; with the cavity shank model every accepted step extends its
    tip path (rejected steps do not), and the chunk ends early, to be called again with
    a larger path buffer, when the buffer is nearly full.

    The Jacobian is held for up to ``jacobian_age`` accepted steps (1: a fresh one every
    step) and rebuilt at the start of the chunk, whenever the body enters or leaves the
    target (the free-flight Jacobian has no force rows), and before retrying a rejected
    step with a held one; ``analytic`` selects the closed-form velocity Jacobian
    (see ``_jacobian``).

    ``stop`` (int64 array of one, or None) is read before every step and every retried
    step: when ``stop[0]`` is not 0 (Ctrl-C or the wall budget, set by another thread,
    :class:`pencore.integrators.driver.RunGuard`) the chunk ends at once with ``RUNNING``
    and the step in progress is dropped.

    ``fs`` (None, or an (n_max, 14) array): row ``i`` receives the right-hand side at the
    ``i``-th accepted state, as the next step starts from it (evaluated at the step's new
    state before its quaternion is normalised and, with the cavity model, before its tip
    path is extended). None is a specialisation of its own, compiled without the stores:
    a search's runs go as fast as before there was a buffer.

    Returns
    -------
    ts : (k,) times (s) of the accepted steps; ys : (k, 14) states there;
    code : int index into ``OUTCOMES`` (``RUNNING`` when ``n_max`` steps were taken).
    """
    ts = np.empty(n_max)
    ys = np.empty((n_max, NY))
    jac = np.zeros((NY, NY))
    wmat = np.empty((NY, NY))
    piv = np.empty(NY, dtype=np.int64)
    t = sf[SF_T]
    h = sf[SF_H]
    clear = sf[SF_CLEAR]
    k = 0
    age = jacobian_age  # no Jacobian yet
    jac_in_target = clear <= 0.0
    code = RUNNING
    cavity = model[0][0] == SHANK_CAVITY
    path, npath = model[3], model[4]
    lc, spacing = model[1][2], model[1][3]
    halt = np.zeros(1, dtype=np.int64) if stop is None else stop
    while True:
        code = stop_code(y, t, t_max, si[SI_ENTERED] == 1, clear, v_stop)
        if code != RUNNING or k == n_max or halt[0] != 0:
            break
        if cavity and path.shape[0] - npath[0] <= MAX_SAMPLES_PER_STEP:
            break
        speed = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
        wmag = math.sqrt(y[10] ** 2 + y[11] ** 2 + y[12] ** 2)
        hmax = max_travel / max(speed, 1e-3)
        if clear > 0.0:
            # free flight: do not step past the first touch of the surface
            hmax = min(hmax, max(clear, 1e-6 * reach) / max(speed + wmag * reach, 1e-3))
        if thin.shape[0] > 0:
            # near a thin layer or gap: do not step over it
            hmax = min(hmax, layer_step_bound(y, rings, thin, reach))
        h = min(h, hmax, t_max - t)
        in_target = clear <= 0.0
        if age >= jacobian_age or in_target != jac_in_target:
            _jacobian(
                jac, si, y, f0, clear, reach, mass, inertia, gravity, rings, bounds, coef,
                fric, eps, n_gauss, model, analytic,
            )  # fmt: skip
            age = 0
            jac_in_target = in_target
        rejected = False
        while True:
            ynew, f2, clear_new, err = _attempt(
                h, y, f0, jac, wmat, piv, rtol, atol, mass, inertia, gravity, rings,
                bounds, coef, fric, eps, n_gauss, model,
            )  # fmt: skip
            si[SI_N_RHS] += 2
            if err <= 1.0:
                break
            si[SI_N_REJ] += 1
            rejected = True
            if age > 0:
                # a held Jacobian may be what failed: rebuild it before shrinking the step
                _jacobian(
                    jac, si, y, f0, clear, reach, mass, inertia, gravity, rings, bounds,
                    coef, fric, eps, n_gauss, model, analytic,
                )  # fmt: skip
                age = 0
            if not math.isfinite(err):
                h = 0.2 * h
            else:
                h = h * max(0.2, 0.8 * err ** (-1.0 / 3.0))
            if h < h_min or halt[0] != 0:
                break
        if halt[0] != 0 and not (err <= 1.0):
            break
        if not (err <= 1.0):
            code = STEP_UNDERFLOW if math.isfinite(err) else NON_FINITE
            sf[SF_ERR] = err
            break
        t += h
        normalise_quaternion(ynew)
        finite = True
        for i in range(NY):
            if not math.isfinite(ynew[i]):
                finite = False
        if not finite:
            code = NON_FINITE
            break
        if cavity:
            push_path(path, npath, y, ynew, h, lc, spacing)
        y[:] = ynew
        f0[:] = f2
        clear = clear_new
        age += 1
        ts[k] = t
        ys[k] = y
        if fs is not None:
            fs[k] = f0
        k += 1
        if si[SI_ENTERED] == 0 and clear <= 0.0:
            si[SI_ENTERED] = 1
            sf[SF_T_CONTACT] = t
        if si[SI_ENTERED] == 1 and clear <= 0.0 and y[8] >= 0.0 and si[SI_REV] == 0:
            if speed_of(y) >= v_stop:
                si[SI_REV] = 1
                if stop_at_reversal:
                    code = 3
                    break
        if si[SI_ENTERED] == 1 and perforated(y, rings, bounds):
            code = PERFORATED
            break
        h_acc = h
        h = _next_step(h, err)
        if rejected:
            h = min(h, h_acc)
    sf[SF_T] = t
    sf[SF_H] = h
    sf[SF_CLEAR] = clear
    return ts[:k], ys[:k], code


def integrate(
    problem: Problem,
    y0: np.ndarray,
    velocity: float,
    *,
    stop_at_reversal: bool = False,
    keep_derivatives: bool = False,
) -> RunResult:
    """Integrate one trajectory from state ``y0`` (SI units) with the Rosenbrock pair.

    Drives :func:`integrate_chunk` ``CHUNK_STEPS`` accepted steps at a time, so results
    grow as needed; the run is bounded by ``max_steps`` accepted steps (outcome
    ``step_limit``) and ``max_wall`` seconds of wall time (outcome ``wall_limit``, looked
    at on a time basis, :class:`~pencore.integrators.driver.RunGuard`), and Ctrl-C raises
    ``KeyboardInterrupt`` after the step in progress. A chunk of
    ``CHUNK_STEPS`` accepted steps that moves the centre of mass less than
    ``stall_distance`` (m) and changes its speed by less than 1 % ends the run as
    ``chatter``: the steps are accepted, but so small that the run would only end at
    ``max_steps`` (the discontinuous law, ``eps = 0``, does this on an oblique shank:
    steps of ~1e-8 s). A run slowing to a stop changes its speed by far more than 1 %
    over 500 steps, so it is not mistaken for one; nor is a body backing out of the
    target at a pace that takes it out within the step budget
    (:func:`~pencore.integrators.driver.leaving`: a slow rebound, whose steps the
    creeping lateral contact of its shank holds to ~1e-7 s).

    ``problem`` carries the arrays and the numerics
    (:class:`~pencore.integrators.problem.Problem`); ``velocity``
    (m/s) is the impact speed, which sets the absolute tolerances
    (:meth:`~pencore.integrators.problem.Problem.atol`). ``numerics.jacobian_age`` is the most
    accepted steps a
    Jacobian is held for (see :func:`integrate_chunk` and the module notes on the
    W-method property); ``numerics.jacobian`` is ``"analytic"`` (closed-form velocity
    derivatives, used where :func:`pencore.kernels.jacobian.analytic_jacobian_applies`)
    or ``"finite_difference"``.

    With ``keep_derivatives`` the run keeps the right-hand side at each saved state
    (``RunResult.fs``, from which :func:`pencore.run.loads.body_loads` reads the loads);
    a search's runs do without.

    Returns
    -------
    RunResult
        ``outcome`` is one of :data:`~pencore.kernels.state.OUTCOMES` (never ``running``)
        or ``wall_limit``.
    """
    with RunGuard(problem.numerics.max_wall) as guard:
        return _integrate(problem, y0, velocity, stop_at_reversal, guard, keep_derivatives)


def _integrate(
    problem: Problem,
    y0: np.ndarray,
    velocity: float,
    stop_at_reversal: bool,
    guard: RunGuard,
    keep: bool,
) -> RunResult:
    """The body of :func:`integrate`, under ``guard``."""
    num = problem.numerics
    t_max, rtol, h_min, v_stop = num.t_max, num.rtol, num.h_min, num.v_stop
    max_steps = num.max_steps
    atol = problem.atol(velocity)
    h_init = 1e-7
    max_travel = num.max_travel
    thin = problem.thin_layers
    stall_distance = problem.stall_distance(CHUNK_STEPS)
    mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model = problem.load_args()
    reach = problem.reach
    y = np.array(y0, dtype=float)
    normalise_quaternion(y)
    model = start_path(model, y)
    f0, clear = rhs_model(y, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model)
    entered = clear <= 0.0
    sf = np.array([0.0, h_init, 0.0 if entered else math.nan, clear, 0.0])
    si = np.array([int(entered), 0, 1, 0, 0], dtype=np.int64)
    analytic = num.jacobian == "analytic" and analytic_jacobian_applies(eps, n_gauss)
    ts_parts = [np.zeros(1)]
    ys_parts = [y[None, :].copy()]
    fs_parts = [f0[None, :].copy()]
    n_saved = 0
    while True:
        n_max = max(0, min(CHUNK_STEPS, max_steps - n_saved))
        model = reserve_path(model, (n_max + 1) * MAX_SAMPLES_PER_STEP)
        fs = np.empty((n_max, NY)) if keep else None
        ts, ys, code = integrate_chunk(
            y, f0, sf, si, n_max, t_max, rtol, atol, h_min, max_travel, v_stop,
            stop_at_reversal, mass, inertia, gravity, rings, bounds, coef, fric, eps,
            n_gauss, reach, thin, model, num.jacobian_age, analytic, guard.stop, fs,
        )  # fmt: skip
        guard.check_interrupt()
        ts_parts.append(ts)
        ys_parts.append(ys)
        if fs is not None:
            fs_parts.append(fs[: ts.size])
        n_saved += ts.size
        if code != RUNNING:
            outcome = OUTCOMES[code]
            break
        if n_saved >= max_steps:
            outcome = "step_limit"
            break
        if ts.size == CHUNK_STEPS and stalled(ys, stall_distance):
            depth = bounds[0, 0] - body_extent(ys[-1], rings)[0]
            if not leaving(ys, depth, max_steps - n_saved):
                outcome = "chatter"
                break
        if guard.out_of_time:
            outcome = "wall_limit"
            break
    return RunResult(
        np.concatenate(ts_parts),
        np.concatenate(ys_parts),
        outcome,
        bool(si[SI_REV]),
        float(sf[SF_T_CONTACT]),
        int(si[SI_N_RHS]),
        int(si[SI_N_REJ]),
        float(sf[SF_ERR]),
        path_of(model),
        int(si[SI_N_JAC]),
        np.concatenate(fs_parts) if keep else None,
    )


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
