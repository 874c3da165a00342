"""Figs 16-17: normal impact with an initial angular velocity, and how alpha moves with
the unstated start height.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, simulate
from pencore.studies.common import (
    PARAMETER_ATTRS,
    STRING_DTYPE,
    axis_values,
    numerics_record,
    start_from_height,
    var_attrs,
)
from pencore.studies.config import StudySettings
from pencore.studies.trajectories.stack import trajectory_set
from pencore.workflowconfig.parts import values

__all__ = ["spin_trajectories", "start_height_study", "run_fig16", "run_start_height"]


def spin_trajectories(
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
    hs = axis_values(heights, "heights")
    om = axis_values(omegas, "omegas")
    num = resolve_numerics(numerics)
    pr = prepare(projectile, target, num)
    shape = (hs.size, om.size)
    alpha = np.full(shape, np.nan)
    alpha_s = np.full(shape, np.nan)
    th_c = np.full(shape, np.nan)
    rev = np.zeros(shape, dtype=np.int8)
    out = np.empty(shape, dtype=STRING_DTYPE)
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
                var_attrs(
                    "degree",
                    "trajectory deviation from the normal alpha (final deviation)",
                    speed_fraction=float(speed_fraction),
                ),
            ),
            "alpha_signed": (
                dims,
                alpha_s,
                var_attrs("degree", "signed in-plane final deviation (positive towards +x)"),
            ),
            "theta_at_contact": (
                dims,
                th_c,
                var_attrs(
                    "degree", "axis angle from the normal at first contact (free-flight rotation)"
                ),
            ),
            "reversed": (dims, rev, var_attrs("1", "1 if the run turned back towards the surface")),
            "outcome": (dims, out, {"units": "1", "long_name": "how the run ended"}),
        },
        coords={
            "start_height": (
                "start_height",
                hs,
                var_attrs("m", "height of the nose tip above the surface at t = 0 (0: touching)"),
            ),
            "omega": ("omega", om, PARAMETER_ATTRS["omega"]),
        },
        attrs={
            "title": "Figs 16-17: sensitivity of alpha to the start height (not in the paper)",
            "projectile": projectile,
            "target": target,
            "velocity_m_s": float(velocity),
            "numerics_json": json.dumps(numerics_record(num)),
            "Conventions": "CF-1.8",
        },
    )


def run_fig16(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    return spin_trajectories(
        cfg["projectile"],
        c.target,
        float(cfg["velocity_m_s"]),
        values(cfg["omega_rad_s"]),
        start_height=c.start_height,
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )


def run_start_height(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    return start_height_study(
        cfg["projectile"],
        c.target,
        float(cfg["velocity_m_s"]),
        values(cfg["omega_rad_s"]),
        values(cfg["start_heights_m"]),
        numerics=c.numerics,
        speed_fraction=c.speed_fraction,
    )
