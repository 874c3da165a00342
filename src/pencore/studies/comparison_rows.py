"""Row helpers of the paper comparison table: formatting, rounding, and looking up
search results in a dataset.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from itertools import product
from typing import Any

import numpy as np
import xarray as xr

__all__ = []


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


def _nose_rows(ds: xr.Dataset) -> list[dict[str, Any]]:
    """Verdicts on the paper's Fig. 12 statements about the final nose direction."""
    src = "results/fig12/vcr_yaw.nc: nose_direction"
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
