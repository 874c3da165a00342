"""The closed-form arc integrals of pencore.kernels.arcs against each other and quadrature."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.kernels.arcs import (
    TWO_PI,
    _level_arc,
    _poly_arc_cubic_moments,
    _poly_arc_integrals,
    _poly_arc_moments,
    _poly_centred_arc_integrals,
    _poly_centred_arc_moments,
)

RNG = np.random.default_rng(7)


def _case():
    poly = np.zeros(10)
    deg = int(RNG.integers(0, 4))
    poly[: deg + 1] = RNG.normal(size=deg + 1)
    a, k = RNG.normal(), abs(RNG.normal())
    phi0 = RNG.uniform(0, TWO_PI)
    level = RNG.normal()
    return poly, deg, a, k, phi0, level


@pytest.mark.parametrize("seed", range(40))
def test_centred_arc_equals_the_general_form(seed):
    # the whole-ring fast path against the general arc-set path on the same arc (the
    # two differ by the order of round-off only: 1e-12 of the integrand's scale)
    poly, deg, a, k, phi0, level = _case()
    if seed % 10 == 0:
        k = 0.0  # a ring with no normal-velocity variation: all or nothing
    lo, hi = np.empty(16), np.empty(16)
    n = _level_arc(a, k, phi0, level, True, lo, hi)
    s = np.zeros(12)
    cs = (math.cos(phi0), math.sin(phi0))
    ref = _poly_arc_integrals(poly, deg, a, k, phi0, *cs, lo, hi, n, s.copy(), s.copy(), s.copy())
    got = _poly_centred_arc_integrals(poly, deg, a, k, *cs, level, s.copy(), s.copy())
    scale = np.abs(poly).sum() * (abs(a) + k + 1.0) ** deg * TWO_PI
    assert np.allclose(got, ref, rtol=0.0, atol=1e-12 * scale)


@pytest.mark.parametrize("seed", range(40))
def test_centred_moments_equal_the_general_form(seed):
    # the Jacobian's whole-ring moments against the general arc-set path on the same
    # arc (round-off apart: 1e-12 of the integrand's scale)
    poly, deg, a, k, phi0, level = _case()
    if seed % 10 == 0:
        k = 0.0  # a ring with no normal-velocity variation: all or nothing
    if seed % 10 == 1:
        level = a - k - 1.0  # the whole ring is loaded
        phi0 = 0.0
    lo, hi = np.empty(16), np.empty(16)
    n = _level_arc(a, k, phi0, level, True, lo, hi)
    s = np.zeros(12)
    ref = np.zeros(6)
    cs = (math.cos(phi0), math.sin(phi0))
    _poly_arc_moments(poly, deg, a, k, phi0, *cs, lo, hi, n, s.copy(), s.copy(), s.copy(), ref)
    got = np.zeros(6)
    _poly_centred_arc_moments(poly, deg, a, k, *cs, level, s.copy(), s.copy(), got)
    scale = np.abs(poly).sum() * (abs(a) + k + 1.0) ** deg * TWO_PI
    assert np.allclose(got, ref, rtol=0.0, atol=1e-12 * scale)
    if seed % 10 == 1:
        # symmetric about phi = 0: the sine moments are exact zeros, not round-off
        assert got[2] == 0.0 and got[4] == 0.0


@pytest.mark.parametrize("seed", range(10))
def test_moments_match_quadrature(seed):
    # the six moments against 20000-point midpoint quadrature on the same arcs (error
    # O(h^2 f'') ~ 1e-8 of the scale at h = 3e-4 rad)
    poly, deg, a, k, phi0, level = _case()
    lo, hi = np.empty(16), np.empty(16)
    # an arc not centred on phi0, so the moments odd in sin(phi - phi0) are not 0
    n = _level_arc(a, k, phi0 + 1.3, level, True, lo, hi)
    out = np.zeros(6)
    s = np.zeros(12)
    cs = (math.cos(phi0), math.sin(phi0))
    _poly_arc_moments(poly, deg, a, k, phi0, *cs, lo, hi, n, s.copy(), s.copy(), s.copy(), out)
    ref = np.zeros(6)
    for m in range(n):
        edges = np.linspace(lo[m], hi[m], 20001)
        phi = 0.5 * (edges[1:] + edges[:-1])
        v = a + k * np.cos(phi - phi0)
        p = np.polyval(poly[: deg + 1][::-1], v) * np.diff(edges)
        c, sn = np.cos(phi), np.sin(phi)
        ref += [p.sum(), (p * c).sum(), (p * sn).sum(), (p * c * c).sum(), (p * c * sn).sum(),
                (p * sn * sn).sum()]  # fmt: skip
    scale = np.abs(poly).sum() * (abs(a) + k + 1.0) ** deg * TWO_PI
    assert np.allclose(out, ref, rtol=0.0, atol=1e-7 * scale)


@pytest.mark.parametrize("seed", range(10))
def test_cubic_moments_match_quadrature(seed):
    # the ten moments up to cos, sin cubed (the Jacobian's band ramps) against 20000-point
    # midpoint quadrature on the same arcs (1e-7 of the scale, as above); their first six
    # are the six of _poly_arc_moments
    poly, deg, a, k, phi0, level = _case()
    if seed == 0:
        level = a - k - 1.0  # the whole ring
    lo, hi = np.empty(16), np.empty(16)
    # an arc not centred on phi0, so the moments odd in sin(phi - phi0) are not 0
    n = _level_arc(a, k, phi0 + 1.3, level, True, lo, hi)
    cs = (math.cos(phi0), math.sin(phi0))
    out = np.zeros(10)
    s = np.zeros(12)
    _poly_arc_cubic_moments(
        poly, deg, a, k, phi0, *cs, lo, hi, n, s.copy(), s.copy(), s.copy(), out
    )
    six = np.zeros(6)
    _poly_arc_moments(poly, deg, a, k, phi0, *cs, lo, hi, n, s.copy(), s.copy(), s.copy(), six)
    ref = np.zeros(10)
    for m in range(n):
        edges = np.linspace(lo[m], hi[m], 20001)
        phi = 0.5 * (edges[1:] + edges[:-1])
        p = np.polyval(poly[: deg + 1][::-1], a + k * np.cos(phi - phi0)) * np.diff(edges)
        c, sn = np.cos(phi), np.sin(phi)
        powers = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3)]
        ref += [(p * c**i * sn**j).sum() for i, j in powers]
    scale = np.abs(poly).sum() * (abs(a) + k + 1.0) ** deg * TWO_PI
    assert np.allclose(out, ref, rtol=0.0, atol=1e-7 * scale)
    assert np.allclose(out[:6], six, rtol=0.0, atol=1e-12 * scale)
