"""Rows of the comparison table for the spin claims (paper Figs 16-18, Sect. 4.3): the
deviation alpha and the turning back at an initial angular velocity, with the
start-height study beside them, and omega_c of #2 at 1000 m/s.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pencore.paper.claims import at
from pencore.studies.comparison_rows import _close, _pencore_rel, _row, _search_value

__all__: list[str] = []

Claim = Mapping[str, Any]
Rows = list[dict[str, Any]]


def _start_heights(d: Mapping[str, Any], w: float) -> list[tuple[float, float, int]]:
    """(tip start height m, alpha deg, reversed 0/1) of the start-height study at spin w."""
    sh = d.get("start_height")
    if sh is None or not _close(sh["omega"], w):
        return []
    cells = [sh.sel(omega=w, start_height=hh) for hh in sh["start_height"].values]
    return [(float(x["start_height"]), float(x["alpha"]), int(x["reversed"])) for x in cells]


def _fig16_alpha(c: Claim, d: Mapping[str, Any]) -> Rows:
    w, a = float(at(c["at"])[0]["omega"]), float(c["value"])
    rows = []
    fig16 = d.get("fig16")
    if fig16 is not None and _close(fig16["omega"], w):
        h = float(fig16.attrs.get("start_height_m", 0.0))
        pen = float(fig16["final_deviation"].sel(omega=w))
        rows.append(
            _row(
                f"Fig. 16: deviation alpha of #2, 1000 m/s, omega = {w:g} rad/s",
                a,
                pen,
                c["units"],
                f"{_pencore_rel(pen, a)}; tip starting {h:g} m above the surface",
                "value",
                "results/fig16/trajectories.nc",
            )
        )
    for hh, pen, rev in _start_heights(d, w):
        rows.append(
            _row(
                f"Start-height sensitivity: alpha at omega = {w:g} rad/s, tip {hh:g} m above",
                a,
                pen,
                c["units"],
                f"{_pencore_rel(pen, a)}; reversed = {rev}",
                "value",
                "results/fig16/start_height.nc",
            )
        )
    return rows


def _fig16_reverses(c: Claim, d: Mapping[str, Any]) -> Rows:
    w = float(at(c["at"])[0]["omega"])
    rows = []
    fig16 = d.get("fig16")
    if fig16 is not None and _close(fig16["omega"], w):
        h = float(fig16.attrs.get("start_height_m", 0.0))
        rev = int(fig16["reversed"].sel(omega=w))
        rows.append(
            _row(
                f"Fig. 16: turns back at omega = {w:g} rad/s (#2, 1000 m/s)",
                c["value"],
                "yes" if rev else "no",
                "",
                f"tip starting {h:g} m above the surface",
                "verdict",
                "results/fig16/trajectories.nc",
            )
        )
    for hh, pen, rev in _start_heights(d, w):
        rows.append(
            _row(
                f"Start-height sensitivity: turns back at omega = {w:g} rad/s, tip {hh:g} m above",
                c["value"],
                "yes" if rev else "no",
                "",
                f"alpha = {pen:.3g} deg",
                "verdict",
                "results/fig16/start_height.nc",
            )
        )
    return rows


def _omega_c_p2(c: Claim, d: Mapping[str, Any]) -> Rows:
    fig18 = d.get("fig18")
    if (
        fig18 is None
        or "p2" not in fig18["projectile"].values
        or not _close(fig18["velocity"], 1000.0)
    ):
        return []
    lo_p, hi_p = float(c["value"]), float(c["value_hi"])
    val, note = _search_value(fig18, "omega_c", {"projectile": "p2", "velocity": 1000.0})
    return [
        _row(
            "omega_c of #2 at 1000 m/s (Figs 16-17)",
            0.5 * (lo_p + hi_p),
            val,
            c["units"],
            f"paper: {lo_p:g} does not turn back, {hi_p:g} does (derived: midpoint of "
            f"({lo_p:g}, {hi_p:g}]); pencore {note}",
            "value",
            "results/fig18/omega_c.nc",
        )
    ]
