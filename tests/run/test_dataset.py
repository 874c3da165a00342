"""The trajectory Dataset's derived results: the final slope of a vertical motion."""

import math

import numpy as np
import pytest

import pencore
from pencore.run.dataset import VERTICAL_RATIO, final_slope

ULP = float(np.finfo(float).eps)
FOIL = {"name": "foil", "layers": [{"medium": "aluminium", "thickness": 1e-12}]}
VERTICAL = [0.0, -0.0, 0.5 * ULP, -0.5 * ULP, 1e-40, VERTICAL_RATIO, -VERTICAL_RATIO]


@pytest.mark.parametrize("vy", [-300.0, -1.0, 2.5])
@pytest.mark.parametrize("ratio", VERTICAL, ids=[repr(r) for r in VERTICAL])
def test_round_off_of_vertical_is_infinite_with_the_sign_of_vy(vy, ratio):
    """A horizontal component up to VERTICAL_RATIO (16 ulps) of |vy|, of either sign, is
    vertical motion: -inf moving down, +inf moving up."""
    vx = ratio * abs(vy)
    assert final_slope(np.array([vx, vy, 0.0])) == math.copysign(math.inf, vy)


@pytest.mark.parametrize("vy", [-300.0, -1.0, 2.5])
@pytest.mark.parametrize(
    "ratio", [2.0 * VERTICAL_RATIO, -2.0 * VERTICAL_RATIO, 4.5e-12, 1e-3, 1.0, -7.0]
)
def test_any_other_direction_keeps_the_ratio_bit_for_bit(vy, ratio):
    """Beyond VERTICAL_RATIO the slope is the plain ratio vy / vx, to the bit."""
    vx = ratio * abs(vy)
    assert final_slope(np.array([vx, vy, 1.0])) == np.float64(vy) / np.float64(vx)


def test_no_velocity_in_the_plane_has_no_slope():
    assert math.isnan(final_slope(np.array([0.0, 0.0, 3.0])))


def test_normal_perforation_under_radau_ends_moving_down():
    """Radau through a 1e-12 m foil at normal incidence ends with a horizontal velocity of
    round-off (|vx| / |vy| ~ 1e-40, positive vy / vx); the run moves straight down."""
    ds = pencore.simulate("p2", FOIL, 300.0, method="Radau")
    assert ds.attrs["outcome"] == "perforated"
    assert abs(float(ds.vel_x[-1])) <= VERTICAL_RATIO * abs(float(ds.vel_y[-1]))
    assert float(ds.vel_y[-1]) < 0.0
    assert float(ds.final_slope) == -math.inf
