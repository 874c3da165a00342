"""Validation and verification studies of the paper's Section 3.

* :func:`table2` (code in :mod:`pencore.studies.table2`) - the five soil tests of
  Forrestal & Luk (1992) (paper Table 2), run with every candidate projectile and both
  depth measures; the candidate closest to the paper's predicted column is selected and
  reported.
* :func:`fig5` - penetration depth against impact velocity into concrete and aluminium
  (paper Fig. 5), with the closed-form depth beside it and experimental points when
  supplied.
* :func:`verification` - pencore against :func:`pencore.closedform.depth` for normal,
  frictionless impact over a velocity range (verification, not validation).

Units: SI (m, m/s); angles in degrees as in the paper's tables.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore import closedform
from pencore.errors import InputError
from pencore.inputs.geometry import OgiveNose
from pencore.inputs.library import get_projectile, get_target
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.inputs.target import Medium
from pencore.run.impact import prepare, simulate
from pencore.studies.common import _attrs

__all__ = [
    "fig5",
    "verification",
    "verification_summary",
    "normalise_cases",
    "velocity_grid",
]


# ----------------------------------------------------------------------------- cases


def normalise_cases(
    cases: Iterable[Mapping[str, Any]] | Mapping[str, Mapping[str, Any]],
) -> list[dict[str, Any]]:
    """Cases as a list of dicts with ``name, projectile, target, v_min, v_max, label``.

    ``cases`` is a sequence of mappings (``name`` optional, defaulting to the projectile
    name) or a mapping ``name -> {projectile, target, ...}``. ``v_min`` / ``v_max`` (m/s)
    limit the velocities run for that case (default: all).
    """
    if isinstance(cases, Mapping):
        items = [{"name": k, **dict(v)} for k, v in cases.items()]
    else:
        items = [dict(c) for c in cases]
    out: list[dict[str, Any]] = []
    for k, c in enumerate(items):
        for key in ("projectile", "target"):
            if key not in c:
                raise InputError(f"case {k} ({c.get('name', '?')!r}) lacks {key!r}")
        name = str(c.get("name") or c["projectile"])
        v_min = c.get("v_min")
        v_max = c.get("v_max")
        out.append(
            {
                "name": name,
                "projectile": str(c["projectile"]),
                "target": str(c["target"]),
                "v_min": 0.0 if v_min is None else float(v_min),
                "v_max": math.inf if v_max is None else float(v_max),
                "label": str(c.get("label") or name),
            }
        )
    names = [c["name"] for c in out]
    if len(set(names)) != len(names):
        raise InputError(f"case names must be unique, got {names}")
    if not out:
        raise InputError("no cases given")
    return out


def velocity_grid(min: float, max: float, n: int) -> np.ndarray:
    """``n`` impact velocities (m/s) evenly spaced from ``min`` to ``max`` inclusive."""
    lo, hi, n = float(min), float(max), int(n)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 < lo < hi):
        raise InputError(f"velocity range needs 0 < min < max (m/s), got min={lo}, max={hi}")
    if n < 2:
        raise InputError(f"velocity range needs n >= 2, got {n}")
    return np.linspace(lo, hi, n)


def _half_space_medium(target: str) -> Medium:
    t = get_target(target)
    if len(t.layers) != 1 or math.isfinite(t.layers[0].thickness):
        raise InputError(f"closed form needs a homogeneous half-space; {target!r} is layered")
    return t.medium


def _crh(projectile: str) -> float:
    nose = get_projectile(projectile).nose
    return float(nose.crh) if isinstance(nose, OgiveNose) else math.nan


def _velocity_axis(velocities: Sequence[float]) -> np.ndarray:
    v = np.asarray(velocities, dtype=float).ravel()
    if v.size == 0 or not np.all(np.isfinite(v)) or np.any(v <= 0):
        raise InputError(f"velocities must be positive numbers of m/s, got {list(v)}")
    return np.unique(v)


def _depth_grid(
    cases: list[dict[str, Any]], velocities: np.ndarray, numerics: Numerics
) -> xr.Dataset:
    """pencore and closed-form depth on (case, velocity); NaN outside a case's range."""
    pen = np.full((len(cases), velocities.size), np.nan)
    path = np.full_like(pen, np.nan)
    cf = np.full_like(pen, np.nan)
    for ic, c in enumerate(cases):
        pr = prepare(c["projectile"], c["target"], numerics)
        medium = _half_space_medium(c["target"])
        proj = get_projectile(c["projectile"])
        for iv, v in enumerate(velocities):
            if not (c["v_min"] <= v <= c["v_max"]):
                continue
            ds = simulate(c["projectile"], c["target"], float(v), prepared=pr)
            pen[ic, iv] = float(ds["penetration_depth"])
            path[ic, iv] = float(ds["path_length"])
            cf[ic, iv] = closedform.depth(proj, medium, float(v))
    rel = (pen - cf) / cf
    return xr.Dataset(
        {
            "pencore_depth": (
                ("case", "velocity"),
                pen,
                _attrs("m", "pencore penetration depth (deepest point of the nose tip)"),
            ),
            "pencore_path_length": (
                ("case", "velocity"),
                path,
                _attrs("m", "pencore length of the nose-tip path below the surface"),
            ),
            "closedform_depth": (
                ("case", "velocity"),
                cf,
                _attrs(
                    "m",
                    "closed-form depth for normal frictionless impact "
                    "(exact nose entry + tunnel phase, pencore.closedform.depth)",
                ),
            ),
            "rel_diff": (
                ("case", "velocity"),
                rel,
                _attrs("1", "(pencore - closed form) / closed form"),
            ),
        },
        coords={
            "case": (
                "case",
                np.array([c["name"] for c in cases], dtype=object),
                {"long_name": "case"},
            ),
            "velocity": ("velocity", velocities, _attrs("m s-1", "impact velocity V_i")),
            "projectile": (
                "case",
                np.array([c["projectile"] for c in cases], dtype=object),
                {"long_name": "projectile"},
            ),
            "target": (
                "case",
                np.array([c["target"] for c in cases], dtype=object),
                {"long_name": "target"},
            ),
            "label": (
                "case",
                np.array([c["label"] for c in cases], dtype=object),
                {"long_name": "legend label"},
            ),
            "crh": (
                "case",
                np.array([_crh(c["projectile"]) for c in cases]),
                _attrs("1", "calibre radius head of the ogive nose (0.5: hemisphere)"),
            ),
            "mass": (
                "case",
                np.array([get_projectile(c["projectile"]).mass_properties().mass for c in cases]),
                _attrs("kg", "projectile mass"),
            ),
            "diameter": (
                "case",
                np.array([get_projectile(c["projectile"]).diameter for c in cases]),
                _attrs("m", "shank diameter"),
            ),
        },
        attrs={
            "Conventions": "CF-1.8",
            "numerics_json": json.dumps(asdict(numerics), sort_keys=True),
        },
    )


