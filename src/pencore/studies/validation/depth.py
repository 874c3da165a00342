"""Validation and verification studies of the paper's Section 3.

* :func:`~pencore.studies.validation.table2.table2` (code in
  :mod:`pencore.studies.validation.table2`) - the five soil tests of
  Forrestal & Luk (1992) (paper Table 2), run with every candidate projectile and both
  depth measures; the candidate closest to the paper's predicted column is selected and
  reported.
* :func:`fig5` - penetration depth against impact velocity into concrete and aluminium
  (paper Fig. 5), with both closed forms beside it and the measured shots of the sources
  (each run at its measured impact by :mod:`pencore.studies.validation.measurements`).
* :func:`verification` - pencore against :func:`pencore.closedform.depth` for normal,
  frictionless impact over a velocity range (verification, not validation).

Units: SI (m, m/s); angles in degrees as in the paper's tables.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
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
from pencore.measured.shots import read_body_shot_table, read_shot_table
from pencore.run.impact import prepare, simulate
from pencore.studies.common import var_attrs

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
                var_attrs("m", "pencore penetration depth (deepest point of the nose tip)"),
            ),
            "pencore_path_length": (
                ("case", "velocity"),
                path,
                var_attrs("m", "pencore length of the nose-tip path below the surface"),
            ),
            "closedform_depth": (
                ("case", "velocity"),
                cf,
                var_attrs(
                    "m",
                    "closed-form depth for normal frictionless impact "
                    "(exact nose entry + tunnel phase, pencore.closedform.depth)",
                ),
            ),
            "rel_diff": (
                ("case", "velocity"),
                rel,
                var_attrs("1", "(pencore - closed form) / closed form"),
            ),
        },
        coords={
            "case": (
                "case",
                np.array([c["name"] for c in cases], dtype=object),
                {"long_name": "case"},
            ),
            "velocity": ("velocity", velocities, var_attrs("m s-1", "impact velocity V_i")),
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
                var_attrs("1", "calibre radius head of the ogive nose (0.5: hemisphere)"),
            ),
            "mass": (
                "case",
                np.array([get_projectile(c["projectile"]).mass_properties().mass for c in cases]),
                var_attrs("kg", "projectile mass"),
            ),
            "diameter": (
                "case",
                np.array([get_projectile(c["projectile"]).diameter for c in cases]),
                var_attrs("m", "shank diameter"),
            ),
        },
        attrs={
            "Conventions": "CF-1.8",
            "numerics_json": json.dumps(asdict(numerics), sort_keys=True),
        },
    )


# ----------------------------------------------------------------------------- Fig. 5


def fig5(
    cases: Iterable[Mapping[str, Any]] | Mapping[str, Mapping[str, Any]],
    velocities: Sequence[float],
    numerics: Numerics | Mapping[str, Any] | None = None,
    *,
    shots: Sequence[str | Path] = (),
    body_shots: Mapping[str | Path, Mapping[str, str]] | None = None,
) -> xr.Dataset:
    """Penetration depth against impact velocity (paper Fig. 5), with the measured shots.

    Parameters
    ----------
    cases : sequence of mappings
        ``{name, projectile, target, v_min?, v_max?, label?}`` (see :func:`normalise_cases`).
    velocities : sequence of float
        Impact velocities (m/s), shared by all cases; each case runs those within its
        ``[v_min, v_max]``, the rest are NaN.
    numerics : Numerics or mapping, optional
    shots : sequence of paths
        Shot tables (:func:`pencore.measured.shots.read_shot_table`); every shot's
        projectile must be the projectile of at least one case. The shots are drawn, not
        run here: :func:`pencore.studies.validation.measurements.measured_vs_predicted` runs each at
        its measured impact.
    body_shots : mapping, optional
        Body shot tables (:func:`pencore.measured.shots.read_body_shot_table`): path -> {set:
        library projectile of the case that draws the set's shots}. Drawn, not run here
        (:func:`pencore.studies.validation.measurements.measured_vs_predicted` runs them).

    Returns
    -------
    xarray.Dataset
        On ``(case, velocity)``: ``pencore_depth``, ``pencore_path_length``,
        ``closedform_depth`` (exact nose entry), ``cavity_form_depth`` (full nose force from
        contact: :func:`pencore.closedform.tunnel_depth` from the impact speed, the form of
        Piekutowski et al. 1999, Eq. 1) and ``rel_diff``; on ``experiment`` the measured
        shots (``experiment_shot``, ``experiment_projectile``, ``experiment_velocity``,
        ``experiment_depth`` (NaN where the source prints none), ``experiment_rigid``,
        ``experiment_remark``, ``experiment_source``).

    Raises
    ------
    InputError
        A bad case, velocity or shot table, or a shot whose projectile no case draws.
    """
    cs = normalise_cases(cases)
    v = _velocity_axis(velocities)
    num = resolve_numerics(numerics)
    ds = _depth_grid(cs, v, num)
    cavity = np.full(ds["closedform_depth"].shape, np.nan)
    density = np.full(len(cs), np.nan)
    for ic, c in enumerate(cs):
        proj, medium = get_projectile(c["projectile"]), _half_space_medium(c["target"])
        density[ic] = medium.density
        for iv, vel in enumerate(v):
            if c["v_min"] <= vel <= c["v_max"]:
                cavity[ic, iv] = closedform.tunnel_depth(proj, medium, float(vel))
    ds["cavity_form_depth"] = (
        ("case", "velocity"),
        cavity,
        var_attrs(
            "m",
            "closed-form depth with the full nose force from first contact "
            "(pencore.closedform.tunnel_depth; Piekutowski et al. 1999, Eq. 1)",
        ),
    )
    ds = ds.assign_coords(
        target_density=("case", density, var_attrs("kg m-3", "target density (NaN: not given)"))
    )
    tables = [read_shot_table(f) for f in shots]
    tables += [_body_shots(f, sets) for f, sets in (body_shots or {}).items()]
    table = (
        pd.concat(tables, ignore_index=True)
        if tables
        else pd.DataFrame(columns=["test", "projectile", "velocity_m_s", "measured_depth_m"])
    )
    drawn = {c["projectile"] for c in cs}
    stray = sorted(set(table["projectile"]) - drawn)
    if stray:
        raise InputError(
            f"Fig. 5 shots of projectile(s) {stray} match no case; cases draw {sorted(drawn)}"
        )

    def col(name: str, dtype: Any = object) -> np.ndarray:
        return np.asarray(table[name] if name in table else [], dtype=dtype)

    ds["experiment_shot"] = ("experiment", col("test").astype(str).astype(object))
    ds["experiment_shot"].attrs["long_name"] = "shot id as printed by its source"
    ds["experiment_projectile"] = (
        "experiment",
        col("projectile"),
        {"long_name": "library projectile of the shot"},
    )
    ds["experiment_velocity"] = (
        "experiment",
        col("velocity_m_s", float),
        var_attrs("m s-1", "measured striking velocity"),
    )
    ds["experiment_depth"] = (
        "experiment",
        col("measured_depth_m", float),
        var_attrs("m", "measured penetration depth (NaN: none printed)"),
    )
    ds["experiment_rigid"] = (
        "experiment",
        col("rigid", bool).astype(np.int8),
        {
            "long_name": "1: rigid by its authors' limits, 0: deformed or eroded",
            "flag_values": np.array([0, 1], dtype=np.int8),
            "flag_meanings": "not_rigid rigid",
        },
    )
    ds["experiment_remark"] = ("experiment", col("remark"), {"long_name": "authors' remark"})
    ds["experiment_source"] = (
        "experiment",
        col("source"),
        {"long_name": "publication, table and page of the shot"},
    )
    ds.attrs.update(
        title="Paper Fig. 5: penetration depth against impact velocity, concrete and "
        "aluminium targets",
        n_experiments=int(table.shape[0]),
        note="Aluminium: the measured rods and shots of Piekutowski et al. (1999) and "
        "Forrestal & Piekutowski (2000); the paper's Table 1 law ('aluminium') and its "
        "source's three-term law ('aluminium_3term'). Concrete: the paper's Table 1 law "
        "and the measured 12.9 mm, 0.064 kg rods into 13.5 MPa grout (Forrestal et al. 1996 "
        "via a secondary compilation, config/concrete_ogive_shots.csv).",
    )
    return ds


def _body_shots(path: str | Path, sets: Mapping[str, str]) -> pd.DataFrame:
    """The shots of ``sets`` (set -> library projectile) of a body shot table, in the form
    of :func:`pencore.measured.shots.read_shot_table` (normal impact, rigid as compiled)."""
    df = read_body_shot_table(path)
    unknown = sorted(set(sets) - set(df["set"]))
    if unknown:
        raise InputError(f"Fig. 5 body shots: no set(s) {unknown} in {str(path)!r}")
    df = df[df["set"].isin(list(sets))]
    return pd.DataFrame(
        {
            "test": df["row"].to_numpy(),
            "projectile": df["set"].map(dict(sets)).to_numpy(),
            "velocity_m_s": df["striking_velocity_m_s"].to_numpy(),
            "measured_depth_m": df["depth_m"].to_numpy(),
            "rigid": True,
            "remark": "normal impact; rigid as compiled (no deformation recorded)",
            "source": (df["reference"] + "; compilation row " + df["row"]).to_numpy(),
        }
    )


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
        var_attrs("1", "largest |pencore - closed form| / closed form over velocity"),
    )
    ds["max_abs_rel_diff"] = (
        (),
        float(absrel[ic, iv]),
        var_attrs(
            "1", "largest |pencore - closed form| / closed form over all cases and velocities"
        ),
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
