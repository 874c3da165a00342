"""Initial state of an impact, and the checks of the impact conditions.

Conventions as in :mod:`pencore.run.impact` (angles in radians here, degrees at the API).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from pencore.errors import InputError, hint_keywords
from pencore.inputs.conventions import SPIN_CENTRES
from pencore.inputs.gate import brief
from pencore.inputs.geometry import Projectile
from pencore.inputs.limits import number
from pencore.kernels.dynamics import quat_to_matrix

__all__ = [
    "initial_state",
]


def _axis_quaternion(obliquity: float) -> np.ndarray:
    """Quaternion turning body axis 1 onto (sin phi1, -cos phi1, 0)."""
    th = obliquity - 0.5 * math.pi
    if obliquity == 0.0:
        # cos and sin of -pi/4 differ in the last bit; equal magnitudes make the axis
        # exactly -y, so a normal impact is exactly axisymmetric
        h = math.sqrt(0.5)
        return np.array([h, 0.0, 0.0, -h])
    return np.array([math.cos(0.5 * th), 0.0, 0.0, math.sin(0.5 * th)])


def initial_state(
    projectile: Projectile,
    rings: np.ndarray,
    velocity: float,
    obliquity: float,
    yaw: float,
    omega: float,
    start: tuple[float, float, float] | None,
    azimuth: float = 0.0,
    spin_about: str = "cm",
) -> np.ndarray:
    """State vector at t = 0 (angles in radians here); ``spin_about`` is ``"cm"`` or
    ``"tip"`` (the point whose velocity is the impact velocity)."""
    if spin_about not in SPIN_CENTRES:
        raise InputError(f"spin_about must be one of {', '.join(SPIN_CENTRES)}, got {spin_about!r}")
    mp = projectile.mass_properties()
    q = _axis_quaternion(obliquity)
    rot = quat_to_matrix(q)
    axis = rot[:, 0]
    alpha = obliquity + yaw
    y = np.zeros(14)
    y[3:7] = q
    y[7:10] = velocity * np.array([math.sin(alpha), -math.cos(alpha), 0.0])
    y[10:13] = rot.T @ np.array([0.0, 0.0, omega])
    if spin_about == "tip":  # v_cm = v_tip + w x (cm - tip), with cm - tip = -lc axis
        y[7:10] += np.cross(np.array([0.0, 0.0, omega]), -mp.lc * axis)
    if start is None:
        # lowest point of every ring circle, and the tip, relative to the centre of mass
        x1, r = rings[:, 0], rings[:, 1]
        low = rot[1, 0] * x1 - r * math.hypot(rot[1, 1], rot[1, 2])
        low = min(float(low.min()), rot[1, 0] * mp.lc)
        cm = np.array([0.0, 0.0, 0.0]) - mp.lc * axis
        cm[1] = -low + 1e-9
    else:
        cm = np.asarray(start, dtype=float) - mp.lc * axis
    y[0:3] = cm
    if azimuth != 0.0:
        ca, sa = math.cos(azimuth), math.sin(azimuth)
        ry = np.array([[ca, 0.0, sa], [0.0, 1.0, 0.0], [-sa, 0.0, ca]])
        y[0:3] = ry @ y[0:3]
        y[7:10] = ry @ y[7:10]
        qa = np.array([math.cos(0.5 * azimuth), 0.0, math.sin(0.5 * azimuth), 0.0])
        y[3:7] = _qmul(qa, y[3:7])
    return y


def _qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ]
    )


def _check_inputs(
    velocity: Any, obliquity: Any, yaw: Any, omega: Any, azimuth: Any, start: Any
) -> tuple[float, float, float, float, float, tuple[float, float, float] | None]:
    """Checked impact conditions (SI, angles in degrees), or :class:`InputError`."""
    v = number(velocity, "velocity")
    ob = number(obliquity, "obliquity")
    yw = number(yaw, "yaw")
    if not abs(ob + yw) < 90.0:
        raise InputError(
            f"yaw must keep the velocity pointing into the target: |obliquity + yaw| < 90 "
            f"deg, got obliquity {obliquity!r} deg and yaw {yaw!r} deg"
        )
    om = number(omega, "omega")
    az = number(azimuth, "azimuth")
    if start is None:
        return v, ob, yw, om, az, None
    ordered = isinstance(start, Sequence | np.ndarray) and not isinstance(start, str | bytes)
    if not ordered or len(start) != 3:  # a set or a mapping has no x, y, z order
        raise InputError(
            f"start must be three numbers (x, y, z) in m, in order (a list, tuple or "
            f"array), got {brief(start)} ({type(start).__name__})"
        )
    # judged plausible once the start is accepted (it must also reach the target)
    xyz = tuple(
        number(c, "start", f"start {n}", plausibility=False)
        for c, n in zip(start, "xyz", strict=True)
    )
    if xyz[1] < 0.0:
        raise InputError(
            f"start y must be >= 0 m: the nose tip starts at or above the target's surface "
            f"y = 0 (the target is y <= 0), got y = {xyz[1]:g} m"
        )
    return v, ob, yw, om, az, xyz  # type: ignore[return-value]


def _check_reaches_target(y0: np.ndarray, reach: float, num: Any) -> None:
    """Refuse a start from which no point of the body can touch the surface within
    ``t_max``: the body's lowest point is at least ``y_cm - reach`` high and moves down no
    faster than ``-vy + g t``. ``reach`` (m) is the largest distance from the centre of
    mass to a point of the body (the nose tip included). Not called for the default
    start, which touches the target (its nose tip 1 nm above the surface, its lowest
    band already reaching it): any ``t_max`` is a run, ended by ``time_limit``."""
    height = y0[1] - reach
    if height <= 0.0:
        return
    vy = -y0[8]
    g = num.gravity
    # earliest time at which height - vy t - g t^2 / 2 = 0
    t_hit = height / vy if g == 0.0 else (-vy + math.sqrt(vy * vy + 2 * g * height)) / g
    if not t_hit <= num.t_max:
        raise InputError(
            f"start height {y0[1] + 0.0:.4g} m (centre of mass) is too high: at the impact's "
            f"downward speed of {vy:.4g} m/s the body cannot reach the target within "
            f"t_max = {num.t_max:g} s; lower the start or raise numerics t_max"
        )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
