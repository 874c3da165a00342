"""Fig. 9: the total turning angle d(theta)_12 against Lc/L."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore import analysis
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import simulate
from pencore.studies.common import (
    PROJECTILES,
    STRING_DTYPE,
    axis_values,
    projectile_coords,
    start_point,
    var_attrs,
)
from pencore.studies.config import StudySettings
from pencore.studies.trajectories.stack import stack_trajectories
from pencore.workflowconfig.parts import values

__all__ = ["turning_angle_study", "run_fig9"]


def turning_angle_study(
    projectiles: Sequence[str] = PROJECTILES,
    target: str = "soil",
    *,
    obliquity: float = 45.0,
    velocity: float = 1000.0,
    start: Sequence[float] | None = (-1.0, 1.0, 0.0),
    fractions: Sequence[float] = (0.01, 0.02, 0.05, 0.1),
    numerics: Numerics | Mapping[str, Any] | None = None,
    n_time: int = 500,
) -> xr.Dataset:
    """Paper Fig. 9: total turning angle d(theta)_12 = theta_2 - theta_1 against Lc/L.

    Points 1 and 2 by :func:`pencore.analysis.turning.turning_angle` (``bracket`` method) for
    each fraction of the peak curvature in ``fractions`` (dimension
    ``bracket_fraction``), and by the ``sign_change`` method (``delta_theta_sign_change``),
    so the reader sees how much the definition moves the number. Trajectories on
    ``(projectile, time)``.
    """
    names = list(projectiles)
    fr = axis_values(fractions, "fractions")
    num = resolve_numerics(numerics)
    runs = {}
    keys = ("delta_theta", "theta_1", "theta_2", "x_1", "y_1", "x_2", "y_2")
    out = {k: np.full((len(names), fr.size), np.nan) for k in keys}
    reason = np.full((len(names), fr.size), "", dtype=STRING_DTYPE)
    sign = np.full(len(names), np.nan)
    for ip, p in enumerate(names):
        run = simulate(p, target, velocity, obliquity, start=start_point(start), numerics=num)
        runs[(ip,)] = run
        for jf, f in enumerate(fr):
            ta = analysis.turning_angle(run, fraction=float(f))
            for k in keys:
                out[k][ip, jf] = getattr(ta, k)
            reason[ip, jf] = ta.reason
        sign[ip] = analysis.turning_angle(run, method="sign_change").delta_theta
    pc = projectile_coords(names)
    ds = stack_trajectories(
        runs, {"projectile": (pc["projectile"][1], pc["projectile"][2])}, n_time=n_time
    )
    d2 = ("projectile", "bracket_fraction")
    long = {
        "delta_theta": ("degree", "total turning angle theta_2 - theta_1 (Eq. 12)"),
        "theta_1": ("degree", "axis angle from the normal at Point 1"),
        "theta_2": ("degree", "axis angle from the normal at Point 2"),
        "x_1": ("m", "centre of mass x at Point 1"),
        "y_1": ("m", "centre of mass y at Point 1"),
        "x_2": ("m", "centre of mass x at Point 2"),
        "y_2": ("m", "centre of mass y at Point 2"),
    }
    for k in keys:
        ds[k] = (d2, out[k], var_attrs(*long[k]))
    ds["turning_angle_note"] = (d2, reason, {"units": "1", "long_name": "why delta_theta is NaN"})
    ds["delta_theta_sign_change"] = (
        "projectile",
        sign,
        var_attrs("degree", "theta_2 - theta_1 between the first and last sign changes of d2y/dx2"),
    )
    ds = ds.assign_coords(
        lc_over_l=("projectile", pc["lc_over_l"][1], pc["lc_over_l"][2]),
        bracket_fraction=(
            "bracket_fraction",
            fr,
            var_attrs("1", "fraction of the peak |curvature| that marks Points 1 and 2"),
        ),
    )
    ds.attrs.pop("projectile", None)
    ds.attrs.pop("lc_over_l", None)
    ds.attrs.update(
        {
            "title": "Paper Fig. 9: total turning angle against L_c/L",
            "obliquity_deg": float(obliquity),
            "velocity_m_s": float(velocity),
            "start_m": "surface contact at x = 0" if start is None else str(list(start)),
            "primary_bracket_fraction": analysis.DEFAULT_BRACKET_FRACTION,
        }
    )
    return ds


def run_fig9(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    """Run the study from its configuration entry ``cfg`` and the shared ``c`` (its
    record in :mod:`pencore.workflowconfig.registry` names this function)."""
    return turning_angle_study(
        list(cfg["projectiles"]),
        c.target,
        obliquity=float(cfg["obliquity_deg"]),
        velocity=float(cfg["velocity_m_s"]),
        start=c.start,
        fractions=values(cfg["bracket_fractions"]),
        numerics=c.numerics,
        n_time=c.n_time,
    )
