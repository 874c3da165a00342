"""The paper comparison table: every claim of ``config/paper_claims.csv`` beside pencore's.

Each claim names, in its ``computed_by`` column, an entry of :data:`HANDLERS`: a function
of the claim and the study datasets that returns the claim's table rows (none when its
study was not given). A claim's ``study`` column names its dataset, ``results/<study>.nc``;
the handler finds that study's record in :data:`pencore.workflowconfig.registry.STUDIES`
and reads the dataset given under the record's id, and the rows' sources are the record's
dataset path. The paper's values come from the claim, never from code; verdicts
on the paper's trends are computed from the datasets with
:func:`~pencore.studies.trends.trend`. The rows are
formatted, rounded and looked up in the search datasets by the helpers below; the spin
claims (Figs 16-18, Sect. 4.3) compare the deviation alpha and the turning back at an
initial angular velocity, with the start-height study beside them, and omega_c of #2.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from itertools import product
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore import analysis
from pencore.errors import InputError
from pencore.inputs.library import get_projectile
from pencore.paper.claims import at, load_claims
from pencore.studies.trends import trend
from pencore.workflowconfig.registry import STUDIES, Study, study

__all__ = ["paper_comparison", "HANDLERS"]

Claim = Mapping[str, Any]
Rows = list[dict[str, Any]]


# ----------------------------------------------------------------------------- studies


def _record(c: Claim) -> Study:
    """The registry record of a claim's study: the one whose dataset is ``results/<study>.nc``."""
    path = f"results/{c['study']}.nc"
    for s in STUDIES.values():
        if s.dataset == path:
            return s
    known = ", ".join(
        s.dataset.removeprefix("results/").removesuffix(".nc") for s in STUDIES.values()
    )
    raise InputError(
        f"paper claims: claim {c['id']!r} has study {c['study']!r}, which names no Section 4 "
        f"dataset (one of {known})"
    )


def _dataset(c: Claim, d: Mapping[str, Any]) -> tuple[xr.Dataset | None, Study]:
    """(the dataset of the claim's study, or ``None`` when not given; its record)."""
    rec = _record(c)
    return d["datasets"].get(rec.id), rec


def _siblings(rec: Study) -> list[Study]:
    """The other studies of ``rec``'s configuration entry (e.g. the start-height study
    beside Figs 16-17)."""
    return [s for s in STUDIES.values() if s.entry == rec.entry and s.id != rec.id]


# ----------------------------------------------------------------------------- rows


def _search_lines(
    ds: xr.Dataset, name: str, along: str, *, fixed: Mapping[str, Any] | None = None
) -> list[tuple[str, np.ndarray, np.ndarray, np.ndarray]]:
    """Lines of a search dataset along ``along`` for every other index."""
    sub = ds.sel(fixed) if fixed else ds
    da_lo = sub[f"{name}_lo"]
    others = [d for d in da_lo.dims if d != along]
    par = _parameter_values(sub, along)
    lines = []
    for idx in product(*(range(sub.sizes[d]) for d in others)):
        sel = dict(zip(others, idx, strict=True))
        lo = sub[f"{name}_lo"].isel(sel).transpose(along).values
        hi = sub[f"{name}_hi"].isel(sel).transpose(along).values
        label = ", ".join(f"{d}={_fmt_coord(sub[d].values[i])}" for d, i in sel.items())
        lines.append((label or name, par, lo, hi))
    return lines


def _parameter_values(ds: xr.Dataset, along: str) -> np.ndarray:
    if along == "projectile":
        return np.asarray(ds["lc_over_l"].values, float)
    return np.asarray(ds[along].values, float)


def _fmt_coord(v: Any) -> str:
    return f"{v:g}" if isinstance(v, float | np.floating) else str(v)


_COLUMNS = [
    "quantity",
    "paper_value",
    "pencore_value",
    "difference",
    "units",
    "note",
    "kind",
    "source",
]


def _row(
    quantity: str, paper: Any, pencore: Any, units: str, note: str, kind: str, source: str
) -> dict[str, Any]:
    if kind == "value" and _is_num(paper) and _is_num(pencore):
        diff: Any = float(pencore) - float(paper)
    elif kind == "verdict":
        diff = "agrees" if str(paper) == str(pencore) else "differs"
    else:
        diff = ""
    return dict(
        quantity=quantity,
        paper_value=_round(paper),
        pencore_value=_round(pencore),
        difference=_round(diff),
        units=units,
        note=note,
        kind=kind,
        source=source,
    )


