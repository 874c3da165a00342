"""``simulate``: one penetration trajectory as an :class:`xarray.Dataset`.

Geometry of the impact (angles in degrees at this interface, radians inside):

* the target is ``y <= 0``, the projectile moves towards ``+x`` and ``-y``;
* ``obliquity`` (phi1) is the angle between the projectile axis and the target normal
  (``-y``), measured towards ``+x``;
* ``yaw`` (phi2) is the velocity angle minus the axis angle (paper Fig. 10), so the
  velocity makes ``alpha = phi1 + phi2`` with the normal;
* ``omega`` is the initial angular velocity about the centre of mass, about ``+z``
  (rad/s); positive turns the nose towards ``+x``;
* ``start`` is the initial nose-tip position (m); by default the tip is at ``x = z = 0``
  and the body is lowered until its lowest surface point just touches ``y = 0``;
* ``azimuth`` turns the whole impact (position, velocity, attitude, spin) about the
  target normal ``+y`` (deg); 0 keeps the motion in the x-y plane. The target is
  invariant under this rotation, so the trajectory just turns with it.
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import asdict, dataclass, replace
from typing import Any

import numpy as np
import xarray as xr

from . import __version__
from .dynamics import quat_to_matrix
from .geometry import Projectile
from .integrate import OUTCOMES, integrate
from .library import InputError, get_projectile, get_target
from .target import Target

__all__ = ["Numerics", "simulate", "initial_state", "SolverError", "DEFAULT_NUMERICS"]


class SolverError(RuntimeError):
    """The integration could not finish (step limit)."""


@dataclass(frozen=True)
class Numerics:
    """Numerical parameters (defaults chosen by ``benchmarks/convergence.py``).

    Attributes
    ----------
    n_nose, n_shank, n_face : int
        Surface bands on the nose, on each 5 calibres of shank, and on each flat face.
    eps : float
        Half-width of the smoothed contact step in normal velocity (m/s).
    rtol : float
        Relative tolerance of the adaptive step control.
    max_travel : float
        Largest distance (m) the centre of mass may move in one step.
    v_stop : float
        Speed (m/s) below which the projectile is taken as stopped.
    t_max : float
        Time limit (s).
    max_steps : int
        Largest number of accepted steps.
    n_gauss : int
        Gauss points per 45-degree arc piece in the friction integral.
    gravity : float
        Gravitational acceleration (m/s^2) along ``-y``; 0 by default (as in the paper).
    """

    n_nose: int = 48
    n_shank: int = 24
    n_face: int = 4
    eps: float = 1e-3
    rtol: float = 1e-5
    max_travel: float = 0.1
    v_stop: float = 1.0
    t_max: float = 1.0
    max_steps: int = 400_000
    n_gauss: int = 4
    gravity: float = 0.0

    def __post_init__(self) -> None:
        for k in ("n_nose", "n_shank", "n_face", "max_steps"):
            if int(getattr(self, k)) < 1:
                raise InputError(f"numerics {k} must be >= 1, got {getattr(self, k)!r}")
        for k in ("rtol", "max_travel", "v_stop", "t_max"):
            v = float(getattr(self, k))
            if not (v > 0.0 and math.isfinite(v)):
                raise InputError(f"numerics {k} must be > 0, got {v!r}")
        if not (self.eps >= 0.0):
            raise InputError(f"numerics eps must be >= 0 m/s, got {self.eps!r}")


DEFAULT_NUMERICS = Numerics()


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
) -> np.ndarray:
    """State vector at t = 0 (angles in radians here)."""
    mp = projectile.mass_properties()
    q = _axis_quaternion(obliquity)
    rot = quat_to_matrix(q)
    axis = rot[:, 0]
    alpha = obliquity + yaw
    y = np.zeros(14)
    y[3:7] = q
    y[7:10] = velocity * np.array([math.sin(alpha), -math.cos(alpha), 0.0])
    y[10:13] = rot.T @ np.array([0.0, 0.0, omega])
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
    velocity: float, obliquity: float, yaw: float, omega: float, azimuth: float = 0.0
) -> None:
    if not (math.isfinite(velocity) and velocity > 0.0):
        raise InputError(f"velocity must be a positive number of m/s, got {velocity!r}")
    if not (math.isfinite(obliquity) and -90.0 < obliquity < 90.0):
        raise InputError(f"obliquity must be in (-90, 90) degrees, got {obliquity!r}")
    if not (math.isfinite(yaw) and abs(obliquity + yaw) < 90.0):
        raise InputError(
            f"yaw must keep the velocity below the horizon: |obliquity + yaw| < 90 deg, "
            f"got yaw={yaw!r}"
        )
    if not math.isfinite(azimuth):
        raise InputError(f"azimuth must be a finite number of degrees, got {azimuth!r}")
    if not math.isfinite(omega):
        raise InputError(f"omega must be a finite number of rad/s, got {omega!r}")


def _target_dict(t: Target) -> dict[str, Any]:
    return {
        "name": t.name,
        "layers": [
            {
                "thickness": lay.thickness,
                "medium": {
                    "name": lay.medium.name,
                    "coefficients": list(lay.medium.coefficients),
                    "friction": [
                        list(p)
                        for p in zip(
                            lay.medium.friction_speeds, lay.medium.friction_mu, strict=True
                        )
                    ],
                    "source": lay.medium.source,
                },
            }
            for lay in t.layers
        ],
    }


def _projectile_dict(p: Projectile) -> dict[str, Any]:
    d = asdict(p)
    d["nose"]["kind"] = type(p.nose).__name__
    return d


@dataclass
class _Prepared:
    projectile: Projectile
    target: Target
    numerics: Numerics
    rings: np.ndarray
    bounds: np.ndarray
    coef: np.ndarray
    fric: np.ndarray
    mass: float
    inertia: np.ndarray
    lc: float


def prepare(
    projectile: Any, target: Any, numerics: Numerics | None = None, **overrides: Any
) -> _Prepared:
    """Resolve names and build the kernel arrays (reusable across many trajectories)."""
    num = numerics or DEFAULT_NUMERICS
    if overrides:
        unknown = set(overrides) - set(Numerics.__dataclass_fields__)
        if unknown:
            raise InputError(f"unknown numerics option(s): {', '.join(sorted(unknown))}")
        num = replace(num, **overrides)
    p = get_projectile(projectile)
    t = get_target(target)
    mp = p.mass_properties()
    rings = p.rings(num.n_nose, num.n_shank, num.n_face).as_array()
    bounds, coef, fric = t.kernel_arrays()
    inertia = np.array([mp.i_axial, mp.i_transverse, mp.i_transverse])
    return _Prepared(p, t, num, rings, bounds, coef, fric, mp.mass, inertia, mp.lc)


def simulate(
    projectile: str | Projectile,
    target: str | Target,
    velocity: float,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    omega: float = 0.0,
    *,
    start: tuple[float, float, float] | None = None,
    azimuth: float = 0.0,
    stop_at_reversal: bool = False,
    numerics: Numerics | None = None,
    prepared: _Prepared | None = None,
    **overrides: Any,
) -> xr.Dataset:
    """Simulate one impact.

    Parameters
    ----------
    projectile : str or Projectile
        Name (``p1``..``p4``, validation projectiles), YAML path, or object.
    target : str or Target
        Name (``soil``, ``concrete``, ``aluminium``), YAML path, or object.
    velocity : float
        Impact speed (m/s), > 0.
    obliquity : float
        Axis angle from the target normal (deg).
    yaw : float
        Velocity angle minus axis angle (deg).
    omega : float
        Initial angular velocity about the centre of mass, about +z (rad/s).
    start : (3,) float, optional
        Initial nose-tip position (m). Default: just touching the surface at x = 0.
    azimuth : float
        Rotation of the whole impact about the target normal (deg).
    stop_at_reversal : bool
        End the run at the first reversal (outcome ``reversed``).
    numerics : Numerics, optional
        Numerical parameters; keyword overrides (``eps=...``, ``rtol=...``) apply on top.
    prepared : optional
        Output of :func:`prepare`, to skip re-resolving in loops.

    Returns
    -------
    xarray.Dataset
        Time histories on dimension ``time`` (s) and scalar results; see the README.
    """
    _check_inputs(velocity, obliquity, yaw, omega, azimuth)
    pr = prepared or prepare(projectile, target, numerics, **overrides)
    num = pr.numerics
    y0 = initial_state(
        pr.projectile,
        pr.rings,
        velocity,
        math.radians(obliquity),
        math.radians(yaw),
        omega,
        start,
        math.radians(azimuth),
    )
    length = pr.projectile.length
    atol = (
        num.rtol
        * np.array([length] * 3 + [1.0] * 4 + [velocity] * 3 + [velocity / length] * 3)
        * 1e-2
    )
    gravity = np.array([0.0, -num.gravity, 0.0])
    t0 = time.perf_counter()
    ts, ys, outcome, rev, t_contact, n_rhs, n_rej = integrate(
        y0,
        num.t_max,
        num.rtol,
        atol,
        1e-7,
        num.max_travel,
        num.v_stop,
        stop_at_reversal,
        num.max_steps,
        pr.mass,
        pr.inertia,
        gravity,
        pr.rings,
        pr.bounds,
        pr.coef,
        pr.fric,
        num.eps,
        num.n_gauss if not pr.target.frictionless else 0,
    )
    wall = time.perf_counter() - t0
    if OUTCOMES[outcome] == "step_limit":
        raise SolverError(
            f"step limit of {num.max_steps} steps reached at t = {ts[-1]:.4g} s; "
            "raise numerics max_steps or loosen rtol"
        )
    return _to_dataset(
        pr,
        ts,
        ys,
        OUTCOMES[outcome],
        rev,
        t_contact,
        n_rhs,
        n_rej,
        wall,
        dict(
            velocity=velocity,
            obliquity=obliquity,
            yaw=yaw,
            omega=omega,
            azimuth=azimuth,
            start=None if start is None else list(map(float, start)),
            stop_at_reversal=stop_at_reversal,
        ),
    )


def _to_dataset(
    pr: _Prepared, ts, ys, outcome, rev, t_contact, n_rhs, n_rej, wall, inputs
) -> xr.Dataset:
    n = len(ts)
    axes = np.empty((n, 3))
    for i in range(n):
        axes[i] = quat_to_matrix(ys[i, 3:7])[:, 0]
    cm = ys[:, 0:3]
    tip = cm + pr.lc * axes
    vel = ys[:, 7:10]
    om = ys[:, 10:13]
    theta = np.degrees(np.unwrap(np.arctan2(axes[:, 0], -axes[:, 1])))
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = vel[:, 1] / vel[:, 0]
    deviation = np.degrees(np.arctan2(np.hypot(vel[:, 0], vel[:, 2]), -vel[:, 1]))
    ke = 0.5 * pr.mass * (vel**2).sum(1) + 0.5 * (pr.inertia * om**2).sum(1)
    below = tip[:, 1] <= 0.0
    depth = float(max(0.0, -tip[:, 1].min()))
    seg = np.linalg.norm(np.diff(tip, axis=0), axis=1)
    # tip path below the surface: segments whose end is below y = 0, first one clipped
    path = 0.0
    for i in range(1, n):
        if below[i]:
            if below[i - 1]:
                path += seg[i - 1]
            else:
                frac = tip[i, 1] / (tip[i, 1] - tip[i - 1, 1])
                path += frac * seg[i - 1]
    v0 = inputs["velocity"]

    def var(data, units, long_name, **extra):
        return ("time", np.asarray(data), {"units": units, "long_name": long_name, **extra})

    ds = xr.Dataset(
        {
            "tip_x": var(tip[:, 0], "m", "nose tip x (along the surface)"),
            "tip_y": var(tip[:, 1], "m", "nose tip y (height above the target surface)"),
            "tip_z": var(tip[:, 2], "m", "nose tip z"),
            "cm_x": var(cm[:, 0], "m", "centre of mass x"),
            "cm_y": var(cm[:, 1], "m", "centre of mass y"),
            "cm_z": var(cm[:, 2], "m", "centre of mass z"),
            "vel_x": var(vel[:, 0], "m s-1", "centre of mass velocity x"),
            "vel_y": var(vel[:, 1], "m s-1", "centre of mass velocity y"),
            "vel_z": var(vel[:, 2], "m s-1", "centre of mass velocity z"),
            "omega_1": var(om[:, 0], "rad s-1", "angular velocity about the symmetry axis"),
            "omega_2": var(om[:, 1], "rad s-1", "angular velocity about body axis 2"),
            "omega_3": var(om[:, 2], "rad s-1", "angular velocity about body axis 3"),
            "axis_x": var(axes[:, 0], "1", "projectile axis (towards the nose) x"),
            "axis_y": var(axes[:, 1], "1", "projectile axis (towards the nose) y"),
            "axis_z": var(axes[:, 2], "1", "projectile axis (towards the nose) z"),
            "theta": var(
                theta,
                "degree",
                "angle from the target normal (-y) to the projectile axis, towards +x",
            ),
            "slope": var(slope, "1", "trajectory slope dy/dx of the centre of mass path"),
            "deviation": var(
                deviation, "degree", "angle between the centre of mass velocity and the normal -y"
            ),
            "speed": var(np.linalg.norm(vel, axis=1), "m s-1", "centre of mass speed"),
            "kinetic_energy": var(ke, "J", "translational + rotational kinetic energy"),
            "work": var(ys[:, 13], "J", "work done by the contact stresses"),
            "penetration_depth": (
                (),
                depth,
                {"units": "m", "long_name": "deepest point of the nose tip below the surface"},
            ),
            "path_length": (
                (),
                float(path),
                {"units": "m", "long_name": "length of the nose-tip path below the surface"},
            ),
            "final_slope": (
                (),
                float(slope[-1]),
                {"units": "1", "long_name": "trajectory slope dy/dx at the end"},
            ),
            "final_deviation": (
                (),
                float(deviation[-1]),
                {"units": "degree", "long_name": "velocity angle from the normal at the end"},
            ),
        },
        coords={"time": ("time", ts, {"units": "s", "long_name": "time since start"})},
        attrs={
            "title": "pencore trajectory",
            "outcome": outcome,
            "reversed": int(rev),
            "t_first_contact_s": float(t_contact) if np.isfinite(t_contact) else -1.0,
            "impact_velocity_m_s": float(v0),
            "obliquity_deg": float(inputs["obliquity"]),
            "yaw_deg": float(inputs["yaw"]),
            "omega_rad_s": float(inputs["omega"]),
            "projectile": pr.projectile.name,
            "target": pr.target.name,
            "mass_kg": pr.mass,
            "lc_m": pr.lc,
            "length_m": pr.projectile.length,
            "lc_over_l": pr.lc / pr.projectile.length,
            "inputs_json": json.dumps(
                {
                    "impact": inputs,
                    "projectile": _projectile_dict(pr.projectile),
                    "target": _target_dict(pr.target),
                    "numerics": asdict(pr.numerics),
                },
                default=str,
            ),
            "n_rhs": int(n_rhs),
            "n_rejected": int(n_rej),
            "n_steps": int(n - 1),
            "wall_time_s": float(wall),
            "pencore_version": __version__,
            "Conventions": "CF-1.10",
        },
    )
    return ds
