"""The :class:`xarray.Dataset` of one trajectory: time histories with units, the scalar
results (depth, path length, final slope and deviation) and the inputs as attributes."""

from __future__ import annotations

import json
import math
from dataclasses import asdict
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import hint_keywords
from pencore.inputs.geometry import Projectile
from pencore.inputs.target import Target
from pencore.integrators.driver import RunResult
from pencore.version import __version__

__all__ = [
    "VERTICAL_RATIO",
    "final_slope",
    "trajectory_dataset",
    "load_variables",
    "rotation_matrices",
]

#: Standard acceleration of gravity g0 (m/s^2), the unit of a deceleration "in g"
#: (3rd CGPM, 1901; exact by definition).
STANDARD_GRAVITY = 9.80665

#: Largest ``|vx| / |vy|`` at which :func:`final_slope` takes the motion as vertical:
#: 16 units in the last place of ``|vy|`` (``16 * 2**-52``, 3.6e-15).
VERTICAL_RATIO = 16 * float(np.finfo(float).eps)


def _layer_dict(lay: Any) -> dict[str, Any]:
    if lay.is_gap:
        return {"thickness": lay.thickness, "gap": True}
    return {
        "thickness": lay.thickness,
        "medium": {
            "name": lay.medium.name,
            "coefficients": list(lay.medium.coefficients),
            "friction": [
                list(p)
                for p in zip(lay.medium.friction_speeds, lay.medium.friction_mu, strict=True)
            ],
            "source": lay.medium.source,
            # the depth windows only when on (default runs record what they always did)
            **{
                k: getattr(lay.medium, k)
                for k in ("crater_depth", "free_surface_depth", "plastic_zone_ratio")
                if getattr(lay.medium, k) > 0.0
            },
        },
    }


def _law_resolved(t: Target) -> dict[str, str]:
    """``law_resolved``: what a law that depends on the projectile was resolved to (the
    diameter, the crater depth, the size term's factor and ``S``:
    :meth:`pencore.inputs.target.Medium.for_projectile`), per medium; absent otherwise (a
    default run records what it always did)."""
    notes = [
        f"{lay.medium.name}: {lay.medium.source.split('; resolved for ', 1)[1]}"
        for lay in t.solid_layers
        if "; resolved for " in lay.medium.source
    ]
    return {"law_resolved": "resolved for " + " | ".join(notes)} if notes else {}


def _target_dict(t: Target) -> dict[str, Any]:
    return {"name": t.name, "layers": [_layer_dict(lay) for lay in t.layers]}


def _projectile_dict(p: Projectile) -> dict[str, Any]:
    d = asdict(p)
    d["nose"]["kind"] = type(p.nose).__name__
    for key in ("mass", "centre_of_mass", "inertia", "yield_strength"):  # only when given
        if d[key] is None:
            del d[key]
    return d


def rotation_matrices(q: np.ndarray) -> np.ndarray:
    """Rotation matrices (body -> fixed), (n, 3, 3), of the quaternion rows of ``q``
    (n, 4; normalised here): :func:`pencore.kernels.dynamics.quat_to_matrix` for all rows at
    once, with the same operations in the same order (so the same bits)."""
    nq = np.sqrt(q[:, 0] * q[:, 0] + q[:, 1] * q[:, 1] + q[:, 2] * q[:, 2] + q[:, 3] * q[:, 3])
    w, x, y, z = (q[:, k] / nq for k in range(4))
    r = np.empty((q.shape[0], 3, 3))
    r[:, 0, 0] = w * w + x * x - y * y - z * z
    r[:, 0, 1] = 2 * (x * y - w * z)
    r[:, 0, 2] = 2 * (x * z + w * y)
    r[:, 1, 0] = 2 * (x * y + w * z)
    r[:, 1, 1] = w * w - x * x + y * y - z * z
    r[:, 1, 2] = 2 * (y * z - w * x)
    r[:, 2, 0] = 2 * (x * z - w * y)
    r[:, 2, 1] = 2 * (y * z + w * x)
    r[:, 2, 2] = w * w - x * x - y * y + z * z
    return r


