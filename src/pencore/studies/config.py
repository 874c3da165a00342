"""From the workflow configuration to studies: which studies exist, how they split into
job parts, running one part (:func:`~pencore.studies.config.from_config`) and joining parts
(:func:`~pencore.studies.config.gather`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import xarray as xr

from pencore import analysis
from pencore.errors import InputError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.search.threshold import OMEGA_TOL, VELOCITY_TOL
from pencore.studies.common import combine
from pencore.studies.fig07_trajectories import fig7
from pencore.studies.fig08_vcr import fig8, vcr_study
from pencore.studies.fig09_turning_angle import fig9
from pencore.studies.fig13_yaw import fig13
from pencore.studies.fig15_vci import vci_study
from pencore.studies.fig16_spin import fig16, start_height_study
from pencore.studies.fig18_omega_c import omega_c_study
from pencore.studies.parts import SPLIT_STUDIES, STUDIES
from pencore.studies.parts import values as _values
from pencore.studies.trajectories import trajectory_set

__all__ = ["REGISTRY", "from_config", "gather"]


def _range(d: Mapping[str, Any]) -> tuple[float, float]:
    lo, hi = float(d["min"]), float(d["max"])
    if not lo < hi:
        raise InputError(f"range needs min < max, got {dict(d)}")
    return lo, hi


@dataclass(frozen=True)
class _Common:
    """What every study reads from the block's shared keys and its own entry (SI units)."""

    target: str
    n_time: int
    speed_fraction: float
    velocity_tol: float
    omega_tol: float
    scan: int | None
    start_height: float
    numerics: Numerics
    start: Any
    projectile: str | None
    obliquity: float | None
    yaw_convention: str


