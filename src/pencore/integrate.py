"""Time integration of a penetration trajectory.

Scheme: the linearly implicit Rosenbrock (2,3) pair of Shampine & Reichelt (1997), the
formula behind MATLAB's ``ode23s``: second order, L-stable, with a third-order error
estimate and adaptive steps. It is used because the smoothed contact step of
:mod:`pencore.dynamics` is stiff: on a shank moving almost straight, the lateral force
changes by ``~a0 * area`` over a normal-velocity band of ``2 eps``, an eigenvalue of
order ``1e6-1e8 1/s`` that would force an explicit scheme to sub-microsecond steps. The
implicit stages hold the shank in that band (the sliding mode of the discontinuous law)
at the cost of a Jacobian per step.

Jacobian: the kinematic rows are exact; the force and moment derivatives with respect to
the velocities are finite differences; the derivatives with respect to position and
attitude are left out (they are not stiff), which the error control absorbs.

Stopping: the run ends when, after first contact, the speed falls below ``v_stop``
(``stopped``), no part of the body is below the surface any more (``exited``), the
centre-of-mass velocity turns towards the surface while in the target and
``stop_at_reversal`` is set (``reversed``), or ``t_max`` is reached (``time_limit``).
"""

from __future__ import annotations

import hashlib
import math
from pathlib import Path

import numba as nb
import numpy as np

from . import dynamics
from .dynamics import rhs


def _invalidate_stale_cache() -> None:
    """numba keys a cached function on its own file only; ``integrate`` inlines the
    kernel of :mod:`pencore.dynamics`, so drop its cache when that kernel has changed."""
    here = Path(__file__)
    cache_dir = here.parent / "__pycache__"
    digest = hashlib.sha256(Path(dynamics.__file__).read_bytes()).hexdigest()
    stamp = cache_dir / "integrate.kernel-hash"
    try:
        if stamp.exists() and stamp.read_text() == digest:
            return
        for f in cache_dir.glob("integrate.*.nb[ic]"):
            f.unlink()
        cache_dir.mkdir(exist_ok=True)
        stamp.write_text(digest)
    except OSError:  # read-only install: numba falls back to compiling in memory
        pass


_invalidate_stale_cache()

OUTCOMES = ("stopped", "exited", "time_limit", "reversed", "step_limit")
_D = 1.0 / (2.0 + math.sqrt(2.0))
_E32 = 6.0 + math.sqrt(2.0)


@nb.njit(cache=True)
def _lu(a, piv):
    n = a.shape[0]
    for k in range(n):
        p = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                p = i
        piv[k] = p
        if p != k:
            for j in range(n):
                tmp = a[k, j]
                a[k, j] = a[p, j]
                a[p, j] = tmp
        akk = a[k, k]
        for i in range(k + 1, n):
            a[i, k] /= akk
            f = a[i, k]
            if f != 0.0:
                for j in range(k + 1, n):
                    a[i, j] -= f * a[k, j]


@nb.njit(cache=True)
def _solve(lu, piv, b):
    n = lu.shape[0]
    x = b.copy()
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = x[k]
            x[k] = x[p]
            x[p] = tmp
    for i in range(n):
        for j in range(i):
            x[i] -= lu[i, j] * x[j]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, n):
            x[i] -= lu[i, j] * x[j]
        x[i] /= lu[i, i]
    return x


@nb.njit(cache=True)
def _normalise(y):
    n = math.sqrt(y[3] ** 2 + y[4] ** 2 + y[5] ** 2 + y[6] ** 2)
    for k in range(3, 7):
        y[k] /= n


