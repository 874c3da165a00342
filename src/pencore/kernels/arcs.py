"""Arc sets on a surface ring and closed-form integrals over them (compiled).

A ring of the body surface (:mod:`pencore.inputs.geometry`) is parametrised by its angle
``phi``; every quantity the contact law needs on it, the height of its points and
their normal velocity, has the form ``c0 + ck cos(phi - phik)``. The loaded part of a
ring is therefore a union of arcs whose ends are where such a function crosses a level
(``_level_arc``), and the integrals of a polynomial in one of them times ``1``,
``cos`` and ``sin`` (the loads, ``_poly_arc_integrals``) or times their six
products (the velocity Jacobian and the band ramps, ``_poly_arc_moments``) are
closed form: Taylor-shift the polynomial to powers of ``cos(phi - phik)`` and use the
recursions for the integrals of ``cos^j`` and ``cos^j sin``. Where the region is the
whole ring, the loaded arc is centred on ``phik`` and its ends need no trigonometry
(``_poly_centred_arc_integrals``, ``_poly_centred_arc_moments``).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.cache import use_kernel_cache

TWO_PI = 2.0 * math.pi
_MAXI = 16  # max number of arcs in an interval set
_MAXD = 10  # max polynomial degree + 2


# ---------------------------------------------------------------- arc sets on [0, 2pi)


@nb.njit(cache=True, inline="always")
def _arc(center: float, half: float, lo: np.ndarray, hi: np.ndarray) -> int:
    """Write the arc |phi - center| <= half as intervals in [0, 2pi); return the count."""
    if half >= math.pi:
        lo[0] = 0.0
        hi[0] = TWO_PI
        return 1
    if half <= 0.0:
        return 0
    a = (center - half) % TWO_PI
    b = a + 2.0 * half
    if b <= TWO_PI:
        lo[0] = a
        hi[0] = b
        return 1
    lo[0] = a
    hi[0] = TWO_PI
    lo[1] = 0.0
    hi[1] = b - TWO_PI
    return 2


@nb.njit(cache=True, inline="always")
def _intersect(alo, ahi, na, blo, bhi, nb_, olo, ohi) -> int:
    n = np.int64(0)
    for i in range(na):
        for j in range(nb_):
            lo = max(alo[i], blo[j])
            hi = min(ahi[i], bhi[j])
            if hi > lo and n < _MAXI:
                olo[n] = lo
                ohi[n] = hi
                n += 1
    return n


@nb.njit(cache=True, inline="always")
def _level_arc(c0: float, ck: float, phik: float, level: float, above: bool, lo, hi) -> int:
    """Arc set where ``c0 + ck cos(phi - phik) >= level`` (above) or ``<= level``."""
    if ck < 1e-300:
        ok = (c0 >= level) if above else (c0 <= level)
        if ok:
            lo[0] = 0.0
            hi[0] = TWO_PI
            return 1
        return 0
    c = (level - c0) / ck
    if above:  # cos(phi - phik) >= c
        if c <= -1.0:
            return _arc(0.0, math.pi, lo, hi)
        if c > 1.0:
            return 0
        return _arc(phik, math.acos(c), lo, hi)
    # cos(phi - phik) <= c  <=>  |phi - phik - pi| <= pi - acos(c)
    if c >= 1.0:
        return _arc(0.0, math.pi, lo, hi)
    if c < -1.0:
        return 0
    return _arc(phik + math.pi, math.pi - math.acos(c), lo, hi)


@nb.njit(cache=True, inline="always")
def ring_height_terms(ycm, r10, r11, r12, x1, r):
    """Height of a ring's points as ``y0 + yk cos(phi - phiy)``: ``(y0, yk, yc, ys)``
    (m) from the centre-of-mass height ``ycm`` and row 1 of the rotation matrix, with
    ``yk cos(phiy), yk sin(phiy) = yc, ys``. The angle ``phiy = atan2(ys, yc)`` is left
    to the caller: only partial arcs need it."""
    y0 = ycm + r10 * x1
    yc = r11 * r
    ys = r12 * r
    yk = math.sqrt(yc * yc + ys * ys)
    if yk < 1e-12 * r:
        # ring parallel to the surface: a round-off tilt would orient its partial
        # contact arc at random, so it is either wholly in or wholly out
        yk = 0.0
    return y0, yk, yc, ys


@nb.njit(cache=True, inline="always")
def side_poly(coef, lay, eps, side, poly):
    """Fill ``poly`` with the normal stress of layer ``lay`` on one side of the smoothed
    step, as a polynomial in ``Vn``; returns ``(level, degree)``: the stress applies
    where ``Vn >= level``. ``eps = 0``: ``sigma(V)`` from 0 (one side). ``eps > 0``: the
    step ``H_eps sigma`` is the side-0 term ``(V + eps) sigma / (2 eps)`` on
    ``V >= -eps`` minus the side-1 term ``(V - eps) sigma / (2 eps)`` on ``V >= eps``."""
    ncoef = coef.shape[1]
    if eps <= 0.0:
        for c in range(ncoef):
            poly[c] = coef[lay, c]
        return 0.0, ncoef - 1
    inv = 0.5 / eps
    level = -eps if side == 0 else eps
    sgn = 1.0 if side == 0 else -1.0
    for c in range(ncoef + 1):
        poly[c] = 0.0
    for c in range(ncoef):
        poly[c + 1] += sgn * inv * coef[lay, c]
        poly[c] += -sgn * inv * level * coef[lay, c]
    return level, ncoef


# ---------------------------------------------------------------- closed-form arc integrals


@nb.njit(cache=True, inline="always")
def _taylor_shift(poly, deg, a, e):
    """Taylor coefficients ``e`` of ``P(a + x)`` from those of ``P(V) = sum poly[i] V^i``
    (i <= deg), by repeated synthetic division (Horner shifts)."""
    for i in range(deg + 1):
        e[i] = poly[i]
    for j in range(deg):
        for i in range(deg - 1, j - 1, -1):
            e[i] += a * e[i + 1]


@nb.njit(cache=True, inline="always")
def _cos_moments(pa, pb, nc, nd, cj, dj):
    """``cj[j]``, j < nc: integral of ``cos^j`` over ``[pa, pb]`` (rad); ``dj[j]``,
    j < nd: integral of ``cos^j sin``; by the reduction formula (nc >= 2)."""
    ca, sa = math.cos(pa), math.sin(pa)
    cb, sb = math.cos(pb), math.sin(pb)
    cj[0] = pb - pa
    cj[1] = sb - sa
    cpa = ca  # cos^(j-1) at a, starting j = 2
    cpb = cb
    for j in range(2, nc):
        cj[j] = (cpb * sb - cpa * sa) / j + (j - 1) / j * cj[j - 2]
        cpa *= ca
        cpb *= cb
    cpa = ca
    cpb = cb
    for j in range(nd):
        dj[j] = (cpa - cpb) / (j + 1)
        cpa *= ca
        cpb *= cb


@nb.njit(cache=True, inline="always")
def _poly_arc_integrals(poly, deg, a, k, phi0, cph, sph, lo, hi, n, e, cj, dj):
    """Integrals of P(V), P(V) cos(phi), P(V) sin(phi) over the intervals, where
    ``V = a + k cos(phi - phi0)`` and ``P(V) = sum poly[i] V^i`` (i <= deg); ``cph,
    sph`` are ``cos(phi0), sin(phi0)`` (the caller has them without trigonometry).
    ``e, cj, dj`` are scratch arrays of length >= deg + 2."""
    _taylor_shift(poly, deg, a, e)
    s0 = 0.0
    sc = 0.0
    ss = 0.0
    for m in range(n):
        if lo[m] == 0.0 and hi[m] == TWO_PI:
            # whole ring: exact integrals (odd powers and the sine moments vanish), so
            # round-off cannot create a lateral load on an axisymmetric state
            for j in range(deg + 2):
                cj[j] = _full_circle_cos_power(j)
            kp = 1.0
            for j in range(deg + 1):
                f = e[j] * kp
                s0 += f * cj[j]
                sc += f * cph * cj[j + 1]
                ss += f * sph * cj[j + 1]
                kp *= k
            continue
        _cos_moments(lo[m] - phi0, hi[m] - phi0, deg + 2, deg + 1, cj, dj)
        kp = 1.0
        for j in range(deg + 1):
            f = e[j] * kp
            s0 += f * cj[j]
            sc += f * (cph * cj[j + 1] - sph * dj[j])
            ss += f * (cph * dj[j] + sph * cj[j + 1])
            kp *= k
    return s0, sc, ss


@nb.njit(cache=True, inline="always")
def _centred_cos_powers(a, k, level, nc, cj):
    """``cj[j]``, j < nc: integral of ``cos^j psi`` over the arc ``|psi| <= h`` where
    ``a + k cos(psi) >= level`` (``cos h = (level - a) / k``; the whole turn when that
    is <= -1 or ``k = 0`` with ``a >= level``); False when the arc is empty. Only
    ``acos`` is needed: ``sin h = sqrt(1 - cos^2 h)``, and the odd powers of a whole
    turn come out as exact zeros (nc >= 2)."""
    if k < 1e-300:
        if a < level:
            return False
        ch, sh, h = -1.0, 0.0, math.pi
    else:
        c = (level - a) / k
        if c > 1.0:
            return False
        if c <= -1.0:
            ch, sh, h = -1.0, 0.0, math.pi
        else:
            ch, sh, h = c, math.sqrt(1.0 - c * c), math.acos(c)
    cj[0] = 2.0 * h
    cj[1] = 2.0 * sh
    cp = ch  # cos^(j-1) h
    for j in range(2, nc):
        cj[j] = 2.0 * cp * sh / j + (j - 1) / j * cj[j - 2]
        cp *= ch
    return True


@nb.njit(cache=True, inline="always")
def _poly_centred_arc_integrals(poly, deg, a, k, cph, sph, level, e, cj):
    """``_poly_arc_integrals`` over the whole-ring arc where ``V >= level``, with
    ``V = a + k cos(phi - phi0)`` and ``cph, sph = cos(phi0), sin(phi0)``.

    That arc is ``|phi - phi0| <= h`` with ``cos h = (level - a) / k``: symmetric about
    ``phi0``, so the sine moments vanish and its ends need no trigonometry (``cos h``
    is known, ``sin h = sqrt(1 - cos^2 h)``); ``C_j`` is the integral of ``cos^j`` over
    it. The whole ring (``h = pi``) gives exact zeros for the odd ``C_j``. ``e, cj``
    are scratch of length >= deg + 2."""
    if not _centred_cos_powers(a, k, level, deg + 2, cj):
        return 0.0, 0.0, 0.0
    _taylor_shift(poly, deg, a, e)
    s0 = 0.0
    s1 = 0.0
    kp = 1.0
    for j in range(deg + 1):
        f = e[j] * kp
        s0 += f * cj[j]
        s1 += f * cj[j + 1]
        kp *= k
    return s0, cph * s1, sph * s1


@nb.njit(cache=True)
def _poly_centred_arc_moments(poly, deg, a, k, cph, sph, level, e, cj, out):
    """``_poly_arc_moments`` over the whole-ring arc where ``V >= level``, with
    ``V = a + k cos(phi - phi0)`` and ``cph, sph = cos(phi0), sin(phi0)``: adds the six
    moments to ``out[0:6]``.

    As in ``_poly_centred_arc_integrals``, the arc ``|phi - phi0| <= h`` is
    symmetric about ``phi0``, so the moments with an odd power of ``sin(phi - phi0)``
    vanish and only ``acos`` is needed, not the trigonometry of arc ends and of
    ``phi0``. ``e, cj`` are scratch of length >= deg + 3."""
    if not _centred_cos_powers(a, k, level, deg + 3, cj):
        return
    _taylor_shift(poly, deg, a, e)
    i0 = ic = icc = iss = 0.0
    kp = 1.0
    for j in range(deg + 1):
        f = e[j] * kp
        i0 += f * cj[j]
        ic += f * cj[j + 1]
        icc += f * cj[j + 2]
        iss += f * (cj[j] - cj[j + 2])
        kp *= k
    c, s = cph, sph
    out[0] += i0
    out[1] += c * ic
    out[2] += s * ic
    out[3] += c * c * icc + s * s * iss
    out[4] += c * s * (icc - iss)
    out[5] += s * s * icc + c * c * iss


@nb.njit(cache=True, inline="always")
def _full_circle_cos_power(j):
    """Integral of cos^j over a full turn: 0 for odd j, 2 pi (j-1)!!/j!! for even j."""
    if j % 2 == 1:
        return 0.0
    v = TWO_PI
    for i in range(2, j + 1, 2):
        v *= (i - 1.0) / i
    return v


@nb.njit(cache=True, inline="always")
def _arc_cos_moments(lo, hi, phi0, nc, cj, dj):
    """:func:`_cos_moments` of the arc ``[lo, hi]`` in ``psi = phi - phi0``: ``cj[j]``,
    j < nc, and ``dj[j]``, j < nc - 1; a whole turn (``[0, 2 pi]``) exactly, so its odd
    ``C_j`` and all ``D_j`` are zeros, not round-off."""
    if lo == 0.0 and hi == TWO_PI:
        for j in range(nc):
            cj[j] = _full_circle_cos_power(j)
            dj[j] = 0.0
    else:
        _cos_moments(lo - phi0, hi - phi0, nc, nc - 1, cj, dj)


@nb.njit(cache=True)
def _poly_arc_moments(poly, deg, a, k, phi0, cph, sph, lo, hi, n, e, cj, dj, out):
    """Add to ``out[0:6]`` the integrals of ``P(V)`` times ``1, cos, sin, cos^2,
    cos sin, sin^2`` (of ``phi``) over the intervals, with ``V = a + k cos(phi - phi0)``
    and ``P(V) = sum poly[i] V^i`` (i <= deg); ``cph, sph`` are ``cos(phi0),
    sin(phi0)``; ``e, cj, dj`` are scratch of length >= deg + 3."""
    _taylor_shift(poly, deg, a, e)
    # moments in psi = phi - phi0: cos^j psi (C_j) and cos^j psi sin psi (D_j)
    i0 = ic = isn = icc = ics = iss = 0.0
    for m in range(n):
        _arc_cos_moments(lo[m], hi[m], phi0, deg + 3, cj, dj)
        kp = 1.0
        for j in range(deg + 1):
            f = e[j] * kp
            i0 += f * cj[j]
            ic += f * cj[j + 1]
            isn += f * dj[j]
            icc += f * cj[j + 2]
            ics += f * dj[j + 1]
            iss += f * (cj[j] - cj[j + 2])
            kp *= k
    # back to phi: cos phi = c cos psi - s sin psi, sin phi = s cos psi + c sin psi
    c = cph
    s = sph
    out[0] += i0
    out[1] += c * ic - s * isn
    out[2] += s * ic + c * isn
    out[3] += c * c * icc - 2.0 * c * s * ics + s * s * iss
    out[4] += c * s * (icc - iss) + (c * c - s * s) * ics
    out[5] += s * s * icc + 2.0 * c * s * ics + c * c * iss


@nb.njit(cache=True)
def _poly_arc_cubic_moments(poly, deg, a, k, phi0, cph, sph, lo, hi, n, e, cj, dj, out):
    """Add to ``out[0:10]`` the integrals of ``P(V)`` times ``1, c, s, c^2, c s, s^2,
    c^3, c^2 s, c s^2, s^3`` (``c, s = cos(phi), sin(phi)``) over the intervals, with
    ``V = a + k cos(phi - phi0)``, ``P(V) = sum poly[i] V^i`` (i <= deg) and ``cph, sph
    = cos(phi0), sin(phi0)``: ``_poly_arc_moments`` one power further, for the band
    ramps of the velocity Jacobian (:mod:`pencore.kernels.jacobian`), whose share ``chi`` adds
    one factor of ``cos(phi - phiy)``. ``e, cj, dj`` are scratch of length >= deg + 4.

    The moments ``M_pq`` of ``cos^p psi sin^q psi`` (``psi = phi - phi0``, p + q <= 3)
    come from ``C_j`` (``cos^j``) and ``D_j`` (``cos^j sin``) with ``sin^2 = 1 - cos^2``;
    ``c = C u - S v`` and ``s = S u + C v`` (``u, v = cos psi, sin psi``) take them back
    to ``phi``."""
    _taylor_shift(poly, deg, a, e)
    m = np.zeros(10)  # M00, M10, M01, M20, M11, M02, M30, M21, M12, M03
    for i in range(n):
        _arc_cos_moments(lo[i], hi[i], phi0, deg + 4, cj, dj)
        kp = 1.0
        for j in range(deg + 1):
            f = e[j] * kp
            m[0] += f * cj[j]
            m[1] += f * cj[j + 1]
            m[2] += f * dj[j]
            m[3] += f * cj[j + 2]
            m[4] += f * dj[j + 1]
            m[5] += f * (cj[j] - cj[j + 2])
            m[6] += f * cj[j + 3]
            m[7] += f * dj[j + 2]
            m[8] += f * (cj[j + 1] - cj[j + 3])
            m[9] += f * (dj[j] - dj[j + 2])
            kp *= k
    c, s = cph, sph
    cc, ss, cs = c * c, s * s, c * s
    out[0] += m[0]
    out[1] += c * m[1] - s * m[2]
    out[2] += s * m[1] + c * m[2]
    out[3] += cc * m[3] - 2.0 * cs * m[4] + ss * m[5]
    out[4] += cs * (m[3] - m[5]) + (cc - ss) * m[4]
    out[5] += ss * m[3] + 2.0 * cs * m[4] + cc * m[5]
    # (C u - S v)^3, (C u - S v)^2 (S u + C v), (C u - S v) (S u + C v)^2, (S u + C v)^3
    out[6] += c * cc * m[6] - 3.0 * cc * s * m[7] + 3.0 * c * ss * m[8] - s * ss * m[9]
    out[7] += (
        cc * s * m[6] + (c * cc - 2.0 * c * ss) * m[7] + (s * ss - 2.0 * cc * s) * m[8]
        + c * ss * m[9]
    )  # fmt: skip
    out[8] += (
        c * ss * m[6] + (2.0 * cc * s - s * ss) * m[7] + (c * cc - 2.0 * c * ss) * m[8]
        - cc * s * m[9]
    )  # fmt: skip
    out[9] += s * ss * m[6] + 3.0 * ss * c * m[7] + 3.0 * s * cc * m[8] + c * cc * m[9]


@nb.njit(cache=True, inline="always")
def band_regions(
    y0, yk, phiy, hb, top, bot, wl, l1lo, l1hi, l2lo, l2hi, blo, bhi, rlo, rhi, rn, rpar
) -> int:
    """Regions of a ring over which the share of its band inside a layer is affine.

    The band of a ring (half-height ``hb``, m: :func:`pencore.kernels.bands.band_half_height`)
    at angle ``phi`` spans the heights ``y(phi) +- hb`` with ``y(phi) = y0 + yk cos(phi
    - phiy)``; the share of it below a level is the ramp ``R = clip((level - y + hb) /
    (2 hb), 0, 1)``, and the share inside the layer ``[bot, top]`` is ``R(top) -
    R(bot)``. Each level gives a core (``y <= level - hb``, ``R = 1``) and a ramp
    (``|y - level| < hb``, ``R = alpha - beta cos(phi - phiy)``). Writes up to four
    regions into rows of ``rlo, rhi`` (arcs), ``rn`` (arc counts) and ``rpar`` (alpha,
    beta, signed area weight ``+-wl``); returns their number. The ``l*, b*`` arrays are
    scratch. With ``hb = 0`` this is the sharp test ``bot <= y <= top``.
    """
    nreg = 0
    for edge in range(2):
        level = top if edge == 0 else bot
        if edge == 1 and not (level > -np.inf):
            break
        we = wl if edge == 0 else -wl
        if y0 - yk >= level + hb:
            continue  # the band is wholly above this level
        n = np.int64(0)
        if y0 - yk <= level - hb:
            n = _level_arc(y0, yk, phiy, level - hb, False, l1lo, l1hi)
        if n > 0:
            for m in range(n):
                rlo[nreg, m] = l1lo[m]
                rhi[nreg, m] = l1hi[m]
            rn[nreg] = n
            rpar[nreg, 0] = 1.0
            rpar[nreg, 1] = 0.0
            rpar[nreg, 2] = we
            nreg += 1
        if hb > 0.0 and y0 + yk > level - hb:
            n1 = _level_arc(y0, yk, phiy, level - hb, True, l1lo, l1hi)
            n2 = _level_arc(y0, yk, phiy, level + hb, False, l2lo, l2hi)
            n = _intersect(l1lo, l1hi, n1, l2lo, l2hi, n2, blo, bhi)
            if n > 0:
                for m in range(n):
                    rlo[nreg, m] = blo[m]
                    rhi[nreg, m] = bhi[m]
                rn[nreg] = n
                rpar[nreg, 0] = (level + hb - y0) / (2.0 * hb)
                rpar[nreg, 1] = yk / (2.0 * hb)
                rpar[nreg, 2] = we
                nreg += 1
    return nreg


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