def _round(x: Any, digits: int = 6) -> Any:
    """Floats to ``digits`` significant digits (the table is for reading)."""
    if isinstance(x, float | np.floating) and math.isfinite(float(x)):
        return float(f"{float(x):.{digits}g}")
    return x


def _is_num(x: Any) -> bool:
    return isinstance(x, int | float | np.integer | np.floating) and math.isfinite(float(x))


def _search_value(ds: xr.Dataset, name: str, sel: Mapping[str, Any]) -> tuple[Any, str]:
    """(value or bound string, note) of one search cell."""
    cell = ds.sel(sel)
    status = str(cell["status"].values)
    lo, hi = float(cell[f"{name}_lo"]), float(cell[f"{name}_hi"])
    if status in ("ok", "non_monotone"):
        note = f"bracket [{lo:.6g}, {hi:.6g}]"
        if status == "non_monotone":
            note += "; verdict NOT monotone (lowest threshold found)"
        return float(cell[name]), note
    if status == "above_range":
        return f"> {lo:g}", "above_range: no event up to the top of the search range"
    if status == "below_range":
        return f"<= {hi:g}", "below_range: event already at the bottom of the search range"
    return float(cell[name]), f"status {status}: bracket [{lo:.6g}, {hi:.6g}]"


def _pencore_rel(pencore: Any, paper: float) -> str:
    if _is_num(pencore) and paper:
        return f"{100.0 * (float(pencore) - paper) / paper:+.1f} %"
    return ""


def _nose_rows(ds: xr.Dataset, dataset: str) -> list[dict[str, Any]]:
    """Verdicts on the paper's Fig. 12 statements about the final nose direction of ``ds``,
    read from the file ``dataset``."""
    src = f"{dataset}: nose_direction"
    nd = ds["nose_direction"]
    known = nd != ""
    minus = (nd == "-x") & known
    rows = []
    neg = ds["yaw"] < 0
    n_neg = int((known & neg).sum())
    n_neg_plus = int(((nd == "+x") & neg).sum())
    rows.append(
        _row(
            "Fig. 12: nose points +x at Vcr for every negative yaw",
            "yes",
            "yes" if n_neg and n_neg_plus == n_neg else "no",
            "",
            f"{n_neg_plus} of {n_neg} negative-yaw cases end +x",
            "verdict",
            src,
        )
    )

    def count(**sel: Any) -> int:
        return int(minus.sel(sel).sum())

    obl = [float(o) for o in ds["obliquity"].values]
    if len(obl) >= 2:
        lo_o, hi_o = min(obl), max(obl)
        a, b = count(obliquity=lo_o), count(obliquity=hi_o)
        rows.append(
            _row(
                f"Fig. 12: flip to -x more likely at {lo_o:g} than {hi_o:g} deg",
                "yes",
                "yes" if a > b else "no",
                "",
                f"-x cases: {a} at {lo_o:g} deg, {b} at {hi_o:g} deg",
                "verdict",
                src,
            )
        )
    projs = list(ds["projectile"].values)
    if len(projs) >= 2:
        lcl = ds["lc_over_l"].values
        p_lo, p_hi = projs[int(np.argmin(lcl))], projs[int(np.argmax(lcl))]
        a, b = count(projectile=p_hi), count(projectile=p_lo)
        rows.append(
            _row(
                f"Fig. 12: flip to -x more likely for larger Lc/L ({p_hi} than {p_lo})",
                "yes",
                "yes" if a > b else "no",
                "",
                f"-x cases: {a} for {p_hi}, {b} for {p_lo}",
                "verdict",
                src,
            )
        )
    n_minus = int(minus.sum())
    n_big = int((minus & (ds["yaw"] > 1.0)).sum())
    rows.append(
        _row(
            "Fig. 12: the flip to -x happens only for yaw > 1 deg",
            "yes",
            "yes" if n_minus and n_big == n_minus else "no",
            "",
            f"{n_minus} -x case(s), {n_big} of them at yaw > 1 deg",
            "verdict",
            src,
        )
    )
    return rows


def _close(values: Any, v: float) -> bool:
    """Whether any of ``values`` is ``v`` (to numpy's ``isclose``)."""
    return bool(np.any(np.isclose(np.asarray(values, float), v)))


# ----------------------------------------------------------------------------- spin (Figs 16-18)