# ----------------------------------------------------------------------------- Fig. 5

FIG5_EXPERIMENT_COLUMNS = ("target", "projectile", "velocity_m_s", "depth_m", "source")


def fig5(
    cases: Iterable[Mapping[str, Any]] | Mapping[str, Mapping[str, Any]],
    velocities: Sequence[float],
    numerics: Numerics | Mapping[str, Any] | None = None,
    *,
    experiments: pd.DataFrame | None = None,
) -> xr.Dataset:
    """Penetration depth against impact velocity (paper Fig. 5).

    Parameters
    ----------
    cases : sequence of mappings
        ``{name, projectile, target, v_min?, v_max?, label?}`` (see :func:`normalise_cases`).
    velocities : sequence of float
        Impact velocities (m/s), shared by all cases; each case runs those within its
        ``[v_min, v_max]``, the rest are NaN.
    numerics : Numerics or mapping, optional
    experiments : pandas.DataFrame, optional
        Measured points with columns ``target, projectile, velocity_m_s, depth_m, source``;
        may be empty. Each point must match a case by (projectile, target); pencore is
        also run at each point's velocity.

    Returns
    -------
    xarray.Dataset
        ``pencore_depth``, ``pencore_path_length``, ``closedform_depth``, ``rel_diff`` on
        ``(case, velocity)``; and on ``experiment`` the measured points
        (``experiment_case``, ``experiment_velocity``, ``experiment_depth``,
        ``experiment_source``, ``experiment_pencore_depth``, ``experiment_rel_diff``).
    """
    cs = normalise_cases(cases)
    v = _velocity_axis(velocities)
    num = resolve_numerics(numerics)
    ds = _depth_grid(cs, v, num)

    exp = (
        experiments
        if experiments is not None
        else pd.DataFrame(columns=list(FIG5_EXPERIMENT_COLUMNS))
    )
    missing = [c for c in FIG5_EXPERIMENT_COLUMNS if c not in exp.columns]
    if missing:
        raise InputError(f"experiments lack column(s) {', '.join(missing)}")
    by_key = {(c["projectile"], c["target"]): c["name"] for c in cs}
    e_case, e_v, e_d, e_src, e_pen = [], [], [], [], []
    prepared: dict[str, Any] = {}
    for k, row in exp.reset_index(drop=True).iterrows():
        key = (str(row["projectile"]), str(row["target"]))
        if key not in by_key:
            raise InputError(
                f"experiment row {k}: (projectile, target) = {key} matches no Fig. 5 case; "
                f"cases: {sorted(by_key)}"
            )
        vel = float(row["velocity_m_s"])
        if not (math.isfinite(vel) and vel > 0):
            raise InputError(f"experiment row {k}: velocity must be > 0 m/s, got {vel!r}")
        name = by_key[key]
        if name not in prepared:
            prepared[name] = prepare(key[0], key[1], num)
        sim = simulate(key[0], key[1], vel, prepared=prepared[name])
        e_case.append(name)
        e_v.append(vel)
        e_d.append(float(row["depth_m"]))
        e_src.append(str(row["source"]))
        e_pen.append(float(sim["penetration_depth"]))
    e_d_arr = np.asarray(e_d, dtype=float)
    e_pen_arr = np.asarray(e_pen, dtype=float)
    ds["experiment_case"] = (
        "experiment",
        np.asarray(e_case, dtype=object),
        {"long_name": "Fig. 5 case of the measured point"},
    )
    ds["experiment_velocity"] = (
        "experiment",
        np.asarray(e_v, dtype=float),
        _attrs("m s-1", "measured impact velocity"),
    )
    ds["experiment_depth"] = ("experiment", e_d_arr, _attrs("m", "measured penetration depth"))
    ds["experiment_source"] = (
        "experiment",
        np.asarray(e_src, dtype=object),
        {"long_name": "provenance: paper, derived or assumed"},
    )
    ds["experiment_pencore_depth"] = (
        "experiment",
        e_pen_arr,
        _attrs("m", "pencore depth at the measured impact velocity"),
    )
    with np.errstate(divide="ignore", invalid="ignore"):
        ds["experiment_rel_diff"] = (
            "experiment",
            (e_pen_arr - e_d_arr) / e_d_arr,
            _attrs("1", "(pencore - measured) / measured"),
        )
    ds.attrs.update(
        title="Paper Fig. 5: penetration depth against impact velocity, concrete and "
        "aluminium targets",
        n_experiments=len(e_case),
        note="Projectiles are assumed (the paper's text does not give them) until the "
        "published geometry and points are supplied; experimental points come from the "
        "experiments CSV.",
    )
    return ds