def _fig7(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    return fig7(
        cfg["projectile"],
        c.target,
        float(cfg["obliquity_deg"]),
        _values(cfg["velocities_m_s"]),
        start=c.start,
        numerics=c.numerics,
        n_time=c.n_time,
    )


def _fig8(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    lo, hi = _range(cfg["velocity_range_m_s"])
    return fig8(
        [c.projectile],
        _values(cfg["obliquity_deg"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.velocity_tol,
        scan=c.scan,
        start=c.start,
        numerics=c.numerics,
        low_speeds=_values(cfg.get("low_velocities_m_s", [])),
    )


def _fig9(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    return fig9(
        list(cfg["projectiles"]),
        c.target,
        obliquity=float(cfg["obliquity_deg"]),
        velocity=float(cfg["velocity_m_s"]),
        start=c.start,
        fractions=_values(cfg["bracket_fractions"]),
        numerics=c.numerics,
        n_time=c.n_time,
    )


def _fig11(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    ds = trajectory_set(
        cfg["projectile"],
        c.target,
        "yaw",
        _values(cfg["yaw_deg"]),
        velocity=float(cfg["velocity_m_s"]),
        obliquity=float(cfg["obliquity_deg"]),
        start=c.start,
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )
    ds.attrs["title"] = "Paper Fig. 11: trajectories of #4 at 30 deg with yaw -1 and +1"
    return ds


def _fig12(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    if c.obliquity is None:
        raise InputError("study 'fig12' runs per (projectile, obliquity): give obliquity=")
    lo, hi = _range(cfg["velocity_range_m_s"])
    ds = vcr_study(
        [c.projectile],
        [float(c.obliquity)],
        _values(cfg["yaw_deg"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.velocity_tol,
        scan=c.scan,
        start=c.start,
        numerics=c.numerics,
        nose=True,
        low_speeds=_values(cfg.get("low_velocities_m_s", [])),
    )
    ds.attrs["title"] = "Paper Figs 11-12: V_cr against yaw, final nose direction"
    return ds


def _fig13(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    return fig13(
        cfg["projectile"],
        c.target,
        float(cfg["yaw_deg"]),
        _values(cfg["velocities_m_s"]),
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )


def _fig15(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    lo, hi = _range(cfg["velocity_range_m_s"])
    ths = sorted(set(_values(cfg["thresholds_deg"])) | {float(cfg["threshold_deg"])})
    return vci_study(
        [c.projectile],
        _values(cfg["yaw_deg"]),
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


def _fig16(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    return fig16(
        cfg["projectile"],
        c.target,
        float(cfg["velocity_m_s"]),
        _values(cfg["omega_rad_s"]),
        start_height=c.start_height,
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )


def _start_height(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    return start_height_study(
        cfg["projectile"],
        c.target,
        float(cfg["velocity_m_s"]),
        _values(cfg["omega_rad_s"]),
        _values(cfg["start_heights_m"]),
        numerics=c.numerics,
        speed_fraction=c.speed_fraction,
    )


def _fig18(cfg: Mapping[str, Any], c: _Common) -> xr.Dataset:
    lo, hi = _range(cfg["omega_range_rad_s"])
    return omega_c_study(
        [c.projectile],
        _values(cfg["velocities_m_s"]),
        target=c.target,
        lo=lo,
        hi=hi,
        tol=c.omega_tol,
        scan=c.scan,
        start_height=c.start_height,
        numerics=c.numerics,
    )


#: Study name -> the function that runs it from (its config entry, the common values).
#: Adding a study: a function here, its name in :data:`pencore.studies.parts.STUDIES`.
REGISTRY: dict[str, Callable[[Mapping[str, Any], _Common], xr.Dataset]] = {
    "fig7": _fig7,
    "fig8": _fig8,
    "fig9": _fig9,
    "fig11": _fig11,
    "fig12": _fig12,
    "fig13": _fig13,
    "fig15": _fig15,
    "fig16": _fig16,
    "start_height": _start_height,
    "fig18": _fig18,
}


def from_config(
    study: str,
    cfg: Mapping[str, Any],
    shared: Mapping[str, Any],
    numerics: Numerics | Mapping[str, Any] | None = None,
    *,
    projectile: str | None = None,
    obliquity: float | None = None,
) -> xr.Dataset:
    """Run one study (or one part of a split study) from its configuration entries.

    Parameters
    ----------
    study : str
        One of :data:`~pencore.studies.parts.STUDIES` (each run by its entry of :data:`REGISTRY`).
    cfg : mapping
        The study's entry of the ``section4`` configuration block (keys as in
        ``config/config.yaml``; units in the key names).
    shared : mapping
        The block's shared keys (``target``, ``velocity_tol_m_s``, ``omega_tol_rad_s``,
        ``scan_points``, ``trajectory_samples``, ``speed_fraction``, ``yaw_convention``,
        ``start_height_m``); only those the study uses are read.
    numerics : Numerics or mapping, optional
        Overrides of pencore's numerical defaults.
    projectile, obliquity
        The part of a split study (:data:`~pencore.studies.parts.SPLIT_STUDIES`) to run.
    """
    if study not in STUDIES:
        raise InputError(f"unknown Section 4 study {study!r}; known: {', '.join(STUDIES)}")
    if study in SPLIT_STUDIES and projectile is None:
        raise InputError(f"study {study!r} runs per projectile: give projectile=")
    scan = shared.get("scan_points", 9)
    common = _Common(
        target=shared.get("target", "soil"),
        n_time=int(shared.get("trajectory_samples", 500)),
        speed_fraction=float(shared.get("speed_fraction", analysis.DEFAULT_SPEED_FRACTION)),
        velocity_tol=float(shared.get("velocity_tol_m_s", VELOCITY_TOL)),
        omega_tol=float(shared.get("omega_tol_rad_s", OMEGA_TOL)),
        scan=None if scan is None else int(scan),
        start_height=float(shared.get("start_height_m", 0.0)),
        numerics=resolve_numerics(numerics),
        start=cfg.get("start_m"),
        projectile=projectile,
        obliquity=obliquity,
        yaw_convention=shared.get("yaw_convention", "axis_tilted"),
    )
    return REGISTRY[study](cfg, common)


def gather(study: str, parts: Sequence[xr.Dataset]) -> xr.Dataset:
    """Join the parts of a split study (:data:`~pencore.studies.parts.SPLIT_STUDIES`) into one
    dataset.

    Parts may come in any order; projectiles keep their first-seen order, obliquities are
    sorted.
    """
    if study not in SPLIT_STUDIES:
        raise InputError(f"{study!r} is not split into parts")
    parts = list(parts)
    if not parts:
        raise InputError("no parts to gather")
    projs = list(dict.fromkeys(str(p["projectile"].values[0]) for p in parts))
    by_p: dict[str, list[xr.Dataset]] = {p: [] for p in projs}
    for p in parts:
        by_p[str(p["projectile"].values[0])].append(p)
    rows = []
    for p in projs:
        ps = by_p[p]
        if study == "fig12":
            ps = sorted(ps, key=lambda d: float(d["obliquity"].values[0]))
            rows.append(combine(ps, "obliquity") if len(ps) > 1 else ps[0])
        else:
            if len(ps) != 1:
                raise InputError(f"{len(ps)} parts for projectile {p}; expected 1")
            rows.append(ps[0])
    out = combine(rows, "projectile") if len(rows) > 1 else rows[0]
    for k in ("study", "config_json", "config_sha256", "created_utc", "git_commit", "git_dirty"):
        out.attrs.pop(k, None)
    return out
