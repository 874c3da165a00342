"""The shank band's widened contact step (pencore.kernels.bands.band_eps): its closed form,
where it applies, and the continuity it gives the shank's load."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.kernels.bands import band_eps
from pencore.kernels.dynamics import contact_loads
from pencore.run.impact import prepare

EPS = 1e-3


def test_band_eps_closed_form_and_rate():
    r, w = 0.05, 0.05 * 0.02  # a shank band 20 mm long
    w2, w3 = 7.0, -24.0  # |lateral spin| 25 rad/s
    epsr, rate = band_eps(EPS, r, 0.0, w, w2, w3)
    # half-width sqrt(eps^2 + s^2) with s = dl/2 |(w2, w3)| = 0.01 m * 25 rad/s
    assert epsr == pytest.approx(math.hypot(EPS, 0.25), rel=1e-14)
    # the rate is d epsr / d w2 = rate w2 (and the same for w3): central differences
    h = 1e-4
    for k in (0, 1):
        up = [w2, w3]
        dn = [w2, w3]
        up[k] += h
        dn[k] -= h
        fd = (band_eps(EPS, r, 0.0, w, *up)[0] - band_eps(EPS, r, 0.0, w, *dn)[0]) / (2 * h)
        assert rate * (w2, w3)[k] == pytest.approx(fd, rel=1e-8)


@pytest.mark.parametrize(
    "r, na, eps, w2, w3",
    [
        (0.05, 0.3, EPS, 7.0, -24.0),  # a nose band: the normal velocity has na v1
        (0.05, -1.0, EPS, 7.0, -24.0),  # a flat face
        (0.05, 0.0, 0.0, 7.0, -24.0),  # the sharp law stays sharp
        (0.05, 0.0, EPS, 0.0, 0.0),  # no lateral spin: nothing to spread
    ],
)
def test_band_eps_keeps_eps_elsewhere(r, na, eps, w2, w3):
    # exactly eps, so every run without lateral spin (normal impact, Table 2) and every
    # non-cylindrical band is unchanged to the bit
    assert band_eps(eps, r, na, 0.05 * 0.02, w2, w3) == (eps, 0.0)


def test_shank_ring_load_is_continuous_as_the_zero_point_sweeps_it():
    # one shank ring, fully immersed, moving axially at 500 m/s and turning at 30 rad/s:
    # its lateral velocity v2 + w3 x1 passes 0 as v2 sweeps, and the a0 term's load
    # flips from +2 a0 w to -2 a0 w. With eps alone it flips within 2 eps = 2e-3 m/s, one
    # sample of the sweep below; spread over the band (+-0.30 m/s) it takes ~70 samples,
    # the largest step between samples being pi/(2 x 70) ~ 2 % of the flip (measured
    # 1.2 %). 5 % fails the unwidened step (a 100 % jump) by 20x
    pr = prepare("p2", "soil")
    shank = np.flatnonzero(pr.rings[:, 2] == 0.0)
    ring = np.ascontiguousarray(pr.rings[shank[len(shank) // 2]][None, :])
    x1, r, _, _, w = ring[0]
    w3 = 30.0
    spread = 0.5 * (w / r) * w3
    y = np.zeros(14)
    y[1] = -5.0  # deep in the half-space
    y[3] = 1.0  # axis along x
    y[7] = 500.0
    y[12] = w3
    flip = 4.0 * pr.coef[0, 0] * w
    loads = []
    for v2 in np.linspace(-w3 * x1 - 3 * spread, -w3 * x1 + 3 * spread, 201):
        y[8] = v2
        loads.append(contact_loads(y, ring, pr.bounds, pr.coef, pr.fric, EPS, 0)[0][1])
    loads = np.array(loads)
    # it does flip (both signs, nearly the full 2 a0 w each way) ...
    assert loads.max() > 0.45 * flip and loads.min() < -0.45 * flip
    # ... and gradually
    assert np.abs(np.diff(loads)).max() < 0.05 * flip