def load_variables(
    loads: np.ndarray, mass: float, time: np.ndarray
) -> tuple[dict[str, tuple], dict[str, float]]:
    """The load histories of a trajectory and their peaks.

    Parameters
    ----------
    loads : (k, 6) ndarray
        Contact force (N) and moment (N m) in body axes at those states
        (:func:`pencore.run.loads.body_loads`).
    mass : float
        Mass of the projectile (kg).
    time : (k,) ndarray
        The saved times (s).

    Returns
    -------
    variables : dict
        ``axial_force`` (N, positive resisting: towards the tail), ``lateral_force`` (N,
        magnitude across the axis), ``deceleration``
        (m s-2: ``axial_force / mass``, what an axial accelerometer at the centre of mass
        reads) and ``deceleration_g`` (the same in units of g0 = 9.80665 m s-2), on
        ``time``.
    peaks : dict
        ``peak_axial_force_N``, ``peak_lateral_force_N``, ``peak_deceleration_m_s2``,
        ``peak_deceleration_g`` (largest magnitudes) and ``time_of_peak_deceleration_s``.
    """
    fb = loads[:, 0:3]
    axial = -fb[:, 0]
    lateral = np.hypot(fb[:, 1], fb[:, 2])
    decel = axial / mass

    def var(data, units, long_name):
        return ("time", np.asarray(data), {"units": units, "long_name": long_name})

    variables = {
        "axial_force": var(
            axial, "N", "axial contact force on the body (positive: towards the tail, resisting)"
        ),
        "lateral_force": var(lateral, "N", "contact force across the projectile axis (magnitude)"),
        "deceleration": var(
            decel, "m s-2", "axial deceleration by the contact stresses (axial force / mass)"
        ),
        "deceleration_g": var(
            decel / STANDARD_GRAVITY,
            "1",
            "axial deceleration in units of standard gravity g0 = 9.80665 m s-2",
        ),
    }
    if len(time) == 0:
        return variables, {}
    i = int(np.argmax(np.abs(decel)))
    peaks = {
        "peak_axial_force_N": float(np.abs(axial).max()),
        "peak_lateral_force_N": float(lateral.max()),
        "peak_deceleration_m_s2": float(abs(decel[i])),
        "peak_deceleration_g": float(abs(decel[i]) / STANDARD_GRAVITY),
        "time_of_peak_deceleration_s": float(time[i]),
    }
    return variables, peaks


def _path_below(tip: np.ndarray, below: np.ndarray) -> float:
    """Length (m) of the tip path below the surface: the segments whose end is below
    ``y = 0``, the first of each stretch clipped at the surface; summed in order."""
    seg = np.linalg.norm(np.diff(tip, axis=0), axis=1)
    end, start = below[1:], below[:-1]
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = tip[1:, 1] / (tip[1:, 1] - tip[:-1, 1])
    part = np.where(end & start, seg, np.where(end, frac * seg, 0.0))
    # a running sum adds left to right, as the loop it replaces did
    return float(np.cumsum(part)[-1]) if part.size else 0.0


def final_slope(vel: np.ndarray) -> float:
    """Slope ``dy/dx`` of the centre-of-mass path for the velocity ``vel`` (m/s; x, y, z)
    at the end of a run: ``vy / vx``, or ``-inf`` (moving down) or ``+inf`` (moving up)
    when ``|vx| <= VERTICAL_RATIO * |vy|``; NaN when ``vx = vy = 0``.

    In a normal impact the exact ``vx`` is 0, but the forces on the body are sums in
    floating point whose x parts cancel only to the rounding of terms the size of the y
    parts, so an integrator can end with a ``vx`` of round-off (measured: up to half an
    ulp of ``|vy|``) of either sign, and ``vy / vx`` is then a number like 1e16 or 1e40
    with the sign of the noise (positive: moving up). A component below a few ulps of
    the speed is below the rounding of the velocity itself, so the direction is vertical
    to the precision of the state. 16 ulps is 30 times the round-off measured and over
    three orders of magnitude below the smallest non-zero ``|vx| / |vy|`` of physical
    origin seen (4.5e-12, a spinning impact's first steps); its slope, 2.8e14, is a
    deviation from the normal of 2e-13 deg. ``vx = -0.0`` is vertical too, so a body
    moving down is never reported at ``+inf``.

    Parameters
    ----------
    vel : (3,) ndarray
        Centre-of-mass velocity (m/s).

    Returns
    -------
    float
        ``dy/dx`` (dimensionless).
    """
    vx, vy = float(vel[0]), float(vel[1])
    if vy != 0.0 and abs(vx) <= VERTICAL_RATIO * abs(vy):
        return math.copysign(math.inf, vy)
    with np.errstate(divide="ignore", invalid="ignore"):
        return float(np.float64(vy) / np.float64(vx))


