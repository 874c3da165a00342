"""Closed-form velocity Jacobian of the DAFL ring loads (compiled).

The Rosenbrock integrator (:mod:`pencore.integrators.rosenbrock`) needs the derivatives of the
accelerations with respect to the velocities, where the smoothed contact step makes the
right-hand side stiff. The finite-difference form costs six right-hand-side calls; this
module gives the same matrix in closed form at the cost of about one call.

On a ring the normal velocity is affine in ``cos(phi)`` and ``sin(phi)``
(:mod:`pencore.kernels.dynamics`)::

    Vn(phi) = av + bc cos(phi) + bs sin(phi)
    av = na v1,  bc = nr v2 + q w3,  bs = nr v3 - q w2,  q = nr x1 - na r

and its loads are ``-w B^T (s0, sc, ss)`` with ``s = integral of G(Vn) (1, cos, sin)``
over the loaded arcs, ``G = H_eps sigma`` and ``B`` the 3 x 6 matrix of ``(av, bc, bs)``
against the body velocities ``(v1, v2, v3, w1, w2, w3)``. With the smoothed step
(``eps > 0``) ``G`` is continuous and vanishes at the ends of the arcs that depend on
the velocity (``Vn = -eps``), so differentiating under the integral sign is exact
(Leibniz's rule has no end terms)::

    d(loads)/du = -w B^T S B,   S = integral of G'(Vn) (1, cos, sin) (1, cos, sin)^T

``S`` is symmetric, so the load Jacobian is too, and negative semi-definite where
``G' >= 0``: the frictionless DAFL is a dissipative force derived from a potential in
the velocities. The arc integrals of ``G'`` times the six products of ``1, cos, sin``
are closed form like the loads' (:mod:`pencore.kernels.arcs`).

With the band immersion ramp (:mod:`pencore.kernels.dynamics`) ``G`` carries the band's share
``chi(phi)``, which depends on the position only; the ramps of tilted rings take one
more power of ``cos, sin`` (``_ramp_moments``), closed form as well, and a whole
ring's core needs no trigonometry of arc ends
(``pencore.kernels.arcs._poly_centred_arc_moments``).

The shank bands' step half-width depends on the lateral spin
(:func:`pencore.kernels.bands.band_eps`), which adds ``-w B^T t (d epsr / d(w2, w3))`` to the
``w2, w3`` columns, ``t`` the integrals of ``dG/d(epsr) = -sgn V sigma(V) / (2 epsr^2)``
over the band arcs (no end terms either: ``G`` vanishes at both band edges' ends). That
part is not symmetric; the rest of the matrix is, and all of it is without lateral spin.

Point loads (panels, and the cavity shank's points) are ``-A G(vn) g`` with
``g = (n, p x n)`` and the area ``A`` depending on the position only, so their part is
``-A G'(vn) g g^T`` per point (:func:`pencore.kernels.contact_points.point_loads`), symmetric
and negative semi-definite too (:func:`model_load_jacobian`).

Only the velocity derivatives are formed, as in the finite-difference form: the
position and attitude derivatives are not stiff, and the error control absorbs their
omission. Friction (Gauss quadrature of a ``mu(v_t)`` table) and the sharp law
(``eps = 0``: a jump at the arc ends) are left to finite differences
(``pencore.integrators.rosenbrock._jacobian``).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.inputs.models import SHANK_CAVITY, SURFACE_PANELS
from pencore.kernels.arcs import (
    _MAXD,
    _MAXI,
    TWO_PI,
    _intersect,
    _level_arc,
    _poly_arc_cubic_moments,
    _poly_arc_moments,
    _poly_centred_arc_moments,
    band_regions,
    ring_height_terms,
    side_poly,
)
from pencore.kernels.bands import band_eps, band_half_height
from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.contact_points import point_loads
from pencore.kernels.crater import element_factor, fill_reference, has_crater
from pencore.kernels.dynamics import (
    arc_angles,
    body_velocity,
    near_level,
    quat_to_matrix,
    ring_velocity_terms,
)
from pencore.kernels.wholering import whole_ring_moments
from pencore.kernels.windows import depth_factor

__all__ = [
    "analytic_jacobian_applies",
    "load_jacobian",
    "model_load_jacobian",
    "velocity_jacobian",
]


@nb.njit(cache=True, inline="always")
def _ramp_moments(dpoly, deg, av, kv, phi0, cph, sph, alpha, beta, cy, sy, lo, hi, n, e, cj,
                  dj, out):  # fmt: skip
    """Add to ``out[0:6]`` the integrals of ``P(V) chi`` times ``1, cos, sin, cos^2,
    cos sin, sin^2`` over the arcs, with ``V = av + kv cos(phi - phi0)`` and the band
    share ``chi = alpha - beta cos(phi - phiy)`` (:func:`pencore.kernels.arcs.band_regions`;
    ``cy, sy = cos(phiy), sin(phiy)``), in closed form from the moments of ``P(V)`` up
    to the third power of ``cos, sin`` (:func:`pencore.kernels.arcs._poly_arc_cubic_moments`)."""
    m = np.zeros(10)
    _poly_arc_cubic_moments(dpoly, deg, av, kv, phi0, cph, sph, lo, hi, n, e, cj, dj, m)
    # chi m = alpha m - beta (cy cos + sy sin) m
    out[0] += alpha * m[0] - beta * (cy * m[1] + sy * m[2])
    out[1] += alpha * m[1] - beta * (cy * m[3] + sy * m[4])
    out[2] += alpha * m[2] - beta * (cy * m[4] + sy * m[5])
    out[3] += alpha * m[3] - beta * (cy * m[6] + sy * m[7])
    out[4] += alpha * m[4] - beta * (cy * m[7] + sy * m[8])
    out[5] += alpha * m[5] - beta * (cy * m[8] + sy * m[9])


@nb.njit(cache=True)
def load_jacobian(y, rings, bounds, coef, eps):
    """Derivatives of the frictionless contact loads with respect to the body velocities.

    Parameters
    ----------
    y : (14,) state (see :mod:`pencore.kernels.dynamics`).
    rings, bounds, coef : as :func:`pencore.kernels.dynamics.contact_loads`.
    eps : float
        Half-width of the smoothed contact step (m/s); must be > 0.

    Returns
    -------
    (6, 6) array
        ``d(F1, F2, F3, M1, M2, M3) / d(v1, v2, v3, w1, w2, w3)``, body frame
        (N s/m, N s, N s). Symmetric (see the module notes).
    """
    rot = quat_to_matrix(y[3:7])
    v1, v2, v3 = body_velocity(rot, y)
    w2, w3 = y[11], y[12]
    out = np.zeros((6, 6))
    nlay = bounds.shape[0]
    ncoef = coef.shape[1]
    poly = np.zeros(_MAXD)
    dpoly = np.zeros(_MAXD)
    epoly = np.zeros(_MAXD)
    se = np.zeros(_MAXD + 2)
    scj = np.zeros(_MAXD + 2)
    sdj = np.zeros(_MAXD + 2)
    mom = np.zeros(6)
    emom = np.zeros(6)
    l1lo = np.empty(_MAXI)
    l1hi = np.empty(_MAXI)
    l2lo = np.empty(_MAXI)
    l2hi = np.empty(_MAXI)
    blo = np.empty(_MAXI)
    bhi = np.empty(_MAXI)
    vlo = np.empty(_MAXI)
    vhi = np.empty(_MAXI)
    slo = np.empty(_MAXI)
    shi = np.empty(_MAXI)
    bmat = np.zeros((3, 6))
    rlo = np.empty((4, _MAXI))
    rhi = np.empty((4, _MAXI))
    rn = np.zeros(4, dtype=np.int64)
    rpar = np.empty((4, 3))
    rk = math.sqrt(rot[1, 1] ** 2 + rot[1, 2] ** 2)
    # as in pencore.kernels.dynamics.contact_loads: on a one-layer target without windows, a
    # band clear of the layer's levels is a whole ring of it (or below a plate's
    # bottom); the moments of all such rings are computed together, vectorised
    # (pencore.kernels.wholering.whole_ring_moments, same operations per ring), and added in
    # ring order below, so the Jacobian is bit-identical to the one-ring form
    simple = nlay == 1 and bounds.shape[1] < 5
    n = rings.shape[0]
    geo = np.empty((15, n))  # y0 yk yc ys hb q av bc bs kv cph sph epsr rate need
    # with a crater region, each element's factor as the loads have it (held fixed: its
    # own dependence on the axial speed is left out, see analytic_jacobian_applies)
    crater = has_crater(bounds)
    ref = np.empty((2 + nlay if crater else 0, n))
    if crater:
        fill_reference(
            ref, 0, rings[:, 0], rings[:, 1], rings[:, 2], rings[:, 3], rings[:, 4], bounds,
            coef, v1, eps,
        )  # fmt: skip
    kind = np.empty(n, dtype=np.int64)  # -1 out, -2 general, else slot in the tables
    slot2 = np.empty(n, dtype=np.int64)  # slot in the step-width tables (rate > 0)
    tab = np.empty((4, n))
    tab2 = np.empty((4, n))
    dps = np.empty((2, _MAXD, n))
    eps_ = np.empty((2, _MAXD, n))
    lev = np.empty((2, n))
    lev2 = np.empty((2, n))
    nf = np.int64(0)
    nf2 = np.int64(0)
    last = np.nan
    for i in range(n):
        x1 = rings[i, 0]
        r = rings[i, 1]
        na = rings[i, 2]
        nr = rings[i, 3]
        w = rings[i, 4]
        y0, yk, yc, ys = ring_height_terms(y[1], rot[1, 0], rot[1, 1], rot[1, 2], x1, r)
        hb = band_half_height(rot[1, 0], rk, r, na, nr, w)
        kind[i] = -1
        if y0 - yk - hb > bounds[0, 0]:
            continue
        q, av, bc, bs, kv = ring_velocity_terms(x1, r, na, nr, v1, v2, v3, w2, w3)
        cph = bc / kv if kv > 0.0 else 1.0  # cos(phi0), sin(phi0)
        sph = bs / kv if kv > 0.0 else 0.0
        need = yk == 0.0 or near_level(y0 - yk - hb, y0 + yk + hb, bounds)
        epsr, rate = band_eps(eps, r, na, w, w2, w3)
        for c, v in enumerate((y0, yk, yc, ys, hb, q, av, bc, bs, kv, cph, sph, epsr, rate)):
            geo[c, i] = v
        geo[14, i] = 1.0 if need else 0.0
        kind[i] = -2
        if not (simple and not need):
            continue
        if y0 + yk + hb < bounds[0, 1]:
            kind[i] = -1  # wholly below a plate's bottom face
            continue
        kind[i] = nf
        tab[0, nf], tab[1, nf], tab[2, nf], tab[3, nf] = av, kv, cph, sph
        for side in range(2):
            if epsr != last:  # G' of this side (the same for bands of one step width)
                level, _ = side_poly(coef, 0, epsr, side, poly)
                lev[side, nf] = level
                for c in range(ncoef):
                    dps[side, c, nf] = (c + 1) * poly[c + 1]
            else:
                lev[side, nf] = lev[side, nf - 1]
                for c in range(ncoef):
                    dps[side, c, nf] = dps[side, c, nf - 1]
        last = epsr
        nf += 1
        if rate > 0.0:
            slot2[i] = nf2
            tab2[0, nf2], tab2[1, nf2], tab2[2, nf2], tab2[3, nf2] = av, kv, cph, sph
            for side in range(2):
                _eps_poly(coef, 0, epsr, side, epoly)
                lev2[side, nf2] = lev[side, nf - 1]
                for c in range(ncoef + 1):
                    eps_[side, c, nf2] = epoly[c]
            nf2 += 1
    moms = np.empty((6, nf))
    if nf > 0:
        whole_ring_moments(tab, nf, dps, lev, ncoef - 1, moms)
    emoms = np.empty((6, nf2))
    if nf2 > 0:
        whole_ring_moments(tab2, nf2, eps_, lev2, ncoef, emoms)

    for i in range(n):
        if kind[i] == -1:
            continue
        x1 = rings[i, 0]
        r = rings[i, 1]
        na = rings[i, 2]
        nr = rings[i, 3]
        w = rings[i, 4]
        y0, yk, yc, ys, hb = geo[0, i], geo[1, i], geo[2, i], geo[3, i], geo[4, i]
        q, av, bc, bs, kv = geo[5, i], geo[6, i], geo[7, i], geo[8, i], geo[9, i]
        cph, sph, epsr, rate = geo[10, i], geo[11, i], geo[12, i], geo[13, i]
        need = geo[14, i] != 0.0
        phiy, phi0, cy, sy = 0.0, 0.0, 1.0, 0.0
        if kind[i] < 0:
            phiy, phi0, cy, sy = arc_angles(need, yc, ys, bc, bs, kv)
        bmat[0, 0] = na
        bmat[1, 1] = nr
        bmat[1, 5] = q
        bmat[2, 2] = nr
        bmat[2, 4] = -q
        if kind[i] >= 0:
            _add_btsb(out, na, nr, q, moms[:, kind[i]], -w)
            if rate > 0.0:
                _add_eps_columns(out, bmat, emoms[:, slot2[i]], -w * rate * w2, -w * rate * w3)
            continue
        for lay in range(nlay):
            if y0 + yk + hb < bounds[lay, 1]:
                continue
            wl = w
            if bounds.shape[1] >= 5:
                wl = w * depth_factor(y0, bounds, lay)
                if bounds[lay, 2] > 0.0:
                    wl *= element_factor(y0, bounds[lay, 9] - x1, v1, bounds, coef, lay, ref, 0)
                if wl == 0.0:
                    continue
            nreg = band_regions(
                y0, yk, phiy, hb, bounds[lay, 0], bounds[lay, 1], wl, l1lo, l1hi, l2lo, l2hi,
                blo, bhi, rlo, rhi, rn, rpar,
            )  # fmt: skip
            for g in range(nreg):
                alpha, beta, we = rpar[g, 0], rpar[g, 1], rpar[g, 2]
                for c in range(6):
                    mom[c] = 0.0
                    emom[c] = 0.0
                whole = rn[g] == 1 and rlo[g, 0] == 0.0 and rhi[g, 0] == TWO_PI
                for side in range(2):
                    # G on this side (pencore.kernels.arcs.side_poly); dpoly is G', epoly
                    # d(side's G)/d(epsr) = -sgn V sigma(V) / (2 epsr^2), no end terms
                    level, _ = side_poly(coef, lay, epsr, side, poly)
                    for c in range(ncoef):
                        dpoly[c] = (c + 1) * poly[c + 1]
                    if rate > 0.0:
                        _eps_poly(coef, lay, epsr, side, epoly)
                    if whole and beta == 0.0:
                        # a whole-ring core (chi = alpha): the loaded arc is centred on phi0
                        for c in range(ncoef):
                            dpoly[c] *= alpha
                        _poly_centred_arc_moments(
                            dpoly, ncoef - 1, av, kv, cph, sph, level, se, scj, mom
                        )
                        if rate > 0.0:
                            for c in range(ncoef + 1):
                                epoly[c] *= alpha
                            _poly_centred_arc_moments(
                                epoly, ncoef, av, kv, cph, sph, level, se, scj, emom
                            )
                        continue
                    nv = _level_arc(av, kv, phi0, level, True, vlo, vhi)
                    ns = _intersect(rlo[g], rhi[g], rn[g], vlo, vhi, nv, slo, shi)
                    if ns == 0:
                        continue
                    _region_moments(
                        dpoly, ncoef - 1, av, kv, phi0, cph, sph, alpha, beta, cy, sy, slo,
                        shi, ns, se, scj, sdj, mom,
                    )  # fmt: skip
                    if rate > 0.0:
                        _region_moments(
                            epoly, ncoef, av, kv, phi0, cph, sph, alpha, beta, cy, sy, slo,
                            shi, ns, se, scj, sdj, emom,
                        )  # fmt: skip
                # S = [[1, c, s], [c, cc, cs], [s, cs, ss]]; the loads' Jacobian -w B^T S B
                _add_btsb(out, na, nr, q, mom, -we)
                if rate > 0.0:
                    # the widened band's half-width depends on w2, w3 (band_eps): the
                    # loads' part -w B^T t (d epsr / d(w2, w3)), t the moments above
                    _add_eps_columns(out, bmat, emom, -we * rate * w2, -we * rate * w3)
    return out


@nb.njit(cache=True, inline="always")
def _region_moments(p, deg, av, kv, phi0, cph, sph, alpha, beta, cy, sy, lo, hi, n, e, cj, dj, out):
    """Add to ``out[0:6]`` the moments of ``P(V) chi`` over the arcs of a band region
    (``chi = alpha - beta cos(phi - phiy)``, :func:`pencore.kernels.arcs.band_regions`;
    ``cph, sph`` and ``cy, sy`` the cosines and sines of ``phi0`` and ``phiy``). With
    ``beta = 0`` (a core, or a level band) ``chi = alpha`` is folded into ``p`` (which
    is scaled in place) and the moments are closed form, so a full ring's odd moments
    stay exactly 0; a ramp goes to ``_ramp_moments``."""
    if beta == 0.0:
        for c in range(deg + 1):
            p[c] *= alpha
        _poly_arc_moments(p, deg, av, kv, phi0, cph, sph, lo, hi, n, e, cj, dj, out)
    else:
        _ramp_moments(
            p, deg, av, kv, phi0, cph, sph, alpha, beta, cy, sy, lo, hi, n, e, cj, dj, out
        )


@nb.njit(cache=True, inline="always")
def _eps_poly(coef, lay, eps, side, epoly):
    """Fill ``epoly`` with the derivative of :func:`pencore.kernels.arcs.side_poly`'s
    polynomial with respect to ``eps``: ``-sgn V sigma(V) / (2 eps^2)`` (degree
    ``ncoef``; ``sgn`` +1 on side 0, -1 on side 1)."""
    ncoef = coef.shape[1]
    k = (-1.0 if side == 0 else 1.0) * 0.5 / (eps * eps)
    epoly[0] = 0.0
    for c in range(ncoef):
        epoly[c + 1] = k * coef[lay, c]


@nb.njit(cache=True)
def _add_eps_columns(out, bmat, t, s4, s5):
    """``out[:, 4] += s4 B^T t`` and ``out[:, 5] += s5 B^T t`` (``t = mom[0:3]``)."""
    for a in range(6):
        bt = bmat[0, a] * t[0] + bmat[1, a] * t[1] + bmat[2, a] * t[2]
        out[a, 4] += s4 * bt
        out[a, 5] += s5 * bt


@nb.njit(cache=True, inline="always")
def _add_btsb(out, na, nr, q, mom, scale):
    """``out += scale * B^T S B`` with S the symmetric 3 x 3 of the moments ``mom`` and
    B the ring's 3 x 6 map from ``(v1, v2, v3, w1, w2, w3)`` to ``(av, bc, bs)``: its
    columns are ``(na, 0, 0)``, ``(0, nr, 0)``, ``(0, 0, nr)``, 0, ``(0, 0, -q)`` and
    ``(0, q, 0)`` (module notes), so ``B^T S B`` has 15 distinct non-zero entries,
    written out here instead of a dense triple product."""
    s00, s01, s02, s11, s12, s22 = mom[0], mom[1], mom[2], mom[3], mom[4], mom[5]
    a0 = scale * na
    a1 = scale * nr
    a4 = scale * q
    _add_sym(out, 0, 0, a0 * na * s00)
    _add_sym(out, 0, 1, a0 * nr * s01)
    _add_sym(out, 0, 2, a0 * nr * s02)
    _add_sym(out, 0, 4, -a0 * q * s02)
    _add_sym(out, 0, 5, a0 * q * s01)
    _add_sym(out, 1, 1, a1 * nr * s11)
    _add_sym(out, 1, 2, a1 * nr * s12)
    _add_sym(out, 1, 4, -a1 * q * s12)
    _add_sym(out, 1, 5, a1 * q * s11)
    _add_sym(out, 2, 2, a1 * nr * s22)
    _add_sym(out, 2, 4, -a1 * q * s22)
    _add_sym(out, 2, 5, a1 * q * s12)
    _add_sym(out, 4, 4, a4 * q * s22)
    _add_sym(out, 4, 5, -a4 * q * s12)
    _add_sym(out, 5, 5, a4 * q * s11)


@nb.njit(cache=True, inline="always")
def _add_sym(out, a, b, v):
    """``out[a, b] += v`` and, off the diagonal, ``out[b, a] += v``."""
    out[a, b] += v
    if a != b:
        out[b, a] += v


@nb.njit(cache=True)
def model_load_jacobian(y, rings, bounds, coef, fric, eps, model):
    """:func:`load_jacobian` under ``model`` (:mod:`pencore.kernels.forces`): the rings' part
    unless the surface is panels, plus the point loads' part (panels, or the cavity
    shank's points) from :func:`pencore.kernels.contact_points.point_loads`, whose loads are
    ``-A G(vn) g`` per point with ``A`` depending on the position only."""
    ipar, cav, pts, path, npath = model
    cavity = ipar[0] == SHANK_CAVITY
    # run-time booleans, not literals: a literal bool argument would compile a
    # specialisation of point_loads of its own (the Jacobian is frictionless)
    no_friction = np.bool_(False)
    if ipar[1] == SURFACE_PANELS:
        d = np.zeros((6, 6))
        point_loads(y, pts, bounds, coef, fric, eps, no_friction, cavity, cav, path, npath, d)
        return d
    d = load_jacobian(y, rings, bounds, coef, eps)
    if cavity:
        point_loads(y, pts, bounds, coef, fric, eps, no_friction, cavity, cav, path, npath, d)
    return d


@nb.njit(cache=True)
def velocity_jacobian(jac, y, f0, mass, inertia, gravity, rings, bounds, coef, fric, eps, model):
    """Fill rows 7-13, columns 7-12 of the state Jacobian ``jac`` in closed form.

    The same entries as the finite-difference form of
    ``pencore.integrators.rosenbrock._jacobian``
    (Newton's and Euler's equations and the power of the contact stresses, against the
    fixed-frame velocity ``y[7:10]`` and the body-frame angular velocity ``y[10:13]``),
    from :func:`load_jacobian` and the chain rule: ``v_body = R^T v``, ``dv/dt = R F / m
    + g``, ``dw/dt = (M + gyroscopic terms) / I``, ``dW/dt = F . v_body + M . w``.
    ``f0`` is the state derivative at ``y``; the loads ``F, M`` the power row needs are
    recovered from it.
    """
    rot = quat_to_matrix(y[3:7])
    d = model_load_jacobian(y, rings, bounds, coef, fric, eps, model)
    i1, i2, i3 = inertia[0], inertia[1], inertia[2]
    w1, w2, w3 = y[10], y[11], y[12]
    vb = np.array(body_velocity(rot, y))
    fb = np.empty(3)
    for j in range(3):
        fb[j] = mass * (
            rot[0, j] * (f0[7] - gravity[0])
            + rot[1, j] * (f0[8] - gravity[1])
            + rot[2, j] * (f0[9] - gravity[2])
        )
    mb = np.empty(3)
    mb[0] = f0[10] * i1 - (i2 - i3) * w2 * w3
    mb[1] = f0[11] * i2 - (i3 - i1) * w3 * w1
    mb[2] = f0[12] * i3 - (i1 - i2) * w1 * w2
    # d against the fixed-frame velocity: columns 0-2 of d times R^T
    dv = np.empty((6, 3))
    for a in range(6):
        for b in range(3):
            dv[a, b] = d[a, 0] * rot[b, 0] + d[a, 1] * rot[b, 1] + d[a, 2] * rot[b, 2]
    inert = (i1, i2, i3)
    for a in range(3):
        for b in range(3):
            # translation: R (dF/dv_fixed) / m and R (dF/dw) / m
            jac[7 + a, 7 + b] = (
                rot[a, 0] * dv[0, b] + rot[a, 1] * dv[1, b] + rot[a, 2] * dv[2, b]
            ) / mass
            jac[7 + a, 10 + b] = (
                rot[a, 0] * d[0, 3 + b] + rot[a, 1] * d[1, 3 + b] + rot[a, 2] * d[2, 3 + b]
            ) / mass
            # rotation: (dM/dv_fixed) / I and (dM/dw) / I
            jac[10 + a, 7 + b] = dv[3 + a, b] / inert[a]
            jac[10 + a, 10 + b] = d[3 + a, 3 + b] / inert[a]
    # gyroscopic terms of Euler's equations (I2 = I3 makes the first row vanish)
    jac[10, 11] += (i2 - i3) * w3 / i1
    jac[10, 12] += (i2 - i3) * w2 / i1
    jac[11, 10] += (i3 - i1) * w3 / i2
    jac[11, 12] += (i3 - i1) * w1 / i2
    jac[12, 10] += (i1 - i2) * w2 / i3
    jac[12, 11] += (i1 - i2) * w1 / i3
    # power row: d(F . vb + M . w)
    for b in range(3):
        pv = 0.0
        for j in range(3):
            pv += (
                fb[j]
                + vb[0] * d[0, j]
                + vb[1] * d[1, j]
                + vb[2] * d[2, j]
                + w1 * d[3, j]
                + w2 * d[4, j]
                + w3 * d[5, j]
            ) * rot[b, j]
        jac[13, 7 + b] = pv
        jac[13, 10 + b] = (
            mb[b]
            + vb[0] * d[0, 3 + b]
            + vb[1] * d[1, 3 + b]
            + vb[2] * d[2, 3 + b]
            + w1 * d[3, 3 + b]
            + w2 * d[4, 3 + b]
            + w3 * d[5, 3 + b]
        )


def analytic_jacobian_applies(eps: float, n_gauss: int) -> bool:
    """Whether the closed-form velocity Jacobian (:mod:`pencore.kernels.jacobian`) covers this
    right-hand side: the smoothed step (``eps > 0``) and no friction (``n_gauss == 0``,
    a frictionless target). Every shank model and surface of :mod:`pencore.kernels.forces`
    is covered (rings, panels, the cavity shank's points), and the crater region with each
    element's factor (:func:`pencore.kernels.crater.element_factor`) held fixed: its own
    dependence on the axial speed is smooth and small beside the smoothed step's, and the
    Rosenbrock step is a W-method, whose order does not rest on an exact Jacobian (with the
    finite-difference one instead, a crater run near the map's ballistic limit took 12 820
    steps where the same run without the crater takes 629)."""
    return eps > 0.0 and n_gauss == 0


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