# ----------------------------------------------------------------------------- verification


def verification(
    cases: Iterable[Mapping[str, Any]] | Mapping[str, Mapping[str, Any]],
    velocities: Sequence[float],
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """pencore against the closed form (:func:`pencore.closedform.depth`), normal impact.

    Returns the depth grid of :func:`fig5` (without experiments) plus
    ``case_max_abs_rel_diff(case)`` and the scalar ``max_abs_rel_diff``, the largest
    ``|pencore - closed form| / closed form`` over all cases and velocities, with the
    case and velocity where it occurs in the attributes.
    """
    cs = normalise_cases(cases)
    v = _velocity_axis(velocities)
    num = resolve_numerics(numerics)
    ds = _depth_grid(cs, v, num)
    absrel = np.abs(ds["rel_diff"].values)
    if not np.isfinite(absrel).any():
        raise InputError("no velocity falls inside any case's [v_min, v_max]")
    case_max = np.nanmax(np.where(np.isfinite(absrel), absrel, -np.inf), axis=1)
    case_max = np.where(np.isfinite(case_max), case_max, np.nan)
    ic, iv = np.unravel_index(int(np.nanargmax(absrel)), absrel.shape)
    ds["case_max_abs_rel_diff"] = (
        "case",
        case_max,
        _attrs("1", "largest |pencore - closed form| / closed form over velocity"),
    )
    ds["max_abs_rel_diff"] = (
        (),
        float(absrel[ic, iv]),
        _attrs("1", "largest |pencore - closed form| / closed form over all cases and velocities"),
    )
    ds.attrs.update(
        title="Verification: pencore against the closed form, normal frictionless impact",
        max_abs_rel_diff_case=str(ds["case"].values[ic]),
        max_abs_rel_diff_velocity_m_s=float(v[iv]),
    )
    return ds


def verification_summary(ds: xr.Dataset) -> str:
    """Text table of :func:`verification` results (one line per case, then the maximum)."""
    lines = [f"{'case':20s} {'projectile':18s} {'target':10s} {'max |rel diff|':>14s}"]
    for c in ds["case"].values:
        sub = ds.sel(case=c)
        lines.append(
            f"{c!s:20s} {sub['projectile'].item()!s:18s} {sub['target'].item()!s:10s} "
            f"{float(sub['case_max_abs_rel_diff']):14.3e}"
        )
    lines.append(
        f"largest |pencore - closed form| / closed form = {float(ds['max_abs_rel_diff']):.3e} "
        f"({ds.attrs['max_abs_rel_diff_case']}, "
        f"V = {ds.attrs['max_abs_rel_diff_velocity_m_s']:g} m/s)"
    )
    return "\n".join(lines)
