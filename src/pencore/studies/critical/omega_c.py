"""Fig. 18: the critical angular velocity omega_c on (projectile, impact velocity)."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.search import critical
from pencore.search.threshold import OMEGA_TOL
from pencore.studies.common import (
    PARAMETER_ATTRS,
    axis_values,
    numerics_record,
    projectile_coords,
    search_grid,
    search_variables,
    start_from_height,
)
from pencore.studies.config import StudySettings
from pencore.workflowconfig.parts import value_range, values

__all__ = ["omega_c_study", "run_fig18"]


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

    Each cell is :func:`pencore.search.critical.omega_c` on ``[lo, hi]`` rad/s, normal impact,
    zero yaw, the tip starting ``start_height`` (m) above the surface. ``above_range``
    means no reversal up to ``hi``.
    """
    names = list(projectiles)
    vel = axis_values(velocities, "velocities")
    num = resolve_numerics(numerics)
    res = search_grid((len(names), vel.size), "the omega_c table (projectiles x velocities)")
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
    data = search_variables(res, "omega_c", "rad s-1", "critical angular velocity omega_c", dims)
    return xr.Dataset(
        data,
        coords={
            **projectile_coords(names),
            "velocity": ("velocity", vel, PARAMETER_ATTRS["velocity"]),
        },
        attrs={
            "title": "Paper Fig. 18: critical angular velocity against impact velocity",
            "target": target,
            "search_range_rad_s": np.array([float(lo), float(hi)]),
            "tolerance_rad_s": float(tol),
            "scan_points": -1 if scan is None else int(scan),
            "start_height_m": float(start_height),
            "numerics_json": json.dumps(numerics_record(num)),
            "Conventions": "CF-1.8",
        },
    )


def run_fig18(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    lo, hi = value_range(cfg["omega_range_rad_s"])
    return omega_c_study(
        [c.projectile],
        values(cfg["velocities_m_s"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.omega_tol,
        scan=c.scan,
        start_height=c.start_height,
        numerics=c.numerics,
    )