def _start_heights(
    rec: Study, d: Mapping[str, Any], w: float
) -> list[tuple[float, float, int, str]]:
    """(tip start height m, alpha deg, reversed 0/1, dataset path) at spin ``w`` of the
    start-height studies beside ``rec`` (the studies of its configuration entry)."""
    out = []
    for s in _siblings(rec):
        sh = d["datasets"].get(s.id)
        if sh is None or not _close(sh["omega"], w):
            continue
        cells = [sh.sel(omega=w, start_height=hh) for hh in sh["start_height"].values]
        out += [
            (float(x["start_height"]), float(x["alpha"]), int(x["reversed"]), s.dataset)
            for x in cells
        ]
    return out


def _fig16_alpha(c: Claim, d: Mapping[str, Any]) -> Rows:
    w, a = float(at(c["at"])[0]["omega"]), float(c["value"])
    rows = []
    ds, rec = _dataset(c, d)
    if ds is not None and _close(ds["omega"], w):
        h = float(ds.attrs.get("start_height_m", 0.0))
        pen = float(ds["final_deviation"].sel(omega=w))
        rows.append(
            _row(
                f"Fig. 16: deviation alpha of #2, 1000 m/s, omega = {w:g} rad/s",
                a,
                pen,
                c["units"],
                f"{_pencore_rel(pen, a)}; tip starting {h:g} m above the surface",
                "value",
                rec.dataset,
            )
        )
    for hh, pen, rev, src in _start_heights(rec, d, w):
        rows.append(
            _row(
                f"Start-height sensitivity: alpha at omega = {w:g} rad/s, tip {hh:g} m above",
                a,
                pen,
                c["units"],
                f"{_pencore_rel(pen, a)}; reversed = {rev}",
                "value",
                src,
            )
        )
    return rows


def _fig16_reverses(c: Claim, d: Mapping[str, Any]) -> Rows:
    w = float(at(c["at"])[0]["omega"])
    rows = []
    ds, rec = _dataset(c, d)
    if ds is not None and _close(ds["omega"], w):
        h = float(ds.attrs.get("start_height_m", 0.0))
        rev = int(ds["reversed"].sel(omega=w))
        rows.append(
            _row(
                f"Fig. 16: turns back at omega = {w:g} rad/s (#2, 1000 m/s)",
                c["value"],
                "yes" if rev else "no",
                "",
                f"tip starting {h:g} m above the surface",
                "verdict",
                rec.dataset,
            )
        )
    for hh, pen, rev, src in _start_heights(rec, d, w):
        rows.append(
            _row(
                f"Start-height sensitivity: turns back at omega = {w:g} rad/s, tip {hh:g} m above",
                c["value"],
                "yes" if rev else "no",
                "",
                f"alpha = {pen:.3g} deg",
                "verdict",
                src,
            )
        )
    return rows


