"""Figs 8 and 12: the critical ricochet velocity Vcr on (projectile, obliquity, yaw),
with the final nose direction at Vcr.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.errors import InputError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, run_impact, simulate
from pencore.search import critical
from pencore.search.threshold import VELOCITY_TOL
from pencore.studies.common import (
    PARAMETER_ATTRS,
    PROJECTILES,
    STRING_DTYPE,
    axis_values,
    numerics_record,
    projectile_coords,
    search_grid,
    search_variables,
    start_point,
    var_attrs,
)
from pencore.studies.config import StudySettings
from pencore.workflowconfig.parts import grid, value_range, values

__all__ = ["vcr_study", "vcr_obliquity_study", "run_fig8", "run_fig12"]


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

    Each cell is :func:`pencore.search.critical.vcr` on ``[lo, hi]`` m/s to ``tol`` with a
    ``scan``-point monotonicity check. With ``nose=True`` the run at the bracket's high
    end (the lowest speed seen to reverse) is simulated in full, and the side the nose
    points to at its end is recorded (``nose_direction``, ``final_theta``,
    ``outcome_at_vcr``). ``low_speeds`` (m/s, below ``lo``) are also run and their
    reversal recorded (``low_speed_reversed``): at large obliquity slow projectiles
    ricochet during nose entry, which is not the turn-back that Vcr is about, and is why
    ``lo`` is above them.
    """
    names = list(projectiles)
    obl = axis_values(obliquities, "obliquities")
    yw = axis_values(yaws, "yaws")
    low = np.asarray(list(low_speeds), dtype=float)
    num = resolve_numerics(numerics)
    st = start_point(start)
    shape = (len(names), obl.size, yw.size)
    res = search_grid(shape, "the Vcr table (projectiles x obliquities x yaws)")
    nose_dir = np.full(shape, "", dtype=STRING_DTYPE)
    final_theta = np.full(shape, np.nan)
    outcome_hi = np.full(shape, "", dtype=STRING_DTYPE)
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
                    low_rev[ip, io, iy, il] = int(
                        run_impact(
                            pr.projectile,
                            pr.target,
                            float(v),
                            float(ob),
                            float(y),
                            start=st,
                            prepared=pr,
                            stop_at_reversal=True,
                        ).reversed
                    )
    dims = ("projectile", "obliquity", "yaw")
    data = search_variables(res, "vcr", "m s-1", "critical reverse velocity V_cr", dims)
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
            var_attrs("degree", "axis angle from the normal at the end of the full run at vcr_hi"),
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
            var_attrs("1", "1 if the run at this low speed turned back (ricochet during entry)"),
        )
    coords = {
        **projectile_coords(names),
        "obliquity": ("obliquity", obl, PARAMETER_ATTRS["obliquity"]),
        "yaw": ("yaw", yw, PARAMETER_ATTRS["yaw"]),
    }
    if low.size:
        coords["low_velocity"] = (
            "low_velocity",
            low,
            var_attrs("m s-1", "impact velocity below the search range"),
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
            "numerics_json": json.dumps(numerics_record(num)),
            "Conventions": "CF-1.8",
        },
    )


def vcr_obliquity_study(
    projectiles: Sequence[str] = PROJECTILES,
    obliquities: Sequence[float] = tuple(grid(15.0, 75.0, 7.5)),
    **kwargs: Any,
) -> xr.Dataset:
    """Paper Fig. 8: ``vcr`` (m/s) on ``(projectile, obliquity)`` at zero yaw.

    Keyword arguments as :func:`vcr_study` (without ``yaws``); ``yaw`` stays as a scalar
    coordinate.
    """
    if "yaws" in kwargs:
        raise InputError("vcr_obliquity_study is at zero yaw; use vcr_study for other yaws")
    ds = vcr_study(projectiles, obliquities, (0.0,), **kwargs).isel(yaw=0)
    ds.attrs["title"] = "Paper Fig. 8: critical reverse velocity against obliquity"
    return ds


def run_fig8(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    lo, hi = value_range(cfg["velocity_range_m_s"])
    return vcr_obliquity_study(
        [c.projectile],
        values(cfg["obliquity_deg"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.velocity_tol,
        scan=c.scan,
        start=c.start,
        numerics=c.numerics,
        low_speeds=values(cfg.get("low_velocities_m_s", [])),
    )


def run_fig12(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    if c.obliquity is None:
        raise InputError("Vcr against yaw runs per (projectile, obliquity): give obliquity=")
    lo, hi = value_range(cfg["velocity_range_m_s"])
    ds = vcr_study(
        [c.projectile],
        [float(c.obliquity)],
        values(cfg["yaw_deg"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.velocity_tol,
        scan=c.scan,
        start=c.start,
        numerics=c.numerics,
        nose=True,
        low_speeds=values(cfg.get("low_velocities_m_s", [])),
    )
    ds.attrs["title"] = "Paper Figs 11-12: V_cr against yaw, final nose direction"
    return ds
