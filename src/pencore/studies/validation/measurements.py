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
An entry may name several targets (``targets``: the same medium under different laws);
every shot is then run once per target, and the statistics are kept per law.

A *shot table* (:data:`pencore.measured.shots.SHOT_COLUMNS`, read by
:func:`pencore.measured.shots.read_shot_table`, which maps the measured angles of attack to
pencore's impact angles) is the other accepted form: the shots of a penetration paper as it
prints them, at normal incidence. Shots flagged not rigid are run and kept, but left out of
the statistics (the model is of a rigid body).

Beside pencore's 3-D run, every depth shot gets two closed forms of the same law at the
striking speed, normal incidence, no yaw: :func:`pencore.closedform.depth` (the model's
exact 1-D depth, nose entry included) and :func:`pencore.closedform.tunnel_depth` from
the striking speed (the cavity-expansion literature's form, with the full nose force
from first contact: Piekutowski et al. 1999, Eq. 1, and Forrestal & Piekutowski 2000 use
it). 3-D against the exact closed form is the solver's and the angles' share of the
error; the exact closed form against the literature's is the nose entry's; the
literature's form against the measurement is the law's.

Only numbers read from a citable source belong in these files; none are filled in by
guess. What ships: paper Table 2, the five soil shots of Forrestal & Luk (1992) as the
paper quotes them (``config/table2.csv``), and the aluminium shots of Piekutowski et al.
(1999) and Forrestal & Piekutowski (2000) read from the papers' tables
(``config/aluminium_*_shots.csv``). A user who has another table adds a file in one of
these forms and an entry in the config.

Error statistics (:func:`pencore.analysis.errors.error_statistics`): relative error
``e = predicted / measured - 1`` per shot (shots measured at 0, e.g. no perforation, have
only an absolute error); mean, RMS and largest ``|e|``, and the mean with a 95 % Student-t
interval. The validation summary (:func:`summary`) gives, per data set and law, the rigid
shots' mean ``|e|``, bias (mean ``e``) and worst ``e`` of pencore and of both closed forms.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore import closedform
from pencore.analysis.errors import relative_errors, sample_statistics, summary_statistics
from pencore.errors import InputError, TargetError
from pencore.inputs.library import get_projectile, get_target
from pencore.inputs.limits import check_keys, half_space_plates
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.inputs.target import Target
from pencore.measured.shots import BODY_SHOT_COLUMNS, SHOT_COLUMNS, read_data_csv, shot_table
from pencore.run.impact import prepare, simulate
from pencore.studies.perforation.slabs import slab_target
from pencore.studies.validation.bodies import body_rows

__all__ = [
    "QUANTITIES",
    "NEAR_SURFACE_KEYS",
    "MODELS",
    "load_measurements",
    "measured_vs_predicted",
    "summary",
    "summary_table",
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
ENTRY_KEYS = (
    "name",
    "csv",
    "projectile",
    "target",
    "targets",
    "laws",
    "depth_measure",
    "label",
)

#: Predictions compared with each depth shot in :func:`summary`: variable -> label.
MODELS = {
    "predicted": "pencore (3-D, measured angles)",
    "closedform_depth": "closed form, exact nose entry",
    "cavity_form_depth": "closed form, full nose force from contact",
    "forrestal_form_depth": "Forrestal's closed form, crater of 2 calibers",
}


def _entry(entry: Mapping[str, Any]) -> dict[str, Any]:
    if not isinstance(entry, Mapping):
        raise InputError(f"measurements entry must be a mapping, got {entry!r}")
    check_keys(entry, ENTRY_KEYS, "measurements entry")
    for k in ("name", "csv"):
        if not isinstance(entry.get(k), str) or not entry[k]:
            raise InputError(f"measurements entry needs a non-empty {k!r}, got {entry.get(k)!r}")
    e = {"depth_measure": "path_length", "label": entry["name"], **entry}
    if "targets" in e:
        t = e["targets"]
        if "target" in e:
            raise InputError(f"measurements {e['name']}: give target or targets, not both")
        if (
            not isinstance(t, Sequence)
            or isinstance(t, str)
            or not t
            or not all(isinstance(x, str) and x for x in t)
            or len(set(t)) != len(t)
        ):
            raise InputError(
                f"measurements {e['name']}: targets must be a non-empty list of distinct "
                f"target names, got {t!r}"
            )
    if e["depth_measure"] not in DEPTH_MEASURES:
        raise InputError(
            f"measurements {e['name']}: depth_measure must be one of "
            f"{', '.join(DEPTH_MEASURES)}, got {e['depth_measure']!r}"
        )
    return e


def _is_body_table(e: Mapping[str, Any]) -> bool:
    """Whether the entry's file is a body shot table (:data:`BODY_SHOT_COLUMNS`): shots
    whose rods and targets are given by measured properties."""
    df = read_data_csv(e["csv"], (), f"measurements {e['name']}")
    body = set(BODY_SHOT_COLUMNS) <= set(df.columns)
    if not body and "laws" in e:
        raise InputError(f"measurements {e['name']}: laws apply to a body shot table only")
    return body


def _read_rows(e: Mapping[str, Any]) -> pd.DataFrame:
    """The entry's file in the common form (a shot table by
    :func:`pencore.measured.shots.shot_table`), read once."""
    label = f"measurements {e['name']}"
    df = read_data_csv(e["csv"], (), label)
    shots = "striking_velocity_m_s" in df.columns
    missing = [c for c in (SHOT_COLUMNS if shots else REQUIRED) if c not in df.columns]
    if missing:
        raise InputError(f"{label}: {e['csv']} lacks column(s) {missing}")
    if shots:
        return shot_table(df, label)
    return df.assign(
        pitch_measured_deg=np.nan,
        yaw_measured_deg=np.nan,
        rigid=True,
        remark="",
        unmeasured=False,
    )


def load_measurements(entry: Mapping[str, Any]) -> pd.DataFrame:
    """Rows of one data file, checked, with ``projectile`` and ``target`` filled in.

    Parameters
    ----------
    entry : mapping
        ``name``, ``csv`` (path), and ``projectile`` / ``target`` (library names) unless
        the file has those columns, or ``targets`` (a list: every shot once per target);
        ``depth_measure`` (default ``path_length``).

    Returns
    -------
    pandas.DataFrame
        One row per shot (and target) with ``quantity`` (a :data:`QUANTITIES` name),
        ``measured``, ``rigid`` and the measured angles of attack (NaN where the file
        has none).

    Raises
    ------
    InputError
        A missing file or column, a row with no or two measured values, a non-positive
        or non-finite number, or a row with no source; the message names the row.
    """
    e = _entry(entry)
    if _is_body_table(e):
        return body_rows(e)
    df = _read_rows(e)
    qcols = [c for c in QUANTITIES if c in df.columns]
    targets = e.get("targets") or [None]
    rows = []
    for i, r in df.iterrows():
        where = f"measurements {e['name']} row {i + 1} (test {r['test']!r})"
        if not isinstance(r["source"], str) or not r["source"].strip():
            raise InputError(f"{where}: no source")
        given = [c for c in qcols if pd.notna(r[c])]
        if r["unmeasured"]:
            given = ["measured_depth_m"]
        if len(given) != 1:
            raise InputError(f"{where}: exactly one measured value needed, got {given or 'none'}")
        col = given[0]
        checked = ("velocity_m_s", "obliquity_deg", "yaw_deg")
        for c in checked if r["unmeasured"] else (*checked, col):
            v = r[c]
            if not isinstance(v, (int, float, np.number)) or not math.isfinite(float(v)):
                raise InputError(f"{where}: {c} must be a finite number, got {v!r}")
        if float(r["velocity_m_s"]) <= 0 or float(r[col]) < 0:  # NaN passes: unmeasured
            raise InputError(f"{where}: velocity must be > 0 and {col} >= 0")
        proj = r.get("projectile") if pd.notna(r.get("projectile", np.nan)) else e.get("projectile")
        for tgt in targets:
            targ = tgt or (
                r.get("target") if pd.notna(r.get("target", np.nan)) else e.get("target")
            )
            if not proj or not targ:
                raise InputError(f"{where}: no projectile/target (column or config entry)")
            thick = r.get("thickness_m", np.nan)
            if QUANTITIES[col][0] == "residual_velocity" and not (
                pd.notna(thick) and float(thick) > 0
            ):
                raise InputError(f"{where}: a residual velocity needs thickness_m > 0")
            shot = f"{e['name']}:{r['test']}" if tgt is None else f"{e['name']}:{tgt}:{r['test']}"
            rows.append(
                {
                    "shot": shot,
                    "dataset": e["name"],
                    "label": e["label"],
                    "projectile": str(proj),
                    "target": str(targ),
                    "thickness_m": float(thick) if pd.notna(thick) else math.inf,
                    "velocity_m_s": float(r["velocity_m_s"]),
                    "obliquity_deg": float(r["obliquity_deg"]),
                    "yaw_deg": float(r["yaw_deg"]),
                    "pitch_measured_deg": float(r["pitch_measured_deg"]),
                    "yaw_measured_deg": float(r["yaw_measured_deg"]),
                    "rigid": bool(r["rigid"]),
                    "remark": str(r["remark"]),
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
    body = _body(row)
    key = (row["projectile"], row["target_key"] if body else row["target"], row["thickness_m"])
    if key not in cache:
        if body:
            t = row["target_body"]
            try:
                target = t.with_windows(**options) if options else t
                cache[key] = (target, prepare(row["projectile_body"], target, num))
            except TargetError as err:
                if not options:
                    raise
                # an option this rod cannot take (a crater shorter than its nose)
                cache[key] = (None, f"option not applicable: {err}")
        else:
            target = _slab(row["target"], row["thickness_m"], options)
            with half_space_plates():  # the measured plates, with each option and with none
                cache[key] = (target, prepare(row["projectile"], target, num))
    target, pr = cache[key]
    if target is None:
        return math.nan, pr
    ds = simulate(
        row["projectile_body"] if body else row["projectile"],
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


def _body(row: pd.Series) -> bool:
    """Whether the row is a body shot (its projectile and target built, not named)."""
    return isinstance(row.get("target_body"), Target)


def _closed_forms(row: pd.Series, cache: dict) -> tuple[float, float, float]:
    """The closed-form depths (m) of a depth shot into a half-space at its striking speed
    (normal incidence, no yaw): exact nose entry, full nose force from contact, and (body
    shots only) Forrestal's form with its crater region of two calibers
    (:func:`pencore.closedform.forrestal_crater_depth`, k = 2). NaN for other quantities,
    finite targets, or laws the closed forms do not cover."""
    nan3 = (math.nan, math.nan, math.nan)
    if row["quantity"] != "penetration_depth" or math.isfinite(row["thickness_m"]):
        return nan3
    body = _body(row)
    if body:
        proj, medium, single = row["projectile_body"], row["target_body"].layers[0].medium, True
    else:
        key = (row["projectile"], row["target"])
        if key not in cache:
            layers = get_target(row["target"]).layers
            cache[key] = (get_projectile(row["projectile"]), layers[0].medium, len(layers) == 1)
        proj, medium, single = cache[key]
    if not single:
        return nan3
    v = row["velocity_m_s"]
    try:
        exact = closedform.depth(proj, medium, v), closedform.tunnel_depth(proj, medium, v)
    except ValueError:  # friction, higher terms, near-surface options: no closed form
        return nan3
    crater = math.nan
    if body:
        try:
            crater = closedform.forrestal_crater_depth(proj, medium, v)
        except ValueError:  # a nose longer than the crater's two calibers (CRH > 4.25)
            pass
    return (*exact, crater)


def measured_vs_predicted(
    entries: Sequence[Mapping[str, Any]], numerics: Numerics | Mapping | None = None
) -> xr.Dataset:
    """Run every shot of every data file and compare with the measurement.

    Parameters
    ----------
    entries : sequence of mappings
        Data files (see :func:`load_measurements`).
    numerics : Numerics or mapping, optional
        Solver settings for every run.

    Returns
    -------
    xarray.Dataset
        On dimension ``shot``: inputs, ``measured``, ``predicted``, ``rel_error``
        (predicted / measured - 1), ``outcome``, ``source``, ``rigid``, the measured
        angles of attack, the two closed-form depths (:data:`MODELS`) and their relative
        errors; per quantity (dimension ``quantity``) the
        :func:`pencore.analysis.errors.error_statistics` of the rigid shots; per data set
        and law (dimension ``group``) the :func:`summary`.
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
    cf_cache: dict = {}
    closed = [_closed_forms(r, cf_cache) for _, r in df.iterrows()]
    df["closedform_depth"] = [c[0] for c in closed]
    df["cavity_form_depth"] = [c[1] for c in closed]
    df["forrestal_form_depth"] = [c[2] for c in closed]

    def a(units: str, long_name: str) -> dict[str, str]:
        return {"units": units, "long_name": long_name}

    def text(col: pd.Series | Sequence[str]) -> tuple[str, np.ndarray]:
        return ("shot", np.asarray(col).astype(str))

    units = df["quantity"].map({q: u for q, u, _ in QUANTITIES.values()})
    same = "(units: variable measured_units)"
    measured = df["measured"].to_numpy()
    rigid = df["rigid"].to_numpy(dtype=bool)
    depth_m = a("m", "")
    ds = xr.Dataset(
        {
            "velocity": ("shot", df["velocity_m_s"].to_numpy(), a("m s-1", "impact velocity")),
            "obliquity": ("shot", df["obliquity_deg"].to_numpy(), a("degree", "obliquity")),
            "yaw": ("shot", df["yaw_deg"].to_numpy(), a("degree", "yaw angle")),
            "pitch_measured": (
                "shot",
                df["pitch_measured_deg"].to_numpy(),
                a("degree", "measured pitch angle of attack (NaN: none in the file)"),
            ),
            "yaw_measured": (
                "shot",
                df["yaw_measured_deg"].to_numpy(),
                a("degree", "measured yaw angle of attack (NaN: none in the file)"),
            ),
            "thickness": (
                "shot",
                df["thickness_m"].to_numpy(),
                a("m", "target thickness (inf: half-space)"),
            ),
            "measured": ("shot", measured, {"long_name": f"measured value {same}"}),
            "predicted": ("shot", df["predicted"].to_numpy(), {"long_name": f"pencore {same}"}),
            "rel_error": (
                "shot",
                relative_errors(measured, df["predicted"].to_numpy()),
                a("1", "predicted / measured - 1 (NaN: measured 0)"),
            ),
            "rigid": (
                "shot",
                rigid.astype(np.int8),
                {
                    "long_name": "1: the projectile stayed rigid by its authors' limits, "
                    "0: it did not (run, kept, left out of the statistics)",
                    "flag_values": np.array([0, 1], dtype=np.int8),
                    "flag_meanings": "not_rigid rigid",
                },
            ),
            "measured_units": text(units),
            "quantity_of_shot": text(df["quantity"]),
            "dataset": text(df["dataset"]),
            "label": text(df["label"]),
            "projectile": text(df["projectile"]),
            "target": text(df["target"]),
            "depth_measure": text(df["depth_measure"]),
            "outcome": text(outcome),
            "remark": text(df["remark"]),
            "source": text(df["source"]),
        },
        coords={"shot": df["shot"].to_numpy().astype(str)},
    )
    for var, long_name in (
        ("closedform_depth", "closed-form depth, exact nose entry (pencore.closedform.depth)"),
        (
            "cavity_form_depth",
            "closed-form depth, full nose force from contact (pencore.closedform.tunnel_depth)",
        ),
        (
            "forrestal_form_depth",
            "Forrestal's closed-form depth with a crater of two calibers "
            "(pencore.closedform.forrestal_crater_depth; NaN: not a body shot)",
        ),
    ):
        values = df[var].to_numpy(dtype=float)
        ds[var] = ("shot", values, {**depth_m, "long_name": f"{long_name}; normal, no yaw"})
        ds[f"{var}_rel_error"] = (
            "shot",
            relative_errors(measured, values),
            a("1", f"{var} / measured - 1"),
        )
    quantities = sorted(df["quantity"].unique())
    st = {}
    for q in quantities:
        sel = (df["quantity"] == q).to_numpy() & rigid & np.isfinite(measured)
        st[q] = sample_statistics(measured[sel], df["predicted"].to_numpy()[sel])
    for k in next(iter(st.values())):
        # the absolute error has the units of its quantity (variable measured_units), so
        # it carries no single CF units attribute; the other statistics are dimensionless
        attrs = (
            a("1", k.replace("_", " ") + " (rigid shots)")
            if k != "mean_abs_error"
            else {"long_name": f"mean |predicted - measured| {same} (rigid shots)"}
        )
        ds[f"stat_{k}"] = ("quantity", [st[q][k] for q in quantities], attrs)
    ds = ds.assign_coords(quantity=("quantity", np.array(quantities, dtype=str)))
    ds = ds.merge(summary(ds))
    ds.attrs.update(
        title="pencore against published measurements",
        entries_json=json.dumps([_entry(e) for e in entries], sort_keys=True),
        numerics_json=json.dumps(asdict(num), sort_keys=True),
    )
    return ds


def summary(ds: xr.Dataset) -> xr.Dataset:
    """The validation summary: per data set and law, how each model meets the shots.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`measured_vs_predicted` result (its per-shot variables).

    Returns
    -------
    xarray.Dataset
        On ``group`` (``dataset/target``), ``model`` (:data:`MODELS`) and ``subset``
        (``rigid``: the shots whose projectile stayed rigid by its authors' limits, the
        model's own domain; ``all``: every shot with a measured value, deformed and
        eroding projectiles included, for comparison only): ``summary_n`` (shots
        compared), ``summary_mean_abs_rel_error`` (mean ``|e|``), ``summary_bias`` (mean
        ``e``) and ``summary_worst_rel_error`` (the ``e`` of largest magnitude, signed),
        ``e = predicted / measured - 1``; on ``group``, ``summary_n_not_rigid``.
    """
    group = np.array(
        [f"{d}/{t}" for d, t in zip(ds["dataset"].values, ds["target"].values, strict=True)]
    )
    groups = list(dict.fromkeys(group))
    rigid = ds["rigid"].values.astype(bool)
    models = list(MODELS)
    subsets = {"rigid": rigid, "all": np.ones_like(rigid)}
    shape = (len(groups), len(models), len(subsets))
    out = {k: np.full(shape, np.nan) for k in ("n", "mean", "bias", "worst")}
    n_out = np.zeros(len(groups))
    for ig, g in enumerate(groups):
        in_g = group == g
        n_out[ig] = np.count_nonzero(in_g & ~rigid)
        for im, m in enumerate(models):
            rel = ds["rel_error" if m == "predicted" else f"{m}_rel_error"].values
            for js, keep in enumerate(subsets.values()):
                st = summary_statistics(rel[in_g & keep])
                out["n"][ig, im, js] = st["n"]
                out["mean"][ig, im, js] = st["mean_abs_rel_error"]
                out["bias"][ig, im, js] = st["bias"]
                out["worst"][ig, im, js] = st["worst"]

    def a(long_name: str) -> dict[str, str]:
        return {"units": "1", "long_name": long_name}

    dims = ("group", "model", "subset")
    return xr.Dataset(
        {
            "summary_n": (dims, out["n"], a("shots compared")),
            "summary_n_not_rigid": ("group", n_out, a("shots whose projectile did not stay rigid")),
            "summary_mean_abs_rel_error": (dims, out["mean"], a("mean |predicted / measured - 1|")),
            "summary_bias": (dims, out["bias"], a("mean (predicted / measured - 1)")),
            "summary_worst_rel_error": (
                dims,
                out["worst"],
                a("predicted / measured - 1 of largest magnitude"),
            ),
            "model_label": ("model", np.array([MODELS[m] for m in models], dtype=str)),
        },
        coords={
            "group": np.array(groups, dtype=str),
            "model": np.array(models, dtype=str),
            "subset": np.array(list(subsets), dtype=str),
        },
    )


def summary_table(measurements: xr.Dataset, ratios: xr.Dataset | None = None) -> pd.DataFrame:
    """The validation summary over every measurement, one row per data set, law and model.

    Parameters
    ----------
    measurements : xarray.Dataset
        A :func:`measured_vs_predicted` result (its :func:`summary` variables).
    ratios : xarray.Dataset, optional
        A :func:`pencore.studies.perforation.obliquity.compare_obliquity` result: the measured
        obliquity ratios ``V_bl(theta) / V_bl(0)`` of plates, compared with pencore's
        analog (the paper's model, option ``none``) and with the line-of-sight rule.

    Returns
    -------
    pandas.DataFrame
        Columns ``data_set``, ``quantity``, ``law``, ``model``, ``n`` (shots compared:
        rigid ones for depths), ``n_left_out`` (shots whose projectile deformed or
        eroded), ``mean_abs_rel_error``, ``bias`` (mean ``e``) and ``worst`` (the ``e`` of
        largest magnitude, signed), with ``e = predicted / measured - 1``. No parameter of
        any model is fitted to these data.
    """
    rows = []
    for g in measurements["group"].values:
        dataset, law = str(g).split("/", 1)
        quantity = str(
            measurements["quantity_of_shot"].values[(measurements["dataset"] == dataset).values][0]
        )
        for m in measurements["model"].values:
            st = measurements.sel(group=g, model=m, subset="rigid")
            n = int(st["summary_n"])
            if m != "predicted" and n == 0:
                continue  # no shot to compare (none rigid, or no closed form)
            rows.append(
                {
                    "data_set": dataset,
                    "quantity": quantity,
                    "law": law,
                    "model": MODELS[str(m)],
                    "n": n,
                    "n_left_out": int(st["summary_n_not_rigid"]),
                    "mean_abs_rel_error": float(st["summary_mean_abs_rel_error"]),
                    "bias": float(st["summary_bias"]),
                    "worst": float(st["summary_worst_rel_error"]),
                }
            )
    if ratios is not None:
        measured = ratios["measured_ratio"].values
        for model, predicted in (
            ("pencore analog (paper's model)", ratios["pencore_ratio"].sel(option="none").values),
            ("line of sight, sec(theta)", ratios["los_ratio"].values),
        ):
            ok = np.isfinite(predicted) & np.isfinite(measured) & (measured > 0)
            rows.append(
                {
                    "data_set": "oblique_ballistic_limits",
                    "quantity": "obliquity ratio V_bl(theta) / V_bl(0)",
                    "law": "analog: " + str(ratios.attrs.get("analog", "")),
                    "model": model,
                    "n_left_out": int(np.count_nonzero(~ok)),
                    **summary_statistics(predicted[ok] / measured[ok] - 1.0),
                }
            )
    return pd.DataFrame(rows)


def statistics_by_option(
    entries: Sequence[Mapping[str, Any]],
    options: Mapping[str, Mapping[str, float]],
    numerics: Numerics | Mapping | None = None,
) -> xr.Dataset:
    """Error statistics per near-surface option, material and kind of measurement.

    Every shot of every data file is run once per option set (``options``: name ->
    settings of :data:`NEAR_SURFACE_KEYS` applied to every medium of the target; ``{}``
    is the paper's model). Groups are ``material`` (the target's name) and ``quantity``
    (:data:`QUANTITIES`). A body shot whose rod an option cannot apply to (a crater shorter
    than its nose) has no prediction under that option (NaN) and is left out of that
    option's statistics.

    Returns
    -------
    xarray.Dataset
        ``predicted`` and ``rel_error`` on ``(option, shot)``, ``measured`` on ``shot``,
        and the :func:`pencore.analysis.errors.error_statistics` on ``(option, group)``,
        ``group`` labelled ``material/quantity``.
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
    rigid = df["rigid"].to_numpy(dtype=bool)
    groups = sorted({f"{t}/{q}" for t, q in zip(df["target"], df["quantity"], strict=True)})
    key = np.array([f"{t}/{q}" for t, q in zip(df["target"], df["quantity"], strict=True)])
    stats: dict[str, np.ndarray] = {}
    for i in range(len(names)):
        for g, grp in enumerate(groups):
            # a shot the option cannot apply to (NaN) is left out of that option's group
            sel = (key == grp) & rigid & np.isfinite(measured) & np.isfinite(pred[i])
            for k, v in sample_statistics(measured[sel], pred[i, sel]).items():
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