def _omega_c_p2(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None or "p2" not in ds["projectile"].values or not _close(ds["velocity"], 1000.0):
        return []
    lo_p, hi_p = float(c["value"]), float(c["value_hi"])
    val, note = _search_value(ds, "omega_c", {"projectile": "p2", "velocity": 1000.0})
    return [
        _row(
            "omega_c of #2 at 1000 m/s (Figs 16-17)",
            0.5 * (lo_p + hi_p),
            val,
            c["units"],
            f"paper: {lo_p:g} does not turn back, {hi_p:g} does (derived: midpoint of "
            f"({lo_p:g}, {hi_p:g}]); pencore {note}",
            "value",
            rec.dataset,
        )
    ]


# ----------------------------------------------------------------------------- claims


def _trend_row(quantity: str, claim: Claim, lines: list, source: str) -> dict[str, Any]:
    tr = trend(lines, claim["value"])
    return _row(quantity, claim["value"], tr.verdict, "", tr.note(), "trend", source)


# ----------------------------------------------------------------------------- Tables 2, 3


def _table2_rows(c: Claim, d: Mapping[str, Any]) -> Rows:
    t2 = d.get("table2")
    if t2 is None:
        return []
    rows = []
    for _, r in t2.iterrows():
        paper = float(r["paper_predicted_depth_m"])
        pen = float(r["pencore_depth_m"])
        rows.append(
            _row(
                f"Table 2 test {int(r['test'])}: penetration depth "
                f"(V={r['velocity_m_s']:g} m/s, obliquity {r['obliquity_deg']:g} deg, "
                f"yaw {r['yaw_deg']:g} deg)",
                paper,
                pen,
                "m",
                f"{_pencore_rel(pen, paper)}; measured {r['measured_depth_m']:g} m; "
                f"pencore {r['projectile']}, {r['depth_measure']} (selected as closest "
                "to the paper's column)",
                "value",
                "results/validation/table2.csv",
            )
        )
    return rows


def _table3(c: Claim, d: Mapping[str, Any], what: str) -> Rows:
    if not d.get("table3", True):
        return []
    p = str(at(c["at"])[0]["projectile"])
    proj = get_projectile(p)
    mp = proj.mass_properties()
    pen = float(mp.mass) if what == "mass" else float(mp.lc / proj.length)
    return [
        _row(
            f"Table 3 {p}: {'mass' if what == 'mass' else 'Lc/L'}",
            float(c["value"]),
            pen,
            c["units"],
            "pencore geometry derived by pencore.inputs.library.table3_fit",
            "value",
            "pencore.inputs.library",
        )
    ]


# ----------------------------------------------------------------------------- Figs 7-9


def _fig7_reverses(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    v = float(at(c["at"])[0]["velocity"])
    if ds is None or not _close(ds["velocity"], v):
        return []
    pen_rev = bool(int(ds["reversed"].sel(velocity=v, method="nearest")))
    return [
        _row(
            f"Fig. 7 (#2, 45 deg, tip from (-1, 1) m): turns back at Vi = {v:g} m/s",
            c["value"],
            "yes" if pen_rev else "no",
            "",
            "",
            "verdict",
            f"{rec.dataset}: reversed",
        )
    ]


def _fig7_x_linear(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None:
        return []
    rows = []
    for cond in at(c["at"]):
        v = float(cond["velocity"])
        if not _close(ds["velocity"], v):
            continue
        x2 = float(ds["x_linear"].sel(velocity=v, method="nearest"))
        rows.append(
            _row(
                f"Fig. 7: x where the curved path becomes straight, Vi = {v:g} m/s",
                float(c["value"]),
                x2 if math.isfinite(x2) else "n/a",
                "m",
                "paper: approximately 7 m for 1641-1700 m/s; pencore: centre of "
                "mass x at Point 2 (|curvature| below 5 % of its peak)",
                "value",
                f"{rec.dataset}: x_linear",
            )
        )
    return rows


def _vcr_p2_45(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None or "p2" not in ds["projectile"].values or not _close(ds["obliquity"], 45):
        return []
    lo_p, hi_p = float(c["value"]), float(c["value_hi"])
    val, note = _search_value(ds, "vcr", {"projectile": "p2", "obliquity": 45.0})
    mid = 0.5 * (lo_p + hi_p)
    return [
        _row(
            "Vcr of #2 at 45 deg obliquity (Fig. 7)",
            mid,
            val,
            c["units"],
            f"paper: {lo_p:g} does not reverse, {hi_p:g} does (derived: midpoint "
            f"of ({lo_p:g}, {hi_p:g}]); pencore {note}; {_pencore_rel(val, mid)}",
            "value",
            f"{rec.dataset}: vcr",
        )
    ]


def _search_trend(name: str, along: str, quantity: str):
    """Handler: the trend of search quantity ``name`` along ``along`` in the claim's study."""

    def handler(c: Claim, d: Mapping[str, Any]) -> Rows:
        ds, rec = _dataset(c, d)
        if ds is None:
            return []
        return [_trend_row(quantity, c, _search_lines(ds, name, along), rec.dataset)]

    return handler


def _fig9_lc(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None:
        return []
    f0 = float(ds.attrs.get("primary_bracket_fraction", analysis.DEFAULT_BRACKET_FRACTION))
    fr = ds["bracket_fraction"].values
    fsel = fr[int(np.argmin(np.abs(fr - f0)))]
    dth = ds["delta_theta"].sel(bracket_fraction=fsel).values
    tr = trend([("delta_theta", ds["lc_over_l"].values, dth, dth)], c["value"])
    spread = ds["delta_theta"].max("bracket_fraction") - ds["delta_theta"].min("bracket_fraction")
    values = ", ".join(
        f"{p}: {v:.2f} deg" for p, v in zip(ds["projectile"].values, dth, strict=True)
    )
    return [
        _row(
            "Fig. 9: total turning angle d(theta)_12 against Lc/L (45 deg, 1000 m/s)",
            c["value"],
            tr.verdict,
            "",
            f"{tr.note()}; values {values} (bracket fraction {fsel:g}; other fractions "
            f"move them by up to {float(spread.max()):.2f} deg)",
            "trend",
            rec.dataset,
        )
    ]


# ----------------------------------------------------------------------------- Figs 11-12


def _fig11_nose(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None:
        return []
    neg, pos = str(c["value"]).split("/")[::-1]  # "-x/+x": positive yaw -x, negative +x
    rows = []
    for y in ds["yaw"].values:
        if float(y) == 0.0:
            continue
        sub = ds.sel(yaw=y)
        rows.append(
            _row(
                f"Fig. 11 (#4, {ds.attrs.get('velocity_fixed', 1000):g} m/s, "
                f"{ds.attrs.get('obliquity_fixed', 30):g} deg): nose direction at "
                f"the end, yaw {y:g} deg",
                neg if y < 0 else pos,
                str(sub["nose_direction"].item()),
                "",
                "paper: implied by the text (negative yaw keeps the nose +x, positive "
                "yaw can turn it to -x); pencore: sign of the axis x component at the "
                f"end of the run ({sub['outcome'].item()}, final theta "
                f"{float(sub['final_theta']):.0f} deg)",
                "verdict",
                f"{rec.dataset}: nose_direction",
            )
        )
    return rows


def _fig12_nose(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    if ds is None or "nose_direction" not in ds:
        return []
    return _nose_rows(ds, rec.dataset)


# ----------------------------------------------------------------------------- Figs 13-15


def _fig13_phi(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    v, phi = float(at(c["at"])[0]["velocity"]), float(c["value"])
    if ds is None or not _close(ds["velocity"], v):
        return []
    rows = []
    for conv in (str(x) for x in ds["convention"].values):
        pen = float(ds["final_deviation"].sel(convention=conv, velocity=v))
        tag = " (configured)" if conv == d.get("yaw_convention", "axis_tilted") else ""
        rows.append(
            _row(
                f"Fig. 13: deviation phi of #4, yaw 0.1 deg, Vi = {v:g} m/s, {conv}{tag}",
                phi,
                pen,
                c["units"],
                f"{_pencore_rel(pen, phi)}; phi = final deviation (last state with "
                "speed >= 0.1 Vi)",
                "value",
                rec.dataset,
            )
        )
    return rows


def _fig13_large(c: Claim, d: Mapping[str, Any]) -> Rows:
    ds, rec = _dataset(c, d)
    v = float(at(c["at"])[0]["velocity"])
    if ds is None or not _close(ds["velocity"], v):
        return []
    thr = d.get("vci_threshold")
    thr = 5.0 if thr is None else float(thr)
    rows = []
    for conv in (str(x) for x in ds["convention"].values):
        pen = float(ds["final_deviation"].sel(convention=conv, velocity=v))
        rev = int(ds["reversed"].sel(convention=conv, velocity=v))
        rows.append(
            _row(
                f"Fig. 13: large deviation at Vi = {v:g} m/s, {conv}",
                c["value"],
                "yes" if (pen > thr or rev) else "no",
                "",
                f"pencore phi = {pen:.3g} deg, reversed = {rev}; 'large' = above "
                f"the Vci threshold {thr:g} deg",
                "verdict",
                rec.dataset,
            )
        )
    return rows


def _fig15(along: str, label: str):
    def handler(c: Claim, d: Mapping[str, Any]) -> Rows:
        ds, rec = _dataset(c, d)
        if ds is None:
            return []
        th = ds["threshold"].values
        thr = d.get("vci_threshold")
        t0 = float(th[np.argmin(np.abs(th - (5.0 if thr is None else thr)))])
        return [
            _trend_row(
                f"Fig. 15: Vci against {label} (threshold {t:g} deg"
                f"{', primary' if t == t0 else ''})",
                c,
                _search_lines(ds, "vci", along, fixed={"threshold": t}),
                rec.dataset,
            )
            for t in th
        ]

    return handler


# ----------------------------------------------------------------------------- Figs 16-18


#: ``computed_by`` of a claim -> function(claim, datasets) -> table rows.
HANDLERS: dict[str, Callable[[Claim, Mapping[str, Any]], Rows]] = {
    "table2_rows": _table2_rows,
    "table3_mass": lambda c, d: _table3(c, d, "mass"),
    "table3_lc": lambda c, d: _table3(c, d, "lc"),
    "fig7_reverses": _fig7_reverses,
    "fig7_x_linear": _fig7_x_linear,
    "vcr_p2_45": _vcr_p2_45,
    "fig8_obliquity": _search_trend("vcr", "obliquity", "Fig. 8: Vcr against obliquity"),
    "fig8_lc": _search_trend("vcr", "projectile", "Fig. 8: Vcr against Lc/L"),
    "fig9_lc": _fig9_lc,
    "fig11_nose": _fig11_nose,
    "fig12_yaw": _search_trend("vcr", "yaw", "Fig. 12: Vcr against yaw"),
    "fig12_obliquity": _search_trend(
        "vcr", "obliquity", "Fig. 12: Vcr against obliquity (30 -> 60 deg)"
    ),
    "fig12_lc": _search_trend("vcr", "projectile", "Fig. 12: Vcr against Lc/L (#2 -> #4)"),
    "fig12_nose": _fig12_nose,
    "fig13_phi": _fig13_phi,
    "fig13_large": _fig13_large,
    "fig15_lc": _fig15("projectile", "Lc/L"),
    "fig15_yaw": _fig15("yaw", "yaw"),
    "fig16_alpha": _fig16_alpha,
    "fig16_reverses": _fig16_reverses,
    "omega_c_p2": _omega_c_p2,
    "fig18_velocity": _search_trend(
        "omega_c", "velocity", "Fig. 18: omega_c against impact velocity"
    ),
    "fig18_lc": _search_trend("omega_c", "projectile", "Fig. 18: omega_c against Lc/L"),
}


def paper_comparison(
    *,
    datasets: Mapping[str, xr.Dataset] | None = None,
    claims: pd.DataFrame | None = None,
    table2: pd.DataFrame | None = None,
    table3: bool = True,
    yaw_convention: str = "axis_tilted",
    vci_threshold: float | None = None,
) -> pd.DataFrame:
    """Every claim of the claims file beside pencore's value, in the file's order.

    Parameters
    ----------
    datasets : mapping of str to xarray.Dataset, optional
        The study datasets by study id (the keys of
        :data:`pencore.workflowconfig.registry.STUDIES`); a study not given skips the
        claims it computes. An unknown id is an :class:`~pencore.errors.InputError`.
    claims : pandas.DataFrame, optional
        :func:`pencore.paper.claims.load_claims` (default: ``config/paper_claims.csv``).
    table2 : pandas.DataFrame, optional
        ``results/validation/table2.csv``. ``table3``: include the Table 3 rows.
    yaw_convention : str
        The configured yaw convention (marked in the Fig. 13 rows).
    vci_threshold : float, optional
        The deviation threshold (deg) the Vci rows lead with; default the
        ``primary_threshold_deg`` attribute of the given dataset that has one (the Vci
        study's), else 5 deg.

    Returns
    -------
    pandas.DataFrame
        Columns ``quantity, paper_value, pencore_value, difference, units, note, kind,
        source, claim, where``. ``kind`` is ``value`` (``difference`` = pencore - paper),
        ``verdict`` (``difference`` = agrees / differs) or ``trend`` (``pencore_value``
        holds / partly holds / does not hold / undetermined, the count of steps in
        ``note``); brackets are compared at their midpoint, with the bracket in ``note``.
    """
    given = dict(datasets or {})
    for name in given:
        study(name)  # InputError naming the known ids
    df = load_claims() if claims is None else claims
    if vci_threshold is None:
        primary = [
            float(ds.attrs["primary_threshold_deg"])
            for ds in given.values()
            if ds is not None and "primary_threshold_deg" in ds.attrs
        ]
        vci_threshold = primary[0] if primary else None
    data = dict(
        datasets={k: ds for k, ds in given.items() if ds is not None},
        table2=table2,
        table3=table3,
        yaw_convention=yaw_convention,
        vci_threshold=vci_threshold,
    )
    rows: Rows = []
    for c in df.to_dict("records"):
        handler = HANDLERS.get(c["computed_by"])
        if handler is None:
            raise InputError(
                f"paper claims: claim {c['id']!r} has computed_by {c['computed_by']!r}, "
                f"which pencore does not know (one of {', '.join(HANDLERS)})"
            )
        for r in handler(c, data):
            rows.append({**r, "claim": c["id"], "where": c["where"]})
    return pd.DataFrame(rows, columns=[*_COLUMNS, "claim", "where"])
