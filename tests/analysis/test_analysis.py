"""pencore.analysis on synthetic paths with known answers (no solver)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

import pencore
from pencore import analysis as A


def _jittered(a: float, b: float, n: int, seed: int = 0) -> np.ndarray:
    """Strictly increasing, clearly non-uniform grid on [a, b]."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(0.3, 1.7, n - 1)
    return a + (b - a) * np.concatenate(([0.0], np.cumsum(h))) / h.sum()


# ------------------------------------------------------------------ straight line


def test_line_slope_constant_and_no_inflection():
    t = _jittered(0.0, 1e-2, 200)
    x = -1.0 + 700.0 * t
    y = 1.0 - 700.0 * t  # 45 deg obliquity: slope -1
    s = A.slope(x, y, t)
    np.testing.assert_allclose(s, -1.0, rtol=1e-12)
    np.testing.assert_allclose(A.slope(x, y), -1.0, rtol=1e-12)  # chord-length parameter
    assert len(A.inflection_points(x, y, t)) == 0
    ta = A.turning_angle({"t": t, "x": x, "y": y, "theta": np.full_like(t, 45.0)})
    assert math.isnan(ta.delta_theta) and "straight" in ta.reason and not ta.ok


def test_vertical_line_curvature_zero_slope_infinite():
    t = np.linspace(0.0, 1.0, 50)
    x, y = np.zeros_like(t), -3.0 * t
    assert np.all(np.isinf(A.slope(x, y, t)))
    np.testing.assert_allclose(A.signed_curvature(x, y, t), 0.0, atol=1e-12)
    assert len(A.inflection_points(x, y, t)) == 0


# ------------------------------------------------------------------ circular arc


def test_arc_constant_curvature_tangent_slope_no_inflection():
    r = 2.5
    t = _jittered(0.0, 1.0, 300, seed=1)
    phi = -0.25 * math.pi + 0.8 * (t + 0.5 * t**2)  # non-uniform angular speed as well
    x, y = r * np.cos(phi), r * np.sin(phi)
    # counter-clockwise circle: curvature +1/r; tangent slope dy/dx = -cot(phi)
    kappa = A.signed_curvature(x, y, t)
    np.testing.assert_allclose(kappa[2:-2], 1.0 / r, rtol=2e-3)  # one-sided at the ends
    np.testing.assert_allclose(kappa, 1.0 / r, rtol=2e-2)
    # compare directions (the slope itself is huge where the path is nearly vertical)
    np.testing.assert_allclose(
        np.arctan(A.slope(x, y, t)), np.arctan(-1.0 / np.tan(phi)), atol=1e-4
    )
    assert len(A.inflection_points(x, y, t)) == 0
    assert len(A.inflection_points(x, y)) == 0
    # clockwise traversal flips the sign
    t_back = t[-1] - t[::-1]
    np.testing.assert_allclose(
        A.signed_curvature(x[::-1], y[::-1], t_back)[2:-2], -1.0 / r, rtol=2e-3
    )


def test_arc_with_exact_velocities():
    r, w = 3.0, 2.0
    t = _jittered(0.0, 1.0, 200, seed=2)
    x, y = r * np.cos(w * t), r * np.sin(w * t)
    vx, vy = -r * w * np.sin(w * t), r * w * np.cos(w * t)
    np.testing.assert_allclose(A.signed_curvature(x, y, t, vx=vx, vy=vy), 1 / r, rtol=2e-3)


# ------------------------------------------------------------------ cubic inflection


