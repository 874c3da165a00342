"""From the workflow configuration to studies: running one study or one job part of it
(:func:`from_config`) and joining the parts (:func:`gather`), dispatched through the
records of :mod:`pencore.workflowconfig.registry`; the ``run_*`` functions those records
name read a study's configuration entry.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
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
from pencore.studies.parts import values as _values
from pencore.studies.trajectories import trajectory_set
from pencore.workflowconfig import registry

__all__ = [
    "StudySettings",
    "from_config",
    "gather",
    "run_fig7",
    "run_fig8",
    "run_fig9",
    "run_fig11",
    "run_fig12",
    "run_fig13",
    "run_fig15",
    "run_fig16",
    "run_start_height",
    "run_fig18",
]


def _range(d: Mapping[str, Any]) -> tuple[float, float]:
    lo, hi = float(d["min"]), float(d["max"])
    if not lo < hi:
        raise InputError(f"range needs min < max, got {dict(d)}")
    return lo, hi


@dataclass(frozen=True)
class StudySettings:
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


def run_fig7(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    return fig7(
        cfg["projectile"],
        c.target,
        float(cfg["obliquity_deg"]),
        _values(cfg["velocities_m_s"]),
        start=c.start,
        numerics=c.numerics,
        n_time=c.n_time,
    )


def run_fig8(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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


def run_fig9(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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


def run_fig11(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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


def run_fig12(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    if c.obliquity is None:
        raise InputError("Vcr against yaw runs per (projectile, obliquity): give obliquity=")
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


def run_fig13(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    return fig13(
        cfg["projectile"],
        c.target,
        float(cfg["yaw_deg"]),
        _values(cfg["velocities_m_s"]),
        numerics=c.numerics,
        n_time=c.n_time,
        speed_fraction=c.speed_fraction,
    )


def run_fig15(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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


def run_fig16(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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


def run_start_height(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
    return start_height_study(
        cfg["projectile"],
        c.target,
        float(cfg["velocity_m_s"]),
        _values(cfg["omega_rad_s"]),
        _values(cfg["start_heights_m"]),
        numerics=c.numerics,
        speed_fraction=c.speed_fraction,
    )


def run_fig18(cfg: Mapping[str, Any], c: StudySettings) -> xr.Dataset:
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
        The id of a record of :data:`pencore.workflowconfig.registry.STUDIES`; its
        ``run`` function runs it.
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
        The part of a split study (its record's ``split_by``) to run.
    """
    record = registry.study(study)
    if record.split_by and projectile is None:
        raise InputError(f"study {study!r} runs per projectile: give projectile=")
    if "obliquity" in record.split_by and obliquity is None:
        raise InputError(f"study {study!r} runs per (projectile, obliquity): give obliquity=")
    scan = shared.get("scan_points", 9)
    common = StudySettings(
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
    return registry.resolve(record.run)(cfg, common)


def gather(study: str, parts: Sequence[xr.Dataset]) -> xr.Dataset:
    """Join the parts of a split study (its record's ``split_by`` not empty) into one
    dataset.

    Parts may come in any order; projectiles keep their first-seen order, obliquities are
    sorted.
    """
    record = registry.study(study)
    if not record.split_by:
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
        if "obliquity" in record.split_by:
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
