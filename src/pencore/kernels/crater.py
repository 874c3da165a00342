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

Element by element: every element's DAFL stress (its own normal velocity and normal) is
multiplied by the factor of the normal-entry state that puts it at its own depth::

    lam(z_e, V_a) = g(z_e / (k d)) F_full(V_a) / R_q(z_e, V_a),   z_e = h + s_t,

with ``h`` the element's depth below the layer's top face (the ring centre's, for a ring),
``s_t`` its axial distance from the nose tip, ``V_a >= 0`` the body's axial speed,
``F_full = sum_k a_k V^k J_k(L_n)`` the frictionless DAFL axial force on the whole nose in
normal entry, ``J_k(z) = int 2 pi r n_a^k dr`` over the nose's exact profile from the tip
to axial distance ``z`` (the layer's columns; :func:`nose_moment`), and ``R_q(z, V)`` the
model's own quadrature of the normal-entry resistance of the nose tip-first to depth ``z``
(:func:`fill_reference`, :func:`reference_resistance`: each ring's load times the share
of its band below the face). Written against the exact profile's resistance ``R(z)``
(:func:`nose_resistance`), ``lam = Lambda(z_e) R(z_e) / R_q(z_e)``: ``Lambda = g F_full /
R``, the factor Forrestal's law puts on the DAFL, which no ring mesh enters, times the
rings' correction of their own quadrature at that depth, which tends to 1 as the rings
are refined. The correction keeps the load finite at a sharp tip: the rings load their
first band a little before the tip reaches the face, and ``Lambda`` grows like ``1 /
z``, so the product of the two alone would not be. So:

* normal entry: every element has ``z_e = z``, the tip's depth, and one factor
  ``g F_full / R_q(z)``: the axial load is ``g F_full = c z`` on any ring mesh, to
  round-off, with the exact profile's ``N*``;
* oblique or yawed entry (Forrestal's form says nothing there): each element carries the
  factor it would carry in normal entry at its own depth, so an element well below the
  face carries the DAFL's stress times about ``g <= 1`` wherever the tip is; the factor
  exceeds 1 only on the elements near a sharp tip that are themselves near the face
  (where Forrestal's linear force exceeds the DAFL's quadratic resistance of a pointed
  nose). The load's direction and centre of pressure follow the elements; it is not
  ``c z``;
* a plate: ``R_q`` is the medium's half-space resistance (Forrestal's ``c z`` is a
  half-space's force), so a plate thinner than the embedded part of the nose carries
  the half-space's factor on the load it really takes (a slice of the half-space's crater);
* ``z_e >= k d``: ``lam = 1`` (the DAFL unchanged; ``k d >= L_n``, and the step there is
  the rings' ``F_full`` against the exact one, 2e-4 at 48 nose rings); ``z_e <= 0``:
  ``lam = 0``.

``beta`` uses the ``a2`` term and ``J_2(L_n) = pi a^2 N*``, so the reduction to ``c z`` is
exact for Forrestal's law ``a0 + a2 Vn^2``; other terms of the law are scaled by the same
``g``. Friction, where a layer has it, is scaled by the same factor as the normal stress.

Layer columns (:meth:`pencore.inputs.target.Target.kernel_arrays`): 2 ``k d`` (m), 5 the
projectile mass (kg), 8 the body radius ``a`` (m), 9 the tip's axial coordinate (m),
:data:`COL_NOSE` the nose kind (``NOSE_OGIVE``, ``NOSE_CONE``, ``NOSE_FLAT``),
then its parameter (the ogive radius ``2 CRH a``, m; the cone's ``tan`` of its
half-angle), its length ``L_n`` (m), and the full-nose moments ``J_k(L_n)`` (m^2) from
column :data:`COL_MOMENTS` on.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.bands import band_half_height
from pencore.kernels.cache import use_kernel_cache

__all__ = [
    "COL_NOSE",
    "COL_MOMENTS",
    "NOSE_OGIVE",
    "NOSE_CONE",
    "NOSE_FLAT",
    "has_crater",
    "crater_shape",
    "nose_moment",
    "nose_resistance",
    "fill_reference",
    "reference_resistance",
    "element_factor",
]

#: Column of the layer array holding the nose kind; its parameter and length follow.
COL_NOSE = 10
#: First column of the full-nose moments ``J_k(L_n)``, k = 0, 1, ...
COL_MOMENTS = 13
NOSE_OGIVE, NOSE_CONE, NOSE_FLAT = 1.0, 2.0, 3.0

# Gauss-Legendre nodes for the ogive's partial moments: the integrand is smooth on an
# interval of at most pi / 2 in the meridian angle, so 12 points are exact to round-off
# (tests/kernels/test_crater.py checks them against the 96-point full-nose moments)
_GX, _GW = np.polynomial.legendre.leggauss(12)


@nb.njit(cache=True)
def has_crater(bounds):
    """True when a layer of ``bounds`` (:meth:`pencore.inputs.target.Target.kernel_arrays`)
    has a crater region (column 2 > 0; the crater needs the nose columns)."""
    if bounds.shape[1] <= COL_MOMENTS:
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
def nose_moment(z, k, bounds, lay):
    """``J_k(z) = int 2 pi r n_a^k dr`` (m^2) over the nose of layer ``lay``'s columns from
    the tip to axial distance ``z`` (m, clipped to ``[0, L_n]``): the frictionless DAFL
    axial resistance in normal entry is ``sum_k a_k V^k J_k``. Exact profile: tangent ogive
    (meridian angle ``b``, ``r = R_o cos b - (R_o - a)``, ``n_a = sin b``; Gauss-Legendre in
    ``b``), cone ``pi (z tan t)^2 sin^k t``, flat face ``pi a^2``."""
    ln = bounds[lay, COL_NOSE + 2]
    if z >= ln:
        return bounds[lay, COL_MOMENTS + k]
    if z <= 0.0:
        return 0.0
    kind = bounds[lay, COL_NOSE]
    a = bounds[lay, 8]
    if kind == NOSE_FLAT:
        return math.pi * a * a
    if kind == NOSE_CONE:
        tn = bounds[lay, COL_NOSE + 1]
        r = z * tn
        return math.pi * r * r * (tn / math.sqrt(1.0 + tn * tn)) ** k
    ro = bounds[lay, COL_NOSE + 1]
    b_tip = math.asin(min(ln / ro, 1.0))
    b_z = math.asin(min((ln - z) / ro, 1.0))
    half = 0.5 * (b_tip - b_z)
    mid = 0.5 * (b_tip + b_z)
    acc = 0.0
    for j in range(_GX.shape[0]):
        b = mid + half * _GX[j]
        sb = math.sin(b)
        acc += _GW[j] * (ro * math.cos(b) - (ro - a)) * sb ** (k + 1)
    return 2.0 * math.pi * ro * half * acc


@nb.njit(cache=True)
def nose_resistance(z, va, bounds, coef, lay):
    """``R(z, V) = sum_k a_k V^k J_k(z)`` (N): the frictionless DAFL axial resistance of the
    nose of layer ``lay``'s columns tip-first to depth ``z`` (m) at axial speed ``va`` (m/s)
    in normal entry, on the exact profile (:func:`nose_moment`), in one pass."""
    ncoef = coef.shape[1]
    ln = bounds[lay, COL_NOSE + 2]
    if z >= ln or bounds[lay, COL_NOSE] != NOSE_OGIVE:
        out = 0.0
        vk = 1.0
        for k in range(ncoef):
            out += coef[lay, k] * vk * nose_moment(z, k, bounds, lay)
            vk *= va
        return out
    if z <= 0.0:
        return 0.0
    a = bounds[lay, 8]
    ro = bounds[lay, COL_NOSE + 1]
    b_tip = math.asin(min(ln / ro, 1.0))
    b_z = math.asin(min((ln - z) / ro, 1.0))
    half = 0.5 * (b_tip - b_z)
    mid = 0.5 * (b_tip + b_z)
    acc = 0.0
    for j in range(_GX.shape[0]):
        b = mid + half * _GX[j]
        sb = math.sin(b)
        vn = va * sb
        sigma = 0.0
        for k in range(ncoef - 1, -1, -1):
            sigma = sigma * vn + coef[lay, k]
        acc += _GW[j] * (ro * math.cos(b) - (ro - a)) * sb * sigma
    return 2.0 * math.pi * ro * half * acc


@nb.njit(cache=True)
def fill_reference(tab, row0, x1, r, na, nr, w, bounds, coef, va, eps):
    """Rows ``row0`` on of ``tab`` (``2 + n_layers`` by ``n`` elements): the model's own
    quadrature of the normal-entry resistance, element by element. Row ``row0``: the
    element's axial distance from the tip ``s_j = tip - x1`` (m); ``row0 + 1``: the
    half-height of its band's immersion ramp in normal entry (m;
    :func:`pencore.kernels.bands.band_half_height`, 0 for a point); ``row0 + 2 + lay``: its
    axial load in normal entry at axial speed ``va`` (m/s) wholly in layer ``lay``,
    ``2 pi w n_a sigma(V n_a) H_eps(V n_a)`` (N; for a point of area ``w``, ``w n_a sigma
    H_eps``: pass ``r = 0`` and ``w`` already times ``1 / (2 pi)``). ``x1, r, na, nr, w``
    are the element arrays (m, m, -, -, m^2)."""
    tip = bounds[0, 9]
    v = max(va, 0.0)
    ncoef = coef.shape[1]
    for j in range(x1.shape[0]):
        tab[row0, j] = tip - x1[j]
        tab[row0 + 1, j] = band_half_height(-1.0, 0.0, r[j], na[j], nr[j], w[j])
        vn = v * na[j]
        if eps > 0.0:
            h = min(max((vn + eps) / (2.0 * eps), 0.0), 1.0)
        else:
            h = 1.0 if vn >= 0.0 else 0.0
        for lay in range(bounds.shape[0]):
            sigma = 0.0
            for k in range(ncoef - 1, -1, -1):
                sigma = sigma * vn + coef[lay, k]
            tab[row0 + 2 + lay, j] = 2.0 * math.pi * w[j] * na[j] * sigma * h


@nb.njit(cache=True)
def reference_resistance(z, tab, row0, lay):
    """The model's quadrature of the normal-entry axial resistance (N) of layer ``lay``'s
    half-space with the tip ``z`` (m) deep, from the table of :func:`fill_reference`: each
    element's load times the share of its band below the face (the ramp of
    :func:`pencore.kernels.dynamics.contact_loads` in normal entry; a point: 0 or 1)."""
    out = 0.0
    for j in range(tab.shape[1]):
        load = tab[row0 + 2 + lay, j]
        if load == 0.0:
            continue
        d = z - tab[row0, j]
        hb = tab[row0 + 1, j]
        if hb > 0.0:
            share = min(max((d + hb) / (2.0 * hb), 0.0), 1.0)
        else:
            share = 1.0 if d >= 0.0 else 0.0
        out += share * load
    return out


@nb.njit(cache=True)
def element_factor(height, s_tip, va, bounds, coef, lay, tab, row0):
    """Crater factor (module docstring) of an element at ``height`` (m) in layer ``lay``,
    ``s_tip`` (m) from the nose tip along the axis, the body moving at ``va`` (m/s) along
    its axis (negative taken as 0): ``g(z_e / k d) F_full(V_a) / R_q(z_e)`` with ``R_q`` the
    model's quadrature of the normal-entry resistance (:func:`reference_resistance` on the
    table ``tab`` from row ``row0``). 1 when the layer has no crater or ``z_e = top -
    height + s_tip >= k d``, 0 when ``z_e <= 0``."""
    kd = bounds[lay, 2]
    if kd <= 0.0:
        return 1.0
    z = bounds[lay, 0] - height + s_tip
    if z >= kd:
        return 1.0
    if z <= 0.0:
        return 0.0
    v = max(va, 0.0)
    ncoef = coef.shape[1]
    full = 0.0
    vk = 1.0
    for k in range(ncoef):
        full += coef[lay, k] * vk * bounds[lay, COL_MOMENTS + k]
        vk *= v
    beta = 0.0
    if ncoef > 2:
        beta = kd * coef[lay, 2] * bounds[lay, COL_MOMENTS + 2] / bounds[lay, 5]
    g = crater_shape(z / kd, beta)
    resist = reference_resistance(z, tab, row0, lay)
    if not resist > 0.0:
        return g
    return g * full / resist


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