@pytest.mark.parametrize("use_t", [True, False])
def test_cubic_inflection_at_x2_on_nonuniform_grid(use_t):
    t = _jittered(0.0, 1.0, 400, seed=3)
    x = 4.0 * t + 0.5 * np.sin(2.0 * t)  # non-uniform in x too
    y = (x - 2.0) ** 3 + 0.7 * x
    ip = A.inflection_points(x, y, t if use_t else None)
    assert len(ip) == 1
    assert abs(ip.x[0] - 2.0) < 1e-3
    assert abs(ip.y[0] - 1.4) < 2e-3
    assert ip.direction[0] == 1  # d2y/dx2 = 6 (x - 2): negative -> positive
    i = ip.index[0]
    assert x[i] <= ip.x[0] <= x[i + 1]
    # the parametric d2y/dx2 matches the analytic one away from the ends
    d2 = A.d2y_dx2(x, y, t if use_t else None)
    np.testing.assert_allclose(d2[5:-5], 6.0 * (x[5:-5] - 2.0), atol=0.1)


def test_wiggles_below_threshold_are_ignored():
    t = np.linspace(0.0, 1.0, 2001)
    x = 4.0 * t
    u = x - 2.0
    # peak |curvature| of u^3 is 1.76 1/m; add a wiggle of curvature amplitude 0.1 1/m
    w = 2.0 * math.pi / 0.04
    y = u**3 + 0.1 / w**2 * np.sin(w * x)
    raw = A.inflection_points(x, y, t, rel_threshold=0.0)
    assert len(raw) == 3  # the wiggle adds two sign changes around x = 2
    ip = A.inflection_points(x, y, t, rel_threshold=0.1)
    assert len(ip) == 1 and abs(ip.x[0] - 2.0) < 0.01
    assert ip.threshold == pytest.approx(0.1 * ip.peak)


def test_noise_on_straight_parts_is_ignored_by_default():
    rng = np.random.default_rng(10)
    d = _line_arc_line()
    n = d["t"].size
    x = d["x"] + 1e-12 * rng.standard_normal(n)
    y = d["y"] + 1e-12 * rng.standard_normal(n)
    raw = A.inflection_points(x, y, d["t"], rel_threshold=0.0)
    assert len(raw) > 10  # round-off curvature on the straight parts changes sign a lot
    assert len(A.inflection_points(x, y, d["t"])) == 0  # a single arc: no inflection
    assert A.turning_angle(dict(d, x=x, y=y)).delta_theta == pytest.approx(30.0, abs=0.05)


def test_two_inflections_of_sine():
    t = _jittered(0.0, 1.0, 500, seed=5)
    x = 3.0 * math.pi * t
    y = np.sin(x)
    ip = A.inflection_points(x, y, t)
    # interior zeros of -sin(x) on (0, 3 pi): pi and 2 pi
    np.testing.assert_allclose(ip.x, [math.pi, 2 * math.pi], atol=2e-3)
    assert list(ip.direction) == [1, -1]


# ------------------------------------------------------------------ line -> arc -> line


def _line_arc_line(r=2.0, turn_deg=30.0, speed=500.0, n=(120, 300, 150), theta0=45.0):
    """CM path at constant speed: straight at 45 deg down, a circular arc of radius r
    turning by ``turn_deg`` (positive: towards the surface), then straight. The axis
    follows the velocity, so theta changes by exactly ``turn_deg``."""
    a0 = math.radians(-45.0)  # velocity heading (from +x, counter-clockwise)
    turn = math.radians(turn_deg)
    sg = math.copysign(1.0, turn)
    L1, L2, L3 = 1.5, r * abs(turn), 2.0
    s = np.concatenate(
        (
            _jittered(0.0, L1, n[0], seed=6)[:-1],
            _jittered(L1, L1 + L2, n[1], seed=7)[:-1],
            _jittered(L1 + L2, L1 + L2 + L3, n[2], seed=8),
        )
    )
    heading = np.where(s < L1, a0, np.where(s < L1 + L2, a0 + sg * (s - L1) / r, a0 + turn))
    x0, y0 = -1.0, 1.0
    xa, ya = x0 + L1 * math.cos(a0), y0 + L1 * math.sin(a0)
    cx, cy = xa - sg * r * math.sin(a0), ya + sg * r * math.cos(a0)  # centre of the arc
    xb, yb = cx + sg * r * math.sin(a0 + turn), cy - sg * r * math.cos(a0 + turn)
    x = np.where(
        s < L1,
        x0 + s * math.cos(a0),
        np.where(
            s < L1 + L2, cx + sg * r * np.sin(heading), xb + (s - L1 - L2) * math.cos(a0 + turn)
        ),
    )
    y = np.where(
        s < L1,
        y0 + s * math.sin(a0),
        np.where(
            s < L1 + L2, cy - sg * r * np.cos(heading), yb + (s - L1 - L2) * math.sin(a0 + turn)
        ),
    )
    t = s / speed
    theta = theta0 + np.degrees(heading - a0)  # axis angle from -y grows as the path turns
    vx, vy = speed * np.cos(heading), speed * np.sin(heading)
    return dict(t=t, x=x, y=y, theta=theta, vx=vx, vy=vy)


