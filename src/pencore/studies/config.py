"""From the workflow configuration to studies: running one study or one job part of it
(:func:`~pencore.studies.config.from_config`) and joining the parts
(:func:`~pencore.studies.config.gather`), dispatched through the
records of :mod:`pencore.workflowconfig.registry`; each record names the ``run_*`` function,
beside its study's physics, that reads the study's configuration entry.
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
from pencore.workflowconfig import registry

__all__ = ["StudySettings", "from_config", "gather"]


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
