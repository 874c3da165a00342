"""Trajectories with yaw: Fig. 11 (oblique impact of #4 with yaw -1 and +1 deg,
:func:`run_fig11` on :func:`pencore.studies.trajectories.stack.trajectory_set`) and
Figs 13-14: normal impact with a small yaw, under both yaw conventions.

For a *normal* impact with yaw the paper does not say whether the velocity or the axis
is normal; :func:`pencore.inputs.conventions.normal_impact_angles` maps both readings
(``axis_tilted``: the velocity is normal, the axis tilted by the yaw;
``velocity_tilted``: the other way).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.inputs.conventions import YAW_CONVENTIONS, normal_impact_angles
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, simulate
from pencore.studies.common import PARAMETER_ATTRS, STRING_DTYPE, axis_values
from pencore.studies.config import StudySettings
from pencore.studies.trajectories.stack import stack_trajectories, trajectory_set
from pencore.workflowconfig.parts import values

__all__ = ["yaw_trajectories", "run_fig11", "run_fig13"]


def yaw_trajectories(
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
    vals = axis_values(velocities, "velocities")
    conv = list(conventions)
    for c in conv:
        normal_impact_angles(yaw, c)  # validates the name
    num = resolve_numerics(numerics)
    pr = prepare(projectile, target, num)
    runs = {}
    for ic, c in enumerate(conv):
        obl, yw = normal_impact_angles(yaw, c)
        for iv, v in enumerate(vals):
            runs[(ic, iv)] = simulate(pr.projectile, pr.target, float(v), obl, yw, prepared=pr)
    ds = stack_trajectories(
        runs,
        {
            "convention": (
                np.array(conv, dtype=STRING_DTYPE),
                {
                    "units": "1",
                    "long_name": "yaw convention: axis_tilted (velocity normal, axis "
                    "tilted by the yaw) or velocity_tilted (axis normal, velocity tilted)",
                },
            ),
            "velocity": (vals, PARAMETER_ATTRS["velocity"]),
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


def run_fig11(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    ds = trajectory_set(
        cfg["projectile"],
        c.target,
        "yaw",
        values(cfg["yaw_deg"]),
        velocity=float(cfg["velocity_m_s"]),
        obliquity=float(cfg["obliquity_deg"]),
        start=c.start,
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )
    ds.attrs["title"] = "Paper Fig. 11: trajectories of #4 at 30 deg with yaw -1 and +1"
    return ds


def run_fig13(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    return yaw_trajectories(
        cfg["projectile"],
        c.target,
        float(cfg["yaw_deg"]),
        values(cfg["velocities_m_s"]),
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )
