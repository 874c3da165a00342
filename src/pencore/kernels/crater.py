"""The near-surface (crater) region of Forrestal et al. (1994), element by element (compiled).

Forrestal, Altman, Cargile & Hanchak, "An empirical equation for penetration depth of
ogive-nose projectiles into concrete targets", IJIE 15 (1994) 395-405 (and Frew et al.,
IJSS 35 (1998) 4235-4250) take the axial force on the nose as linear in the tip depth
``z`` over a crater of ``k d`` (``k = 2`` there)::

    F = c z                          (0 <= z < k d)
    F = pi a^2 (a0 + N* a2 V^2)      (z >= k d),

with ``c`` fixed by continuity at ``z = k d``: ``c k d = pi a^2 (a0 + N* a2 V1^2)``, ``V1``
the speed there. ``c`` depends on the future speed ``V1``, but it is a constant of the
motion, so it can be read off the present state: the crater phase has
``m V^2 = m V1^2 + c ((k d)^2 - z^2)``, and eliminating ``V1`` gives, with ``s = z / (k d)``
and ``beta = pi a^2 N* a2 k d / m``::

    F = g(s) F_full(V),  g(s) = s / (1 + beta (1 - s^2)),  F_full(V) = pi a^2 (a0 + N* a2 V^2)

a force of the present depth and speed only, equal to ``c z`` on every normal trajectory
(``g(0) = 0``, ``g(1) = 1``). The depth is then Forrestal's closed form exactly
(:func:`pencore.closedform.forrestal_crater_depth`).

Element by element: every element's stress is the DAFL's (its own normal velocity and
normal) times one factor of the layer, ``lam(z, V_a) = g(s) F_full(V_a) / R_ref(z, V_a)``,
with ``z`` the tip's depth below the layer's top face (``s = z / (k d)``), ``V_a`` the
velocity component along the body axis, and ``R_ref`` the DAFL axial resistance of the
same body in *normal* entry at tip depth ``z`` and speed ``V_a`` into a half-space of the
layer's medium (evaluated by the kernel itself on that reference state,
:func:`reference_state`, :func:`reference_bounds`). So:

* normal entry: the reference state is the state, and the axial force is
  ``g(s) F_full(V) = c z``, Forrestal's law, whatever part of the nose is embedded;
* oblique or yawed entry: each element carries the factor it would carry in normal
  entry at the same tip depth and axial speed; the distribution of the load over the
  elements (its direction, its centre of pressure) is the DAFL's; the axial load is not
  ``c z`` (a tilted nose has a different part of itself below a given tip depth);
* a plate thinner than the embedded part of the nose: each element carries the
  half-space's factor, on the load the plate really takes, so a thin plate's crater
  load vanishes with its thickness (the plate is a slice of the half-space's crater);
* ``s >= 1``: ``lam = 1`` (the DAFL unchanged); tip above the face: the deepest point's
  depth stands in for ``z`` (a body touching side-first); ``z <= 0``: ``lam = 0``.

``F_full`` and ``N*`` are the full-nose moments ``B_k = sum 2 pi w na^(k+1)`` over the
rings of the kernel (``na > 0``), so that at full embedment ``lam`` tends to ``g``. ``beta``
uses the ``a2`` term, so the reduction to ``c z`` is exact for Forrestal's law
``a0 + a2 Vn^2``; other terms of the law are scaled by the same ``g``.
"""

from __future__ import annotations

import math

import numba as nb

from pencore.kernels.cache import use_kernel_cache

__all__ = [
    "has_crater",
    "crater_shape",
    "crater_depth_and_speed",
    "reference_state",
    "reference_bounds",
    "crater_factor",
]


@nb.njit(cache=True)
def has_crater(bounds):
    """True when a layer of ``bounds`` (:meth:`pencore.inputs.target.Target.kernel_arrays`)
    has a crater region (column 2 > 0; the crater needs all 10 near-surface columns)."""
    if bounds.shape[1] < 10:
        return False
    for lay in range(bounds.shape[0]):
        if bounds[lay, 2] > 0.0:
            return True
    return False


