"""The paper comparison table: every number and trend Section 4 of the paper states,
beside pencore's.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from .. import analysis
from ..library import get_projectile
from .common import PAPER
from .comparison_rows import _COLUMNS, _nose_rows, _pencore_rel, _row, _search_lines, _search_value
from .trends import trend

__all__ = ["paper_comparison"]


def paper_comparison(
    *,
    fig7: xr.Dataset | None = None,
    fig8: xr.Dataset | None = None,
    fig9: xr.Dataset | None = None,
    fig11: xr.Dataset | None = None,
    fig12: xr.Dataset | None = None,
    fig13: xr.Dataset | None = None,
    fig15: xr.Dataset | None = None,
    fig16: xr.Dataset | None = None,
    start_height: xr.Dataset | None = None,
    fig18: xr.Dataset | None = None,
    table2: pd.DataFrame | None = None,
    table3: bool = True,
    yaw_convention: str = "axis_tilted",
    vci_threshold: float | None = None,
) -> pd.DataFrame:
    """Every number and trend the paper states in Sections 3-4, beside pencore's.

    Each argument is the dataset of one study (``None`` skips its rows); ``table2`` is the
    validation table (``results/validation/table2.csv``). Verdicts on the paper's trends
    are computed here from the datasets with :func:`trend`, never written in.

    Returns
    -------
    pandas.DataFrame
        Columns ``quantity, paper_value, pencore_value, difference, units, note, kind,
        source``. ``kind`` is ``value`` (``difference`` = pencore - paper), ``verdict``
        (a yes/no statement; ``difference`` = agrees / differs) or ``trend``
        (``paper_value`` is the claim, ``pencore_value`` holds / partly holds / does not
        hold / undetermined, with the count of steps in ``note``).
    """
    rows: list[dict[str, Any]] = []
    add = rows.append

    # ---- Section 3: Table 2 and Table 3
    if table2 is not None:
        for _, r in table2.iterrows():
            paper = float(r["paper_predicted_depth_m"])
            pen = float(r["pencore_depth_m"])
            add(
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
    if table3:
        for p, (m, lcl) in PAPER["table3"].items():
            proj = get_projectile(p)
            mp = proj.mass_properties()
            add(
                _row(
                    f"Table 3 {p}: mass",
                    m,
                    float(mp.mass),
                    "kg",
                    "pencore geometry derived by pencore.library.table3_fit",
                    "value",
                    "pencore.library",
                )
            )
            add(
                _row(
                    f"Table 3 {p}: Lc/L",
                    lcl,
                    float(mp.lc / proj.length),
                    "1",
                    "pencore geometry derived by pencore.library.table3_fit",
                    "value",
                    "pencore.library",
                )
            )

    # ---- Fig. 7
    if fig7 is not None:
        vel = fig7["velocity"].values
        for v, rev in PAPER["fig7_reverses"].items():
            if np.any(np.isclose(vel, v)):
                pen_rev = bool(int(fig7["reversed"].sel(velocity=v, method="nearest")))
                add(
                    _row(
                        f"Fig. 7 (#2, 45 deg, tip from (-1, 1) m): turns back at Vi = {v:g} m/s",
                        "yes" if rev else "no",
                        "yes" if pen_rev else "no",
                        "",
                        "",
                        "verdict",
                        "results/fig7/trajectories.nc: reversed",
                    )
                )
        for v in (1641.0, 1650.0, 1700.0):
            if np.any(np.isclose(vel, v)):
                x2 = float(fig7["x_linear"].sel(velocity=v, method="nearest"))
                add(
                    _row(
                        f"Fig. 7: x where the curved path becomes straight, Vi = {v:g} m/s",
                        PAPER["fig7_x_linear_m"],
                        x2 if math.isfinite(x2) else "n/a",
                        "m",
                        "paper: approximately 7 m for 1641-1700 m/s; pencore: centre of "
                        "mass x at Point 2 (|curvature| below 5 % of its peak)",
                        "value",
                        "results/fig7/trajectories.nc: x_linear",
                    )
                )

    # ---- Fig. 8
    if fig8 is not None:
        lo_p, hi_p = PAPER["vcr_p2_45_bracket"]
        if "p2" in fig8["projectile"].values and np.any(np.isclose(fig8["obliquity"], 45.0)):
            val, note = _search_value(fig8, "vcr", {"projectile": "p2", "obliquity": 45.0})
            mid = 0.5 * (lo_p + hi_p)
            add(
                _row(
                    "Vcr of #2 at 45 deg obliquity (Fig. 7)",
                    mid,
                    val,
                    "m s-1",
                    f"paper: {lo_p:g} does not reverse, {hi_p:g} does (derived: midpoint "
                    f"of ({lo_p:g}, {hi_p:g}]); pencore {note}; {_pencore_rel(val, mid)}",
                    "value",
                    "results/fig8/vcr.nc: vcr",
                )
            )
        tr = trend(_search_lines(fig8, "vcr", "obliquity"), "falls")
        add(
            _row(
                "Fig. 8: Vcr against obliquity",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig8/vcr.nc",
            )
        )
        tr = trend(_search_lines(fig8, "vcr", "projectile"), "falls")
        add(
            _row(
                "Fig. 8: Vcr against Lc/L",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig8/vcr.nc",
            )
        )

    # ---- Fig. 9
    if fig9 is not None:
        f0 = float(fig9.attrs.get("primary_bracket_fraction", analysis.DEFAULT_BRACKET_FRACTION))
        fsel = fig9["bracket_fraction"].values[
            int(np.argmin(np.abs(fig9["bracket_fraction"].values - f0)))
        ]
        dth = fig9["delta_theta"].sel(bracket_fraction=fsel).values
        tr = trend([("delta_theta", fig9["lc_over_l"].values, dth, dth)], "rises")
        spread = fig9["delta_theta"].max("bracket_fraction") - fig9["delta_theta"].min(
            "bracket_fraction"
        )
        add(
            _row(
                "Fig. 9: total turning angle d(theta)_12 against Lc/L (45 deg, 1000 m/s)",
                "rises",
                tr.verdict,
                "",
                tr.note()
                + "; values "
                + ", ".join(
                    f"{p}: {v:.2f} deg" for p, v in zip(fig9["projectile"].values, dth, strict=True)
                )
                + f" (bracket fraction {fsel:g}; other fractions move them by up to "
                f"{float(spread.max()):.2f} deg)",
                "trend",
                "results/fig9/turning_angle.nc",
            )
        )

    # ---- Figs 11-12
    if fig11 is not None:
        for y in fig11["yaw"].values:
            if float(y) == 0.0:
                continue
            expect = "+x" if y < 0 else "-x"
            sub = fig11.sel(yaw=y)
            add(
                _row(
                    f"Fig. 11 (#4, {fig11.attrs.get('velocity_fixed', 1000):g} m/s, "
                    f"{fig11.attrs.get('obliquity_fixed', 30):g} deg): nose direction at "
                    f"the end, yaw {y:g} deg",
                    expect,
                    str(sub["nose_direction"].item()),
                    "",
                    "paper: implied by the text (negative yaw keeps the nose +x, positive "
                    "yaw can turn it to -x); pencore: sign of the axis x component at the "
                    f"end of the run ({sub['outcome'].item()}, final theta "
                    f"{float(sub['final_theta']):.0f} deg)",
                    "verdict",
                    "results/fig11/trajectories.nc: nose_direction",
                )
            )
    if fig12 is not None:
        tr = trend(_search_lines(fig12, "vcr", "yaw"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against yaw",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        tr = trend(_search_lines(fig12, "vcr", "obliquity"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against obliquity (30 -> 60 deg)",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        tr = trend(_search_lines(fig12, "vcr", "projectile"), "falls")
        add(
            _row(
                "Fig. 12: Vcr against Lc/L (#2 -> #4)",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig12/vcr_yaw.nc",
            )
        )
        if "nose_direction" in fig12:
            for row in _nose_rows(fig12):
                add(row)

    # ---- Figs 13-14
    if fig13 is not None:
        convs = [str(c) for c in fig13["convention"].values]
        for v, phi in PAPER["fig13_phi_deg"].items():
            if not np.any(np.isclose(fig13["velocity"], v)):
                continue
            for c in convs:
                pen = float(fig13["final_deviation"].sel(convention=c, velocity=v))
                tag = " (configured)" if c == yaw_convention else ""
                add(
                    _row(
                        f"Fig. 13: deviation phi of #4, yaw 0.1 deg, Vi = {v:g} m/s, {c}{tag}",
                        phi,
                        pen,
                        "degree",
                        f"{_pencore_rel(pen, phi)}; phi = final deviation (last state with "
                        "speed >= 0.1 Vi)",
                        "value",
                        "results/fig13/trajectories.nc",
                    )
                )
        v_l = PAPER["fig13_large_at"]
        if np.any(np.isclose(fig13["velocity"], v_l)):
            thr = 5.0 if vci_threshold is None else float(vci_threshold)
            for c in convs:
                pen = float(fig13["final_deviation"].sel(convention=c, velocity=v_l))
                rev = int(fig13["reversed"].sel(convention=c, velocity=v_l))
                add(
                    _row(
                        f"Fig. 13: large deviation at Vi = {v_l:g} m/s, {c}",
                        "yes",
                        "yes" if (pen > thr or rev) else "no",
                        "",
                        f"pencore phi = {pen:.3g} deg, reversed = {rev}; 'large' = above "
                        f"the Vci threshold {thr:g} deg",
                        "verdict",
                        "results/fig13/trajectories.nc",
                    )
                )

    # ---- Fig. 15
    if fig15 is not None:
        th = fig15["threshold"].values
        t0 = float(th[np.argmin(np.abs(th - (5.0 if vci_threshold is None else vci_threshold)))])
        for t in th:
            tr = trend(_search_lines(fig15, "vci", "projectile", fixed={"threshold": t}), "falls")
            add(
                _row(
                    f"Fig. 15: Vci against Lc/L (threshold {t:g} deg"
                    f"{', primary' if t == t0 else ''})",
                    "falls",
                    tr.verdict,
                    "",
                    tr.note(),
                    "trend",
                    "results/fig15/vci.nc",
                )
            )
            tr = trend(_search_lines(fig15, "vci", "yaw", fixed={"threshold": t}), "falls")
            add(
                _row(
                    f"Fig. 15: Vci against yaw (threshold {t:g} deg"
                    f"{', primary' if t == t0 else ''})",
                    "falls",
                    tr.verdict,
                    "",
                    tr.note(),
                    "trend",
                    "results/fig15/vci.nc",
                )
            )

    # ---- Figs 16-17
    if fig16 is not None:
        h = float(fig16.attrs.get("start_height_m", 0.0))
        for w, a in PAPER["fig16_alpha_deg"].items():
            if np.any(np.isclose(fig16["omega"], w)):
                pen = float(fig16["final_deviation"].sel(omega=w))
                add(
                    _row(
                        f"Fig. 16: deviation alpha of #2, 1000 m/s, omega = {w:g} rad/s",
                        a,
                        pen,
                        "degree",
                        f"{_pencore_rel(pen, a)}; tip starting {h:g} m above the surface",
                        "value",
                        "results/fig16/trajectories.nc",
                    )
                )
        w = PAPER["fig16_reverses_at"]
        if np.any(np.isclose(fig16["omega"], w)):
            rev = int(fig16["reversed"].sel(omega=w))
            add(
                _row(
                    f"Fig. 16: turns back at omega = {w:g} rad/s (#2, 1000 m/s)",
                    "yes",
                    "yes" if rev else "no",
                    "",
                    f"tip starting {h:g} m above the surface",
                    "verdict",
                    "results/fig16/trajectories.nc",
                )
            )
    if start_height is not None:
        for w in start_height["omega"].values:
            a_paper = PAPER["fig16_alpha_deg"].get(float(w))
            for hh in start_height["start_height"].values:
                pen = float(start_height["alpha"].sel(omega=w, start_height=hh))
                rev = int(start_height["reversed"].sel(omega=w, start_height=hh))
                if a_paper is not None:
                    add(
                        _row(
                            f"Start-height sensitivity: alpha at omega = {w:g} rad/s, tip "
                            f"{hh:g} m above",
                            a_paper,
                            pen,
                            "degree",
                            f"{_pencore_rel(pen, a_paper)}; reversed = {rev}",
                            "value",
                            "results/fig16/start_height.nc",
                        )
                    )
                elif float(w) == PAPER["fig16_reverses_at"]:
                    add(
                        _row(
                            f"Start-height sensitivity: turns back at omega = {w:g} rad/s, "
                            f"tip {hh:g} m above",
                            "yes",
                            "yes" if rev else "no",
                            "",
                            f"alpha = {pen:.3g} deg",
                            "verdict",
                            "results/fig16/start_height.nc",
                        )
                    )

    # ---- Fig. 18
    if fig18 is not None:
        if "p2" in fig18["projectile"].values and np.any(np.isclose(fig18["velocity"], 1000.0)):
            lo_p, hi_p = PAPER["omega_c_p2_1000_bracket"]
            mid = 0.5 * (lo_p + hi_p)
            val, note = _search_value(fig18, "omega_c", {"projectile": "p2", "velocity": 1000.0})
            add(
                _row(
                    "omega_c of #2 at 1000 m/s (Figs 16-17)",
                    mid,
                    val,
                    "rad s-1",
                    f"paper: 20 does not turn back, 25 does (derived: midpoint of (20, 25]); "
                    f"pencore {note}",
                    "value",
                    "results/fig18/omega_c.nc",
                )
            )
        tr = trend(_search_lines(fig18, "omega_c", "velocity"), "falls")
        add(
            _row(
                "Fig. 18: omega_c against impact velocity",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig18/omega_c.nc",
            )
        )
        tr = trend(_search_lines(fig18, "omega_c", "projectile"), "falls")
        add(
            _row(
                "Fig. 18: omega_c against Lc/L",
                "falls",
                tr.verdict,
                "",
                tr.note(),
                "trend",
                "results/fig18/omega_c.nc",
            )
        )

    return pd.DataFrame(rows, columns=_COLUMNS)
