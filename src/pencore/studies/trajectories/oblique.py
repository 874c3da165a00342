"""Fig. 7: trajectories of projectile #2 at 45 deg for velocities around Vcr."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.inputs.numerics import Numerics
from pencore.studies.common import STRING_DTYPE, var_attrs
from pencore.studies.config import StudySettings
from pencore.studies.trajectories.stack import trajectory_set
from pencore.workflowconfig.parts import values

__all__ = ["oblique_trajectories", "run_fig7"]


def oblique_trajectories(
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

    Dims ``(velocity, time)``. Besides the variables of
    :func:`~pencore.studies.trajectories.stack.stack_trajectories`: ``x_linear``
    (x of the centre of mass where the curved part ends, Point 2 of Eq. 12 by
    :func:`pencore.analysis.turning.turning_angle`) and ``delta_theta``.
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
    reason = np.empty(vals.size, dtype=STRING_DTYPE)
    for i in range(vals.size):
        ta = analysis.turning_angle(runs[(i,)], fraction=bracket_fraction)
        x2[i], dth[i], reason[i] = ta.x_2, ta.delta_theta, ta.reason
    ds["x_linear"] = (
        "velocity",
        x2,
        var_attrs(
            "m",
            "centre of mass x where the curved part of the path ends (Point 2, "
            f"|curvature| below {bracket_fraction:g} of its peak)",
        ),
    )
    ds["delta_theta"] = (
        "velocity",
        dth,
        var_attrs("degree", "total turning angle theta_2 - theta_1 (Eq. 12)"),
    )
    ds["turning_angle_note"] = (
        "velocity",
        reason,
        {"units": "1", "long_name": "why delta_theta is NaN (empty when defined)"},
    )
    ds.attrs["title"] = "Paper Fig. 7: trajectories at 45 deg obliquity around Vcr"
    return ds


def run_fig7(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    return oblique_trajectories(
        cfg["projectile"],
        c.target,
        float(cfg["obliquity_deg"]),
        values(cfg["velocities_m_s"]),
        start=c.start,
        numerics=c.numerics,
        n_time=c.n_time,
    )
