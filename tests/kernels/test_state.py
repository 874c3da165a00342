"""pencore.kernels.state: the body's extent and the step bound near thin layers."""

import math

import numpy as np
import pytest

import pencore
from pencore.kernels.state import body_extent, body_top, layer_travel_bound


def _state(height: float, quaternion=(1.0, 0.0, 0.0, 0.0)) -> np.ndarray:
    y = np.zeros(14)
    y[1] = height
    y[3:7] = quaternion
    y[8] = -500.0
    return y


@pytest.fixture(scope="module")
def rings():
    return pencore.prepare("p2", "soil").rings


def test_a_level_body_spans_its_radius_about_the_centre_of_mass(rings):
    # identity attitude: the axis is horizontal; the shank's bands reach one radius
    # below and above the centre of mass, and a nose band's immersion ramp, a little
    # wider than the band where it is tilted, at most half a band length more
    radius = rings[:, 1].max()
    half_band = 0.5 * (rings[rings[:, 1] > 0, 4] / rings[rings[:, 1] > 0, 1]).max()
    bottom, top = body_extent(_state(0.3), rings)
    assert 0.3 - radius - half_band <= bottom <= 0.3 - radius + 1e-15
    assert 0.3 + radius - 1e-15 <= top <= 0.3 + radius + half_band
    assert bottom - 0.3 == pytest.approx(0.3 - top, abs=1e-15)  # symmetric about the axis


def test_turning_the_body_upside_down_mirrors_its_extent(rings):
    # a half turn about the horizontal z axis maps heights h -> -h about the centre
    c, s = math.cos(0.3), math.sin(0.3)  # some tilted attitude, about z
    q = np.array([c, 0.0, 0.0, s])
    flipped = np.array([-s, 0.0, 0.0, c])  # q followed by a half turn about z
    b1, t1 = body_extent(_state(0.0, q), rings)
    b2, t2 = body_extent(_state(0.0, flipped), rings)
    assert b2 == pytest.approx(-t1, abs=1e-12) and t2 == pytest.approx(-b1, abs=1e-12)
    assert t1 - b1 > 0.5 * pencore.prepare("p2", "soil").projectile.length


def test_extent_moves_with_the_centre_of_mass_and_top_is_its_upper_end(rings):
    q = np.array([math.cos(0.5), 0.0, 0.0, math.sin(0.5)])
    b0, t0 = body_extent(_state(0.0, q), rings)
    b1, t1 = body_extent(_state(-2.0, q), rings)
    assert (b1, t1) == pytest.approx((b0 - 2.0, t0 - 2.0), abs=1e-12)
    assert body_top(_state(-2.0, q), rings) == t1


def test_no_thin_layer_no_bound(rings):
    assert layer_travel_bound(_state(0.3), rings, np.zeros((0, 3))) == math.inf


def test_bound_is_the_distance_to_the_layer_plus_its_half_width(rings):
    y = _state(0.0)
    bottom, top = body_extent(y, rings)
    below = np.array([[bottom - 0.2, bottom - 0.21, 0.005]])
    above = np.array([[top + 0.31, top + 0.3, 0.005]])
    spanned = np.array([[0.001, -0.001, 0.004]])
    assert layer_travel_bound(y, rings, below) == pytest.approx(0.2 + 0.005, abs=1e-12)
    assert layer_travel_bound(y, rings, above) == pytest.approx(0.3 + 0.005, abs=1e-12)
    assert layer_travel_bound(y, rings, spanned) == 0.004
    # several layers: the nearest decides
    both = np.vstack([below, above, spanned])
    assert layer_travel_bound(y, rings, both) == 0.004
    assert layer_travel_bound(y, rings, both[:2]) == pytest.approx(0.205, abs=1e-12)
    # a layer the body only touches counts as spanned
    touching = np.array([[bottom, bottom - 1e-6, 0.003]])
    assert layer_travel_bound(y, rings, touching) == 0.003
