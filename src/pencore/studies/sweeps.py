"""Sweeps over impact speed or target for one projectile, as the command line's
``depth-curve``, ``residual-velocity`` and ``ballistic-table`` write them.

* :func:`depth_curve`: for each impact speed, the penetration depth, path length, final
  deviation and the peak loads (deceleration in m/s^2 and g, axial and lateral force);
* :func:`residual_curve`: for each impact speed on a finite target, the residual speed
  and exit pitch, with the Recht-Ipson curve fitted when three or more runs perforate;
* :func:`ballistic_table`: the ballistic limit of a slab of one medium over thickness and
  obliquity (:func:`pencore.ballistic_limit` per cell).

Each takes ``progress``, called with a short text after every point (the command line
prints ``[i/n] ...`` on stderr), so a long sweep shows where it is.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import InputError, SolverError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, simulate
from pencore.search.perforation import fit_recht_ipson
from pencore.search.threshold import VELOCITY_TOL
from pencore.studies.common import STRING_DTYPE, axis_values, var_attrs
from pencore.studies.perforation.slabs import (
    ballistic_limit_grid,
    fitted_curve,
    residual_runs,
    residual_variables,
    run_messages,
)

__all__ = ["depth_curve", "residual_curve", "ballistic_table"]

Progress = Callable[[str], None] | None


def _velocity_coord(v: np.ndarray) -> dict[str, tuple]:
    return {"velocity": ("velocity", v, var_attrs("m s-1", "impact speed"))}


def depth_curve(
    projectile: Any,
    target: Any,
    velocities: Sequence[float],
    obliquity: float = 0.0,
    yaw: float = 0.0,
    *,
    numerics: Numerics | Mapping[str, Any] | None = None,
    progress: Progress = None,
    start: Sequence[float] | None = None,
) -> xr.Dataset:
    """Depth and peak loads against impact speed.

    Parameters
    ----------
    projectile, target
        As for :func:`pencore.simulate`.
    velocities : sequence of float
        Impact speeds (m/s).
    obliquity, yaw : float
        As for :func:`pencore.simulate` (deg).
    numerics : Numerics or mapping, optional
    progress : callable, optional
        Called with a text after each run.
    start : sequence of 3 float, optional
        Initial nose-tip position of every run (m), as for :func:`pencore.simulate`;
        recorded as the attribute ``start_m``. Default: the body touching the surface.

    Returns
    -------
    xarray.Dataset
        On ``velocity`` (m/s): ``penetration_depth``, ``path_length`` (m),
        ``final_deviation`` (deg), ``peak_deceleration`` (m s-2), ``peak_deceleration_g``,
        ``peak_axial_force``, ``peak_lateral_force`` (N), ``outcome``.

    Examples
    --------
    >>> from pencore.studies.sweeps import depth_curve
    >>> ds = depth_curve("p2", "soil", [200.0, 300.0])
    >>> [f"{d:.2f}" for d in ds.penetration_depth.values]
    ['2.68', '4.50']
    """
    v = axis_values(velocities, "velocities")
    pr = prepare(projectile, target, resolve_numerics(numerics))
    names = ["penetration_depth", "path_length", "final_deviation"]
    peaks = {
        "peak_deceleration": ("peak_deceleration_m_s2", "m s-2", "peak axial deceleration"),
        "peak_deceleration_g": ("peak_deceleration_g", "1", "peak axial deceleration in g0"),
        "peak_axial_force": ("peak_axial_force_N", "N", "peak axial contact force"),
        "peak_lateral_force": ("peak_lateral_force_N", "N", "peak lateral contact force"),
    }
    cols: dict[str, np.ndarray] = {k: np.full(v.size, np.nan) for k in [*names, *peaks]}
    outcome = np.empty(v.size, dtype=STRING_DTYPE)
    message = np.full(v.size, "", dtype=STRING_DTYPE)
    attrs: dict[str, dict] = {n: {} for n in names}
    for k, vi in enumerate(v):
        try:
            ds = simulate(pr.projectile, pr.target, float(vi), obliquity, yaw, prepared=pr,
                          start=start)  # fmt: skip
        except SolverError as exc:  # a row of its own, with its reason; the others kept
            outcome[k], message[k] = "solver_error", str(exc)
        else:
            for n in names:
                cols[n][k] = float(ds[n])
                attrs[n] = dict(ds[n].attrs)
            for n, (a, _, _) in peaks.items():
                cols[n][k] = ds.attrs.get(a, math.nan)
            outcome[k] = ds.attrs["outcome"]
        if progress is not None:
            progress(f"{vi:g} m/s: depth {cols['penetration_depth'][k]:.4g} m, peak "
                     f"{cols['peak_deceleration_g'][k]:.4g} g ({outcome[k]})")  # fmt: skip
    data = {n: ("velocity", cols[n], attrs[n]) for n in names}
    for n, (_, units, long_name) in peaks.items():
        data[n] = ("velocity", cols[n], var_attrs(units, long_name))
    data["outcome"] = ("velocity", outcome, {"units": "1", "long_name": "outcome of the run"})
    if any(message):
        data["message"] = run_messages(message)
    return xr.Dataset(
        data,
        coords=_velocity_coord(v),
        attrs={
            "title": "pencore depth and peak loads against impact speed",
            "projectile": pr.projectile.name,
            "target": pr.target.name,
            "obliquity_deg": float(obliquity),
            "yaw_deg": float(yaw),
            **_start_attrs(start),
            "Conventions": "CF-1.8",
        },
    )


def _start_attrs(start: Sequence[float] | None) -> dict[str, list[float]]:
    """``{"start_m": [x, y, z]}`` (m) for a given start, else nothing."""
    return {} if start is None else {"start_m": [float(c) for c in start]}


def residual_curve(
    projectile: Any,
    target: Any,
    velocities: Sequence[float],
    obliquity: float = 0.0,
    yaw: float = 0.0,
    *,
    numerics: Numerics | Mapping[str, Any] | None = None,
    progress: Progress = None,
    start: Sequence[float] | None = None,
) -> xr.Dataset:
    """Residual speed against impact speed on a finite target, with the Recht-Ipson fit.

    ``start``: the initial nose-tip position of every run (m), as for
    :func:`depth_curve`.

    Returns
    -------
    xarray.Dataset
        On ``velocity`` (m/s): ``residual_velocity`` (m/s, 0 when the run does not
        perforate), ``recht_ipson`` (the fitted curve, m/s; NaN without a fit),
        ``exit_pitch`` (deg), ``outcome``; attributes ``recht_ipson_a``, ``_p`` and
        ``v_bl_m_s`` (fitted, all three free; NaN with fewer than three perforating runs)
        as :func:`pencore.plotting.perforation.plot_residual_velocity` draws them, and
        ``recht_ipson_status`` (``"fitted"``, or why not). A run that cannot finish is
        the row ``outcome = "solver_error"`` (residual NaN) with its reason in
        ``message``; the other rows are kept.
        ``thickness_m``, the target's total thickness (m, gaps included).
    """
    v = axis_values(velocities, "velocities")
    pr = prepare(projectile, target, resolve_numerics(numerics))
    if not math.isfinite(pr.target.levels[-1][1]):
        raise InputError(
            f"target {pr.target.name!r} has no rear face (its last layer is a half-space): "
            "a residual velocity needs a finite target (a thickness on every layer)"
        )
    vr, pitch, outcome, message = residual_runs(pr, v, obliquity, yaw, progress, start=start)
    fit = {"a": math.nan, "p": math.nan, "v_bl": math.nan, "rms": math.nan}
    done = np.isfinite(vr)  # the runs that finished
    n_hit = int((vr[done] > 0).sum())
    if n_hit >= 3:
        try:
            fit = fit_recht_ipson(v[done], vr[done])
            status = "fitted"
        except (ValueError, np.linalg.LinAlgError) as exc:  # the runs are kept all the same
            status = f"not fitted: {' '.join(str(exc).split())}"
    else:  # no fit: NaN parameters and curve, and why
        status = f"not fitted: {n_hit} of {v.size} runs perforate, 3 are needed"
    curve = fitted_curve(v, fit)
    return xr.Dataset(
        residual_variables(vr, curve, pitch, outcome, "target", message),
        coords=_velocity_coord(v),
        attrs={
            "title": "pencore residual velocity against impact velocity",
            "projectile": pr.projectile.name,
            "medium": pr.target.name,
            "thickness_m": float(pr.target.thickness),  # m, gaps included
            "obliquity_deg": float(obliquity),
            "yaw_deg": float(yaw),
            **_start_attrs(start),
            "v_bl_m_s": float(fit["v_bl"]),
            "recht_ipson_a": float(fit["a"]),
            "recht_ipson_p": float(fit["p"]),
            "recht_ipson_rms_m_s": float(fit["rms"]),
            "recht_ipson_status": status,
            "Conventions": "CF-1.8",
        },
    )


def ballistic_table(
    projectile: Any,
    medium: str,
    thicknesses: Sequence[float],
    obliquities: Sequence[float],
    *,
    lo: float = 50.0,
    hi: float = 3000.0,
    tol: float = VELOCITY_TOL,
    scan: int | None = 5,
    numerics: Numerics | Mapping[str, Any] | None = None,
    progress: Progress = None,
    windows: tuple[float | None, float | None, float | None] | None = None,
    start: Sequence[float] | None = None,
) -> xr.Dataset:
    """Ballistic limit (m/s) of a slab of ``medium`` on ``(thickness m, obliquity deg)``,
    as :func:`pencore.studies.perforation.slabs.ballistic_limit_map` with progress;
    ``windows`` (``crater_depth``, ``free_surface_depth`` in calibers,
    ``plastic_zone_ratio``; None keeps the medium's own) are set on every slab and
    recorded in the attributes; ``start`` (m) is every run's initial nose-tip position,
    as for :func:`depth_curve`."""
    ds = ballistic_limit_grid(projectile, medium, thicknesses, obliquities, lo=lo, hi=hi,
                              tol=tol, scan=scan, numerics=numerics, progress=progress,
                              windows=windows, start=start)  # fmt: skip
    keys = ("crater_depth_calibers", "free_surface_depth_calibers", "plastic_zone_ratio")
    given = dict(zip(keys, windows or (None, None, None), strict=True))
    ds.attrs = {
        "title": "pencore ballistic limit against slab thickness and obliquity",
        "projectile": str(getattr(projectile, "name", projectile)),
        "medium": medium,
        **{k: float(v) for k, v in given.items() if v is not None},
        "search_lo_m_s": float(lo),
        "search_hi_m_s": float(hi),
        "search_tol_m_s": float(tol),
        **_start_attrs(start),
        "Conventions": "CF-1.8",
    }
    return ds
