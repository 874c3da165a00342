"""Ballistic-limit maps and the obliquity ratio against measured oblique ballistic limits.

:func:`ballistic_map` searches the ballistic limit ``V_bl`` of one projectile against plates
of one medium on a grid of thickness (in projectile calibers, ``t/d``) and obliquity, once
per near-surface option (none, the crater, the finite-sphere free surface, pencore's ramp,
...), and records beside it the line-of-sight rule of plate design: an oblique plate acts
as a normal plate of the line-of-sight thickness ``t sec(theta)``, and for a plate whose
ballistic limit grows linearly with thickness that is ``V_bl(theta) = V_bl(0) sec(theta)``
(the ratio drawn beside the map).

:func:`compare_obliquity` reads measured ballistic limits at normal and oblique incidence
(``config/oblique_ballistic_limits.csv``: each row with its source and where it was read)
and compares the measured obliquity ratio ``V50(theta) / V50(0)`` of each series with
pencore's ratio at the same ``t/d`` (linear interpolation between the map's thickness
columns; rows outside the map get NaN) and with ``sec(theta)``. None of the measured
plates or projectiles is in pencore's library (6082, 2060, 6055, 7017, 7085 aluminium,
and a steel; APM2 bullets and cores), so pencore's ratio is that of an analog -- the
library's 7.11 mm CRH-3 steel rod in the library aluminium law -- and the comparison is of
the shape of ``V_bl(theta)``, not of its level. Statistics per material class and per
option (:func:`pencore.analysis.errors.error_statistics` on the ratio).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore.analysis.errors import error_statistics
from pencore.errors import InputError, SolverError
from pencore.inputs.library import get_projectile
from pencore.inputs.limits import half_space_plates
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.measured.shots import read_data_csv
from pencore.search.perforation import ballistic_limit
from pencore.search.threshold import CriticalResult
from pencore.studies.common import search_grid, search_variables, var_attrs
from pencore.studies.perforation.slabs import slab_target

__all__ = [
    "OPTION_KEYS",
    "load_oblique",
    "ballistic_map",
    "compare_obliquity",
    "obliquity_summary",
]

#: Near-surface option keys an option set may give (calibers, calibers, ``c/a``).
OPTION_KEYS = ("crater_depth", "free_surface_depth", "plastic_zone_ratio")
COLUMNS = (
    "series",
    "material",
    "plate_thickness_m",
    "projectile",
    "projectile_diameter_m",
    "obliquity_deg",
    "measured_v_bl_m_s",
    "source",
    "read_in",
)


def load_oblique(csv: str | Path) -> pd.DataFrame:
    """Rows of a measured oblique ballistic-limit file, checked.

    Raises
    ------
    InputError
        A missing file or column, a non-positive number, a row without source or
        ``read_in``, or a series without its 0 deg row; the message names the row.
    """
    df = read_data_csv(csv, COLUMNS, "oblique ballistic limits")
    for i, r in df.iterrows():
        where = f"oblique ballistic limits row {i + 1} (series {r['series']!r})"
        for c in ("source", "read_in"):
            if not isinstance(r[c], str) or not r[c].strip():
                raise InputError(f"{where}: no {c}")
        for c in ("plate_thickness_m", "projectile_diameter_m", "measured_v_bl_m_s"):
            v = r[c]
            if not isinstance(v, (int, float, np.number)) or not float(v) > 0:
                raise InputError(f"{where}: {c} must be a number > 0, got {v!r}")
        if not 0.0 <= float(r["obliquity_deg"]) < 90.0:
            got = r["obliquity_deg"]
            raise InputError(f"{where}: obliquity_deg must be in [0, 90), got {got!r}")
    normal = df[df["obliquity_deg"] == 0.0].set_index("series")
    lacking = sorted(set(df["series"]) - set(normal.index))
    if lacking:
        raise InputError(f"oblique ballistic limits: series without a 0 deg row: {lacking}")
    if normal.index.duplicated().any():
        raise InputError("oblique ballistic limits: a series has two 0 deg rows")
    df = df.copy()
    df["t_over_d"] = df["plate_thickness_m"] / df["projectile_diameter_m"]
    df["measured_ratio"] = df["measured_v_bl_m_s"] / df["series"].map(normal["measured_v_bl_m_s"])
    return df


def _option_sets(options: Mapping[str, Mapping[str, float]]) -> dict[str, dict[str, float]]:
    if not options:
        raise InputError("obliquity study: no option sets (give at least 'none: {}')")
    out = {}
    for name, opt in options.items():
        if not isinstance(opt, Mapping):
            raise InputError(f"option set {name!r} must be a mapping, got {opt!r}")
        bad = [k for k in opt if k not in OPTION_KEYS]
        if bad:
            raise InputError(f"option set {name!r}: unknown key(s) {bad}; use {OPTION_KEYS}")
        out[str(name)] = {k: float(v) for k, v in opt.items()}
    return out


def ballistic_map(
    projectile: str,
    medium: str,
    t_over_d: Sequence[float],
    obliquities: Sequence[float],
    options: Mapping[str, Mapping[str, float]],
    *,
    lo: float = 50.0,
    hi: float = 3000.0,
    tol: float = 2.0,
    scan: int | None = 5,
    numerics: Numerics | Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """``V_bl`` (m/s) on ``(option, t_over_d, obliquity deg)`` with the line-of-sight rule.

    ``t_over_d`` are plate thicknesses in calibers of ``projectile``; ``options`` maps a
    name to near-surface settings (:data:`OPTION_KEYS`; ``{}`` is the paper's model).
    Adds ``v_bl_los`` (the option's normal-incidence ``V_bl`` times ``sec(theta)``) and
    ``ratio`` (``V_bl(theta) / V_bl(0)``). A cell whose search hit a solver failure has
    status ``solver_error``, NaN values and the error in ``message``.
    """
    sets = _option_sets(options)
    d = get_projectile(projectile).diameter
    tod = np.asarray([float(x) for x in t_over_d])
    obl = np.asarray([float(x) for x in obliquities])
    if tod.size == 0 or obl.size == 0 or obl[0] != 0.0:
        raise InputError("ballistic_map needs thicknesses and obliquities starting at 0 deg")
    num = resolve_numerics(numerics)
    maps = []
    for name, opt in sets.items():
        res = search_grid((tod.size, obl.size), "the ballistic map (thicknesses x obliquities)")
        for i, x in enumerate(tod):
            t = slab_target(medium, float(x * d), **opt)
            for j, o in enumerate(obl):
                try:
                    with half_space_plates():  # option "none": the half-space law, on purpose
                        r = ballistic_limit(
                            projectile, t, float(o), lo=lo, hi=hi, tol=tol, scan=scan,
                            numerics=num,
                        )  # fmt: skip
                    res[i, j] = r
                    message = r.message if r.status == "solver_error" else None
                except SolverError as exc:
                    message = str(exc)
                if message is not None:
                    # a run of the search failed (e.g. a rebound chattering on the face):
                    # the cell is recorded as failed, not guessed, and (as the map has
                    # always recorded it) without the evaluations made before the failure
                    res[i, j] = CriticalResult(
                        math.nan, math.nan, math.nan, 0, True, "solver_error", message, (), tol
                    )
        dims = ("t_over_d", "obliquity")
        ds = xr.Dataset(
            search_variables(
                res, "v_bl", "m s-1", "ballistic limit (lowest speed that perforates)", dims
            ),  # fmt: skip
            coords={"t_over_d": tod, "obliquity": obl},
        )
        ds = ds[["v_bl", "v_bl_lo", "v_bl_hi", "status", "n_evals", "message"]]
        maps.append(ds.expand_dims(option=[name]))
    out = xr.concat(maps, dim="option")
    sec = 1.0 / np.cos(np.radians(obl))
    v0 = out["v_bl"].sel(obliquity=0.0)
    out["v_bl_los"] = v0 * xr.DataArray(sec, dims="obliquity", coords={"obliquity": obl})
    out["v_bl_los"].attrs = var_attrs("m s-1", "line-of-sight rule: V_bl(0) sec(obliquity)")
    out["ratio"] = out["v_bl"] / v0
    out["ratio"].attrs = var_attrs("1", "V_bl(obliquity) / V_bl(0)")
    out["t_over_d"].attrs = var_attrs("1", "plate thickness in projectile calibers")
    out["obliquity"].attrs = var_attrs("degree", "obliquity: shot line from the plate normal")
    out["option"].attrs = {"long_name": "near-surface option set"}
    out.attrs = {
        "title": "pencore ballistic-limit map with the line-of-sight rule",
        "projectile": projectile,
        "medium": medium,
        "diameter_m": float(d),
        "options_json": json.dumps(sets, sort_keys=True),
        "search_tol_m_s": float(tol),
        "numerics_json": json.dumps(num.__dict__, sort_keys=True, default=str),
    }
    return out


def combine_maps(parts: Sequence[xr.Dataset]) -> xr.Dataset:
    """One map from maps of single option sets (:func:`ballistic_map` run per option, as
    the workflow's parallel jobs do): concatenated on ``option``, in the order given, with
    the option sets of all of them in ``options_json``. Every part must share the grid,
    projectile, medium and numerics."""
    if not parts:
        raise InputError("combine_maps needs at least one map")
    keys = ("projectile", "medium", "diameter_m", "search_tol_m_s", "numerics_json")
    first = parts[0]
    for part in parts[1:]:
        for key in keys:
            if part.attrs.get(key) != first.attrs.get(key):
                raise InputError(f"maps differ in {key}: cannot combine them")
    out = xr.concat(list(parts), dim="option")
    sets: dict[str, Any] = {}
    for part in parts:
        sets.update(json.loads(part.attrs["options_json"]))
    out.attrs = {**first.attrs, "options_json": json.dumps(sets, sort_keys=True)}
    return out


def compare_obliquity(rows: pd.DataFrame, bl_map: xr.Dataset) -> xr.Dataset:
    """Measured obliquity ratios against pencore's (per option) and ``sec(theta)``.

    Oblique rows only (the 0 deg rows define the ratio). pencore's ratio is interpolated
    linearly in ``t/d`` between the map's columns at the row's obliquity, which must be
    one of the map's; NaN outside the map's ``t/d`` range.
    """
    obl = rows[rows["obliquity_deg"] > 0.0].reset_index(drop=True)
    if obl.empty:
        raise InputError("compare_obliquity: no oblique rows")
    grid = bl_map["t_over_d"].values
    options = [str(o) for o in bl_map["option"].values]
    pred = np.full((len(options), len(obl)), np.nan)
    for j, r in obl.iterrows():
        th = float(r["obliquity_deg"])
        if th not in bl_map["obliquity"].values:
            raise InputError(f"compare_obliquity: obliquity {th} deg is not on the map")
        x = float(r["t_over_d"])
        if grid.min() <= x <= grid.max():
            for i, o in enumerate(options):
                col = bl_map["ratio"].sel(option=o, obliquity=th).values
                pred[i, j] = float(np.interp(x, grid, col))
    sec = 1.0 / np.cos(np.radians(obl["obliquity_deg"].to_numpy()))
    meas = obl["measured_ratio"].to_numpy()
    text = {k: ("row", obl[k].astype(str).to_numpy()) for k in
            ("series", "material", "projectile", "source", "read_in")}  # fmt: skip
    ds = xr.Dataset(
        {
            **text,
            "obliquity": ("row", obl["obliquity_deg"].to_numpy(), var_attrs("degree", "obliquity")),
            "t_over_d": ("row", obl["t_over_d"].to_numpy(), var_attrs("1", "thickness / diameter")),
            "measured_v_bl": (
                "row",
                obl["measured_v_bl_m_s"].to_numpy(),
                var_attrs("m s-1", "measured ballistic limit"),
            ),  # fmt: skip
            "measured_ratio": ("row", meas, var_attrs("1", "measured V50(theta) / V50(0)")),
            "los_ratio": ("row", sec, var_attrs("1", "line-of-sight rule sec(theta)")),
            "pencore_ratio": (
                ("option", "row"),
                pred,
                var_attrs("1", "pencore V_bl(theta)/V_bl(0)"),
            ),
        },
        coords={"row": np.arange(len(obl)), "option": options},
    )
    classes = {"aluminium": obl["material"].str.startswith("AA").to_numpy()}
    classes["steel"] = ~classes["aluminium"]
    classes["all"] = np.ones(len(obl), dtype=bool)
    names = ["line_of_sight", *options]
    stats: dict[str, list[float]] = {}
    groups = list(classes)
    for model in names:
        for g in groups:
            sel = classes[g].copy()
            p = sec if model == "line_of_sight" else pred[options.index(model)]
            sel &= np.isfinite(p)
            st = (
                error_statistics(meas[sel], p[sel])
                if sel.any()
                else dict.fromkeys(error_statistics([1.0], [1.0]), math.nan)
            )
            for k, v in st.items():
                stats.setdefault(k, []).append(v)
    shape = (len(names), len(groups))
    for k, v in stats.items():
        long_name = f"{k.replace('_', ' ')} of the obliquity ratio"
        ds[f"stat_{k}"] = (
            ("model", "material_class"),
            np.asarray(v).reshape(shape),
            var_attrs("1", long_name),
        )
    ds = ds.assign_coords(model=names, material_class=groups)
    # after assign_coords, which rebuilds the indexes' variables without their attributes
    for name, attrs in (
        ("row", var_attrs("1", "oblique row of the measurements file (0-based)")),
        ("option", {"long_name": "near-surface option set"}),
        ("model", {"long_name": "model of the obliquity ratio"}),
        ("material_class", {"long_name": "plate material class"}),
    ):
        ds[name].attrs = attrs
    ds.attrs = {
        "title": "measured obliquity ratios against pencore and the line-of-sight rule",
        "analog": f"{bl_map.attrs['projectile']} into {bl_map.attrs['medium']}",
        "map_options_json": bl_map.attrs["options_json"],
    }
    return ds


def obliquity_summary(cmp: xr.Dataset) -> str:
    """A Markdown table of the ratio statistics per model and material class."""
    lines = [
        "| model | material | n | mean rel. error | RMS rel. error | max abs rel. error |",
        "|---|---|---|---|---|---|",
    ]
    for m in cmp["model"].values:
        for g in cmp["material_class"].values:
            s = cmp.sel(model=m, material_class=g)
            n = float(s["stat_n"])
            if not n > 0:
                continue
            lines.append(
                f"| {m} | {g} | {n:.0f} | {float(s['stat_mean_rel_error']):+.3f} | "
                f"{float(s['stat_rms_rel_error']):.3f} | {float(s['stat_max_abs_rel_error']):.3f} |"
            )
    return "\n".join(lines)