def trajectory_dataset(
    projectile: Projectile,
    target: Target,
    numerics: Any,
    run: RunResult,
    wall: float,
    inputs: dict[str, Any],
    loads: np.ndarray | None = None,
) -> xr.Dataset:
    """The Dataset of one integrated trajectory.

    Parameters
    ----------
    projectile, target : Projectile, Target
        What was simulated.
    numerics : pencore.Numerics
        The numerical parameters used (recorded in ``inputs_json``).
    run : pencore.integrators.driver.RunResult
        The accepted states (SI units, 14 components: centre of mass position, attitude
        quaternion, velocity, body angular velocity, work of the contact stresses).
    wall : float
        Wall time of the integration (s).
    inputs : dict
        The impact conditions (velocity m/s, angles deg, omega rad/s, start m).
    loads : (k, 6) ndarray, optional
        Contact force (N) and moment (N m), body frame, at the saved states
        (:func:`pencore.run.loads.body_loads`): adds the load histories and their peaks
        (:func:`load_variables`).

    Returns
    -------
    xarray.Dataset
        Time histories on dimension ``time`` (s), the scalars ``penetration_depth``,
        ``path_length`` (m), ``final_slope``, ``final_deviation`` (deg), and attributes;
        a ``perforated`` run also has the residual velocity and exit attitude
        (:func:`exit_attributes`).
    """
    ts, ys = run.ts, run.ys
    mp = projectile.mass_properties()
    lc, mass = mp.lc, mp.mass
    inertia = np.array([mp.i_axial, mp.i_transverse, mp.i_transverse])
    n = len(ts)
    axes = rotation_matrices(ys[:, 3:7])[:, :, 0]  # body axis 1 in the fixed frame
    cm = ys[:, 0:3]
    tip = cm + lc * axes
    vel = ys[:, 7:10]
    om = ys[:, 10:13]
    theta = np.degrees(np.unwrap(np.arctan2(axes[:, 0], -axes[:, 1])))
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = vel[:, 1] / vel[:, 0]
    deviation = np.degrees(np.arctan2(np.hypot(vel[:, 0], vel[:, 2]), -vel[:, 1]))
    ke = 0.5 * mass * (vel**2).sum(1) + 0.5 * (inertia * om**2).sum(1)
    below = tip[:, 1] <= 0.0
    depth = float(max(0.0, -tip[:, 1].min()))
    path = _path_below(tip, below)
    v0 = inputs["velocity"]
    load_vars, peaks = ({}, {}) if loads is None else load_variables(loads, mass, ts)

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
                final_slope(vel[-1]),
                {
                    "units": "1",
                    "long_name": "trajectory slope dy/dx at the end "
                    "(-inf / +inf: moving vertically down / up)",
                },
            ),
            "final_deviation": (
                (),
                float(deviation[-1]),
                {"units": "degree", "long_name": "velocity angle from the normal at the end"},
            ),
            **load_vars,
        },
        coords={"time": ("time", ts, {"units": "s", "long_name": "time since start"})},
        attrs={
            "title": "pencore trajectory",
            "outcome": run.outcome,
            "reversed": int(run.reversed),
            "t_first_contact_s": float(run.t_first_contact)
            if np.isfinite(run.t_first_contact)
            else -1.0,
            "impact_velocity_m_s": float(v0),
            "obliquity_deg": float(inputs["obliquity"]),
            "yaw_deg": float(inputs["yaw"]),
            "omega_rad_s": float(inputs["omega"]),
            "projectile": projectile.name,
            "target": target.name,
            "mass_kg": mass,
            "lc_m": lc,
            "length_m": projectile.length,
            "lc_over_l": lc / projectile.length,
            "i_axial_kg_m2": mp.i_axial,
            "i_transverse_kg_m2": mp.i_transverse,
            **{f"{k}_source": v for k, v in projectile.mass_provenance().items()},
            "inputs_json": json.dumps(
                {
                    "impact": inputs,
                    "projectile": _projectile_dict(projectile),
                    "target": _target_dict(target),
                    "numerics": asdict(numerics),
                },
                default=str,
            ),
            "n_rhs": run.n_rhs,
            "n_rejected": run.n_rejected,
            "n_steps": int(n - 1),
            "wall_time_s": float(wall),
            "pencore_version": __version__,
            "Conventions": "CF-1.8",
            **peaks,
            **_law_resolved(target),
        },
    )
    if run.outcome == "perforated":
        ds.attrs.update(exit_attributes(ys[-1], axes[-1]))
    return ds


def exit_attributes(y: np.ndarray, axis: np.ndarray) -> dict[str, float]:
    """Residual velocity and exit attitude of a perforating run at the state ``y`` where the
    whole body has cleared the rear face of the target (:func:`pencore.kernels.state.perforated`).

    Returns
    -------
    dict
        ``residual_velocity`` (m/s): centre-of-mass speed; ``exit_pitch_deg``: angle from
        the target normal (-y) to the projectile axis, positive towards +x (as ``theta``);
        ``exit_deviation_deg``: angle from the normal to the velocity;
        ``exit_angle_of_attack_deg``: angle between the axis and the velocity;
        ``exit_angular_velocity_rad_s``: magnitude of the transverse angular velocity.
    """
    vel = y[7:10]
    speed = float(np.linalg.norm(vel))
    cos_aoa = float(np.dot(axis, vel)) / max(speed, 1e-300)
    return {
        "residual_velocity": speed,
        "residual_velocity_units": "m s-1",
        "exit_pitch_deg": float(np.degrees(np.arctan2(axis[0], -axis[1]))),
        "exit_deviation_deg": float(np.degrees(np.arctan2(np.hypot(vel[0], vel[2]), -vel[1]))),
        "exit_angle_of_attack_deg": float(np.degrees(np.arccos(np.clip(cos_aoa, -1.0, 1.0)))),
        "exit_angular_velocity_rad_s": float(np.hypot(y[11], y[12])),
    }


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
