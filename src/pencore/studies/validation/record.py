"""The concrete record: every clean shot of the public compilation, scored by pencore.

The public compilation of normal-impact, ogive-nose shots into concrete
(:mod:`pencore.measured.compilation`, ``config/concrete_compilation.csv``) is run shot by
shot with the solver (each rod by its measured mass,
:func:`~pencore.studies.validation.bodies.body_projectile`; the target a
half-space of the shot's ``fc`` and density) under every concrete law pencore ships
(:data:`pencore.inputs.record.RECORD_LAWS`), and beside them three closed forms
(:data:`CLOSED_FORMS`). Two groups of rows are scored: the clean rows, which make the
statistics and the depth bands, and the rows set aside *only* as eroding (striking speed
above the provisional bound), which judge the rigid-regime criterion
(:func:`pencore.inputs.regime.rigid_regime`).

*Held out.* The ``S(fc)`` forms were built on the Sandia/WES shots and the size term's
``d0`` on the rows its constants file names (:func:`pencore.inputs.laws.size_term_constants`:
that family and Wu et al.'s scaled series), so the laws are compared on the rows of every
*other* source (``held_out``). For the size term the fitted rows get held-out predictions
too: ``d0`` refitted with the row's source left out
(:func:`pencore.studies.validation.size_term.fit_size_term`) and the row run again.

Statistics (:func:`record_statistics`): per law the count, median error, mean ``|e|`` and
the share within 25 % (:mod:`pencore.analysis.record`), on the held-out rows, per bin of
diameter, strength, speed and CRH (:data:`BINS`) and per source; the depth band's held-out
calibration (:func:`pencore.analysis.record.calibrate_level`); and the law with the
smallest held-out median ``|e|`` (:data:`CRITERION`; ``best_law``) with the bins it does not
win. The shipped record (:func:`record_rows`, :func:`bands_document`) is what a run's
depth band is made from.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore import closedform
from pencore.analysis.record import LEVELS, STATISTICS, WITHIN, binned, calibrate_level
from pencore.errors import InputError, PlausibilityWarning, SolverError, TargetError, hint_keywords
from pencore.inputs.laws import concrete_law, size_term_constants
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.inputs.record import (
    DEFAULT_RECORD_LAW,
    RECORD_COLUMNS,
    RECORD_LAWS,
    STATED_LEVEL,
    Scores,
)
from pencore.inputs.regime import rigid_regime
from pencore.inputs.target import Medium, Target
from pencore.measured.compilation import read_compilation, rows_allowing
from pencore.run.impact import simulate
from pencore.studies.validation.bodies import body_projectile
from pencore.studies.validation.size_term import fit_d0, fit_rows, implied_factors

__all__ = [
    "CLOSED_FORMS",
    "BINS",
    "ROW_GROUPS",
    "record_rows_to_score",
    "law_medium",
    "score_law",
    "gather_record",
    "record_statistics",
    "CRITERION",
    "scores",
    "statistics_table",
    "record_rows",
    "write_record",
    "bands_document",
]

#: Closed forms scored beside the laws: name -> description.
CLOSED_FORMS = {
    "cf_forrestal": "Forrestal's closed form, S = 82.6 fc^-0.544, no crater (tunnel form)",
    "cf_forrestal_crater": "Forrestal's closed form, S = 82.6 fc^-0.544, crater of 2 calibers",
    "cf_li_chen": "Li & Chen's form: S = 72 fc^-0.5, crater of 0.707 + H/d calibers",
}

#: Bin edges of the statistics: quantity -> (variable, edges, unit of the edges, scale).
BINS: dict[str, tuple[str, tuple[float, ...], str, float]] = {
    "diameter": ("diameter", (0.0, 15.0, 30.0, 60.0, 100.0, math.inf), "mm", 1e3),
    "fc": ("fc", (0.0, 30.0, 50.0, 80.0, 120.0, math.inf), "MPa", 1e-6),
    "speed": ("velocity", (0.0, 300.0, 500.0, 700.0, 1000.0, math.inf), "m/s", 1.0),
    "crh": ("crh", (0.0, 2.5, 3.5, 5.0, math.inf), "", 1.0),
}

#: The statistic the laws are ranked by, on the held-out rows: the median ``|e|``, which a
#: few wild rows (a transcription error the cleaning did not catch) cannot decide.
CRITERION = "median_abs_error"

#: Row groups scored: name -> the reasons a row may be set aside for and still be scored.
ROW_GROUPS = {"clean": (), "eroding": ("eroding",)}


def record_rows_to_score(every: int = 1) -> pd.DataFrame:
    """The compilation's rows the record scores: the clean rows (``group`` ``clean``) and
    those set aside only as eroding (``group`` ``eroding``), with ``in_fit`` (a row the size
    term was fitted to); ``every``: keep every n-th of them (1: all; a quick check)."""
    if isinstance(every, bool) or not isinstance(every, int) or every < 1:
        raise InputError(f"record: every must be a whole number >= 1, got {every!r}")
    df = read_compilation()
    clean = df[df["status"] == "clean"]
    eroding = rows_allowing(df, ROW_GROUPS["eroding"])
    eroding = eroding[eroding["status"] != "clean"]
    out = pd.concat([clean.assign(group="clean"), eroding.assign(group="eroding")])
    fit = {str(r) for r in size_term_constants()["rows"]}
    out = out.assign(in_fit=out["row"].astype(str).isin(fit))
    out = out.sort_values("row", key=lambda s: s.astype(int)).reset_index(drop=True)
    return out.iloc[::every].reset_index(drop=True)


def law_medium(row: Mapping[str, Any], law: str, d0: float | None = None) -> Medium:
    """The shot's concrete under a record law (:data:`~pencore.inputs.record.RECORD_LAWS`), its
    size term's
    ``d0`` replaced when given (a refit)."""
    if law not in RECORD_LAWS:
        raise InputError(f"record: unknown law {law!r}; use one of {', '.join(RECORD_LAWS)}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)  # fc beyond the built range
        m = concrete_law(
            float(row["fc_pa"]), float(row["target_density_kg_m3"]), **RECORD_LAWS[law]
        )
    if d0 is not None and m.size_term is not None:
        m = replace(m, size_term=replace(m.size_term, d0=d0))
    return m


def _run(row: pd.Series, medium: Medium, num: Numerics) -> tuple[float, str]:
    """pencore's depth (m; the tip's path below the face) of one shot and its outcome."""
    proj = body_projectile(row, f"row {row['row']}")
    try:
        with warnings.catch_warnings():
            # fc beyond the built range, the rigid regime: the record keeps its own verdict
            warnings.simplefilter("ignore", PlausibilityWarning)
            ds = simulate(
                proj,
                Target.half_space(medium),
                float(row["striking_velocity_m_s"]),
                numerics=num,
                loads=False,
            )
    except TargetError as err:  # a crater shorter than the nose
        return math.nan, f"not applicable: {err}"
    except SolverError as err:
        return math.nan, f"solver_error: {err}"
    return float(ds["path_length"]), str(ds.attrs["outcome"])


def _refits(law: str) -> dict[str, float]:
    """``d0`` of a size-term law refitted on its declared fit's rows with each of their
    sources left out (source -> d0, m)."""
    opts = RECORD_LAWS[law]
    spec = size_term_constants()
    fit = fit_rows()  # the rows of the declared fit, as it was made
    f = implied_factors(fit, opts["s_model"], opts["crater"])  # per row: once
    d, src = fit["diameter_m"].to_numpy(float), fit["reference_key"].to_numpy()
    out = {}
    for s in sorted(set(src)):
        keep = src != s
        out[s] = fit_d0(d[keep], f[keep], fit["row"][keep], spec["d_ref_m"], spec["exponent"]).d0
    return out


def score_law(
    law: str,
    rows: pd.DataFrame | None = None,
    numerics: Numerics | Mapping | None = None,
    progress: Callable[[str], None] | None = None,
) -> xr.Dataset:
    """Run every row under one law.

    Parameters
    ----------
    law : str
        A record law (:data:`~pencore.inputs.record.RECORD_LAWS`).
    rows : pandas.DataFrame, optional
        The rows (default :func:`record_rows_to_score`).
    numerics : Numerics or mapping, optional
        Solver settings.
    progress : callable, optional
        Called with a line every 100 rows.

    Returns
    -------
    xarray.Dataset
        On ``shot`` (the compilation's Number): ``predicted`` and ``held_out_predicted``
        (m; the same but for the size term's fitted rows, run with ``d0`` refitted without
        their source), ``outcome``, and ``held_out_d0`` (m; NaN without a size term).
    """
    rows = record_rows_to_score() if rows is None else rows
    num = resolve_numerics(numerics)
    sized = RECORD_LAWS[law]["size_term"] != "none"
    refit = _refits(law) if sized else {}
    pred, held, outcome, d0s = [], [], [], []
    t0 = time.perf_counter()
    for i, (_, r) in enumerate(rows.iterrows()):
        depth, out = _run(r, law_medium(r, law), num)
        pred.append(depth)
        outcome.append(out)
        d0 = refit.get(r["reference_key"]) if r["in_fit"] else None
        d0s.append(math.nan if d0 is None else d0)
        held.append(depth if d0 is None else _run(r, law_medium(r, law, d0), num)[0])
        if progress and (i + 1) % 100 == 0:
            progress(f"{law}: {i + 1} of {len(rows)} shots ({time.perf_counter() - t0:.0f} s)")
    shot = rows["row"].astype(int).to_numpy()
    return xr.Dataset(
        {
            "predicted": ("shot", np.array(pred), {"units": "m", "long_name": "pencore depth"}),
            "held_out_predicted": (
                "shot",
                np.array(held),
                {
                    "units": "m",
                    "long_name": "pencore depth with the size term refitted without the "
                    "shot's source (as predicted where the law was not fitted to the shot)",
                },
            ),
            "outcome": ("shot", np.array(outcome, dtype=str), {"long_name": "run outcome"}),
            "held_out_d0": (
                "shot",
                np.array(d0s),
                {"units": "m", "long_name": "size term d0 refitted without the shot's source"},
            ),
        },
        coords={"shot": ("shot", shot, {"long_name": "the compilation's Number"})},
        attrs={"law": law, "law_options": str(RECORD_LAWS[law])},
    )


def _closed_forms(r: pd.Series) -> tuple[float, float, float]:
    """The three :data:`CLOSED_FORMS` of a shot (m; NaN where a form does not apply)."""
    proj = body_projectile(r, f"row {r['row']}")
    v = float(r["striking_velocity_m_s"])
    fc, rho = float(r["fc_pa"]), float(r["target_density_kg_m3"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)
        forrestal = concrete_law(fc, rho, size_term="none")
        li_chen = concrete_law(fc, rho, s_model="li_chen", size_term="none")
    out = [closedform.tunnel_depth(proj, forrestal, v)]
    try:
        out.append(closedform.forrestal_crater_depth(proj, forrestal, v))
    except InputError:  # the nose longer than two calibers
        out.append(math.nan)
    k = 0.707 + proj.nose_length / proj.diameter
    out.append(closedform.forrestal_crater_depth(proj, li_chen, v, k=k))
    return out[0], out[1], out[2]


def _regime(r: pd.Series) -> tuple[float, bool, bool]:
    """The rigid-regime verdict of a shot under the default law: ``R``, rigid, and whether
    the projectile's yield strength was compiled (else the assumed one)."""
    body = body_projectile(r, f"row {r['row']}")
    y = r.get("yield_strength_pa", math.nan)
    given = bool(pd.notna(y) and float(y) > 0)
    p = replace(body, yield_strength=float(y) if given else None)
    medium = law_medium(r, DEFAULT_RECORD_LAW).for_projectile(p.diameter, p.nose_length)
    v = rigid_regime(p, medium, float(r["striking_velocity_m_s"]))
    return v.ratio, v.rigid, given


def gather_record(parts: Sequence[xr.Dataset], rows: pd.DataFrame | None = None) -> xr.Dataset:
    """The scored laws side by side with the shots' inputs and the closed forms.

    Returns
    -------
    xarray.Dataset
        On ``shot``: the inputs (``diameter``, ``mass``, ``crh``, ``fc``, ``density``,
        ``velocity``, ``measured``), ``source`` (the compiler's reference key), ``set``,
        ``group`` (``clean`` / ``eroding``), ``in_fit``, ``held_out`` (a clean row of a
        source no law was fitted to); on ``(model, shot)``: ``predicted``,
        ``held_out_predicted``, ``rel_error`` and ``held_out_rel_error`` (predicted /
        measured - 1), ``outcome``; ``model`` holds the laws then the closed forms
        (``kind``: ``solver`` or ``closed_form``).
    """
    rows = record_rows_to_score() if rows is None else rows
    shot = rows["row"].astype(int).to_numpy()
    laws = [str(p.attrs["law"]) for p in parts]
    if len(set(laws)) != len(laws):
        raise InputError(f"record: a law scored twice among {laws}")
    for p in parts:
        if not np.array_equal(p["shot"].to_numpy(), shot):
            raise InputError(f"record: law {p.attrs['law']!r} scored other shots")
    cf = np.array([_closed_forms(r) for _, r in rows.iterrows()]).T
    regime = [_regime(r) for _, r in rows.iterrows()]
    models = [*laws, *CLOSED_FORMS]
    pred = np.vstack([*(p["predicted"].to_numpy() for p in parts), cf])
    held = np.vstack([*(p["held_out_predicted"].to_numpy() for p in parts), cf])
    outcome = np.vstack(
        [*(p["outcome"].to_numpy().astype(str) for p in parts), np.full(cf.shape, "closed form")]
    )
    measured = rows["depth_m"].to_numpy(float)
    fit_sources = set(rows.loc[rows["in_fit"], "reference_key"])
    held_out = (rows["group"] == "clean") & ~rows["reference_key"].isin(fit_sources)

    def v(values: Any, units: str, long_name: str) -> tuple:
        return ("shot", np.asarray(values), {"units": units, "long_name": long_name})

    def t(values: Any, long_name: str) -> tuple:
        return ("shot", np.asarray(values).astype(str), {"long_name": long_name})

    err = {"units": "1", "long_name": "relative error, predicted / measured - 1"}
    return xr.Dataset(
        {
            "diameter": v(rows["diameter_m"], "m", "projectile diameter"),
            "mass": v(rows["mass_kg"], "kg", "measured projectile mass"),
            "length": v(rows["length_m"], "m", "projectile length, nose included"),
            "crh": v(rows["crh"], "1", "ogive caliber-radius-head"),
            "fc": v(rows["fc_pa"], "Pa", "unconfined compressive strength"),
            "density": v(rows["target_density_kg_m3"], "kg m-3", "target density"),
            "velocity": v(rows["striking_velocity_m_s"], "m s-1", "striking velocity"),
            "measured": v(measured, "m", "measured penetration depth"),
            "source": t(rows["reference_key"], "the compiler's reference key"),
            "reference": t(rows["reference"], "the reference"),
            "set": t(rows["set"], "reference, rod and target"),
            "group": t(rows["group"], "clean, or set aside only as eroding"),
            "in_fit": ("shot", rows["in_fit"].to_numpy(bool), {"long_name": "size-term fit row"}),
            "held_out": (
                "shot",
                held_out.to_numpy(bool),
                {"long_name": "clean row of a source no law was fitted to"},
            ),
            "regime_ratio": (
                "shot",
                np.array([g[0] for g in regime]),
                {
                    "units": "1",
                    "long_name": "nose-tip stress of the default law over the projectile's "
                    "yield strength (pencore.inputs.regime)",
                },
            ),
            "rigid": (
                "shot",
                np.array([g[1] for g in regime]),
                {"long_name": "within the rigid regime (pencore.inputs.regime)"},
            ),
            "strength_given": (
                "shot",
                np.array([g[2] for g in regime]),
                {"long_name": "projectile yield strength compiled (else assumed)"},
            ),
            "predicted": (("model", "shot"), pred, {"units": "m", "long_name": "predicted depth"}),
            "held_out_predicted": (
                ("model", "shot"),
                held,
                {"units": "m", "long_name": "predicted depth, fitted source left out"},
            ),
            "rel_error": (("model", "shot"), pred / measured - 1, err),
            "held_out_rel_error": (("model", "shot"), held / measured - 1, err),
            "outcome": (("model", "shot"), outcome, {"long_name": "run outcome"}),
        },
        coords={
            "shot": ("shot", shot, {"long_name": "the compilation's Number"}),
            "model": ("model", np.array(models), {"long_name": "law or closed form"}),
            "kind": (
                "model",
                np.array(["solver"] * len(laws) + ["closed_form"] * len(CLOSED_FORMS)),
                {"long_name": "solver run or closed form"},
            ),
        },
        attrs={
            "models": "; ".join(
                f"{k}: {d}" for k, d in {**_law_labels(laws), **CLOSED_FORMS}.items()
            )
        },
    )


def _law_labels(laws: Sequence[str]) -> dict[str, str]:
    return {
        k: f"pencore, concrete_law({', '.join(f'{a}={b!r}' for a, b in RECORD_LAWS[k].items())})"
        for k in laws
    }


def scores(ds: xr.Dataset, model: str) -> Scores:
    """A scored law's clean rows as :class:`pencore.inputs.record.Scores` (held-out ratios;
    calibration NaN until :func:`record_statistics` sets it)."""
    sel = ds.sel(model=model)
    keep = (ds["group"] == "clean").to_numpy() & np.isfinite(sel["held_out_predicted"].to_numpy())
    return Scores(
        law=model,
        source=ds["source"].to_numpy()[keep],
        diameter=ds["diameter"].to_numpy()[keep],
        fc=ds["fc"].to_numpy()[keep],
        velocity=ds["velocity"].to_numpy()[keep],
        crh=ds["crh"].to_numpy()[keep],
        ratio=(ds["measured"] / sel["held_out_predicted"]).to_numpy()[keep],
        nominal_level=math.nan,
        held_out_coverage=math.nan,
    )


def _bin_labels(edges: Sequence[float], unit: str) -> list[str]:
    def f(x: float) -> str:
        return f"{x:g}"

    out = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        if lo == 0.0:
            out.append(f"< {f(hi)} {unit}".strip())
        elif math.isinf(hi):
            out.append(f">= {f(lo)} {unit}".strip())
        else:
            out.append(f"{f(lo)}-{f(hi)} {unit}".strip())
    return out


def record_statistics(ds: xr.Dataset) -> xr.Dataset:
    """Held-out statistics of every model, per bin and per source, and each law's band
    calibration (module notes).

    Returns
    -------
    xarray.Dataset
        ``overall_<stat>`` on ``(model, rows)`` (``rows``: ``held_out`` for the rows of
        sources no law was fitted to, ``all_clean`` for every clean row with held-out
        predictions); ``<quantity>_<stat>`` on ``(model, <quantity>_bin)`` over the
        held-out rows for each of :data:`BINS`; ``source_<stat>`` on ``(model, source)``
        over every clean row (held-out predictions); ``regime_<stat>`` on ``(model,
        regime)``: the clean and the eroding rows, each kept (``rigid``) or flagged by the
        rigid-regime criterion; ``<stat>`` one of
        :data:`pencore.analysis.record.STATISTICS`. Per law: ``nominal_level``,
        ``held_out_coverage``, ``coverage_at_stated``, ``n_with_band`` of the band; the
        attribute ``best_law`` (smallest held-out :data:`CRITERION` among the laws) and
        ``best_law_loses`` (the bins where another law has a smaller one).
    """
    models = ds["model"].to_numpy().astype(str)
    kinds = ds["kind"].to_numpy().astype(str)
    clean = (ds["group"] == "clean").to_numpy()
    held_out = ds["held_out"].to_numpy().astype(bool)  # int8 once read from netCDF
    e_all = ds["held_out_rel_error"].to_numpy()
    stats = STATISTICS
    long = {
        "n": ("1", "shots"),
        "median_error": ("1", "median relative error"),
        "median_abs_error": ("1", "median absolute relative error"),
        "mean_abs_error": ("1", "mean absolute relative error"),
        "within": ("1", f"share of shots with |error| <= {WITHIN:g}"),
    }
    out: dict[str, Any] = {}
    coords: dict[str, Any] = {"model": ("model", models), "kind": ("model", kinds)}

    def put(prefix: str, dims: tuple[str, ...], values: dict[str, np.ndarray]) -> None:
        for k in stats:
            unit, name = long[k]
            out[f"{prefix}_{k}"] = (dims, values[k], {"units": unit, "long_name": name})

    def by_group(groups: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """The statistics of every model over each group of rows (a mask)."""
        per = {k: np.full((len(models), len(groups)), np.nan) for k in stats}
        for i in range(len(models)):
            for j, m in enumerate(groups.values()):
                b = binned(e_all[i][m], np.zeros(int(m.sum())), [-1.0, 1.0])
                for k in stats:
                    per[k][i, j] = b[k][0]
        return per

    # overall
    groups = {"held_out": held_out, "all_clean": clean}
    coords["rows"] = ("rows", list(groups))
    put("overall", ("model", "rows"), by_group(groups))

    # per bin, held-out rows
    for q, (var, edges, unit, scale) in BINS.items():
        x = ds[var].to_numpy() * scale
        per = {k: np.full((len(models), len(edges) - 1), np.nan) for k in stats}
        for i in range(len(models)):
            b = binned(e_all[i][held_out], x[held_out], edges)
            for k in stats:
                per[k][i] = b[k]
        coords[f"{q}_bin"] = (f"{q}_bin", _bin_labels(edges, unit))
        put(q, ("model", f"{q}_bin"), per)

    # per source, every clean row
    src = ds["source"].to_numpy().astype(str)
    sources = sorted(set(src[clean]))
    idx = np.array([sources.index(s) if c else -1 for s, c in zip(src, clean, strict=True)])
    per = {k: np.full((len(models), len(sources)), np.nan) for k in stats}
    for i in range(len(models)):
        b = binned(e_all[i][clean], idx[clean].astype(float), np.arange(len(sources) + 1) - 0.5)
        for k in stats:
            per[k][i] = b[k]
    coords["source"] = ("source", sources)
    put("source", ("model", "source"), per)

    # the rigid-regime criterion: rows it keeps and flags, clean and eroding
    rigid = ds["rigid"].to_numpy().astype(bool)
    regime_groups = {
        f"{g}, {v}": (ds["group"].to_numpy() == g) & (rigid == (v == "rigid"))
        for g in ROW_GROUPS
        for v in ("rigid", "flagged")
    }
    coords["regime"] = ("regime", list(regime_groups))
    put("regime", ("model", "regime"), by_group(regime_groups))

    # the band's calibration, per law
    cal = {
        k: np.full(len(models), np.nan)
        for k in ("nominal_level", "held_out_coverage", "coverage_at_stated", "n_with_band")
    }
    for i, m in enumerate(models):
        if kinds[i] != "solver":
            continue
        c = calibrate_level(scores(ds, m))
        for k in cal:
            cal[k][i] = getattr(c, k)
    for k, name in (
        ("nominal_level", "quantile level of the band, calibrated one source left out"),
        ("held_out_coverage", f"share of held-out shots the band held (stated {STATED_LEVEL:g})"),
        ("coverage_at_stated", f"the same at the uncalibrated level {STATED_LEVEL:g}"),
        ("n_with_band", "shots with a held-out band"),
    ):
        out[k] = ("model", cal[k], {"units": "1", "long_name": name})

    laws = [m for m, k in zip(models, kinds, strict=True) if k == "solver"]
    li = [list(models).index(m) for m in laws]
    mae = out[f"overall_{CRITERION}"][1][li, 0]
    best = laws[int(np.nanargmin(mae))]
    loses = []
    for q in BINS:
        v = out[f"{q}_{CRITERION}"][1][li]
        labels = coords[f"{q}_bin"][1]
        for j, lab in enumerate(labels):
            col = v[:, j]
            if np.all(np.isnan(col)):
                continue
            winner = laws[int(np.nanargmin(col))]
            if winner != best:
                loses.append(f"{q} {lab}: {winner}")
    return xr.Dataset(
        out,
        coords=coords,
        attrs={
            "best_law": best,
            "best_law_loses": "; ".join(loses),
            "stated_level": STATED_LEVEL,
            "levels_tried": ", ".join(f"{x:g}" for x in LEVELS),
            "within": WITHIN,
        },
    )


def record_rows(ds: xr.Dataset) -> list[dict[str, Any]]:
    """The rows of the shipped record (:data:`pencore.inputs.record.RECORD_COLUMNS`): per
    law and clean shot with a held-out prediction, its inputs and ratio."""
    rows = []
    for m in ds["model"].to_numpy().astype(str):
        if m not in RECORD_LAWS:
            continue
        s = scores(ds, m)
        keep = (ds["group"] == "clean").to_numpy() & np.isfinite(
            ds["held_out_predicted"].sel(model=m).to_numpy()
        )
        shots = ds["shot"].to_numpy()[keep]
        for j in range(s.ratio.size):
            rows.append(
                dict(
                    zip(
                        RECORD_COLUMNS,
                        (
                            m,
                            int(shots[j]),
                            s.source[j],
                            repr(float(s.diameter[j])),
                            repr(float(s.fc[j])),
                            repr(float(s.velocity[j])),
                            repr(float(s.crh[j])),
                            f"{s.ratio[j]:.6f}",
                        ),
                        strict=True,
                    )
                )
            )
    return rows


def bands_document(stats: xr.Dataset) -> dict[str, Any]:
    """The calibration file's content: per law the nominal level and held-out coverage."""
    laws = {}
    for i, m in enumerate(stats["model"].to_numpy().astype(str)):
        if m not in RECORD_LAWS:
            continue
        laws[str(m)] = {
            "nominal_level": float(stats["nominal_level"][i]),
            "held_out_coverage": round(float(stats["held_out_coverage"][i]), 4),
            "coverage_at_stated": round(float(stats["coverage_at_stated"][i]), 4),
            "n_with_band": int(stats["n_with_band"][i]),
        }
    return {"stated_level": STATED_LEVEL, "best_law": str(stats.attrs["best_law"]), "laws": laws}


def statistics_table(stats: xr.Dataset) -> pd.DataFrame:
    """:func:`record_statistics` as one long table: ``model``, ``kind``, ``grouping``
    (``overall``, a quantity of :data:`BINS`, ``source`` or ``regime``), ``group`` (its
    bin, rows, source or regime group) and the :data:`pencore.analysis.record.STATISTICS`."""
    frames = []
    for grouping, dim in (
        ("overall", "rows"),
        *((q, f"{q}_bin") for q in BINS),
        ("source", "source"),
        ("regime", "regime"),
    ):
        prefix = grouping
        cols = {k: stats[f"{prefix}_{k}"].to_pandas().stack() for k in STATISTICS}
        df = pd.DataFrame(cols).reset_index().rename(columns={dim: "group"})
        df.insert(1, "grouping", grouping)
        frames.append(df)
    out = pd.concat(frames, ignore_index=True)
    kinds = dict(
        zip(stats["model"].values.astype(str), stats["kind"].values.astype(str), strict=True)
    )
    out.insert(1, "kind", out["model"].map(kinds))
    out["n"] = out["n"].astype(int)
    return out


#: The header of the shipped record (:data:`pencore.inputs.record.RECORD_FILE`).
RECORD_HEADER = """\
# The concrete record: per concrete law and clean shot of the public compilation
# (config/concrete_compilation.csv: its row numbers, sources and reasons; a declared
# secondary source), the shot's diameter (m), fc (Pa), striking speed (m/s), CRH and
# ratio = measured / predicted depth, the prediction held out (the size term refitted
# without the shot's source). GENERATED from the archived concrete-record study by
# `python -m pencore.studies.validation.record results/archive/validation` (do not edit);
# tests/studies/validation/test_record.py checks it against the archive.
"""


def write_record(archive: str, record: str | None = None, bands: str | None = None) -> None:
    """Write the shipped record and its calibration from an archived study folder
    (``concrete_record.nc`` and ``concrete_record_stats.nc`` in ``archive``)."""
    from pathlib import Path

    import yaml

    from pencore.inputs.record import BANDS_FILE, RECORD_FILE
    from pencore.io.atomic import atomic_write_text
    from pencore.io.netcdf import read_netcdf

    folder = Path(archive)
    ds = read_netcdf(folder / "concrete_record.nc")
    stats = read_netcdf(folder / "concrete_record_stats.nc")
    import csv
    import io

    buf = io.StringIO()
    writer = csv.DictWriter(buf, RECORD_COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(record_rows(ds))
    atomic_write_text(record or RECORD_FILE, RECORD_HEADER + buf.getvalue())
    doc = bands_document(stats)
    text = (
        "# Each concrete law's depth band, calibrated one source left out at a time\n"
        "# (pencore.analysis.record.calibrate_level) on the rows of concrete_record.csv.\n"
        "# GENERATED with it (do not edit).\n" + yaml.safe_dump(doc, sort_keys=False)
    )
    atomic_write_text(bands or BANDS_FILE, text)


if __name__ == "__main__":  # pragma: no cover - regenerates the shipped record
    import sys

    write_record(sys.argv[1] if len(sys.argv) > 1 else "results/archive/validation")


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