@nb.njit(cache=True)
def integrate(
    y0,
    t_max,
    rtol,
    atol,
    h_init,
    max_travel,
    v_stop,
    stop_at_reversal,
    max_steps,
    mass,
    inertia,
    gravity,
    rings,
    bounds,
    coef,
    fric,
    eps,
    n_gauss,
):
    """Integrate one trajectory.

    Returns
    -------
    ts : (n,) times (s); ys : (n, 14) states at the accepted steps;
    outcome : int index into ``OUTCOMES``; reversed_flag : int;
    t_first_contact : float (s, nan if never); n_rhs : int; n_reject : int.
    """
    ny = 14
    ts = np.empty(max_steps + 1)
    ys = np.empty((max_steps + 1, ny))
    y = y0.copy()
    _normalise(y)
    t = 0.0
    ts[0] = t
    ys[0] = y
    f0, clear = rhs(y, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss)
    n_rhs = 1
    n_rej = 0
    entered = clear <= 0.0
    t_contact = 0.0 if entered else np.nan
    rev = 0
    outcome = 2
    nsave = 1
    h = h_init
    jac = np.zeros((ny, ny))
    wmat = np.empty((ny, ny))
    piv = np.empty(ny, dtype=np.int64)
    # reach of the body from its centre of mass, for the free-flight step bound
    reach = 0.0
    for i in range(rings.shape[0]):
        rr = math.sqrt(rings[i, 0] ** 2 + rings[i, 1] ** 2)
        if rr > reach:
            reach = rr
    while True:
        speed = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
        if entered and speed < v_stop:
            outcome = 0
            break
        if entered and clear > 0.0:
            outcome = 1
            break
        if t >= t_max:
            outcome = 2
            break
        if nsave > max_steps:
            outcome = 4
            break
        wmag = math.sqrt(y[10] ** 2 + y[11] ** 2 + y[12] ** 2)
        hmax = max_travel / max(speed, 1e-3)
        if clear > 0.0:
            # free flight: do not step past the first touch of the surface
            hmax = min(hmax, max(clear, 1e-6 * reach) / max(speed + wmag * reach, 1e-3))
        h = min(h, hmax, t_max - t)
        # ---- Jacobian
        for i in range(ny):
            for j in range(ny):
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
        if clear <= 0.0:
            for c in range(7, 13):
                yp = y.copy()
                scale = speed if c < 10 else max(wmag, speed / max(reach, 1e-9))
                dlt = 1e-7 * max(scale, 1.0)
                if eps > 0.0:
                    dlt = min(dlt, 0.05 * eps) if c < 10 else min(dlt, 0.05 * eps / reach)
                yp[c] += dlt
                fp, _ = rhs(yp, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss)
                n_rhs += 1
                for r in range(7, 14):
                    jac[r, c] = (fp[r] - f0[r]) / dlt
        # ---- step attempts
        while True:
            for i in range(ny):
                for j in range(ny):
                    wmat[i, j] = -h * _D * jac[i, j]
                wmat[i, i] += 1.0
            _lu(wmat, piv)
            k1 = _solve(wmat, piv, f0)
            y1 = y + 0.5 * h * k1
            f1, _ = rhs(y1, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss)
            k2 = _solve(wmat, piv, f1 - k1) + k1
            ynew = y + h * k2
            f2, clear_new = rhs(
                ynew, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss
            )
            k3 = _solve(wmat, piv, f2 - _E32 * (k2 - f1) - 2.0 * (k1 - f0))
            n_rhs += 2
            err = 0.0
            for i in range(13):
                sc = atol[i] + rtol * max(abs(y[i]), abs(ynew[i]))
                e = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]) / sc
                err += e * e
            err = math.sqrt(err / 13.0)
            if err <= 1.0 or h < 1e-12:
                break
            n_rej += 1
            h = h * max(0.2, 0.8 * err ** (-1.0 / 3.0))
        # ---- accept
        t += h
        _normalise(ynew)
        y = ynew
        f0 = f2
        clear = clear_new
        ts[nsave] = t
        ys[nsave] = y
        nsave += 1
        if not entered and clear <= 0.0:
            entered = True
            t_contact = t
        if entered and clear <= 0.0 and y[8] >= 0.0 and rev == 0:
            sp = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
            if sp >= v_stop:
                rev = 1
                if stop_at_reversal:
                    outcome = 3
                    break
        if err == 0.0:
            h = 5.0 * h
        else:
            h = h * min(5.0, max(0.2, 0.8 * err ** (-1.0 / 3.0)))
    return ts[:nsave], ys[:nsave], outcome, rev, t_contact, n_rhs, n_rej