def test_line_arc_line_fixture_is_consistent():
    for turn in (30.0, -20.0):
        d = _line_arc_line(turn_deg=turn)
        np.testing.assert_allclose(
            A.slope(d["x"], d["y"], d["t"])[2:-2], (d["vy"] / d["vx"])[2:-2], rtol=2e-2, atol=2e-3
        )


def test_turning_angle_line_arc_line():
    d = _line_arc_line(turn_deg=30.0)
    ta = A.turning_angle(d)
    assert ta.ok, ta.reason
    assert ta.delta_theta == pytest.approx(30.0, abs=0.05)
    assert ta.theta_1 == pytest.approx(45.0, abs=0.05)
    assert ta.theta_2 == pytest.approx(75.0, abs=0.05)
    # Points 1 and 2 sit at the ends of the arc
    assert ta.x_1 == pytest.approx(-1.0 + 1.5 * math.cos(math.pi / 4), abs=0.02)
    # the same without the exact velocities, and for other fractions
    d2 = {k: d[k] for k in ("t", "x", "y", "theta")}
    for f in (0.01, 0.05, 0.2):
        assert A.turning_angle(d2, fraction=f).delta_theta == pytest.approx(30.0, abs=0.3)
    assert float(ta) == ta.delta_theta


def test_turning_angle_from_dataset_and_opposite_turn():
    d = _line_arc_line(turn_deg=-20.0)
    ds = xr.Dataset(
        {
            "cm_x": ("time", d["x"]),
            "cm_y": ("time", d["y"]),
            "vel_x": ("time", d["vx"]),
            "vel_y": ("time", d["vy"]),
            "theta": ("time", d["theta"]),
        },
        coords={"time": d["t"]},
        attrs={"impact_velocity_m_s": 500.0},
    )
    ta = A.turning_angle(ds)
    assert ta.delta_theta == pytest.approx(-20.0, abs=0.05)


def test_turning_angle_undefined_cases():
    d = _line_arc_line()
    # record ends inside the arc: Point 2 missing, Point 1 still reported
    cut = {k: v[:250] for k, v in d.items()}
    ta = A.turning_angle(cut)
    assert math.isnan(ta.delta_theta) and "Point 2" in ta.reason
    assert ta.theta_1 == pytest.approx(45.0, abs=0.05)
    # record starts inside the arc: Point 1 missing
    late = {k: v[200:] for k, v in d.items()}
    ta = A.turning_angle(late)
    assert math.isnan(ta.delta_theta) and "Point 1" in ta.reason
    # sign-change method: a single arc has no inflection
    ta = A.turning_angle(d, method="sign_change")
    assert math.isnan(ta.delta_theta) and "need 2" in ta.reason
    with pytest.raises(ValueError):
        A.turning_angle(d, method="nope")


def test_turning_angle_ignores_slow_end():
    d = _line_arc_line()
    n = d["t"].size
    # below 10 % of the impact speed the path would curve again; it must be ignored
    slow = np.arange(n) > n - 40
    d["vx"] = np.where(slow, 0.05 * d["vx"], d["vx"])
    d["vy"] = np.where(slow, 0.05 * d["vy"], d["vy"])
    d["theta"] = np.where(slow, d["theta"] + 50.0, d["theta"])
    assert A.turning_angle(d).delta_theta == pytest.approx(30.0, abs=0.05)


