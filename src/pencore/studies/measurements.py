"""Validation against published measurements: shipped data files, measured against predicted.

Each data file is a CSV whose rows are single shots, each with its ``source`` (publication,
table, shot). A row gives the impact (``velocity_m_s``, ``obliquity_deg``, ``yaw_deg``)
and one measured quantity:

``measured_depth_m``
    penetration depth (m) into a semi-infinite target, compared with pencore's
    ``depth_measure`` (``path_length``: length of the nose-tip path below the surface,
    ``vertical_depth``: deepest point of the tip);
``measured_residual_velocity_m_s``
    residual velocity (m/s) after perforating a slab of ``thickness_m`` (m), compared with
    the ``residual_velocity`` of a ``perforated`` run (0 when the run does not perforate).

Projectile and target come from the file's entry in the configuration (the file names
neither when its source does not), or from optional ``projectile`` / ``target`` columns.

Only numbers read from a citable source belong in these files; none are filled in by
guess. What ships today: paper Table 2, the five soil shots of Forrestal & Luk (1992)
as the paper quotes them (``config/table2.csv``). Concrete depths (e.g. Forrestal et al.
1994; Frew et al. 1998) and perforation residual velocities (e.g. Hanchak et al. 1992)
could not be read from a source available to the project, so no file carries them;
a user who has the tables adds a file in this format and an entry in the config.

Error statistics (:func:`error_statistics`): relative error ``e = predicted / measured - 1``
per shot (shots measured at 0, e.g. no perforation, have only an absolute error); mean,
RMS and largest ``|e|``, and the mean with a 95 % Student-t interval.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore.errors import InputError
from pencore.inputs.library import get_target
from pencore.inputs.limits import check_keys
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.inputs.target import Target
from pencore.run.impact import prepare, simulate
from pencore.studies.common import t_half_width
from pencore.studies.perforation import slab_target

__all__ = [
    "QUANTITIES",
    "NEAR_SURFACE_KEYS",
    "load_measurements",
    "measured_vs_predicted",
    "error_statistics",
    "statistics_by_option",
]

#: Near-surface option keys of :func:`statistics_by_option` (calibers, calibers, ``c/a``).
NEAR_SURFACE_KEYS = ("crater_depth", "free_surface_depth", "plastic_zone_ratio")

#: Measured column -> (quantity name, units, long name).
QUANTITIES: dict[str, tuple[str, str, str]] = {
    "measured_depth_m": ("penetration_depth", "m", "penetration depth"),
    "measured_residual_velocity_m_s": ("residual_velocity", "m s-1", "residual velocity"),
}
REQUIRED = ("test", "velocity_m_s", "obliquity_deg", "yaw_deg", "source")
DEPTH_MEASURES = {"path_length": "path_length", "vertical_depth": "penetration_depth"}
ENTRY_KEYS = ("name", "csv", "projectile", "target", "depth_measure", "label")


def _entry(entry: Mapping[str, Any]) -> dict[str, Any]:
    if not isinstance(entry, Mapping):
        raise InputError(f"measurements entry must be a mapping, got {entry!r}")
    check_keys(entry, ENTRY_KEYS, "measurements entry")
    for k in ("name", "csv"):
        if not isinstance(entry.get(k), str) or not entry[k]:
            raise InputError(f"measurements entry needs a non-empty {k!r}, got {entry.get(k)!r}")
    e = {"depth_measure": "path_length", "label": entry["name"], **entry}
    if e["depth_measure"] not in DEPTH_MEASURES:
        raise InputError(
            f"measurements {e['name']}: depth_measure must be one of "
            f"{', '.join(DEPTH_MEASURES)}, got {e['depth_measure']!r}"
        )
    return e


def read_data_csv(path: str | Path, columns: Sequence[str], label: str) -> pd.DataFrame:
    """A data file (CSV, ``#`` comments) that exists, has ``columns`` and has rows.

    Raises
    ------
    InputError
        One line starting with ``label``: no such file, the columns it lacks, or no rows.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{label}: no such file {str(path)!r}")
    df = pd.read_csv(path, comment="#")
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise InputError(f"{label}: {path} lacks column(s) {missing}")
    if df.empty:
        raise InputError(f"{label}: {path} has no rows")
    return df


def load_measurements(entry: Mapping[str, Any]) -> pd.DataFrame:
    """Rows of one data file, checked, with ``projectile`` and ``target`` filled in.

    Parameters
    ----------
    entry : mapping
        ``name``, ``csv`` (path), and ``projectile`` / ``target`` (library names) unless
        the file has those columns; ``depth_measure`` (default ``path_length``).

    Returns
    -------
    pandas.DataFrame
        One row per shot with ``quantity`` (a :data:`QUANTITIES` name) and ``measured``.

    Raises
    ------
    InputError
        A missing file or column, a row with no or two measured values, a non-positive
        or non-finite number, or a row with no source; the message names the row.
    """
    e = _entry(entry)
    path = Path(e["csv"])
    df = read_data_csv(path, REQUIRED, f"measurements {e['name']}")
    qcols = [c for c in QUANTITIES if c in df.columns]
    rows = []
    for i, r in df.iterrows():
        where = f"measurements {e['name']} row {i + 1} (test {r['test']!r})"
        if not isinstance(r["source"], str) or not r["source"].strip():
            raise InputError(f"{where}: no source")
        given = [c for c in qcols if pd.notna(r[c])]
        if len(given) != 1:
            raise InputError(f"{where}: exactly one measured value needed, got {given or 'none'}")
        col = given[0]
        for c in ("velocity_m_s", "obliquity_deg", "yaw_deg", col):
            v = r[c]
            if not isinstance(v, (int, float, np.number)) or not math.isfinite(float(v)):
                raise InputError(f"{where}: {c} must be a finite number, got {v!r}")
        if float(r["velocity_m_s"]) <= 0 or float(r[col]) < 0:
            raise InputError(f"{where}: velocity must be > 0 and {col} >= 0")
        proj = r.get("projectile") if pd.notna(r.get("projectile", np.nan)) else e.get("projectile")
        targ = r.get("target") if pd.notna(r.get("target", np.nan)) else e.get("target")
        if not proj or not targ:
            raise InputError(f"{where}: no projectile/target (column or config entry)")
        thick = r.get("thickness_m", np.nan)
        if QUANTITIES[col][0] == "residual_velocity" and not (pd.notna(thick) and float(thick) > 0):
            raise InputError(f"{where}: a residual velocity needs thickness_m > 0")
        rows.append(
            {
                "shot": f"{e['name']}:{r['test']}",
                "dataset": e["name"],
                "label": e["label"],
                "projectile": str(proj),
                "target": str(targ),
                "thickness_m": float(thick) if pd.notna(thick) else math.inf,
                "velocity_m_s": float(r["velocity_m_s"]),
                "obliquity_deg": float(r["obliquity_deg"]),
                "yaw_deg": float(r["yaw_deg"]),
                "quantity": QUANTITIES[col][0],
                "measured": float(r[col]),
                "depth_measure": e["depth_measure"],
                "source": str(r["source"]),
            }
        )
    return pd.DataFrame(rows)


def _slab(target: str, thickness: float, options: Mapping[str, float] | None = None) -> Target:
    t = get_target(target)
    if math.isfinite(thickness):
        if len(t.layers) != 1:
            raise InputError(f"a slab of {target!r} needs a single-medium target")
        t = slab_target(target, thickness)
    if options:
        t = t.with_windows(**options)
    return t


def _predict(
    row: pd.Series, num: Numerics, cache: dict, options: Mapping[str, float] | None = None
) -> tuple[float, str]:
    key = (row["projectile"], row["target"], row["thickness_m"])
    if key not in cache:
        target = _slab(row["target"], row["thickness_m"], options)
        cache[key] = (target, prepare(row["projectile"], target, num))
    target, pr = cache[key]
    ds = simulate(
        row["projectile"],
        target,
        row["velocity_m_s"],
        row["obliquity_deg"],
        row["yaw_deg"],
        prepared=pr,
    )
    outcome = str(ds.attrs["outcome"])
    if row["quantity"] == "residual_velocity":
        return (float(ds.attrs["residual_velocity"]) if outcome == "perforated" else 0.0), outcome
    return float(ds[DEPTH_MEASURES[row["depth_measure"]]]), outcome


def error_statistics(measured: Sequence[float], predicted: Sequence[float]) -> dict[str, float]:
    """Error statistics of predicted against measured values.

    Returns ``n`` (rows), ``n_relative`` (rows with a measured value > 0, the only ones
    with a relative error: a measured residual velocity of 0 m/s is a shot that did not
    perforate), ``mean_abs_error`` (mean abs(predicted - measured), in the measured units),
    and over the relative errors ``e = predicted / measured - 1`` (dimensionless):
    ``mean_rel_error``, ``rms_rel_error``, ``max_abs_rel_error`` and the 95 % Student-t
    interval of the mean (``ci95_lo``, ``ci95_hi``; NaN for fewer than two values).
    """
    m, p = np.asarray(measured, float), np.asarray(predicted, float)
    if m.shape != p.shape or m.size == 0 or np.any(m < 0) or not np.all(np.isfinite(m)):
        raise InputError("error_statistics needs equal-length, finite, non-negative values")
    pos = m > 0
    e = p[pos] / m[pos] - 1.0
    n = e.size
    nan = math.nan
    mean = float(e.mean()) if n else nan
    half = t_half_width(e)
    return {
        "n": float(m.size),
        "n_relative": float(n),
        "mean_abs_error": float(np.mean(np.abs(p - m))),
        "mean_rel_error": mean,
        "rms_rel_error": float(np.sqrt(np.mean(e**2))) if n else nan,
        "max_abs_rel_error": float(np.max(np.abs(e))) if n else nan,
        "ci95_lo": mean - half,
        "ci95_hi": mean + half,
    }


def measured_vs_predicted(
    entries: Sequence[Mapping[str, Any]], numerics: Numerics | Mapping | None = None
) -> xr.Dataset:
    """Run every shot of every data file and compare with the measurement.

    Returns
    -------
    xarray.Dataset
        On dimension ``shot``: inputs, ``measured``, ``predicted``, ``rel_error``
        (predicted / measured - 1), ``outcome``, ``source``; per quantity (dimension
        ``quantity``) the :func:`error_statistics`.
    """
    if not entries:
        raise InputError("measurements: no data files configured")
    df = pd.concat([load_measurements(e) for e in entries], ignore_index=True)
    if df["shot"].duplicated().any():
        raise InputError(
            f"measurements: duplicate shots {sorted(df['shot'][df['shot'].duplicated()])}"
        )
    num = resolve_numerics(numerics)
    cache: dict = {}
    pred, outcome = zip(*(_predict(r, num, cache) for _, r in df.iterrows()), strict=True)
    df["predicted"], df["outcome"] = pred, outcome

    def a(units: str, long_name: str) -> dict[str, str]:
        return {"units": units, "long_name": long_name}

    def text(col: pd.Series | Sequence[str]) -> tuple[str, np.ndarray]:
        return ("shot", np.asarray(col).astype(str))

    units = df["quantity"].map({q: u for q, u, _ in QUANTITIES.values()})
    same = "(units: variable measured_units)"
    measured = df["measured"].to_numpy()
    rel = np.full(measured.shape, np.nan)
    rel[measured > 0] = df["predicted"].to_numpy()[measured > 0] / measured[measured > 0] - 1.0
    ds = xr.Dataset(
        {
            "velocity": ("shot", df["velocity_m_s"].to_numpy(), a("m s-1", "impact velocity")),
            "obliquity": ("shot", df["obliquity_deg"].to_numpy(), a("degree", "obliquity")),
            "yaw": ("shot", df["yaw_deg"].to_numpy(), a("degree", "yaw angle")),
            "thickness": (
                "shot",
                df["thickness_m"].to_numpy(),
                a("m", "target thickness (inf: half-space)"),
            ),
            "measured": ("shot", measured, {"long_name": f"measured value {same}"}),
            "predicted": ("shot", df["predicted"].to_numpy(), {"long_name": f"pencore {same}"}),
            "rel_error": ("shot", rel, a("1", "predicted / measured - 1 (NaN: measured 0)")),
            "measured_units": text(units),
            "quantity_of_shot": text(df["quantity"]),
            "dataset": text(df["dataset"]),
            "label": text(df["label"]),
            "projectile": text(df["projectile"]),
            "target": text(df["target"]),
            "depth_measure": text(df["depth_measure"]),
            "outcome": text(outcome),
            "source": text(df["source"]),
        },
        coords={"shot": df["shot"].to_numpy().astype(str)},
    )
    quantities = sorted(df["quantity"].unique())
    st = {}
    for q in quantities:
        sel = df["quantity"] == q
        st[q] = error_statistics(df["measured"][sel], df["predicted"][sel])
    for k in next(iter(st.values())):
        # the absolute error has the units of its quantity (variable measured_units), so
        # it carries no single CF units attribute; the other statistics are dimensionless
        attrs = (
            a("1", k.replace("_", " "))
            if k != "mean_abs_error"
            else {"long_name": f"mean |predicted - measured| {same}"}
        )
        ds[f"stat_{k}"] = ("quantity", [st[q][k] for q in quantities], attrs)
    ds = ds.assign_coords(quantity=("quantity", np.array(quantities, dtype=str)))
    ds.attrs.update(
        title="pencore against published measurements",
        entries_json=json.dumps([_entry(e) for e in entries], sort_keys=True),
        numerics_json=json.dumps(asdict(num), sort_keys=True),
    )
    return ds


def statistics_by_option(
    entries: Sequence[Mapping[str, Any]],
    options: Mapping[str, Mapping[str, float]],
    numerics: Numerics | Mapping | None = None,
) -> xr.Dataset:
    """Error statistics per near-surface option, material and kind of measurement.

    Every shot of every data file is run once per option set (``options``: name ->
    settings of :data:`NEAR_SURFACE_KEYS` applied to every medium of the target; ``{}``
    is the paper's model). Groups are ``material`` (the target's name) and ``quantity``
    (:data:`QUANTITIES`).

    Returns
    -------
    xarray.Dataset
        ``predicted`` and ``rel_error`` on ``(option, shot)``, ``measured`` on ``shot``,
        and the :func:`error_statistics` on ``(option, group)``, ``group`` labelled
        ``material/quantity``.
    """
    if not entries:
        raise InputError("measurements: no data files configured")
    if not options:
        raise InputError("statistics_by_option: no option sets (give at least 'none: {}')")
    for name, opt in options.items():
        bad = [k for k in opt if k not in NEAR_SURFACE_KEYS]
        if bad:
            raise InputError(
                f"option set {name!r}: unknown key(s) {bad}; use {list(NEAR_SURFACE_KEYS)}"
            )
    df = pd.concat([load_measurements(e) for e in entries], ignore_index=True)
    num = resolve_numerics(numerics)
    names = [str(n) for n in options]
    pred = np.empty((len(names), len(df)))
    for i, name in enumerate(names):
        cache: dict = {}
        opt = {k: float(v) for k, v in options[name].items()}
        for j, (_, r) in enumerate(df.iterrows()):
            pred[i, j] = _predict(r, num, cache, opt)[0]
    measured = df["measured"].to_numpy()
    rel = np.full(pred.shape, np.nan)
    pos = measured > 0
    rel[:, pos] = pred[:, pos] / measured[pos] - 1.0
    groups = sorted({f"{t}/{q}" for t, q in zip(df["target"], df["quantity"], strict=True)})
    key = np.array([f"{t}/{q}" for t, q in zip(df["target"], df["quantity"], strict=True)])
    stats: dict[str, np.ndarray] = {}
    for i in range(len(names)):
        for g, grp in enumerate(groups):
            sel = key == grp
            for k, v in error_statistics(measured[sel], pred[i, sel]).items():
                stats.setdefault(k, np.full((len(names), len(groups)), np.nan))[i, g] = v
    ds = xr.Dataset(
        {
            "measured": ("shot", measured, {"long_name": "measured value"}),
            "predicted": (("option", "shot"), pred, {"long_name": "pencore"}),
            "rel_error": (("option", "shot"), rel, {"units": "1", "long_name": "rel. error"}),
            "source": ("shot", df["source"].to_numpy().astype(str)),
            **{
                f"stat_{k}": (("option", "group"), v, {"long_name": k.replace("_", " ")})
                for k, v in stats.items()
            },
        },
        coords={
            "option": names,
            "shot": df["shot"].to_numpy().astype(str),
            "group": groups,
        },
    )
    ds.attrs.update(
        title="pencore against published measurements, per near-surface option",
        options_json=json.dumps({n: dict(options[n]) for n in names}, sort_keys=True),
        numerics_json=json.dumps(asdict(num), sort_keys=True),
    )
    return ds
