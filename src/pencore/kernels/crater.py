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

Element by element: the loads of the layer are computed as without a crater (every
element's stress from its own normal velocity, the DAFL), and all of them are multiplied by
one factor ``lam = g(s) F_full(V_a) / R``, with ``R`` the DAFL axial resistance of the
embedded part, ``V_a`` the velocity component along the body axis, and ``s`` the depth of
the body's deepest point below the layer's top face over ``k d``. So:

* normal entry: the axial force is ``g(s) F_full(V) = c z``, Forrestal's law, whatever part
  of the nose is embedded;
* oblique or yawed entry: the axial resistance is still Forrestal's ``c z`` in the axial
  speed and the deepest point's depth, and the lateral force and the moment keep the
  ratio to it that the DAFL gives for the embedded elements (the distribution over the
  elements, hence the direction of the load and its centre of pressure, is the DAFL's);
* ``s >= 1``: ``lam = 1`` (the DAFL unchanged); ``s <= 0``: ``lam = 0``. If the embedded
  part has no axial resistance (``R <= 0``, e.g. a side slap), ``lam = g(s)``.

``F_full`` and ``N*`` are the full-nose moments ``B_k = sum 2 pi w na^(k+1)`` over the
rings of the kernel (``na > 0``), so that at full embedment ``lam`` tends to ``g``. ``beta``
uses the ``a2`` term, so the reduction to ``c z`` is exact for Forrestal's law
``a0 + a2 Vn^2``; other terms of the law are scaled by the same ``g``.
"""

from __future__ import annotations

import math

import numba as nb

__all__ = ["has_crater", "crater_shape", "crater_factor"]


@nb.njit(cache=True)
def has_crater(bounds):
    """True when a layer of ``bounds`` (:meth:`pencore.inputs.target.Target.kernel_arrays`)
    has a crater region (column 2 > 0, present only with the near-surface columns)."""
    if bounds.shape[1] < 6:
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
def crater_factor(y, rot, rings, bounds, coef, lay, axial_force, clearance):
    """Factor ``lam`` on every load of layer ``lay`` (module docstring).

    ``axial_force`` (N) is the body-frame axial component of the layer's loads without the
    crater (negative when it resists), ``clearance`` (m) the height of the body's deepest
    point, ``rot`` the rotation matrix of the state ``y``. 1 when the layer has no crater.
    """
    kd = bounds[lay, 2]
    if kd <= 0.0:
        return 1.0
    s = (bounds[lay, 0] - clearance) / kd
    if s >= 1.0:
        return 1.0
    if s <= 0.0:
        return 0.0
    mass = bounds[lay, 5]
    va = rot[0, 0] * y[7] + rot[1, 0] * y[8] + rot[2, 0] * y[9]
    va = max(va, 0.0)
    ncoef = coef.shape[1]
    full = 0.0
    b2 = 0.0
    for i in range(rings.shape[0]):
        na = rings[i, 2]
        if na <= 0.0:
            continue
        base = 2.0 * math.pi * rings[i, 4] * na
        term = base
        vk = 1.0
        for k in range(ncoef):
            full += coef[lay, k] * vk * term
            if k == 2:
                b2 += term
            term *= na
            vk *= va
    if ncoef > 2:
        beta = kd * coef[lay, 2] * b2 / mass
    else:
        beta = 0.0
    g = crater_shape(s, beta)
    resist = -axial_force
    if not resist > 0.0:
        return g
    return g * full / resist
