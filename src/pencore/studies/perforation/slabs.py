"""Beyond the paper: perforation of finite slabs.

* :func:`ballistic_limit_map`: the ballistic limit v_bl (:func:`~pencore.ballistic_limit`)
  of one projectile against slab thickness and obliquity;
* :func:`residual_velocity_curve`: residual speed against impact speed for one slab,
  with the Recht-Ipson curve ``v_r = a (v^p - v_bl^p)^(1/p)`` fitted to it
  (:func:`pencore.search.perforation.fit_recht_ipson`, ``v_bl`` from the search);
* :func:`ballistic_limit_grid`: the searches of such a map, shared with
  :func:`pencore.studies.sweeps.ballistic_table`;
* :func:`residual_runs` and :func:`residual_variables`: the runs of such a curve and its
  data variables, shared with :func:`pencore.studies.sweeps.residual_curve`.

These are model predictions (no measurement is compared here): the DAFL model with the
paper's concrete law, no crater or free-surface reduction unless the study's ``crater_depth``
/ ``free_surface_depth`` turn them on.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import SolverError
from pencore.inputs.library import get_target
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.inputs.target import Layer, Target
from pencore.run.impact import prepare, simulate
from pencore.search.perforation import ballistic_limit, fit_recht_ipson, recht_ipson
from pencore.search.threshold import VELOCITY_TOL
from pencore.studies.common import (
    STRING_DTYPE,
    axis_values,
    search_grid,
    search_variables,
    var_attrs,
)

__all__ = [
    "slab_target",
    "ballistic_limit_map",
    "residual_velocity_curve",
    "ballistic_limit_grid",
    "residual_runs",
    "residual_variables",
    "fitted_curve",
    "run_messages",
]


def slab_target(
    medium: str,
    thickness: float,
    crater_depth: float = 0.0,
    free_surface_depth: float = 0.0,
    plastic_zone_ratio: float = 0.0,
) -> Target:
    """A single slab of the named medium, ``thickness`` m, with the near-surface options
    (calibers, and the finite-sphere ratio ``c/a``; 0 = off)."""
    t = get_target(medium)
    slab = Target(f"{medium} slab {thickness:g} m", (Layer(t.medium, float(thickness)),))
    if crater_depth or free_surface_depth or plastic_zone_ratio:
        slab = slab.with_windows(crater_depth, free_surface_depth, plastic_zone_ratio)
    return slab


def ballistic_limit_map(
    projectile: str,
    medium: str,
    thicknesses: Sequence[float],
    obliquities: Sequence[float],
    *,
    lo: float = 50.0,
    hi: float = 3000.0,
    tol: float = VELOCITY_TOL,
    scan: int | None = 5,
    crater_depth: float = 0.0,
    free_surface_depth: float = 0.0,
    plastic_zone_ratio: float = 0.0,
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Ballistic limit (m/s) on ``(thickness m, obliquity deg)``: one search per cell."""
    windows = (crater_depth, free_surface_depth, plastic_zone_ratio)
    if not any(windows):  # 0 = off: each medium's own, as slab_target
        windows = None
    ds = ballistic_limit_grid(projectile, medium, thicknesses, obliquities, lo=lo, hi=hi,
                              tol=tol, scan=scan, numerics=numerics, windows=windows)  # fmt: skip
    ds.attrs = {
        "title": "pencore ballistic limit against slab thickness and obliquity",
        "projectile": projectile,
        "medium": medium,
        "crater_depth_calibers": float(crater_depth),
        "free_surface_depth_calibers": float(free_surface_depth),
        **({"plastic_zone_ratio": float(plastic_zone_ratio)} if plastic_zone_ratio else {}),
        "search_lo_m_s": float(lo),
        "search_hi_m_s": float(hi),
        "search_tol_m_s": float(tol),
    }
    return ds


