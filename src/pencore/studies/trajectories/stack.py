"""Trajectory datasets (Figs 7, 11, 16): many runs stacked on one shared time axis.

Trajectory datasets share one time axis per dataset: the union of the runs' own
(adaptive) sample times, thinned evenly in index to about ``n_time`` samples, plus every
run's last time; each run is interpolated linearly onto it and is NaN after its end.
Scalar results (depth, final deviation, nose direction, ...) come from the full runs.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from itertools import product
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.errors import InputError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, simulate
from pencore.studies.common import (
    PARAMETER_ATTRS,
    STRING_DTYPE,
    TRAJECTORY_VARIABLES,
    axis_values,
    signed_deviation,
    start_point,
    var_attrs,
)

__all__ = ["stack_trajectories", "trajectory_set"]


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
        (:func:`pencore.analysis.deviation.final_deviation`).

    Returns
    -------
    xarray.Dataset
        :data:`~pencore.studies.common.TRAJECTORY_VARIABLES` on ``(*dims, time)`` and per-run
        scalars on ``dims``:
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
    t = _shared_time_axis(runs, n_time)
    hist, scalars = _sample(runs, shape, t, speed_fraction)
    first = next(iter(runs.values()))
    data = _history_variables(first, dims, hist)
    data.update(_scalar_variables(dims, scalars, speed_fraction))
    c = {d: (d, np.asarray(v), dict(a)) for d, (v, a) in coords.items()}
    c["time"] = (
        "time",
        t,
        var_attrs("s", "time since start (shared, thinned grid; NaN after a run ends)"),
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
            "Conventions": "CF-1.8",
        }
    )
    return ds


def _shared_time_axis(runs: Mapping[tuple[int, ...], xr.Dataset], n_time: int) -> np.ndarray:
    """The union of the runs' sample times (s) thinned to about ``n_time``, with every
    run's last time kept."""
    all_t = np.unique(np.concatenate([r["time"].values for r in runs.values()]))
    pick = np.unique(np.round(np.linspace(0, all_t.size - 1, int(n_time))).astype(int))
    t = np.union1d(all_t[pick], [float(r["time"].values[-1]) for r in runs.values()])

    return t


def _sample(
    runs: Mapping[tuple[int, ...], xr.Dataset],
    shape: tuple[int, ...],
    t: np.ndarray,
    speed_fraction: float,
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """Every run's histories interpolated onto ``t`` (NaN outside the run) and its
    scalar results, as arrays of ``shape`` (+ time)."""
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
    outcome = np.empty(shape, dtype=STRING_DTYPE)
    nose = np.empty(shape, dtype=STRING_DTYPE)
    for idx, r in runs.items():
        rt = r["time"].values
        for k in TRAJECTORY_VARIABLES:
            src = signed_deviation(r) if k == "deviation_signed" else r[k].values
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

    scal_f.update(reversed=reversed_, n_steps=n_steps, outcome=outcome, nose_direction=nose)
    return hist, scal_f


def _history_variables(
    first: xr.Dataset, dims: list[str], hist: dict[str, np.ndarray]
) -> dict[str, tuple]:
    """The time-history variables on ``(*dims, time)``, with the attributes of a run."""
    tdims = (*dims, "time")
    data = {
        k: (tdims, hist[k], dict(first[k].attrs))
        for k in TRAJECTORY_VARIABLES
        if k != "deviation_signed"
    }
    data["deviation_signed"] = (
        tdims,
        hist["deviation_signed"],
        var_attrs(
            "degree",
            "in-plane angle from the normal -y to the centre of mass velocity, "
            "positive towards +x (unwrapped)",
        ),
    )
    return data


def _scalar_variables(
    dims: list[str], scal_f: dict[str, np.ndarray], speed_fraction: float
) -> dict[str, tuple]:
    """The per-run scalars on ``dims``, with units and long names."""
    outcome, reversed_, n_steps, nose = (
        scal_f["outcome"],
        scal_f["reversed"],
        scal_f["n_steps"],
        scal_f["nose_direction"],
    )
    fd = f"at the last state with speed >= {speed_fraction:g} x impact speed"
    return {
        "outcome": (
            dims,
            outcome,
            {"long_name": "how the run ended (stopped, exited, ...)", "units": "1"},
        ),
        "reversed": (
            dims,
            reversed_,
            var_attrs(
                "1", "1 if the centre of mass velocity turned towards the surface in the target"
            ),
        ),
        "penetration_depth": (
            dims,
            scal_f["penetration_depth"],
            var_attrs("m", "deepest point of the nose tip below the surface"),
        ),
        "path_length": (
            dims,
            scal_f["path_length"],
            var_attrs("m", "length of the nose-tip path below the surface"),
        ),
        "final_deviation": (
            dims,
            scal_f["final_deviation"],
            var_attrs(
                "degree",
                f"trajectory deviation from the normal (paper phi, alpha) {fd}",
                speed_fraction=float(speed_fraction),
            ),
        ),
        "final_deviation_signed": (
            dims,
            scal_f["final_deviation_signed"],
            var_attrs("degree", f"signed in-plane trajectory deviation (positive towards +x) {fd}"),
        ),
        "final_theta": (
            dims,
            scal_f["final_theta"],
            var_attrs("degree", "axis angle from the normal at the end of the run"),
        ),
        "nose_direction": (
            dims,
            nose,
            {"units": "1", "long_name": "side the nose points to at the end (+x or -x)"},
        ),
        "t_first_contact": (
            dims,
            scal_f["t_first_contact"],
            var_attrs("s", "time of first contact with the target"),
        ),
        "t_end": (dims, scal_f["t_end"], var_attrs("s", "time at the end of the run")),
        "n_steps": (dims, n_steps, var_attrs("1", "accepted integration steps")),
        "wall_time": (dims, scal_f["wall_time"], var_attrs("s", "solver wall time")),
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
    if dim not in PARAMETER_ATTRS:
        raise InputError(f"dim must be one of {', '.join(PARAMETER_ATTRS)}, got {dim!r}")
    vals = axis_values(values, dim)
    fixed = dict(velocity=velocity, obliquity=obliquity, yaw=yaw, omega=omega)
    runs = _runs_along(
        projectile, target, dim, vals, resolve_numerics(numerics), start_point(start), fixed
    )
    if _runs is not None:
        _runs.update(runs)
    ds = stack_trajectories(
        runs, {dim: (vals, PARAMETER_ATTRS[dim])}, n_time=n_time, speed_fraction=speed_fraction
    )
    for k, v in fixed.items():
        if k != dim:
            ds.attrs[f"{k}_fixed"] = float(v)
    ds.attrs["start_m"] = "surface contact at x = 0" if start is None else str(list(start))
    return ds
