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
from pencore.studies.common import _STR, _attrs, _axis, start_from_height
from pencore.studies.fig08_vcr import _numerics_dict
from pencore.studies.trajectories import _PARAM_ATTRS, trajectory_set

__all__ = ["fig16", "start_height_study"]


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
            "Conventions": "CF-1.8",
        },
    )