def ballistic_limit_grid(
    projectile: Any,
    medium: str,
    thicknesses: Sequence[float],
    obliquities: Sequence[float],
    *,
    lo: float,
    hi: float,
    tol: float,
    scan: int | None,
    numerics: Numerics | Mapping[str, Any] | None,
    windows: tuple[float | None, float | None, float | None] | None = None,
    progress: Callable[[str], None] | None = None,
    start: Sequence[float] | None = None,
) -> xr.Dataset:
    """The ballistic-limit searches of :func:`ballistic_limit_map` on ``(thickness m,
    obliquity deg)``, without the Dataset's attributes (each caller records its own).

    Parameters
    ----------
    projectile : str or pencore.Projectile
        As for :func:`pencore.ballistic_limit`.
    medium : str
        Target name of the slab's medium.
    thicknesses, obliquities : sequence of float
        Slab thicknesses (m) and obliquities (deg).
    lo, hi, tol : float
        Search range and final bracket width (m/s).
    scan : int or None
        Coarse scan points of each search (None: none).
    numerics : Numerics or mapping, optional
    windows : tuple of float or None, optional
        ``crater_depth``, ``free_surface_depth`` (calibers) and ``plastic_zone_ratio`` set
        on every slab (:meth:`pencore.inputs.target.Target.with_windows`: None keeps the
        medium's own, 0 is off); None: the medium's own.
    progress : callable, optional
        Called with a text after each cell.
    start : sequence of 3 float, optional
        Initial nose-tip position of every run (m), as for :func:`pencore.simulate`;
        default: the body touching the surface.

    Returns
    -------
    xarray.Dataset
        On ``thickness`` and ``obliquity``: the search variables of ``v_bl`` (m/s).
    """
    th = axis_values(thicknesses, "thicknesses")
    obl = axis_values(obliquities, "obliquities")
    num = resolve_numerics(numerics)
    res = search_grid((th.size, obl.size), "the ballistic-limit table (thicknesses x obliquities)")
    at = {} if start is None else {"start": tuple(start)}
    for i, h in enumerate(th):
        t = slab_target(medium, h)
        if windows is not None:
            t = t.with_windows(*windows)
        for j, o in enumerate(obl):
            r = ballistic_limit(projectile, t, float(o), lo=lo, hi=hi, tol=tol, scan=scan,
                                numerics=num, **at)  # fmt: skip
            res[i, j] = r
            if progress is not None:
                shown = f"{r.value:.5g} m/s" if r.converged else f"not found ({r.status})"
                progress(f"{h:g} m at {o:g} deg: v_bl {shown}")
    dims = ("thickness", "obliquity")
    return xr.Dataset(
        search_variables(
            res, "v_bl", "m s-1", "ballistic limit (lowest speed that perforates)", dims
        ),
        coords={
            "thickness": ("thickness", th, var_attrs("m", "slab thickness")),
            "obliquity": ("obliquity", obl, var_attrs("degree", "obliquity of the axis")),
        },
    )


