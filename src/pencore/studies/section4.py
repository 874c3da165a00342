"""Section 4 studies of the paper (Figs 7-18) and the comparison with its numbers.

Each function runs pencore for one figure and returns an :class:`xarray.Dataset` with
named dimensions, and ``units`` and ``long_name`` on every variable. No Snakemake and no
file I/O: ``workflow/scripts/section4.py`` reads the configuration, calls these, and
writes the results with :mod:`pencore.io`.

=====================  ===================================================================
function               paper
=====================  ===================================================================
:func:`fig7`           Fig. 7: trajectories of #2 at 45 deg for velocities around Vcr
:func:`vcr_study`      Figs 8 and 12: Vcr on (projectile, obliquity, yaw), with the final
                       nose direction at Vcr
:func:`fig8`           Fig. 8: :func:`vcr_study` at zero yaw, dims (projectile, obliquity)
:func:`fig9`           Fig. 9: total turning angle d(theta)_12 against Lc/L
:func:`trajectory_set` Figs 11 and 16: trajectories along one impact parameter
:func:`fig13`          Figs 13-14: normal impact with small yaw, both yaw conventions
:func:`fig16`          Figs 16-17: normal impact with initial angular velocity
:func:`vci_study`      Fig. 15: Vci on (projectile, yaw, deviation threshold)
:func:`start_height_study`  Figs 16-17: how alpha moves with the unstated start height
:func:`omega_c_study`  Fig. 18: omega_c on (projectile, impact velocity)
:func:`paper_comparison`  every number and trend the paper states, beside pencore's
=====================  ===================================================================

Conventions (those of :func:`pencore.simulate`): the target is ``y <= 0``; obliquity
phi1 is the angle of the projectile AXIS from the target normal; yaw phi2 is the velocity
angle minus the axis angle (paper Fig. 10). For a *normal* impact with yaw (Figs 13-15)
the paper does not say whether the velocity or the axis is normal;
:func:`pencore.critical.normal_impact_angles` maps both readings (``axis_tilted``: the
velocity is normal, the axis tilted by the yaw; ``velocity_tilted``: the other way).

Trajectory datasets share one time axis per dataset: the union of the runs' own
(adaptive) sample times, thinned evenly in index to about ``n_time`` samples, plus every
run's last time; each run is interpolated linearly onto it and is NaN after its end.
Scalar results (depth, final deviation, nose direction, ...) come from the full runs.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from itertools import product
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from .. import analysis, critical
from ..critical import OMEGA_TOL, VELOCITY_TOL, YAW_CONVENTIONS
from ..library import InputError, get_projectile
from ..solver import Numerics, prepare, simulate
from . import resolve_numerics

__all__ = [
    "PROJECTILES",
    "PAPER",
    "TRAJECTORY_VARIABLES",
    "TrendResult",
    "projectile_coords",
    "start_from_height",
    "grid",
    "stack_trajectories",
    "trajectory_set",
    "fig7",
    "vcr_study",
    "fig8",
    "fig9",
    "fig13",
    "fig16",
    "vci_study",
    "start_height_study",
    "omega_c_study",
    "combine",
    "trend",
    "paper_comparison",
    "STUDIES",
    "SPLIT_STUDIES",
    "parts_of",
    "from_config",
    "gather",
]

#: The paper's projectiles (Table 3), in order of rising Lc/L.
PROJECTILES = ("p1", "p2", "p3", "p4")

#: Numbers the paper states in Section 4 (provenance ``paper``), and brackets derived from
#: them (provenance ``derived``: how).
PAPER: dict[str, Any] = {
    # Fig. 7 (#2, 45 deg, tip from (-1, 1) m): 1641 does not turn back, 1650 and 1700 do
    "fig7_reverses": {1641.0: False, 1650.0: True, 1700.0: True},
    "fig7_x_linear_m": 7.0,  # "curvilinear -> linear at x approx 7 m" for 1641-1700
    # derived from fig7_reverses: Vcr of #2 at 45 deg is in (1641, 1650]
    "vcr_p2_45_bracket": (1641.0, 1650.0),
    # Figs 13-14 (#4, yaw 0.1 deg, normal impact): deviation phi (deg)
    "fig13_phi_deg": {280.0: 0.16, 1000.0: 0.24},
    "fig13_large_at": 2200.0,
    # Figs 16-17 (#2, 1000 m/s, normal impact): deviation alpha (deg), reversal at 25
    "fig16_alpha_deg": {5.0: 0.14, 20.0: 2.86},
    "fig16_reverses_at": 25.0,
    # derived: omega_c of #2 at 1000 m/s is in (20, 25] rad/s
    "omega_c_p2_1000_bracket": (20.0, 25.0),
    # Table 3
    "table3": {"p1": (19.1, 0.504), "p2": (23.1, 0.525), "p3": (32.8, 0.553), "p4": (45.3, 0.571)},
}

#: Time histories kept in trajectory datasets (all written by :func:`pencore.simulate`,
#: plus ``deviation_signed``).
TRAJECTORY_VARIABLES = (
    "tip_x",
    "tip_y",
    "cm_x",
    "cm_y",
    "vel_x",
    "vel_y",
    "slope",
    "deviation",
    "deviation_signed",
    "theta",
    "axis_x",
    "speed",
)

_STR = object  # dtype of string variables (netCDF variable-length strings)


def _attrs(units: str, long_name: str, **extra: Any) -> dict[str, Any]:
    return {"units": units, "long_name": long_name, **extra}


# ----------------------------------------------------------------------------- helpers


def projectile_coords(projectiles: Sequence[str]) -> dict[str, Any]:
    """Coordinates on dimension ``projectile``: names, ``lc_over_l`` and ``mass``."""
    names = list(projectiles)
    if not names:
        raise InputError("need at least one projectile")
    lcl, mass = [], []
    for p in names:
        proj = get_projectile(p)
        mp = proj.mass_properties()
        lcl.append(mp.lc / proj.length)
        mass.append(mp.mass)
    return {
        "projectile": (
            "projectile",
            np.array(names, dtype=_STR),
            {"long_name": "projectile (paper Table 3)", "units": "1"},
        ),
        "lc_over_l": (
            "projectile",
            np.array(lcl),
            _attrs("1", "nose tip to centre of mass over total length, L_c/L (pencore geometry)"),
        ),
        "mass": ("projectile", np.array(mass), _attrs("kg", "projectile mass")),
    }


def start_from_height(height: float) -> tuple[float, float, float] | None:
    """Nose-tip start for a normal impact whose tip starts ``height`` (m) above y = 0.

    ``0`` gives ``None``: :func:`pencore.simulate`'s default, the lowest point of the body
    just touching the surface at x = 0.
    """
    h = float(height)
    if not (math.isfinite(h) and h >= 0.0):
        raise InputError(f"start height must be >= 0 m, got {height!r}")
    return None if h == 0.0 else (0.0, h, 0.0)


def grid(min: float, max: float, step: float) -> np.ndarray:
    """Values from ``min`` to ``max`` inclusive in steps of ``step`` (rounded to 1e-9)."""
    lo, hi, st = float(min), float(max), float(step)
    if not (math.isfinite(lo) and math.isfinite(hi) and math.isfinite(st) and st > 0 and hi >= lo):
        raise InputError(f"grid needs min <= max and step > 0, got {min}, {max}, {step}")
    n = int(math.floor((hi - lo) / st + 1e-9)) + 1
    return np.round(lo + st * np.arange(n), 9)


def _axis(values: Iterable[float], what: str) -> np.ndarray:
    v = np.asarray(list(values), dtype=float).ravel()
    if v.size == 0 or not np.all(np.isfinite(v)):
        raise InputError(f"{what} must be a non-empty list of numbers, got {list(v)}")
    if np.unique(v).size != v.size:
        raise InputError(f"{what} has repeated values: {list(v)}")
    return v


def _start(start: Sequence[float] | None) -> tuple[float, float, float] | None:
    if start is None:
        return None
    s = tuple(float(x) for x in start)
    if len(s) != 3 or not all(math.isfinite(x) for x in s):
        raise InputError(f"start must be 3 finite coordinates (m), got {start!r}")
    return s


def _signed_deviation(ds: xr.Dataset) -> np.ndarray:
    """In-plane velocity angle from -y, positive towards +x, unwrapped (degree)."""
    return np.degrees(np.unwrap(np.arctan2(ds["vel_x"].values, -ds["vel_y"].values)))


# ----------------------------------------------------------------------------- trajectories


def stack_trajectories(
    runs: Mapping[tuple[int, ...], xr.Dataset],
    coords: Mapping[str, tuple[Any, dict[str, Any]]],
    *,
    n_time: int = 500,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
) -> xr.Dataset:
    """Put many :func:`pencore.simulate` runs on shared dimensions ``(*coords, time)``.

    Parameters
    ----------
    runs : mapping
        Index tuple (one index per entry of ``coords``) -> run dataset.
    coords : mapping
        Dimension name -> (values, attributes), in dimension order.
    n_time : int
        About this many samples on the shared time axis (see the module docstring).
    speed_fraction : float
        Fraction of the impact speed that ends the analysed part of a run
        (:func:`pencore.analysis.final_deviation`).

    Returns
    -------
    xarray.Dataset
        :data:`TRAJECTORY_VARIABLES` on ``(*dims, time)`` and per-run scalars on ``dims``:
        ``outcome``, ``reversed``, ``penetration_depth``, ``path_length``,
        ``final_deviation`` (and ``final_deviation_signed``), ``final_theta``,
        ``nose_direction``, ``t_first_contact``, ``t_end``, ``n_steps``, ``wall_time``.
    """
    if int(n_time) < 2:
        raise InputError(f"n_time must be >= 2, got {n_time!r}")
    dims = list(coords)
    shape = tuple(len(np.atleast_1d(v)) for v, _ in coords.values())
    if set(runs) != set(product(*(range(n) for n in shape))):
        raise InputError("runs must hold one dataset for every combination of coordinates")
    all_t = np.unique(np.concatenate([r["time"].values for r in runs.values()]))
    pick = np.unique(np.round(np.linspace(0, all_t.size - 1, int(n_time))).astype(int))
    t = np.union1d(all_t[pick], [float(r["time"].values[-1]) for r in runs.values()])

    hist = {k: np.full(shape + (t.size,), np.nan) for k in TRAJECTORY_VARIABLES}
    scal_f = {
        k: np.full(shape, np.nan)
        for k in (
            "penetration_depth",
            "path_length",
            "final_deviation",
            "final_deviation_signed",
            "final_theta",
            "t_first_contact",
            "t_end",
            "wall_time",
        )
    }
    reversed_ = np.zeros(shape, dtype=np.int8)
    n_steps = np.zeros(shape, dtype=np.int64)
    outcome = np.empty(shape, dtype=_STR)
    nose = np.empty(shape, dtype=_STR)
    for idx, r in runs.items():
        rt = r["time"].values
        for k in TRAJECTORY_VARIABLES:
            src = _signed_deviation(r) if k == "deviation_signed" else r[k].values
            with np.errstate(invalid="ignore"):
                hist[k][idx] = np.interp(t, rt, src, left=np.nan, right=np.nan)
        scal_f["penetration_depth"][idx] = float(r["penetration_depth"])
        scal_f["path_length"][idx] = float(r["path_length"])
        scal_f["final_deviation"][idx] = analysis.final_deviation(r, speed_fraction)
        scal_f["final_deviation_signed"][idx] = analysis.final_deviation(
            r, speed_fraction, signed=True
        )
        scal_f["final_theta"][idx] = float(r["theta"].values[-1])
        tc = float(r.attrs["t_first_contact_s"])
        scal_f["t_first_contact"][idx] = tc if tc >= 0 else np.nan
        scal_f["t_end"][idx] = float(rt[-1])
        scal_f["wall_time"][idx] = float(r.attrs["wall_time_s"])
        reversed_[idx] = int(r.attrs["reversed"])
        n_steps[idx] = int(r.attrs["n_steps"])
        outcome[idx] = str(r.attrs["outcome"])
        nose[idx] = analysis.nose_direction(r)

    first = next(iter(runs.values()))
    tdims = (*dims, "time")
    data = {
        k: (tdims, hist[k], dict(first[k].attrs))
        for k in TRAJECTORY_VARIABLES
        if k != "deviation_signed"
    }
    data["deviation_signed"] = (
        tdims,
        hist["deviation_signed"],
        _attrs(
            "degree",
            "in-plane angle from the normal -y to the centre of mass velocity, "
            "positive towards +x (unwrapped)",
        ),
    )
    fd = f"at the last state with speed >= {speed_fraction:g} x impact speed"
    data.update(
        {
            "outcome": (
                dims,
                outcome,
                {"long_name": "how the run ended (stopped, exited, ...)", "units": "1"},
            ),
            "reversed": (
                dims,
                reversed_,
                _attrs(
                    "1", "1 if the centre of mass velocity turned towards the surface in the target"
                ),
            ),
            "penetration_depth": (
                dims,
                scal_f["penetration_depth"],
                _attrs("m", "deepest point of the nose tip below the surface"),
            ),
            "path_length": (
                dims,
                scal_f["path_length"],
                _attrs("m", "length of the nose-tip path below the surface"),
            ),
            "final_deviation": (
                dims,
                scal_f["final_deviation"],
                _attrs(
                    "degree",
                    f"trajectory deviation from the normal (paper phi, alpha) {fd}",
                    speed_fraction=float(speed_fraction),
                ),
            ),
            "final_deviation_signed": (
                dims,
                scal_f["final_deviation_signed"],
                _attrs(
                    "degree", f"signed in-plane trajectory deviation (positive towards +x) {fd}"
                ),
            ),
            "final_theta": (
                dims,
                scal_f["final_theta"],
                _attrs("degree", "axis angle from the normal at the end of the run"),
            ),
            "nose_direction": (
                dims,
                nose,
                {"units": "1", "long_name": "side the nose points to at the end (+x or -x)"},
            ),
            "t_first_contact": (
                dims,
                scal_f["t_first_contact"],
                _attrs("s", "time of first contact with the target"),
            ),
            "t_end": (dims, scal_f["t_end"], _attrs("s", "time at the end of the run")),
            "n_steps": (dims, n_steps, _attrs("1", "accepted integration steps")),
            "wall_time": (dims, scal_f["wall_time"], _attrs("s", "solver wall time")),
        }
    )
    c = {d: (d, np.asarray(v), dict(a)) for d, (v, a) in coords.items()}
    c["time"] = (
        "time",
        t,
        _attrs("s", "time since start (shared, thinned grid; NaN after a run ends)"),
    )
    ds = xr.Dataset(data, coords=c)
    ds.attrs.update(
        {
            "projectile": first.attrs["projectile"],
            "target": first.attrs["target"],
            "lc_over_l": float(first.attrs["lc_over_l"]),
            "numerics_json": json.dumps(json.loads(first.attrs["inputs_json"])["numerics"]),
            "time_axis": f"union of the runs' sample times thinned to about {int(n_time)}, "
            "runs interpolated linearly",
            "Conventions": "CF-1.10",
        }
    )
    return ds


_PARAM_ATTRS = {
    "velocity": _attrs("m s-1", "impact velocity V_i"),
    "obliquity": _attrs("degree", "angle of obliquity phi_1 (axis from the target normal)"),
    "yaw": _attrs("degree", "yaw angle phi_2 (velocity angle minus axis angle)"),
    "omega": _attrs("rad s-1", "initial angular velocity about the centre of mass (+z)"),
}


def _runs_along(
    projectile: str,
    target: str,
    dim: str,
    values: np.ndarray,
    numerics: Numerics,
    start: tuple[float, float, float] | None,
    fixed: Mapping[str, float],
) -> dict[tuple[int], xr.Dataset]:
    pr = prepare(projectile, target, numerics)
    runs = {}
    for i, v in enumerate(values):
        kw = {**fixed, dim: float(v)}
        runs[(i,)] = simulate(
            pr.projectile,
            pr.target,
            kw["velocity"],
            kw["obliquity"],
            kw["yaw"],
            kw["omega"],
            start=start,
            prepared=pr,
        )
    return runs


def trajectory_set(
    projectile: str,
    target: str,
    dim: str,
    values: Sequence[float],
    *,
    velocity: float = 1000.0,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    omega: float = 0.0,
    start: Sequence[float] | None = None,
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
    _runs: dict | None = None,
) -> xr.Dataset:
    """Full trajectories (not cut at reversal) along one impact parameter.

    ``dim`` is one of ``velocity`` (m/s), ``obliquity``, ``yaw`` (deg), ``omega``
    (rad/s); ``values`` replace that argument, the others are fixed. ``start`` is the
    initial nose-tip position (m), ``None`` for surface contact at x = 0. Returns
    :func:`stack_trajectories` on ``(dim, time)``.
    """
    if dim not in _PARAM_ATTRS:
        raise InputError(f"dim must be one of {', '.join(_PARAM_ATTRS)}, got {dim!r}")
    vals = _axis(values, dim)
    fixed = dict(velocity=velocity, obliquity=obliquity, yaw=yaw, omega=omega)
    runs = _runs_along(
        projectile, target, dim, vals, resolve_numerics(numerics), _start(start), fixed
    )
    if _runs is not None:
        _runs.update(runs)
    ds = stack_trajectories(
        runs, {dim: (vals, _PARAM_ATTRS[dim])}, n_time=n_time, speed_fraction=speed_fraction
    )
    for k, v in fixed.items():
        if k != dim:
            ds.attrs[f"{k}_fixed"] = float(v)
    ds.attrs["start_m"] = "surface contact at x = 0" if start is None else str(list(start))
    return ds


def fig16(
    projectile: str = "p2",
    target: str = "soil",
    velocity: float = 1000.0,
    omegas: Sequence[float] = (5.0, 20.0, 25.0),
    *,
    start_height: float = 0.0,
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
) -> xr.Dataset:
    """Paper Figs 16-17: normal impact of #2 at 1000 m/s with initial angular velocity.

    Dims ``(omega, time)``; ``final_deviation`` is the paper's alpha. The nose tip starts
    ``start_height`` (m) above the surface (0: touching; the paper does not say, see
    :func:`start_height_study`).
    """
    ds = trajectory_set(
        projectile,
        target,
        "omega",
        omegas,
        velocity=velocity,
        start=start_from_height(start_height),
        numerics=numerics,
        n_time=n_time,
        speed_fraction=speed_fraction,
    )
    ds.attrs.update(
        {
            "title": "Paper Figs 16-17: normal impact with angular velocity",
            "start_height_m": float(start_height),
        }
    )
    return ds


def fig7(
    projectile: str = "p2",
    target: str = "soil",
    obliquity: float = 45.0,
    velocities: Sequence[float] = (1000.0, 1500.0, 1641.0, 1650.0, 1700.0),
    *,
    start: Sequence[float] | None = (-1.0, 1.0, 0.0),
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
    bracket_fraction: float = analysis.DEFAULT_BRACKET_FRACTION,
) -> xr.Dataset:
    """Paper Fig. 7: trajectories and slopes of #2 at 45 deg, tip from (-1, 1) m.

    Dims ``(velocity, time)``. Besides :func:`stack_trajectories`' variables: ``x_linear``
    (x of the centre of mass where the curved part ends, Point 2 of Eq. 12 by
    :func:`pencore.analysis.turning_angle`) and ``delta_theta``.
    """
    runs: dict[tuple[int], xr.Dataset] = {}
    ds = trajectory_set(
        projectile,
        target,
        "velocity",
        velocities,
        obliquity=obliquity,
        start=start,
        numerics=numerics,
        n_time=n_time,
        _runs=runs,
    )
    vals = ds["velocity"].values
    x2 = np.full(vals.size, np.nan)
    dth = np.full(vals.size, np.nan)
    reason = np.empty(vals.size, dtype=_STR)
    for i in range(vals.size):
        ta = analysis.turning_angle(runs[(i,)], fraction=bracket_fraction)
        x2[i], dth[i], reason[i] = ta.x_2, ta.delta_theta, ta.reason
    ds["x_linear"] = (
        "velocity",
        x2,
        _attrs(
            "m",
            "centre of mass x where the curved part of the path ends (Point 2, "
            f"|curvature| below {bracket_fraction:g} of its peak)",
        ),
    )
    ds["delta_theta"] = (
        "velocity",
        dth,
        _attrs("degree", "total turning angle theta_2 - theta_1 (Eq. 12)"),
    )
    ds["turning_angle_note"] = (
        "velocity",
        reason,
        {"units": "1", "long_name": "why delta_theta is NaN (empty when defined)"},
    )
    ds.attrs["title"] = "Paper Fig. 7: trajectories at 45 deg obliquity around Vcr"
    return ds


# ----------------------------------------------------------------------------- searches


def _search_vars(
    results: np.ndarray, name: str, units: str, long_name: str, dims: tuple[str, ...]
) -> dict[str, Any]:
    """Variables ``name``, ``name_lo``, ``name_hi``, ``status``, ``n_evals``,
    ``monotone``, ``message``, ``history`` from an object array of CriticalResult."""

    def arr(f, dtype=float):
        out = np.empty(results.shape, dtype=dtype)
        for idx in np.ndindex(results.shape):
            out[idx] = f(results[idx])
        return out

    return {
        name: (
            dims,
            arr(lambda r: r.value),
            _attrs(
                units,
                long_name,
                note="midpoint of the final bracket; NaN unless status is ok or non_monotone",
            ),
        ),
        f"{name}_lo": (
            dims,
            arr(lambda r: r.lo),
            _attrs(units, f"{long_name}: largest value evaluated without the event (bracket low)"),
        ),
        f"{name}_hi": (
            dims,
            arr(lambda r: r.hi),
            _attrs(units, f"{long_name}: smallest value evaluated with the event (bracket high)"),
        ),
        "status": (
            dims,
            arr(lambda r: r.status, _STR),
            {"units": "1", "long_name": "search status: " + ", ".join(critical.STATUSES)},
        ),
        "n_evals": (
            dims,
            arr(lambda r: r.n_evals, np.int64),
            _attrs("1", "number of trajectories run by the search"),
        ),
        "monotone": (
            dims,
            arr(lambda r: int(r.monotone), np.int8),
            _attrs("1", "0 if the coarse scan found the verdict not monotone"),
        ),
        "message": (
            dims,
            arr(lambda r: r.message, _STR),
            {"units": "1", "long_name": "search report"},
        ),
        "history": (
            dims,
            arr(lambda r: json.dumps(r.to_dict()["history"]), _STR),
            {"units": "1", "long_name": "every value evaluated and its verdict (JSON)"},
        ),
    }


def vcr_study(
    projectiles: Sequence[str],
    obliquities: Sequence[float],
    yaws: Sequence[float] = (0.0,),
    *,
    target: str = "soil",
    lo: float = 300.0,
    hi: float = 4000.0,
    tol: float = VELOCITY_TOL,
    scan: int | None = 9,
    start: Sequence[float] | None = (-1.0, 1.0, 0.0),
    numerics: Numerics | Mapping[str, Any] | None = None,
    nose: bool = False,
    low_speeds: Sequence[float] = (),
) -> xr.Dataset:
    """Critical reverse velocity Vcr on ``(projectile, obliquity, yaw)`` (Figs 8, 12).

    Each cell is :func:`pencore.critical.vcr` on ``[lo, hi]`` m/s to ``tol`` with a
    ``scan``-point monotonicity check. With ``nose=True`` the run at the bracket's high
    end (the lowest speed seen to reverse) is simulated in full, and the side the nose
    points to at its end is recorded (``nose_direction``, ``final_theta``,
    ``outcome_at_vcr``). ``low_speeds`` (m/s, below ``lo``) are also run and their
    reversal recorded (``low_speed_reversed``): at large obliquity slow projectiles
    ricochet during nose entry, which is not the turn-back that Vcr is about, and is why
    ``lo`` is above them.
    """
    names = list(projectiles)
    obl = _axis(obliquities, "obliquities")
    yw = _axis(yaws, "yaws")
    low = np.asarray(list(low_speeds), dtype=float)
    num = resolve_numerics(numerics)
    st = _start(start)
    shape = (len(names), obl.size, yw.size)
    res = np.empty(shape, dtype=object)
    nose_dir = np.full(shape, "", dtype=_STR)
    final_theta = np.full(shape, np.nan)
    outcome_hi = np.full(shape, "", dtype=_STR)
    low_rev = np.zeros(shape + (low.size,), dtype=np.int8)
    for ip, p in enumerate(names):
        pr = prepare(p, target, num)
        for io, ob in enumerate(obl):
            for iy, y in enumerate(yw):
                r = critical.vcr(
                    p, target, float(ob), float(y), lo, hi, tol, scan=scan, start=st, numerics=num
                )
                res[ip, io, iy] = r
                if nose and math.isfinite(r.hi):
                    run = simulate(
                        pr.projectile, pr.target, r.hi, float(ob), float(y), start=st, prepared=pr
                    )
                    nose_dir[ip, io, iy] = analysis.nose_direction(run)
                    final_theta[ip, io, iy] = float(run["theta"].values[-1])
                    outcome_hi[ip, io, iy] = str(run.attrs["outcome"])
                for il, v in enumerate(low):
                    run = simulate(
                        pr.projectile,
                        pr.target,
                        float(v),
                        float(ob),
                        float(y),
                        start=st,
                        prepared=pr,
                        stop_at_reversal=True,
                    )
                    low_rev[ip, io, iy, il] = int(run.attrs["reversed"])
    dims = ("projectile", "obliquity", "yaw")
    data = _search_vars(res, "vcr", "m s-1", "critical reverse velocity V_cr", dims)
    if nose:
        data["nose_direction"] = (
            dims,
            nose_dir,
            {
                "units": "1",
                "long_name": "side the nose points to at the end of the full run "
                "at vcr_hi (+x as at impact, -x turned over); empty if no bracket",
            },
        )
        data["final_theta"] = (
            dims,
            final_theta,
            _attrs("degree", "axis angle from the normal at the end of the full run at vcr_hi"),
        )
        data["outcome_at_vcr"] = (
            dims,
            outcome_hi,
            {"units": "1", "long_name": "how the full run at vcr_hi ended"},
        )
    if low.size:
        data["low_speed_reversed"] = (
            (*dims, "low_velocity"),
            low_rev,
            _attrs("1", "1 if the run at this low speed turned back (ricochet during entry)"),
        )
    coords = {
        **projectile_coords(names),
        "obliquity": ("obliquity", obl, _PARAM_ATTRS["obliquity"]),
        "yaw": ("yaw", yw, _PARAM_ATTRS["yaw"]),
    }
    if low.size:
        coords["low_velocity"] = (
            "low_velocity",
            low,
            _attrs("m s-1", "impact velocity below the search range"),
        )
    return xr.Dataset(
        data,
        coords=coords,
        attrs={
            "title": "Critical reverse velocity V_cr (paper Figs 8 and 12)",
            "target": target,
            "search_range_m_s": np.array([float(lo), float(hi)]),
            "tolerance_m_s": float(tol),
            "scan_points": -1 if scan is None else int(scan),
            "start_m": "surface contact at x = 0" if st is None else str(list(st)),
            "verdict": "simulate(..., stop_at_reversal=True).attrs['reversed'] == 1: the centre "
            "of mass velocity turned towards the surface while in the target",
            "numerics_json": json.dumps(_numerics_dict(num)),
            "Conventions": "CF-1.10",
        },
    )


def _numerics_dict(num: Numerics) -> dict[str, Any]:
    return {f: getattr(num, f) for f in Numerics.__dataclass_fields__}


def fig8(
    projectiles: Sequence[str] = PROJECTILES,
    obliquities: Sequence[float] = tuple(grid(15.0, 75.0, 7.5)),
    **kwargs: Any,
) -> xr.Dataset:
    """Paper Fig. 8: ``vcr`` (m/s) on ``(projectile, obliquity)`` at zero yaw.

    Keyword arguments as :func:`vcr_study` (without ``yaws``); ``yaw`` stays as a scalar
    coordinate.
    """
    if "yaws" in kwargs:
        raise InputError("fig8 is at zero yaw; use vcr_study for other yaws")
    ds = vcr_study(projectiles, obliquities, (0.0,), **kwargs).isel(yaw=0)
    ds.attrs["title"] = "Paper Fig. 8: critical reverse velocity against obliquity"
    return ds


def fig9(
    projectiles: Sequence[str] = PROJECTILES,
    target: str = "soil",
    *,
    obliquity: float = 45.0,
    velocity: float = 1000.0,
    start: Sequence[float] | None = (-1.0, 1.0, 0.0),
    fractions: Sequence[float] = (0.01, 0.02, 0.05, 0.1),
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
) -> xr.Dataset:
    """Paper Fig. 9: total turning angle d(theta)_12 = theta_2 - theta_1 against Lc/L.

    Points 1 and 2 by :func:`pencore.analysis.turning_angle` (``bracket`` method) for
    each fraction of the peak curvature in ``fractions`` (dimension
    ``bracket_fraction``), and by the ``sign_change`` method (``delta_theta_sign_change``),
    so the reader sees how much the definition moves the number. Trajectories on
    ``(projectile, time)``.
    """
    names = list(projectiles)
    fr = _axis(fractions, "fractions")
    num = resolve_numerics(numerics)
    runs = {}
    keys = ("delta_theta", "theta_1", "theta_2", "x_1", "y_1", "x_2", "y_2")
    out = {k: np.full((len(names), fr.size), np.nan) for k in keys}
    reason = np.full((len(names), fr.size), "", dtype=_STR)
    sign = np.full(len(names), np.nan)
    for ip, p in enumerate(names):
        run = simulate(p, target, velocity, obliquity, start=_start(start), numerics=num)
        runs[(ip,)] = run
        for jf, f in enumerate(fr):
            ta = analysis.turning_angle(run, fraction=float(f))
            for k in keys:
                out[k][ip, jf] = getattr(ta, k)
            reason[ip, jf] = ta.reason
        sign[ip] = analysis.turning_angle(run, method="sign_change").delta_theta
    pc = projectile_coords(names)
    ds = stack_trajectories(
        runs, {"projectile": (pc["projectile"][1], pc["projectile"][2])}, n_time=n_time
    )
    d2 = ("projectile", "bracket_fraction")
    long = {
        "delta_theta": ("degree", "total turning angle theta_2 - theta_1 (Eq. 12)"),
        "theta_1": ("degree", "axis angle from the normal at Point 1"),
        "theta_2": ("degree", "axis angle from the normal at Point 2"),
        "x_1": ("m", "centre of mass x at Point 1"),
        "y_1": ("m", "centre of mass y at Point 1"),
        "x_2": ("m", "centre of mass x at Point 2"),
        "y_2": ("m", "centre of mass y at Point 2"),
    }
    for k in keys:
        ds[k] = (d2, out[k], _attrs(*long[k]))
    ds["turning_angle_note"] = (d2, reason, {"units": "1", "long_name": "why delta_theta is NaN"})
    ds["delta_theta_sign_change"] = (
        "projectile",
        sign,
        _attrs("degree", "theta_2 - theta_1 between the first and last sign changes of d2y/dx2"),
    )
    ds = ds.assign_coords(
        lc_over_l=("projectile", pc["lc_over_l"][1], pc["lc_over_l"][2]),
        bracket_fraction=(
            "bracket_fraction",
            fr,
            _attrs("1", "fraction of the peak |curvature| that marks Points 1 and 2"),
        ),
    )
    ds.attrs.pop("projectile", None)
    ds.attrs.pop("lc_over_l", None)
    ds.attrs.update(
        {
            "title": "Paper Fig. 9: total turning angle against L_c/L",
            "obliquity_deg": float(obliquity),
            "velocity_m_s": float(velocity),
            "start_m": "surface contact at x = 0" if start is None else str(list(start)),
            "primary_bracket_fraction": analysis.DEFAULT_BRACKET_FRACTION,
        }
    )
    return ds


def fig13(
    projectile: str = "p4",
    target: str = "soil",
    yaw: float = 0.1,
    velocities: Sequence[float] = (280.0, 1000.0, 2200.0),
    *,
    conventions: Sequence[str] = YAW_CONVENTIONS,
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
) -> xr.Dataset:
    """Paper Figs 13-14: normal impact with a small yaw, for each yaw convention.

    Dims ``(convention, velocity, time)``; ``final_deviation`` is the paper's phi. The
    tip starts touching the surface.
    """
    vals = _axis(velocities, "velocities")
    conv = list(conventions)
    for c in conv:
        critical.normal_impact_angles(yaw, c)  # validates the name
    num = resolve_numerics(numerics)
    pr = prepare(projectile, target, num)
    runs = {}
    for ic, c in enumerate(conv):
        obl, yw = critical.normal_impact_angles(yaw, c)
        for iv, v in enumerate(vals):
            runs[(ic, iv)] = simulate(pr.projectile, pr.target, float(v), obl, yw, prepared=pr)
    ds = stack_trajectories(
        runs,
        {
            "convention": (
                np.array(conv, dtype=_STR),
                {
                    "units": "1",
                    "long_name": "yaw convention: axis_tilted (velocity normal, axis "
                    "tilted by the yaw) or velocity_tilted (axis normal, velocity tilted)",
                },
            ),
            "velocity": (vals, _PARAM_ATTRS["velocity"]),
        },
        n_time=n_time,
        speed_fraction=speed_fraction,
    )
    ds.attrs.update(
        {
            "title": "Paper Figs 13-14: normal impact with small yaw",
            "yaw_deg": float(yaw),
            "start_m": "surface contact at x = 0",
        }
    )
    return ds


def vci_study(
    projectiles: Sequence[str],
    yaws: Sequence[float],
    thresholds: Sequence[float],
    *,
    target: str = "soil",
    convention: str = "axis_tilted",
    lo: float = 100.0,
    hi: float = 4000.0,
    tol: float = VELOCITY_TOL,
    scan: int | None = 9,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
    primary_threshold: float | None = None,
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Critical impact velocity for instability Vci on ``(projectile, yaw, threshold)``.

    Each cell is :func:`pencore.critical.vci`: the lowest normal-impact speed at which a
    run with the given yaw turns back or ends with a deviation above ``threshold``
    (deg). The tip starts touching the surface. ``primary_threshold`` (deg; default the
    middle of ``thresholds``) is the one the figure and the comparison lead with; the
    others show how Vci moves with the choice.
    """
    names = list(projectiles)
    yw = _axis(yaws, "yaws")
    th = np.sort(_axis(thresholds, "thresholds"))
    if primary_threshold is None:
        primary_threshold = float(th[(th.size - 1) // 2])
    if not np.any(np.isclose(th, primary_threshold)):
        raise InputError(
            f"primary threshold {primary_threshold} is not one of the thresholds {list(th)}"
        )
    critical.normal_impact_angles(0.0, convention)
    num = resolve_numerics(numerics)
    res = np.empty((len(names), yw.size, th.size), dtype=object)
    for ip, p in enumerate(names):
        for iy, y in enumerate(yw):
            for it, t in enumerate(th):
                res[ip, iy, it] = critical.vci(
                    p,
                    target,
                    float(y),
                    lo,
                    hi,
                    float(t),
                    tol,
                    fraction=speed_fraction,
                    convention=convention,
                    scan=scan,
                    numerics=num,
                )
    dims = ("projectile", "yaw", "threshold")
    data = _search_vars(res, "vci", "m s-1", "critical impact velocity for instability V_ci", dims)
    return xr.Dataset(
        data,
        coords={
            **projectile_coords(names),
            "yaw": ("yaw", yw, _PARAM_ATTRS["yaw"]),
            "threshold": (
                "threshold",
                th,
                _attrs("degree", "final deviation above which a run counts as unstable"),
            ),
        },
        attrs={
            "title": "Paper Fig. 15: critical impact velocity for instability V_ci",
            "target": target,
            "yaw_convention": convention,
            "primary_threshold_deg": float(primary_threshold),
            "search_range_m_s": np.array([float(lo), float(hi)]),
            "tolerance_m_s": float(tol),
            "scan_points": -1 if scan is None else int(scan),
            "speed_fraction": float(speed_fraction),
            "verdict": "reversed, or final deviation (at the last state with speed >= "
            f"{speed_fraction:g} x impact speed) > threshold",
            "numerics_json": json.dumps(_numerics_dict(num)),
            "Conventions": "CF-1.10",
        },
    )


def start_height_study(
    projectile: str = "p2",
    target: str = "soil",
    velocity: float = 1000.0,
    omegas: Sequence[float] = (5.0, 20.0, 25.0),
    heights: Sequence[float] = (0.0, 0.1, 0.25, 0.5, 1.0),
    *,
    numerics: Numerics | Mapping[str, Any] | None = None,
    speed_fraction: float = analysis.DEFAULT_SPEED_FRACTION,
) -> xr.Dataset:
    """How the Fig. 16-17 results move with the height the nose tip starts at.

    The paper does not give the start height of its spinning normal impacts. A spinning
    body turns in free flight before it enters (``theta_at_contact``), so alpha depends on
    it. Dims ``(start_height, omega)``: ``alpha`` (final deviation), ``reversed``,
    ``theta_at_contact``, ``outcome``.
    """
    hs = _axis(heights, "heights")
    om = _axis(omegas, "omegas")
    num = resolve_numerics(numerics)
    pr = prepare(projectile, target, num)
    shape = (hs.size, om.size)
    alpha = np.full(shape, np.nan)
    alpha_s = np.full(shape, np.nan)
    th_c = np.full(shape, np.nan)
    rev = np.zeros(shape, dtype=np.int8)
    out = np.empty(shape, dtype=_STR)
    for ih, h in enumerate(hs):
        for iw, w in enumerate(om):
            run = simulate(
                pr.projectile,
                pr.target,
                velocity,
                0.0,
                0.0,
                float(w),
                start=start_from_height(h),
                prepared=pr,
            )
            alpha[ih, iw] = analysis.final_deviation(run, speed_fraction)
            alpha_s[ih, iw] = analysis.final_deviation(run, speed_fraction, signed=True)
            tc = float(run.attrs["t_first_contact_s"])
            if tc >= 0:
                th_c[ih, iw] = float(np.interp(tc, run["time"].values, run["theta"].values))
            rev[ih, iw] = int(run.attrs["reversed"])
            out[ih, iw] = str(run.attrs["outcome"])
    dims = ("start_height", "omega")
    return xr.Dataset(
        {
            "alpha": (
                dims,
                alpha,
                _attrs(
                    "degree",
                    "trajectory deviation from the normal alpha (final deviation)",
                    speed_fraction=float(speed_fraction),
                ),
            ),
            "alpha_signed": (
                dims,
                alpha_s,
                _attrs("degree", "signed in-plane final deviation (positive towards +x)"),
            ),
            "theta_at_contact": (
                dims,
                th_c,
                _attrs(
                    "degree", "axis angle from the normal at first contact (free-flight rotation)"
                ),
            ),
            "reversed": (dims, rev, _attrs("1", "1 if the run turned back towards the surface")),
            "outcome": (dims, out, {"units": "1", "long_name": "how the run ended"}),
        },
        coords={
            "start_height": (
                "start_height",
                hs,
                _attrs("m", "height of the nose tip above the surface at t = 0 (0: touching)"),
            ),
            "omega": ("omega", om, _PARAM_ATTRS["omega"]),
        },
        attrs={
            "title": "Figs 16-17: sensitivity of alpha to the start height (not in the paper)",
            "projectile": projectile,
            "target": target,
            "velocity_m_s": float(velocity),
            "numerics_json": json.dumps(_numerics_dict(num)),
            "Conventions": "CF-1.10",
        },
    )


def omega_c_study(
    projectiles: Sequence[str],
    velocities: Sequence[float],
    *,
    target: str = "soil",
    lo: float = 0.0,
    hi: float = 500.0,
    tol: float = OMEGA_TOL,
    scan: int | None = 9,
    start_height: float = 0.0,
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Critical angular velocity omega_c on ``(projectile, velocity)`` (paper Fig. 18).

    Each cell is :func:`pencore.critical.omega_c` on ``[lo, hi]`` rad/s, normal impact,
    zero yaw, the tip starting ``start_height`` (m) above the surface. ``above_range``
    means no reversal up to ``hi``.
    """
    names = list(projectiles)
    vel = _axis(velocities, "velocities")
    num = resolve_numerics(numerics)
    res = np.empty((len(names), vel.size), dtype=object)
    for ip, p in enumerate(names):
        for iv, v in enumerate(vel):
            res[ip, iv] = critical.omega_c(
                p,
                target,
                float(v),
                lo,
                hi,
                tol,
                scan=scan,
                start=start_from_height(start_height),
                numerics=num,
            )
    dims = ("projectile", "velocity")
    data = _search_vars(res, "omega_c", "rad s-1", "critical angular velocity omega_c", dims)
    return xr.Dataset(
        data,
        coords={
            **projectile_coords(names),
            "velocity": ("velocity", vel, _PARAM_ATTRS["velocity"]),
        },
        attrs={
            "title": "Paper Fig. 18: critical angular velocity against impact velocity",
            "target": target,
            "search_range_rad_s": np.array([float(lo), float(hi)]),
            "tolerance_rad_s": float(tol),
            "scan_points": -1 if scan is None else int(scan),
            "start_height_m": float(start_height),
            "numerics_json": json.dumps(_numerics_dict(num)),
            "Conventions": "CF-1.10",
        },
    )


def combine(parts: Sequence[xr.Dataset], dim: str = "projectile") -> xr.Dataset:
    """Concatenate per-job parts of a study along ``dim`` (attributes of the first)."""
    parts = list(parts)
    if not parts:
        raise InputError("nothing to combine")
    return xr.concat(
        parts,
        dim=dim,
        data_vars="minimal",
        coords="minimal",
        compat="override",
        combine_attrs="override",
    )


# ----------------------------------------------------------------------------- trends


@dataclass(frozen=True)
class TrendResult:
    """Verdict on a claimed trend along one parameter.

    Each consecutive pair (a at the smaller parameter, b at the larger) compares the
    intervals ``[lo, hi]`` that hold the two values: b *falls* when ``b.hi < a.lo``,
    *rises* when ``b.lo > a.hi``, is *flat* when the intervals overlap (equal within the
    search tolerance), *undetermined* when either is unknown.

    ``verdict`` for the claim "falls" (mirror for "rises"): ``holds`` (no pair against
    the claim and at least one with it), ``partly holds`` (pairs both ways), ``does not
    hold`` (pairs against it, none with it, or all flat), ``undetermined`` (no pair could
    be compared).
    """

    claim: str
    verdict: str
    n_with: int
    n_flat: int
    n_against: int
    n_undetermined: int
    against: tuple[str, ...] = ()

    def note(self) -> str:
        s = (
            f"{self.n_with} step(s) {self.claim}, {self.n_flat} flat within the "
            f"tolerance, {self.n_against} against, {self.n_undetermined} undetermined"
        )
        if self.against:
            s += "; against: " + "; ".join(self.against[:6])
            if len(self.against) > 6:
                s += f"; ... ({len(self.against) - 6} more)"
        return s


def _interval(lo: float, hi: float) -> tuple[float, float]:
    lo = -math.inf if not np.isfinite(lo) else float(lo)
    hi = math.inf if not np.isfinite(hi) else float(hi)
    return lo, hi


def trend(
    lines: Iterable[tuple[str, Sequence[float], Sequence[float], Sequence[float]]],
    claim: str = "falls",
) -> TrendResult:
    """Check a claimed monotone trend on several lines of bracketed values.

    Parameters
    ----------
    lines : iterable of (label, parameter, lo, hi)
        One line per fixed setting of the other parameters: the parameter values
        (sorted here), and the bracket ``[lo, hi]`` of the quantity at each. For an exact
        value give ``lo = hi = value``. NaN in ``lo`` means "unbounded below" and in
        ``hi`` "unbounded above" (e.g. a search that ended ``above_range`` gives
        ``[range_hi, NaN]``); both NaN means unknown.
    claim : {"falls", "rises"}
    """
    if claim not in ("falls", "rises"):
        raise ValueError(f"claim must be 'falls' or 'rises', got {claim!r}")
    n_w = n_f = n_a = n_u = 0
    against = []
    for label, par, lo, hi in lines:
        par = np.asarray(par, float)
        order = np.argsort(par)
        par = par[order]
        lo = np.asarray(lo, float)[order]
        hi = np.asarray(hi, float)[order]
        for i in range(par.size - 1):
            if (np.isnan(lo[i]) and np.isnan(hi[i])) or (
                np.isnan(lo[i + 1]) and np.isnan(hi[i + 1])
            ):
                n_u += 1
                continue
            a_lo, a_hi = _interval(lo[i], hi[i])
            b_lo, b_hi = _interval(lo[i + 1], hi[i + 1])
            falls, rises = b_hi < a_lo, b_lo > a_hi
            if falls or rises:
                if (falls and claim == "falls") or (rises and claim == "rises"):
                    n_w += 1
                else:
                    n_a += 1
                    against.append(
                        f"{label}: {par[i]:g}->{par[i + 1]:g} "
                        f"[{a_lo:.4g}, {a_hi:.4g}] -> [{b_lo:.4g}, {b_hi:.4g}]"
                    )
            elif math.isinf(a_lo) and math.isinf(b_lo) or math.isinf(a_hi) and math.isinf(b_hi):
                n_u += 1  # both unbounded the same way: cannot compare
            else:
                n_f += 1
    if n_w + n_f + n_a == 0:
        verdict = "undetermined"
    elif n_a == 0 and n_w > 0:
        verdict = "holds"
    elif n_a > 0 and n_w > 0:
        verdict = "partly holds"
    else:
        verdict = "does not hold"
    return TrendResult(claim, verdict, n_w, n_f, n_a, n_u, tuple(against))


def _search_lines(
    ds: xr.Dataset, name: str, along: str, *, fixed: Mapping[str, Any] | None = None
) -> list[tuple[str, np.ndarray, np.ndarray, np.ndarray]]:
    """Lines of a search dataset along ``along`` for every other index."""
    sub = ds.sel(fixed) if fixed else ds
    da_lo = sub[f"{name}_lo"]
    others = [d for d in da_lo.dims if d != along]
    par = _parameter_values(sub, along)
    lines = []
    for idx in product(*(range(sub.sizes[d]) for d in others)):
        sel = dict(zip(others, idx, strict=True))
        lo = sub[f"{name}_lo"].isel(sel).transpose(along).values
        hi = sub[f"{name}_hi"].isel(sel).transpose(along).values
        label = ", ".join(f"{d}={_fmt_coord(sub[d].values[i])}" for d, i in sel.items())
        lines.append((label or name, par, lo, hi))
    return lines


def _parameter_values(ds: xr.Dataset, along: str) -> np.ndarray:
    if along == "projectile":
        return np.asarray(ds["lc_over_l"].values, float)
    return np.asarray(ds[along].values, float)


def _fmt_coord(v: Any) -> str:
    return f"{v:g}" if isinstance(v, float | np.floating) else str(v)


# ----------------------------------------------------------------------------- comparison


_COLUMNS = [
    "quantity",
    "paper_value",
    "pencore_value",
    "difference",
    "units",
    "note",
    "kind",
    "source",
]


def _row(
    quantity: str, paper: Any, pencore: Any, units: str, note: str, kind: str, source: str
) -> dict[str, Any]:
    if kind == "value" and _is_num(paper) and _is_num(pencore):
        diff: Any = float(pencore) - float(paper)
    elif kind == "verdict":
        diff = "agrees" if str(paper) == str(pencore) else "differs"
    else:
        diff = ""
    return dict(
        quantity=quantity,
        paper_value=_round(paper),
        pencore_value=_round(pencore),
        difference=_round(diff),
        units=units,
        note=note,
        kind=kind,
        source=source,
    )


def _round(x: Any, digits: int = 6) -> Any:
    """Floats to ``digits`` significant digits (the table is for reading)."""
    if isinstance(x, float | np.floating) and math.isfinite(float(x)):
        return float(f"{float(x):.{digits}g}")
    return x


def _is_num(x: Any) -> bool:
    return isinstance(x, int | float | np.integer | np.floating) and math.isfinite(float(x))


def _search_value(ds: xr.Dataset, name: str, sel: Mapping[str, Any]) -> tuple[Any, str]:
    """(value or bound string, note) of one search cell."""
    cell = ds.sel(sel)
    status = str(cell["status"].values)
    lo, hi = float(cell[f"{name}_lo"]), float(cell[f"{name}_hi"])
    if status in ("ok", "non_monotone"):
        note = f"bracket [{lo:.6g}, {hi:.6g}]"
        if status == "non_monotone":
            note += "; verdict NOT monotone (lowest threshold found)"
        return float(cell[name]), note
    if status == "above_range":
        return f"> {lo:g}", "above_range: no event up to the top of the search range"
    if status == "below_range":
        return f"<= {hi:g}", "below_range: event already at the bottom of the search range"
    return float(cell[name]), f"status {status}: bracket [{lo:.6g}, {hi:.6g}]"


def _pencore_rel(pencore: Any, paper: float) -> str:
    if _is_num(pencore) and paper:
        return f"{100.0 * (float(pencore) - paper) / paper:+.1f} %"
    return ""


def paper_comparison(
    *,
    fig7: xr.Dataset | None = None,
    fig8: xr.Dataset | None = None,
    fig9: xr.Dataset | None = None,
    fig11: xr.Dataset | None = None,
    fig12: xr.Dataset | None = None,
    fig13: xr.Dataset | None = None,
    fig15: xr.Dataset | None = None,
    fig16: xr.Dataset | None = None,
    start_height: xr.Dataset | None = None,
    fig18: xr.Dataset | None = None,
    table2: pd.DataFrame | None = None,
    table3: bool = True,
    yaw_convention: str = "axis_tilted",
    vci_threshold: float | None = None,
) -> pd.DataFrame:
    """Every number and trend the paper states in Sections 3-4, beside pencore's.

    Each argument is the dataset of one study (``None`` skips its rows); ``table2`` is the
    validation table (``results/validation/table2.csv``). Verdicts on the paper's trends
    are computed here from the datasets with :func:`trend`, never written in.

    Returns
    -------
    pandas.DataFrame
        Columns ``quantity, paper_value, pencore_value, difference, units, note, kind,
        source``. ``kind`` is ``value`` (``difference`` = pencore - paper), ``verdict``
        (a yes/no statement; ``difference`` = agrees / differs) or ``trend``
        (``paper_value`` is the claim, ``pencore_value`` holds / partly holds / does not
        hold / undetermined, with the count of steps in ``note``).
    """
    rows: list[dict[str, Any]] = []
    add = rows.append

    # ---- Section 3: Table 2 and Table 3
    if table2 is not None:
        for _, r in table2.iterrows():
            paper = float(r["paper_predicted_depth_m"])
            pen = float(r["pencore_depth_m"])
            add(
                _row(
                    f"Table 2 test {int(r['test'])}: penetration depth "
                    f"(V={r['velocity_m_s']:g} m/s, obliquity {r['obliquity_deg']:g} deg, "
                    f"yaw {r['yaw_deg']:g} deg)",
                    paper,
                    pen,
                    "m",
                    f"{_pencore_rel(pen, paper)}; measured {r['measured_depth_m']:g} m; "
                    f"pencore {r['projectile']}, {r['depth_measure']} (selected as closest "
                    "to the paper's column)",
                    "value",
                    "results/validation/table2.csv",
                )
            )
    if table3:
        for p, (m, lcl) in PAPER["table3"].items():
            proj = get_projectile(p)
            mp = proj.mass_properties()
            add(
                _row(
                    f"Table 3 {p}: mass",
                    m,
                    float(mp.mass),
                    "kg",
                    "pencore geometry derived by pencore.library.table3_fit",
                    "value",
                    "pencore.library",
                )
            )
            add(
                _row(
                    f"Table 3 {p}: Lc/L",
                    lcl,
                    float(mp.lc / proj.length),
                    "1",
                    "pencore geometry derived by pencore.library.table3_fit",
                    "value",
                    "pencore.library",
                )
            )

    # ---- Fig. 7
    if fig7 is not None:
        vel = fig7["velocity"].values
        for v, rev in PAPER["fig7_reverses"].items():
            if np.any(np.isclose(vel, v)):
                pen_rev = bool(int(fig7["reversed"].sel(velocity=v, method="nearest")))
                add(
                    _row(
                        f"Fig. 7 (#2, 45 deg, tip from (-1, 1) m): turns back at Vi = {v:g} m/s",
                        "yes" if rev else "no",
                        "yes" if pen_rev else "no",
                        "",
                        "",
                        "verdict",
                        "results/fig7/trajectories.nc: reversed",
                    )
                )
        for v in (1641.0, 1650.0, 1700.0):
            if np.any(np.isclose(vel, v)):
                x2 = float(fig7["x_linear"].sel(velocity=v, method="nearest"))
                add(
                    _row(
                        f"Fig. 7: x where the curved path becomes straight, Vi = {v:g} m/s",
                        PAPER["fig7_x_linear_m"],
                        x2 if math.isfinite(x2) else "n/a",
                        "m",
                        "paper: approximately 7 m for 1641-1700 m/s; pencore: centre of "
                        "mass x at Point 2 (|curvature| below 5 % of its peak)",
                        "value",
                        "results/fig7/trajectories.nc: x_linear",
                    )
                )

    # ---- Fig. 8
    if fig8 is not None:
        lo_p, hi_p = PAPER["vcr_p2_45_bracket"]
        if "p2" in fig8["projectile"].values and np.any(np.isclose(fig8["obliquity"], 45.0)):
            val, note = _search_value(fig8, "vcr", {"projectile": "p2", "obliquity": 45.0})
            mid = 0.5 * (lo_p + hi_p)
            add(
                _row(
                    "Vcr of #2 at 45 deg obliquity (Fig. 7)",
                    mid,
                    val,
                    "m s-1",
                    f"paper: {lo_p:g} does not reverse, {hi_p:g} does (derived: midpoint "
                    f"of ({lo_p:g}, {hi_p:g}]); pencore {note}; {_pencore_rel(val, mid)}",
                    "value",
                    "results/fig8/vcr.nc: vcr",
                )
            )
        tr = trend(_search_lines(fig8, "vcr", "obliquity"), "falls")
        add(
            _row(
                "Fig. 8: Vcr against obliquity",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig8/vcr.nc",
            )
        )
        tr = trend(_search_lines(fig8, "vcr", "projectile"), "falls")
        add(
            _row(
                "Fig. 8: Vcr against Lc/L",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig8/vcr.nc",
            )
        )

    # ---- Fig. 9
    if fig9 is not None:
        f0 = float(fig9.attrs.get("primary_bracket_fraction", analysis.DEFAULT_BRACKET_FRACTION))
        fsel = fig9["bracket_fraction"].values[
            int(np.argmin(np.abs(fig9["bracket_fraction"].values - f0)))
        ]
        dth = fig9["delta_theta"].sel(bracket_fraction=fsel).values
        tr = trend([("delta_theta", fig9["lc_over_l"].values, dth, dth)], "rises")
        spread = fig9["delta_theta"].max("bracket_fraction") - fig9["delta_theta"].min(
            "bracket_fraction"
        )
        add(
            _row(
                "Fig. 9: total turning angle d(theta)_12 against Lc/L (45 deg, 1000 m/s)",
                "rises",
                tr.verdict,
                "",
                tr.note()
                + "; values "
                + ", ".join(
                    f"{p}: {v:.2f} deg" for p, v in zip(fig9["projectile"].values, dth, strict=True)
                )
                + f" (bracket fraction {fsel:g}; other fractions move them by up to "
                f"{float(spread.max()):.2f} deg)",
                "trend",
                "results/fig9/turning_angle.nc",
            )
        )

    # ---- Figs 11-12
    if fig11 is not None:
        for y in fig11["yaw"].values:
            if float(y) == 0.0:
                continue
            expect = "+x" if y < 0 else "-x"
            sub = fig11.sel(yaw=y)
            add(
                _row(
                    f"Fig. 11 (#4, {fig11.attrs.get('velocity_fixed', 1000):g} m/s, "
                    f"{fig11.attrs.get('obliquity_fixed', 30):g} deg): nose direction at "
                    f"the end, yaw {y:g} deg",
                    expect,
                    str(sub["nose_direction"].item()),
                    "",
                    "paper: implied by the text (negative yaw keeps the nose +x, positive "
                    "yaw can turn it to -x); pencore: sign of the axis x component at the "
                    f"end of the run ({sub['outcome'].item()}, final theta "
                    f"{float(sub['final_theta']):.0f} deg)",
                    "verdict",
                    "results/fig11/trajectories.nc: nose_direction",
                )
            )
    if fig12 is not None:
        tr = trend(_search_lines(fig12, "vcr", "yaw"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against yaw",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        tr = trend(_search_lines(fig12, "vcr", "obliquity"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against obliquity (30 -> 60 deg)",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        tr = trend(_search_lines(fig12, "vcr", "projectile"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against Lc/L (#2 -> #4)",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        if "nose_direction" in fig12:
            for row in _nose_rows(fig12):
                add(row)

    # ---- Figs 13-14
    if fig13 is not None:
        convs = [str(c) for c in fig13["convention"].values]
        for v, phi in PAPER["fig13_phi_deg"].items():
            if not np.any(np.isclose(fig13["velocity"], v)):
                continue
            for c in convs:
                pen = float(fig13["final_deviation"].sel(convention=c, velocity=v))
                tag = " (configured)" if c == yaw_convention else ""
                add(
                    _row(
                        f"Fig. 13: deviation phi of #4, yaw 0.1 deg, Vi = {v:g} m/s, {c}{tag}",
                        phi,
                        pen,
                        "degree",
                        f"{_pencore_rel(pen, phi)}; phi = final deviation (last state with "
                        "speed >= 0.1 Vi)",
                        "value",
                        "results/fig13/trajectories.nc",
                    )
                )
        v_l = PAPER["fig13_large_at"]
        if np.any(np.isclose(fig13["velocity"], v_l)):
            thr = 5.0 if vci_threshold is None else float(vci_threshold)
            for c in convs:
                pen = float(fig13["final_deviation"].sel(convention=c, velocity=v_l))
                rev = int(fig13["reversed"].sel(convention=c, velocity=v_l))
                add(
                    _row(
                        f"Fig. 13: large deviation at Vi = {v_l:g} m/s, {c}",
                        "yes",
                        "yes" if (pen > thr or rev) else "no",
                        "",
                        f"pencore phi = {pen:.3g} deg, reversed = {rev}; 'large' = above "
                        f"the Vci threshold {thr:g} deg",
                        "verdict",
                        "results/fig13/trajectories.nc",
                    )
                )

    # ---- Fig. 15
    if fig15 is not None:
        th = fig15["threshold"].values
        t0 = float(th[np.argmin(np.abs(th - (5.0 if vci_threshold is None else vci_threshold)))])
        for t in th:
            tr = trend(_search_lines(fig15, "vci", "projectile", fixed={"threshold": t}), "falls")
            add(
                _row(
                    f"Fig. 15: Vci against Lc/L (threshold {t:g} deg"
                    f"{', primary' if t == t0 else ''})",
                    "falls",
                    tr.verdict,
                    "",
                    tr.note(),
                    "trend",
                    "results/fig15/vci.nc",
                )
            )
            tr = trend(_search_lines(fig15, "vci", "yaw", fixed={"threshold": t}), "falls")
            add(
                _row(
                    f"Fig. 15: Vci against yaw (threshold {t:g} deg"
                    f"{', primary' if t == t0 else ''})",
                    "falls",
                    tr.verdict,
                    "",
                    tr.note(),
                    "trend",
                    "results/fig15/vci.nc",
                )
            )

    # ---- Figs 16-17
    if fig16 is not None:
        h = float(fig16.attrs.get("start_height_m", 0.0))
        for w, a in PAPER["fig16_alpha_deg"].items():
            if np.any(np.isclose(fig16["omega"], w)):
                pen = float(fig16["final_deviation"].sel(omega=w))
                add(
                    _row(
                        f"Fig. 16: deviation alpha of #2, 1000 m/s, omega = {w:g} rad/s",
                        a,
                        pen,
                        "degree",
                        f"{_pencore_rel(pen, a)}; tip starting {h:g} m above the surface",
                        "value",
                        "results/fig16/trajectories.nc",
                    )
                )
        w = PAPER["fig16_reverses_at"]
        if np.any(np.isclose(fig16["omega"], w)):
            rev = int(fig16["reversed"].sel(omega=w))
            add(
                _row(
                    f"Fig. 16: turns back at omega = {w:g} rad/s (#2, 1000 m/s)",
                    "yes",
                    "yes" if rev else "no",
                    "",
                    f"tip starting {h:g} m above the surface",
                    "verdict",
                    "results/fig16/trajectories.nc",
                )
            )
    if start_height is not None:
        for w in start_height["omega"].values:
            a_paper = PAPER["fig16_alpha_deg"].get(float(w))
            for hh in start_height["start_height"].values:
                pen = float(start_height["alpha"].sel(omega=w, start_height=hh))
                rev = int(start_height["reversed"].sel(omega=w, start_height=hh))
                if a_paper is not None:
                    add(
                        _row(
                            f"Start-height sensitivity: alpha at omega = {w:g} rad/s, tip "
                            f"{hh:g} m above",
                            a_paper,
                            pen,
                            "degree",
                            f"{_pencore_rel(pen, a_paper)}; reversed = {rev}",
                            "value",
                            "results/fig16/start_height.nc",
                        )
                    )
                elif float(w) == PAPER["fig16_reverses_at"]:
                    add(
                        _row(
                            f"Start-height sensitivity: turns back at omega = {w:g} rad/s, "
                            f"tip {hh:g} m above",
                            "yes",
                            "yes" if rev else "no",
                            "",
                            f"alpha = {pen:.3g} deg",
                            "verdict",
                            "results/fig16/start_height.nc",
                        )
                    )

    # ---- Fig. 18
    if fig18 is not None:
        if "p2" in fig18["projectile"].values and np.any(np.isclose(fig18["velocity"], 1000.0)):
            lo_p, hi_p = PAPER["omega_c_p2_1000_bracket"]
            mid = 0.5 * (lo_p + hi_p)
            val, note = _search_value(fig18, "omega_c", {"projectile": "p2", "velocity": 1000.0})
            add(
                _row(
                    "omega_c of #2 at 1000 m/s (Figs 16-17)",
                    mid,
                    val,
                    "rad s-1",
                    f"paper: 20 does not turn back, 25 does (derived: midpoint of (20, 25]); "
                    f"pencore {note}",
                    "value",
                    "results/fig18/omega_c.nc",
                )
            )
        tr = trend(_search_lines(fig18, "omega_c", "velocity"), "falls")
        add(
            _row(
                "Fig. 18: omega_c against impact velocity",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig18/omega_c.nc",
            )
        )
        tr = trend(_search_lines(fig18, "omega_c", "projectile"), "falls")
        add(
            _row(
                "Fig. 18: omega_c against Lc/L",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig18/omega_c.nc",
            )
        )

    return pd.DataFrame(rows, columns=_COLUMNS)


def _nose_rows(ds: xr.Dataset) -> list[dict[str, Any]]:
    """Verdicts on the paper's Fig. 12 statements about the final nose direction."""
    src = "results/fig12/vcr_yaw.nc: nose_direction"
    nd = ds["nose_direction"]
    known = nd != ""
    minus = (nd == "-x") & known
    rows = []
    neg = ds["yaw"] < 0
    n_neg = int((known & neg).sum())
    n_neg_plus = int(((nd == "+x") & neg).sum())
    rows.append(
        _row(
            "Fig. 12: nose points +x at Vcr for every negative yaw",
            "yes",
            "yes" if n_neg and n_neg_plus == n_neg else "no",
            "",
            f"{n_neg_plus} of {n_neg} negative-yaw cases end +x",
            "verdict",
            src,
        )
    )

    def count(**sel: Any) -> int:
        return int(minus.sel(sel).sum())

    obl = [float(o) for o in ds["obliquity"].values]
    if len(obl) >= 2:
        lo_o, hi_o = min(obl), max(obl)
        a, b = count(obliquity=lo_o), count(obliquity=hi_o)
        rows.append(
            _row(
                f"Fig. 12: flip to -x more likely at {lo_o:g} than {hi_o:g} deg",
                "yes",
                "yes" if a > b else "no",
                "",
                f"-x cases: {a} at {lo_o:g} deg, {b} at {hi_o:g} deg",
                "verdict",
                src,
            )
        )
    projs = list(ds["projectile"].values)
    if len(projs) >= 2:
        lcl = ds["lc_over_l"].values
        p_lo, p_hi = projs[int(np.argmin(lcl))], projs[int(np.argmax(lcl))]
        a, b = count(projectile=p_hi), count(projectile=p_lo)
        rows.append(
            _row(
                f"Fig. 12: flip to -x more likely for larger Lc/L ({p_hi} than {p_lo})",
                "yes",
                "yes" if a > b else "no",
                "",
                f"-x cases: {a} for {p_hi}, {b} for {p_lo}",
                "verdict",
                src,
            )
        )
    n_minus = int(minus.sum())
    n_big = int((minus & (ds["yaw"] > 1.0)).sum())
    rows.append(
        _row(
            "Fig. 12: the flip to -x happens only for yaw > 1 deg",
            "yes",
            "yes" if n_minus and n_big == n_minus else "no",
            "",
            f"{n_minus} -x case(s), {n_big} of them at yaw > 1 deg",
            "verdict",
            src,
        )
    )
    return rows


# ----------------------------------------------------------------------------- configuration

#: Studies that :func:`from_config` runs; those in :data:`SPLIT_STUDIES` run per job
#: part (a projectile, or a projectile and an obliquity) and are joined by :func:`gather`.
STUDIES = (
    "fig7",
    "fig8",
    "fig9",
    "fig11",
    "fig12",
    "fig13",
    "fig15",
    "fig16",
    "start_height",
    "fig18",
)
SPLIT_STUDIES = {
    "fig8": ("projectile",),
    "fig12": ("projectile", "obliquity"),
    "fig15": ("projectile",),
    "fig18": ("projectile",),
}


def _range(d: Mapping[str, Any]) -> tuple[float, float]:
    lo, hi = float(d["min"]), float(d["max"])
    if not lo < hi:
        raise InputError(f"range needs min < max, got {dict(d)}")
    return lo, hi


def _values(v: Any) -> list[float]:
    """A list of numbers, or a ``{min, max, step}`` grid."""
    if isinstance(v, Mapping):
        return [float(x) for x in grid(v["min"], v["max"], v["step"])]
    return [float(x) for x in v]


def parts_of(study: str, cfg: Mapping[str, Any]) -> list[dict[str, Any]]:
    """Job parts of a split study: ``[{"projectile": "p1"}, ...]`` or with
    ``"obliquity"`` too (deg), from the study's configuration ``cfg``."""
    if study not in SPLIT_STUDIES:
        raise InputError(f"{study!r} is not split into parts")
    projs = list(cfg["projectiles"])
    if study == "fig12":
        return [
            {"projectile": p, "obliquity": o} for p in projs for o in _values(cfg["obliquity_deg"])
        ]
    return [{"projectile": p} for p in projs]


def from_config(
    study: str,
    cfg: Mapping[str, Any],
    shared: Mapping[str, Any],
    numerics: Numerics | Mapping[str, Any] | None = None,
    *,
    projectile: str | None = None,
    obliquity: float | None = None,
) -> xr.Dataset:
    """Run one study (or one part of a split study) from its configuration entries.

    Parameters
    ----------
    study : str
        One of :data:`STUDIES`.
    cfg : mapping
        The study's entry of the ``section4`` configuration block (keys as in
        ``config/config.yaml``; units in the key names).
    shared : mapping
        The block's shared keys (``target``, ``velocity_tol_m_s``, ``omega_tol_rad_s``,
        ``scan_points``, ``trajectory_samples``, ``speed_fraction``, ``yaw_convention``,
        ``start_height_m``); only those the study uses are read.
    numerics : Numerics or mapping, optional
        Overrides of pencore's numerical defaults.
    projectile, obliquity
        The part of a split study (:data:`SPLIT_STUDIES`) to run.
    """
    if study not in STUDIES:
        raise InputError(f"unknown Section 4 study {study!r}; known: {', '.join(STUDIES)}")
    if study in SPLIT_STUDIES and projectile is None:
        raise InputError(f"study {study!r} runs per projectile: give projectile=")
    target = shared.get("target", "soil")
    n_time = int(shared.get("trajectory_samples", 500))
    frac = float(shared.get("speed_fraction", analysis.DEFAULT_SPEED_FRACTION))
    vtol = float(shared.get("velocity_tol_m_s", VELOCITY_TOL))
    wtol = float(shared.get("omega_tol_rad_s", OMEGA_TOL))
    scan = shared.get("scan_points", 9)
    scan = None if scan is None else int(scan)
    height = float(shared.get("start_height_m", 0.0))
    num = resolve_numerics(numerics)
    start = cfg.get("start_m")

    if study == "fig7":
        return fig7(
            cfg["projectile"],
            target,
            float(cfg["obliquity_deg"]),
            _values(cfg["velocities_m_s"]),
            start=start,
            numerics=num,
            n_time=n_time,
        )
    if study == "fig8":
        lo, hi = _range(cfg["velocity_range_m_s"])
        return fig8(
            [projectile],
            _values(cfg["obliquity_deg"]),
            target=target,
            lo=lo,
            hi=hi,
            tol=vtol,
            scan=scan,
            start=start,
            numerics=num,
            low_speeds=_values(cfg.get("low_velocities_m_s", [])),
        )
    if study == "fig9":
        return fig9(
            list(cfg["projectiles"]),
            target,
            obliquity=float(cfg["obliquity_deg"]),
            velocity=float(cfg["velocity_m_s"]),
            start=start,
            fractions=_values(cfg["bracket_fractions"]),
            numerics=num,
            n_time=n_time,
        )
    if study == "fig11":
        ds = trajectory_set(
            cfg["projectile"],
            target,
            "yaw",
            _values(cfg["yaw_deg"]),
            velocity=float(cfg["velocity_m_s"]),
            obliquity=float(cfg["obliquity_deg"]),
            start=start,
            numerics=num,
            n_time=n_time,
            speed_fraction=frac,
        )
        ds.attrs["title"] = "Paper Fig. 11: trajectories of #4 at 30 deg with yaw -1 and +1"
        return ds
    if study == "fig12":
        if obliquity is None:
            raise InputError("study 'fig12' runs per (projectile, obliquity): give obliquity=")
        lo, hi = _range(cfg["velocity_range_m_s"])
        ds = vcr_study(
            [projectile],
            [float(obliquity)],
            _values(cfg["yaw_deg"]),
            target=target,
            lo=lo,
            hi=hi,
            tol=vtol,
            scan=scan,
            start=start,
            numerics=num,
            nose=True,
            low_speeds=_values(cfg.get("low_velocities_m_s", [])),
        )
        ds.attrs["title"] = "Paper Figs 11-12: V_cr against yaw, final nose direction"
        return ds
    if study == "fig13":
        return fig13(
            cfg["projectile"],
            target,
            float(cfg["yaw_deg"]),
            _values(cfg["velocities_m_s"]),
            numerics=num,
            n_time=n_time,
            speed_fraction=frac,
        )
    if study == "fig15":
        lo, hi = _range(cfg["velocity_range_m_s"])
        ths = sorted(set(_values(cfg["thresholds_deg"])) | {float(cfg["threshold_deg"])})
        return vci_study(
            [projectile],
            _values(cfg["yaw_deg"]),
            ths,
            target=target,
            convention=shared.get("yaw_convention", "axis_tilted"),
            lo=lo,
            hi=hi,
            tol=vtol,
            scan=scan,
            speed_fraction=frac,
            primary_threshold=float(cfg["threshold_deg"]),
            numerics=num,
        )
    if study == "fig16":
        return fig16(
            cfg["projectile"],
            target,
            float(cfg["velocity_m_s"]),
            _values(cfg["omega_rad_s"]),
            start_height=height,
            numerics=num,
            n_time=n_time,
            speed_fraction=frac,
        )
    if study == "start_height":
        return start_height_study(
            cfg["projectile"],
            target,
            float(cfg["velocity_m_s"]),
            _values(cfg["omega_rad_s"]),
            _values(cfg["start_heights_m"]),
            numerics=num,
            speed_fraction=frac,
        )
    # fig18
    lo, hi = _range(cfg["omega_range_rad_s"])
    return omega_c_study(
        [projectile],
        _values(cfg["velocities_m_s"]),
        target=target,
        lo=lo,
        hi=hi,
        tol=wtol,
        scan=scan,
        start_height=height,
        numerics=num,
    )


def gather(study: str, parts: Sequence[xr.Dataset]) -> xr.Dataset:
    """Join the parts of a split study (:data:`SPLIT_STUDIES`) into one dataset.

    Parts may come in any order; projectiles keep their first-seen order, obliquities are
    sorted.
    """
    if study not in SPLIT_STUDIES:
        raise InputError(f"{study!r} is not split into parts")
    parts = list(parts)
    if not parts:
        raise InputError("no parts to gather")
    projs = list(dict.fromkeys(str(p["projectile"].values[0]) for p in parts))
    by_p: dict[str, list[xr.Dataset]] = {p: [] for p in projs}
    for p in parts:
        by_p[str(p["projectile"].values[0])].append(p)
    rows = []
    for p in projs:
        ps = by_p[p]
        if study == "fig12":
            ps = sorted(ps, key=lambda d: float(d["obliquity"].values[0]))
            rows.append(combine(ps, "obliquity") if len(ps) > 1 else ps[0])
        else:
            if len(ps) != 1:
                raise InputError(f"{len(ps)} parts for projectile {p}; expected 1")
            rows.append(ps[0])
    out = combine(rows, "projectile") if len(rows) > 1 else rows[0]
    for k in ("study", "config_json", "config_sha256", "created_utc", "git_commit", "git_dirty"):
        out.attrs.pop(k, None)
    return out