# ------------------------------------------------------------------ deviation, direction


def test_deviation_matches_paper_formula():
    rng = np.random.default_rng(9)
    vx = rng.uniform(1.0, 100.0, 50)
    vy = -rng.uniform(1.0, 100.0, 50)
    phi = A.deviation_from_normal(vx, vy)
    np.testing.assert_allclose(phi, 90.0 + np.degrees(np.arctan(vy / vx)), atol=1e-10)
    assert A.deviation_from_normal(0.0, -5.0) == 0.0
    assert A.deviation_from_normal(1.0, 0.0) == pytest.approx(90.0)
    assert A.deviation_from_normal(1.0, 1.0) == pytest.approx(135.0)  # turned back up
    assert A.deviation_from_normal(-1.0, -1.0) == pytest.approx(45.0)
    assert A.deviation_from_normal(-1.0, -1.0, signed=True) == pytest.approx(-45.0)
    assert A.deviation_from_normal(0.0, -1.0, 1.0) == pytest.approx(45.0)
    assert isinstance(A.deviation_from_normal(1.0, -1.0), float)


def _run_like(vx, vy, axis_x=None, reversed_=0, v0=None):
    n = len(vx)
    vx, vy = np.asarray(vx, float), np.asarray(vy, float)
    ax = np.zeros(n) if axis_x is None else np.asarray(axis_x, float)
    return xr.Dataset(
        {
            "vel_x": ("time", vx),
            "vel_y": ("time", vy),
            "vel_z": ("time", np.zeros(n)),
            "speed": ("time", np.hypot(vx, vy)),
            "axis_x": ("time", ax),
        },
        coords={"time": np.arange(n, dtype=float)},
        attrs={
            "reversed": reversed_,
            "impact_velocity_m_s": float(np.hypot(vx[0], vy[0]) if v0 is None else v0),
        },
    )


def test_final_deviation_uses_last_fast_state():
    speed = np.array([1000.0, 800.0, 400.0, 150.0, 99.0, 20.0])
    ang = np.radians([0.0, 0.1, 0.2, 0.5, 30.0, 80.0])  # sharp turn only when slow
    ds = _run_like(speed * np.sin(ang), -speed * np.cos(ang))
    assert A.final_deviation(ds) == pytest.approx(0.5)  # last state with speed >= 100
    assert A.final_deviation(ds, fraction=0.05) == pytest.approx(30.0)
    assert A.final_deviation(ds, fraction=0.0) == pytest.approx(80.0)
    assert A.final_state_index(ds["speed"].values) == 3
    assert A.final_deviation_arrays(speed * np.sin(ang), -speed * np.cos(ang)) == pytest.approx(0.5)


def test_nose_direction_and_reversed():
    ds = _run_like([1.0, 1.0], [-1.0, -1.0], axis_x=[0.5, -0.2], reversed_=1)
    assert A.nose_direction(ds) == "-x"
    assert A.reversed_in_target(ds) is True
    ds = _run_like([1.0, 1.0], [-1.0, -1.0], axis_x=[0.5, 0.3], reversed_=0)
    assert A.nose_direction(ds) == "+x"
    assert A.nose_direction(np.array([0.1, 0.0])) == "+x"
    assert A.reversed_in_target(ds) is False
    with pytest.raises(pencore.InputError, match="lacks the attribute.s. reversed"):
        A.reversed_in_target(xr.Dataset())


def test_bad_inputs():
    with pytest.raises(ValueError, match="strictly increasing"):
        A.slope([0, 1, 2], [0, 1, 2], [0, 0, 1])
    with pytest.raises(ValueError, match="same length"):
        A.slope([0, 1, 2], [0, 1])
    with pytest.raises(ValueError, match="coincide"):
        A.signed_curvature([0, 1, 1, 2], [0, 1, 1, 2])
    with pytest.raises(ValueError, match="rel_threshold"):
        A.inflection_points([0, 1, 2], [0, 1, 2], rel_threshold=1.5)