@nb.njit(cache=True)
def crater_shape(s, beta):
    """Forrestal's crater force over the full-nose force at the same speed: ``g(s) =
    s / (1 + beta (1 - s^2))`` for ``0 <= s <= 1`` (``s = z / (k d)``), 0 below, 1 above."""
    if s <= 0.0:
        return 0.0
    if s >= 1.0:
        return 1.0
    return s / (1.0 + beta * (1.0 - s * s))


@nb.njit(cache=True)
def crater_depth_and_speed(y, rot, bounds, lay, clearance):
    """Tip depth ``z`` (m) below the top face of layer ``lay`` (the deepest point's depth
    when the tip is above the face) and the axial speed ``V_a >= 0`` (m/s)."""
    tip = y[1] + rot[1, 0] * bounds[lay, 9]
    z = bounds[lay, 0] - tip
    if z <= 0.0:
        z = bounds[lay, 0] - clearance
    va = rot[0, 0] * y[7] + rot[1, 0] * y[8] + rot[2, 0] * y[9]
    return z, max(va, 0.0)


@nb.njit(cache=True)
def reference_state(y, bounds, lay, z, va):
    """The normal-entry state with the tip ``z`` (m) below the top face of layer ``lay``,
    moving along its axis (``-y``) at ``va`` (m/s), no rotation; other entries of ``y``
    (the work) kept."""
    yr = y.copy()
    yr[0] = 0.0
    yr[1] = bounds[lay, 0] - z + bounds[lay, 9]
    yr[2] = 0.0
    # body axis along -y: a quarter turn about z (exact zeros, as the initial state)
    h = math.sqrt(0.5)
    yr[3] = h
    yr[4] = 0.0
    yr[5] = 0.0
    yr[6] = -h
    yr[7] = 0.0
    yr[8] = -va
    yr[9] = 0.0
    yr[10] = 0.0
    yr[11] = 0.0
    yr[12] = 0.0
    return yr


@nb.njit(cache=True)
def reference_bounds(bounds):
    """The one-layer ``bounds`` (1, 10) as a half-space of the same medium: no rear face
    (bottom ``-inf``, no free-surface zone or plastic-zone ratio at it). Forrestal's
    ``c z`` is a half-space's force, so the reference resistance of a plate is that of
    its medium's half-space: a plate thinner than the nose's embedded part then carries
    the factor the half-space would, on the load it really takes."""
    ref = bounds.copy()
    ref[0, 1] = -math.inf
    ref[0, 4] = 0.0
    ref[0, 7] = 0.0
    return ref


@nb.njit(cache=True)
def crater_factor(y, rings, bounds, coef, lay, z, va, ref_axial_force):
    """Factor ``lam`` on every load of layer ``lay`` (module docstring).

    ``z`` (m) and ``va`` (m/s) from :func:`crater_depth_and_speed`; ``ref_axial_force``
    (N) is the body-frame axial load of the layer on :func:`reference_state` without the
    crater (negative when it resists). 1 when the layer has no crater or ``z >= k d``.
    """
    kd = bounds[lay, 2]
    if kd <= 0.0:
        return 1.0
    s = z / kd
    if s >= 1.0:
        return 1.0
    if s <= 0.0:
        return 0.0
    mass = bounds[lay, 5]
    ncoef = coef.shape[1]
    full = 0.0
    b2 = 0.0
    for i in range(rings.shape[0]):
        na = rings[i, 2]
        if na <= 0.0:
            continue
        term = 2.0 * math.pi * rings[i, 4] * na
        vk = 1.0
        for k in range(ncoef):
            full += coef[lay, k] * vk * term
            if k == 2:
                b2 += term
            term *= na
            vk *= va
    beta = kd * coef[lay, 2] * b2 / mass if ncoef > 2 else 0.0
    g = crater_shape(s, beta)
    resist = -ref_axial_force
    if not resist > 0.0:
        return g
    return g * full / resist


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
