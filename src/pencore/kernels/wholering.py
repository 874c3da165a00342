"""Normal-stress integrals of whole immersed rings, all rings at once (numba).

A ring wholly inside one layer, clear of its levels, is loaded on the arc
``|phi - phi0| <= h`` where its normal velocity ``V = av + kv cos(phi - phi0)`` is
above each side's level of the smoothed step (:func:`pencore.kernels.arcs.side_poly`);
``pencore.kernels.arcs._poly_centred_arc_integrals`` integrates one ring and side. This
module does the same operations for many rings with the rings as the innermost loop,
which the compiler turns into vector instructions: the branches and the ``acos`` of the
arc's half-angle stay in a scalar pass, the Taylor shift, the ``cos^j`` recursion and
the sums are branch-free passes over the rings. Each ring's result is the same
sequence of floating-point operations as the one-ring form, so the loads are
bit-identical to it (``tests/kernels/test_dynamics_whole_rings.py``). SI units.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.arcs import _MAXD, side_poly
from pencore.kernels.cache import use_kernel_cache


@nb.njit(cache=True, inline="always")
def _ring_scratch(nf, ncos):
    """Work arrays of :func:`_centred_arcs` (``cj`` with ``ncos`` rows, ``ch, sh, ok,
    cp``), of :func:`_taylor_shift_rings` (``e``) and the powers of ``kv`` (``kp``),
    for ``nf`` rings."""
    return (
        np.empty((ncos, nf)), np.empty((_MAXD, nf)), np.empty(nf), np.empty(nf),
        np.empty(nf), np.empty(nf), np.empty(nf),
    )  # fmt: skip


@nb.njit(cache=True)
def _centred_arcs(av, kv, level, nf, ncos, ok, ch, sh, cp, cj):
    """Per ring m < nf, the arc ``|psi| <= h`` where ``av + kv cos(psi) >= level[m]``
    and the integrals ``cj[j, m]`` (j < ncos) of ``cos^j`` over it, as
    :func:`pencore.kernels.arcs._centred_cos_powers` (same operations); ``ok[m]`` 0 when the
    arc is empty. The end point (branches, ``acos``) in a scalar pass, the recursion
    with the rings innermost (vectorised)."""
    for m in range(nf):
        a = av[m]
        k = kv[m]
        ok[m] = 1.0
        if k < 1e-300:
            if a < level[m]:
                ok[m] = 0.0
            ch[m], sh[m], cj[0, m] = -1.0, 0.0, math.pi
        else:
            c = (level[m] - a) / k
            if c > 1.0:
                ok[m] = 0.0
                ch[m], sh[m], cj[0, m] = 1.0, 0.0, 0.0
            elif c <= -1.0:
                ch[m], sh[m], cj[0, m] = -1.0, 0.0, math.pi
            else:
                ch[m], sh[m], cj[0, m] = c, math.sqrt(1.0 - c * c), math.acos(c)
    for m in range(nf):  # cj[0] held h until here
        cj[0, m] = 2.0 * cj[0, m]
        cj[1, m] = 2.0 * sh[m]
        cp[m] = ch[m]
    for j in range(2, ncos):
        for m in range(nf):
            cj[j, m] = 2.0 * cp[m] * sh[m] / j + (j - 1) / j * cj[j - 2, m]
            cp[m] *= ch[m]


@nb.njit(cache=True)
def _taylor_shift_rings(av, e, deg, nf):
    """``e[:, m]`` := Taylor coefficients of ``P(av[m] + x)`` from those of ``P`` in
    ``e[:, m]``, as :func:`pencore.kernels.arcs._taylor_shift` (same operations), rings
    innermost."""
    for j in range(deg):
        for c in range(deg - 1, j - 1, -1):
            for m in range(nf):
                e[c, m] += av[m] * e[c + 1, m]


@nb.njit(cache=True)
def whole_ring_integrals(tab, nf, coef, nside, out):
    """Integrals of the smoothed-step normal stress over the loaded arcs of ``nf`` whole
    rings of layer 0.

    Parameters
    ----------
    tab : (5, >= nf) array
        Per ring (columns): ``av, kv`` (m/s) of its normal velocity, ``cos, sin`` of
        ``phi0`` and its step half-width ``epsr`` (m/s), in rows 0-4.
    nf : int
        Number of rings (the first ``nf`` columns).
    coef : (nlay, ncoef) array
        Normal-stress coefficients (Pa, Pa s/m, ...); layer 0 is used.
    nside : int
        2 for the smoothed step (``epsr > 0``), 1 for the sharp one.
    out : (3, >= nf) array
        Receives, per ring, the integrals of ``G(V)``, ``G(V) cos(phi)``, ``G(V)
        sin(phi)`` over the turn (Pa rad), summed over the sides in side order.
    """
    cj, e, ch, sh, ok, cp, kp = _ring_scratch(nf, _MAXD + 2)
    s0 = np.empty(nf)
    s1 = np.empty(nf)
    lv = np.empty(nf)
    poly = np.zeros(_MAXD)
    av = tab[0]
    kv = tab[1]
    cph = tab[2]
    sph = tab[3]
    for m in range(nf):
        out[0, m] = 0.0
        out[1, m] = 0.0
        out[2, m] = 0.0
    for side in range(nside):
        # each ring's step polynomial (one per step width) and level
        last = np.nan
        level = 0.0
        deg = np.int64(0)
        for m in range(nf):
            if tab[4, m] != last:
                level, deg = side_poly(coef, 0, tab[4, m], side, poly)
                last = tab[4, m]
            lv[m] = level
            for c in range(deg + 1):
                e[c, m] = poly[c]
        _centred_arcs(av, kv, lv, nf, deg + 2, ok, ch, sh, cp, cj)
        _taylor_shift_rings(av, e, deg, nf)
        for m in range(nf):
            s0[m] = 0.0
            s1[m] = 0.0
            kp[m] = 1.0
        for j in range(deg + 1):
            for m in range(nf):
                f = e[j, m] * kp[m]
                s0[m] += f * cj[j, m]
                s1[m] += f * cj[j + 1, m]
                kp[m] *= kv[m]
        for m in range(nf):
            if ok[m] != 0.0:
                out[0, m] += s0[m]
                out[1, m] += cph[m] * s1[m]
                out[2, m] += sph[m] * s1[m]
            else:
                out[0, m] += 0.0
                out[1, m] += 0.0
                out[2, m] += 0.0


@nb.njit(cache=True)
def whole_ring_moments(tab, nf, polys, levels, deg, out):
    """``pencore.kernels.arcs._poly_centred_arc_moments`` of ``nf`` whole rings at once,
    both sides of the step, rings innermost (the Jacobian's counterpart of
    :func:`whole_ring_integrals`; same operations per ring).

    Parameters
    ----------
    tab : (>= 4, >= nf) array
        Per ring: ``av, kv`` (m/s), ``cos, sin`` of ``phi0`` (rows 0-3).
    nf : int
        Number of rings.
    polys : (2, >= deg + 1, >= nf) array
        Per side and ring, the polynomial in ``V`` to integrate (e.g. ``G'``).
    levels : (2, >= nf) array
        Per side and ring, the level of ``V`` above which it applies (m/s).
    deg : int
        Degree of the polynomials.
    out : (6, >= nf) array
        Receives per ring the six moments (1, c, s, cc, cs, ss of ``phi``), summed over
        the two sides in side order.
    """
    cj, e, ch, sh, ok, cp, kp = _ring_scratch(nf, _MAXD + 3)
    sums = np.empty((4, nf))
    av = tab[0]
    kv = tab[1]
    for m in range(nf):
        for r in range(6):
            out[r, m] = 0.0
    for side in range(2):
        for m in range(nf):
            for c in range(deg + 1):
                e[c, m] = polys[side, c, m]
        _centred_arcs(av, kv, levels[side], nf, deg + 3, ok, ch, sh, cp, cj)
        _taylor_shift_rings(av, e, deg, nf)
        for m in range(nf):
            sums[0, m] = 0.0
            sums[1, m] = 0.0
            sums[2, m] = 0.0
            sums[3, m] = 0.0
            kp[m] = 1.0
        for j in range(deg + 1):
            for m in range(nf):
                f = e[j, m] * kp[m]
                sums[0, m] += f * cj[j, m]
                sums[1, m] += f * cj[j + 1, m]
                sums[2, m] += f * cj[j + 2, m]
                sums[3, m] += f * (cj[j, m] - cj[j + 2, m])
                kp[m] *= kv[m]
        for m in range(nf):
            if ok[m] != 0.0:
                c = tab[2, m]
                s = tab[3, m]
                i0, ic, icc, iss = sums[0, m], sums[1, m], sums[2, m], sums[3, m]
                out[0, m] += i0
                out[1, m] += c * ic
                out[2, m] += s * ic
                out[3, m] += c * c * icc + s * s * iss
                out[4, m] += c * s * (icc - iss)
                out[5, m] += s * s * icc + c * c * iss


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
