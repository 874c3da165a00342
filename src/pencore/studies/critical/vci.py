"""Fig. 15: the critical velocity Vci on (projectile, yaw, deviation threshold)."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.errors import InputError
from pencore.inputs.conventions import normal_impact_angles
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.search import critical
from pencore.search.threshold import VELOCITY_TOL
from pencore.studies.common import (
    PARAMETER_ATTRS,
    axis_values,
    numerics_record,
    projectile_coords,
    search_grid,
    search_variables,
    var_attrs,
)
from pencore.studies.config import StudySettings
from pencore.workflowconfig.parts import value_range, values

__all__ = ["vci_study", "run_fig15"]


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

    Each cell is :func:`pencore.search.critical.vci`: the lowest normal-impact speed at which a
    run with the given yaw turns back or ends with a deviation above ``threshold``
    (deg). The tip starts touching the surface. ``primary_threshold`` (deg; default the
    middle of ``thresholds``) is the one the figure and the comparison lead with; the
    others show how Vci moves with the choice. The searches of one (projectile, yaw)
    share their runs across thresholds (``shared_runs`` of :func:`pencore.search.critical.vci`):
    the results are those of separate searches, with fewer runs.
    """
    names = list(projectiles)
    yw = axis_values(yaws, "yaws")
    th = np.sort(axis_values(thresholds, "thresholds"))
    if primary_threshold is None:
        primary_threshold = float(th[(th.size - 1) // 2])
    if not np.any(np.isclose(th, primary_threshold)):
        raise InputError(
            f"primary threshold {primary_threshold} is not one of the thresholds {list(th)}"
        )
    normal_impact_angles(0.0, convention)
    num = resolve_numerics(numerics)
    res = search_grid(
        (len(names), yw.size, th.size), "the Vci table (projectiles x yaws x thresholds)"
    )
    for ip, p in enumerate(names):
        for iy, y in enumerate(yw):
            runs: dict[float, tuple[bool, float]] = {}
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
                    shared_runs=runs,
                )
    dims = ("projectile", "yaw", "threshold")
    data = search_variables(
        res, "vci", "m s-1", "critical impact velocity for instability V_ci", dims
    )
    return xr.Dataset(
        data,
        coords={
            **projectile_coords(names),
            "yaw": ("yaw", yw, PARAMETER_ATTRS["yaw"]),
            "threshold": (
                "threshold",
                th,
                var_attrs("degree", "final deviation above which a run counts as unstable"),
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
            "numerics_json": json.dumps(numerics_record(num)),
            "Conventions": "CF-1.8",
        },
    )


def run_fig15(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    lo, hi = value_range(cfg["velocity_range_m_s"])
    ths = sorted(set(values(cfg["thresholds_deg"])) | {float(cfg["threshold_deg"])})
    return vci_study(
        [c.projectile],
        values(cfg["yaw_deg"]),
        ths,
        target=c.target,
        convention=c.yaw_convention,
        lo=lo,
        hi=hi,
        tol=c.velocity_tol,
        scan=c.scan,
        speed_fraction=c.speed_fraction,
        primary_threshold=float(cfg["threshold_deg"]),
        numerics=c.numerics,
    )
