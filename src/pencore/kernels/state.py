"""The state of a run as the compiled integrators see it (compiled).

Outcome codes and the indices of the integrators' scratch arrays, the stopping test,
and small helpers on the state vector: LU factorisation and solve of the 14 x 14
Rosenbrock matrix, quaternion normalisation, the body's reach and extent, the step bound
near thin layers, and the perforation test. The state ``y`` is (x, y, z of the centre of
mass (m), quaternion w, x, y, z, velocity (m/s), angular velocity in body axes (rad/s)).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.bands import band_half_height
from pencore.kernels.cache import use_kernel_cache

#: Outcome names, indexed by the integer codes the compiled integrator returns.
OUTCOMES = (
    "stopped",
    "exited",
    "time_limit",
    "reversed",
    "step_limit",
    "step_underflow",
    "non_finite",
    "running",
    "perforated",
)
STEP_LIMIT = 4
STEP_UNDERFLOW = 5
NON_FINITE = 6
RUNNING = 7
#: The whole body is below the rear face of a finite target, moving away from it.
PERFORATED = 8

#: Indices into the float state array ``sf`` of
#: :func:`pencore.integrators.rosenbrock.integrate_chunk`.
SF_T, SF_H, SF_T_CONTACT, SF_CLEAR, SF_ERR = 0, 1, 2, 3, 4
#: Indices into the integer state array ``si``.
SI_ENTERED, SI_REV, SI_N_RHS, SI_N_REJ, SI_N_JAC = 0, 1, 2, 3, 4

NY = 14


@nb.njit(cache=True)
def lu_factor(a, piv):
    """LU factorisation of ``a`` in place with partial pivoting (rows swapped as
    recorded in ``piv``)."""
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
def lu_solve(lu, piv, b):
    """Solve ``a x = b`` from the factors of :func:`lu_factor`."""
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
def normalise_quaternion(y):
    """Scale the attitude quaternion ``y[3:7]`` of state ``y`` to unit length."""
    n = math.sqrt(y[3] ** 2 + y[4] ** 2 + y[5] ** 2 + y[6] ** 2)
    for k in range(3, 7):
        y[k] /= n


@nb.njit(cache=True)
def body_reach(rings):
    """Largest distance (m) from the centre of mass to a ring: the free-flight step bound."""
    reach = 0.0
    for i in range(rings.shape[0]):
        rr = math.sqrt(rings[i, 0] ** 2 + rings[i, 1] ** 2)
        if rr > reach:
            reach = rr
    return reach


@nb.njit(cache=True)
def body_extent(y, rings):
    """Heights ``y`` (m) of the lowest and the highest point of the surface bands in
    state ``y``: ``(bottom, top)``."""
    n = math.sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    w, x, yq, z = y[3] / n, y[4] / n, y[5] / n, y[6] / n
    r10 = 2 * (x * yq + w * z)
    r11 = w * w - x * x + yq * yq - z * z
    r12 = 2 * (yq * z - w * x)
    rk = math.sqrt(r11 * r11 + r12 * r12)
    top = -np.inf
    bottom = np.inf
    for i in range(rings.shape[0]):
        r = rings[i, 1]
        # the top and bottom of the band the ring stands for
        hb = band_half_height(r10, rk, r, rings[i, 2], rings[i, 3], rings[i, 4])
        h = y[1] + r10 * rings[i, 0] + rk * r + hb
        if h > top:
            top = h
        h = y[1] + r10 * rings[i, 0] - rk * r - hb
        if h < bottom:
            bottom = h
    return bottom, top


@nb.njit(cache=True)
def body_top(y, rings):
    """Height ``y`` (m) of the highest point of the surface bands in state ``y``."""
    return body_extent(y, rings)[1]


@nb.njit(cache=True)
def layer_travel_bound(y, rings, thin):
    """Largest distance (m) a surface point may move in the next step near the target's
    thin layers and gaps, so that no step carries the body over one or through one
    unsampled.

    ``thin`` (k, 3) holds each thin layer's top and bottom heights (m) and its
    half-width ``h`` (m; :attr:`pencore.integrators.problem.Problem.thin_layers`). While
    the body's surface bands span a layer (their height range overlaps it) the bound is
    ``h``; a layer at distance ``d`` from the body allows ``d + h``, so the step that
    reaches it ends at most ``h`` into it. ``inf`` when there is no thin layer."""
    bound = np.inf
    if thin.shape[0] == 0:
        return bound
    bottom, top = body_extent(y, rings)
    for k in range(thin.shape[0]):
        b = thin[k, 2]
        if bottom > thin[k, 0]:
            b += bottom - thin[k, 0]  # the layer lies below the body
        elif top < thin[k, 1]:
            b += thin[k, 1] - top  # the layer lies above the body
        if b < bound:
            bound = b
    return bound


@nb.njit(cache=True)
def layer_step_bound(y, rings, thin, reach):
    """Longest step (s) from state ``y`` that moves no surface point further than
    :func:`layer_travel_bound`: a point moves at most ``|v| + |omega| reach`` (m/s),
    ``reach`` (m) the body's largest distance from its centre of mass to a ring. ``inf``
    when no thin layer bounds the step. Used by every integrator with a step control."""
    bound = layer_travel_bound(y, rings, thin)
    if not bound < np.inf:
        return np.inf
    speed = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
    wmag = math.sqrt(y[10] ** 2 + y[11] ** 2 + y[12] ** 2)
    return bound / max(speed + wmag * reach, 1e-3)


@nb.njit(cache=True)
def perforated(y, rings, bounds):
    """True when the target is finite and every surface ring of state ``y`` lies below
    the rear face of its last plate (``bounds[-1, 1]``) while the centre of mass moves
    away from it (``vy < 0``): no element can be loaded again (no gravity-driven return
    is followed). Always False for a semi-infinite target (rear face ``-inf``)."""
    rear = bounds[bounds.shape[0] - 1, 1]
    if not (rear > -np.inf) or y[8] >= 0.0:
        return False
    return body_top(y, rings) < rear


@nb.njit(cache=True)
def speed_of(y):
    """Speed (m/s) of the centre of mass in state ``y``."""
    return math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)


@nb.njit(cache=True)
def stop_code(y, t, t_max, entered, clear, v_stop):
    """The outcome code if the run must end at this accepted state, else ``RUNNING``."""
    speed = speed_of(y)
    if entered and speed < v_stop:
        return 0
    if entered and clear > 0.0:
        return 1
    if t >= t_max:
        return 2
    return RUNNING


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
