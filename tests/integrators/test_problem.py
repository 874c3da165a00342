"""pencore.integrators.problem: what a prepared problem gives every integrator."""

import math

import numpy as np

import pencore
from pencore.integrators.problem import Problem
from pencore.kernels.state import body_reach


def test_prepare_returns_the_public_problem():
    pr = pencore.prepare("p2", "soil")
    assert isinstance(pr, Problem)
    assert pr.model is None and pr.loaded_rings is pr.rings  # the default model


def test_atol_scales_each_component_by_its_size():
    pr = pencore.prepare("p2", "soil", rtol=1e-5)
    length, v = pr.projectile.length, 800.0
    atol = pr.atol(v)
    assert atol.shape == (13,)
    np.testing.assert_allclose(atol[:3], 1e-7 * length, rtol=1e-15)  # m
    np.testing.assert_allclose(atol[3:7], 1e-7, rtol=1e-15)  # quaternion
    np.testing.assert_allclose(atol[7:10], 1e-7 * v, rtol=1e-15)  # m/s
    np.testing.assert_allclose(atol[10:], 1e-7 * v / length, rtol=1e-15)  # rad/s


def test_thin_layers_are_the_layers_and_gaps_a_step_could_cross():
    # plate 1 cm, gap 0.5 m, plate 1 um, backing 0.3 m: with max_travel 0.1 m the layers
    # thinner than 0.2 m are thin; each carries its levels and half of the larger of
    # its thickness and the shortest band
    target = {
        "name": "stack",
        "layers": [
            {"medium": "aluminium", "thickness": 0.01},
            {"gap": 0.5},
            {"medium": "aluminium", "thickness": 1e-6},
            {"gap": 0.05},
            {"medium": "aluminium", "thickness": 0.3},
        ],
    }
    pr = pencore.prepare("p2", target)
    rings = pr.loaded_rings
    band = (rings[rings[:, 1] > 0, 4] / rings[rings[:, 1] > 0, 1]).min()
    assert pr.band_length == band and 1e-3 < band < 1e-2  # m
    np.testing.assert_allclose(
        pr.thin_layers,
        [
            [0.0, -0.01, 0.005],
            [-0.51, -0.510001, 0.5 * band],
            [-0.510001, -0.560001, 0.025],
        ],
        rtol=0,
        atol=1e-15,
    )
    assert pencore.prepare("p2", "soil").thin_layers.shape == (0, 3)
    thick = {"name": "thick", "layers": [{"medium": "aluminium", "thickness": 0.3}]}
    assert pencore.prepare("p2", thick).thin_layers.shape == (0, 3)
    assert pencore.prepare("p2", thick, max_travel=0.2).thin_layers.shape == (1, 3)


def test_friction_points_only_when_the_target_has_friction():
    assert pencore.prepare("p2", "soil").n_gauss == 0  # frictionless soil
    rough = {"name": "rough", "coefficients": [1e6, 0.0, 1e3], "friction": 0.1}
    pr = pencore.prepare("p2", rough, n_gauss=6)
    assert pr.n_gauss == 6


def test_gravity_points_down_and_reach_is_the_farthest_ring():
    pr = pencore.prepare("p2", "soil", gravity=9.81)
    np.testing.assert_array_equal(pr.gravity, [0.0, -9.81, 0.0])
    assert pr.reach == body_reach(pr.rings)
    r = np.hypot(pr.rings[:, 0], pr.rings[:, 1]).max()
    assert math.isclose(pr.reach, r, rel_tol=1e-15)


def test_a_shank_model_loads_its_own_rings():
    pr = pencore.prepare("p4", "soil", shank="cavity")
    assert pr.model is not None and pr.loaded_rings is pr.kernel_rings
    assert pr.load_args()[-1] is pr.model


def test_stall_distance_allows_for_steps_a_thin_layer_bounds():
    # 500 steps that each move the body by a thin layer's half-width are not a stall:
    # a 1-um foil under a fine ring mesh bounds the steps to half the shortest band
    foil = {"name": "foil", "layers": [{"medium": "aluminium", "thickness": 1e-6}]}
    coarse = pencore.prepare("p2", foil)
    assert coarse.stall_distance(500) == 1e-2 * coarse.projectile.length  # unchanged
    fine = pencore.prepare("p2", foil, n_nose=10_000, n_shank=10_000)
    half = float(fine.thin_layers[:, 2].min())
    assert half == 0.5 * fine.band_length
    assert fine.stall_distance(500) == 0.1 * 500 * half < 1e-2 * fine.projectile.length