def residual_velocity_curve(
    projectile: str,
    medium: str,
    thickness: float,
    velocities: Sequence[float],
    *,
    obliquity: float = 0.0,
    lo: float = 50.0,
    hi: float = 3000.0,
    tol: float = 1.0,
    crater_depth: float = 0.0,
    free_surface_depth: float = 0.0,
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Residual speed (m/s) against impact speed for one slab, with the ballistic limit
    (searched to ``tol``) and the Recht-Ipson fit.

    The fit is made twice: with ``v_bl`` fixed at the searched value (``a``, ``p`` free),
    and with the rigid-body values ``a = 1``, ``p = 2`` for comparison (the RMS residual
    of each is recorded).
    """
    v = axis_values(velocities, "velocities")
    num = resolve_numerics(numerics)
    t = slab_target(medium, thickness, crater_depth, free_surface_depth)
    pr = prepare(projectile, t, num)
    vr, pitch, outcome, message = residual_runs(pr, v, obliquity)
    bl = ballistic_limit(projectile, t, obliquity, lo=lo, hi=hi, tol=tol, numerics=num)
    fit = {"a": math.nan, "p": math.nan, "v_bl": bl.value, "rms": math.nan}
    rms_rigid = math.nan
    done = np.isfinite(vr)  # the runs that finished
    if bl.converged and (vr[done] > 0).sum() >= 2:
        fit = fit_recht_ipson(v[done], vr[done], v_bl=bl.value)
        hit = done & (vr > 0)
        rigid = recht_ipson(v[hit], bl.value)
        rms_rigid = float(np.sqrt(np.mean((rigid - vr[hit]) ** 2)))
    curve = fitted_curve(v, fit)
    return xr.Dataset(
        residual_variables(vr, curve, pitch, outcome, "slab", message),
        coords={"velocity": ("velocity", v, var_attrs("m s-1", "impact speed"))},
        attrs={
            "title": "pencore residual velocity against impact velocity",
            "projectile": projectile,
            "medium": medium,
            "thickness_m": float(thickness),
            "obliquity_deg": float(obliquity),
            "crater_depth_calibers": float(crater_depth),
            "free_surface_depth_calibers": float(free_surface_depth),
            "v_bl_m_s": float(bl.value),
            "v_bl_lo_m_s": float(bl.lo),
            "v_bl_hi_m_s": float(bl.hi),
            "v_bl_status": bl.status,
            "recht_ipson_a": float(fit["a"]),
            "recht_ipson_p": float(fit["p"]),
            "recht_ipson_rms_m_s": float(fit["rms"]),
            "recht_ipson_rigid_rms_m_s": rms_rigid,
        },
    )


def residual_runs(
    pr: Any,
    velocities: np.ndarray,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    progress: Callable[[str], None] | None = None,
    *,
    start: Sequence[float] | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """One impact per speed on a prepared finite target.

    Parameters
    ----------
    pr : pencore.integrators.problem.Problem
        The projectile and finite target, prepared (:func:`pencore.run.impact.prepare`).
    velocities : numpy.ndarray
        Impact speeds (m/s).
    obliquity, yaw : float
        As for :func:`pencore.simulate` (deg).
    progress : callable, optional
        Called with a text after each run.
    start : sequence of 3 float, optional
        Initial nose-tip position of every run (m); default: the body touching the
        surface.

    Returns
    -------
    residual, pitch, outcome, message : numpy.ndarray
        Residual speed (m/s; 0 when the run does not perforate, NaN when it could not
        finish), exit pitch (deg; NaN when it does not perforate), the outcome of each
        run (``"solver_error"``: the run could not finish) and the solver's reason for
        such a run (``""`` for the others). A run that cannot finish is a row of its own:
        the others are kept.
    """
    vr = np.zeros(velocities.size)
    pitch = np.full(velocities.size, np.nan)
    outcome = np.empty(velocities.size, dtype=STRING_DTYPE)
    message = np.full(velocities.size, "", dtype=STRING_DTYPE)
    for k, vi in enumerate(velocities):
        try:
            ds = simulate(pr.projectile, pr.target, float(vi), obliquity, yaw, prepared=pr,
                          loads=False, start=start)  # fmt: skip
        except SolverError as exc:
            vr[k], outcome[k], message[k] = math.nan, "solver_error", str(exc)
        else:
            outcome[k] = ds.attrs["outcome"]
            if outcome[k] == "perforated":
                vr[k] = ds.attrs["residual_velocity"]
                pitch[k] = ds.attrs["exit_pitch_deg"]
        if progress is not None:
            progress(f"{vi:g} m/s: residual {vr[k]:.4g} m/s ({outcome[k]})")
    return vr, pitch, outcome, message


def fitted_curve(v: np.ndarray, fit: Mapping[str, float]) -> np.ndarray:
    """The Recht-Ipson curve (m/s) of ``fit`` at the speeds ``v``; NaN everywhere when
    a parameter is NaN (no fit could be made)."""
    if not all(math.isfinite(fit[k]) for k in ("v_bl", "a", "p")):
        return np.full(np.shape(v), math.nan)
    return recht_ipson(v, fit["v_bl"], fit["a"], fit["p"])


def residual_variables(
    vr: np.ndarray,
    curve: np.ndarray,
    pitch: np.ndarray,
    outcome: np.ndarray,
    body: str,
    message: np.ndarray | None = None,
) -> dict[str, tuple]:
    """The data variables on ``velocity`` of a residual-velocity curve: the runs of
    :func:`residual_runs` and the fitted Recht-Ipson ``curve`` (m/s); ``body`` names
    what the projectile clears (``"slab"``, ``"target"``); ``message`` (the reasons of
    runs that could not finish) is a variable when one is not empty."""
    out = {
        "residual_velocity": (
            "velocity",
            vr,
            var_attrs(
                "m s-1", f"centre-of-mass speed when clear of the {body} (0: no perforation)"
            ),
        ),
        "recht_ipson": (
            "velocity",
            curve,
            var_attrs("m s-1", "Recht-Ipson curve a (v^p - v_bl^p)^(1/p) fitted to the runs"),
        ),
        "exit_pitch": (
            "velocity",
            pitch,
            var_attrs("degree", "axis angle from the normal at exit (NaN: no perforation)"),
        ),
        "outcome": ("velocity", outcome, {"units": "1", "long_name": "outcome of the run"}),
    }
    if message is not None and any(message):
        out["message"] = run_messages(message)
    return out


def run_messages(message: np.ndarray) -> tuple:
    """The ``message`` variable on ``velocity``: why a run could not finish."""
    return (
        "velocity",
        message,
        {"units": "1", "long_name": "why the run could not finish (empty: it finished)"},
    )
