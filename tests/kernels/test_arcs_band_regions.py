"""The band immersion ramp of the ring quadrature (pencore.kernels.arcs.band_regions).

Each ring stands for a band of the surface; the share of the band below a level is a
linear ramp over the band's height range instead of a step at the ring's line. Tests:
the loads become continuous in the body's position (the step made a jump per ring),
the layer shares add up across an interface (a partition of unity), a band lying in a
horizontal plane keeps the sharp test, and the mesh convergence becomes second order.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore import get_target
from pencore.inputs.target import Layer, Target
from pencore.kernels.bands import band_half_height
from pencore.kernels.dynamics import contact_loads
from pencore.run.impact import prepare
from pencore.run.initial import initial_state

SOIL = get_target("soil").medium


def _loads(pr, y):
    return contact_loads(y, pr.rings, pr.bounds, pr.coef, pr.fric, 1e-3, 0)


@pytest.mark.parametrize("obliquity", [0.0, 30.0])
def test_loads_are_continuous_in_depth(obliquity):
    # the axial force during nose entry, sampled at spacings d and d/2: for a
    # Lipschitz-continuous force the largest jump between neighbours halves with the
    # spacing (measured: 0.5000 and 0.5003). With the sharp step at each ring line it
    # does not: a normal impact switches a whole ring on at once (ratio 1), and an
    # oblique ring's loaded arc opens like sqrt(depth) (ratio -> 1/sqrt(2); 0.58 on
    # this grid). 0.55 separates the two
    pr = prepare("p2", "soil")
    y0 = initial_state(
        pr.projectile, pr.rings, 500.0, math.radians(obliquity), 0.0, 0.0, None, 0.0, "cm"
    )
    jumps = []
    for spacing in (2e-4, 1e-4):
        depths = np.arange(0.0, 0.1, spacing)
        force = []
        for d in depths:
            y = y0.copy()
            y[1] -= d
            force.append(_loads(pr, y)[0][0])
        jumps.append(np.abs(np.diff(force)).max())
    assert jumps[1] <= 0.55 * jumps[0], jumps


def test_layer_shares_add_up_across_an_interface():
    # R(top - y) - R(bot - y) for the upper layer plus R(bot - y) for the lower one is
    # R(top - y): splitting a medium into two layers at any depth changes no load
    one = prepare("p2", Target("one", (Layer(SOIL),)))
    y = initial_state(one.projectile, one.rings, 500.0, math.radians(35), 0.0, 0.0, None, 0.0, "cm")
    y[1] -= 0.3
    ref_f, ref_m, _ = _loads(one, y)
    for split in (0.05, 0.2, 0.31):
        two = prepare("p2", Target("two", (Layer(SOIL, split), Layer(SOIL))))
        f, m, _ = _loads(two, y)
        # round-off of the subtracted shares: 1e-12 of the load
        assert np.allclose(f, ref_f, rtol=0, atol=1e-12 * np.abs(ref_f).max())
        assert np.allclose(m, ref_m, rtol=0, atol=1e-12 * np.abs(ref_f).max())


def test_horizontal_band_keeps_the_sharp_test():
    # a shank band (normal radial, nr = 1) on a horizontal axis (r10 = 0), or a flat
    # face (nr = 0) on a vertical axis (r10 = 1, rk = 0), lies at one height
    assert band_half_height(0.0, 1.0, 0.05, 0.0, 1.0, 0.05 * 0.01) == 0.0
    assert band_half_height(1.0, 0.0, 0.05, -1.0, 0.0, 0.05 * 0.01) == 0.0
    # a shank band on a vertical axis spans its whole width dl
    assert band_half_height(1.0, 0.0, 0.05, 0.0, 1.0, 0.05 * 0.01) == pytest.approx(0.005)
