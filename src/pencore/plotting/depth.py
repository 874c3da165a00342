"""Penetration-depth figures of Section 3: Table 2 bars, Fig. 5 and the verification runs.

Notation follows the paper: impact velocity ``V_i``, calibre radius head ``CRH``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import hint_keywords
from pencore.plotting.style import (
    _DEPTH,
    _LINESTYLES,
    _MARKERS,
    _VI,
    _c,
    _pname,
    new_figure,
    styled,
)

__all__ = ["plot_table2", "plot_fig5", "plot_verification"]


_ALUMINIUM = "Aluminium 6061-T6511"
_TARGET_TITLES = {
    "concrete": "Grout, fc 13.5 MPa (Forrestal et al. 1996, via a compilation)",
    "aluminium": _ALUMINIUM,
    "aluminium_3term": _ALUMINIUM,
    "soil": "Soil (Forrestal & Luk 1992)",
}


def _crh_label(crh: float) -> str:
    if not np.isfinite(crh):
        return ""
    if abs(crh - 0.5) < 1e-12:
        return "CRH = 0.5 (hemisphere)"
    return f"CRH = {crh:g}"


@styled
def plot_table2(ds: xr.Dataset) -> Figure:
    """Measured, paper-predicted and pencore depths of the Table 2 soil tests (bars)."""
    fig = new_figure(7.0, 4.2)
    ax = fig.add_subplot()
    tests = ds["test"].values
    x = np.arange(tests.size)
    w = 0.27
    p = ds.attrs.get("chosen_projectile", "?")
    m = str(ds.attrs.get("chosen_depth_measure", "?")).replace("_", " ")
    bars = [
        ("measured_depth", "Experiment (Forrestal & Luk 1992)", "0.35"),
        ("paper_predicted_depth", "Li & Flores-Johnson (2011), Table 2", "tab:blue"),
        (
            "pencore_depth",
            f"pencore, projectile #{p[1:] if p.startswith('p') else p}, {m}",
            "tab:orange",
        ),
    ]
    for k, (var, label, colour) in enumerate(bars):
        vals = ds[var].values
        ax.bar(x + (k - 1) * w, vals, w, label=label, color=colour)
        for xi, v in zip(x + (k - 1) * w, vals, strict=True):
            ax.annotate(
                f"{v:.2f}",
                (xi, v),
                ha="center",
                va="bottom",
                fontsize=7,
                xytext=(0, 1),
                textcoords="offset points",
            )
    labels = [
        f"#{int(t)}\n$V_i$={v:g} m/s\n$\\varphi_1$={o:g}°, $\\varphi_2$={y:g}°"
        for t, v, o, y in zip(
            tests, ds["velocity"].values, ds["obliquity"].values, ds["yaw"].values, strict=True
        )
    ]
    ax.set_xticks(x, labels, fontsize=8)
    ax.set_xlabel("Test (paper Table 2)")
    ax.set_ylabel(_DEPTH)
    ax.set_ylim(0, 1.08 * float(np.nanmax([ds[v].values.max() for v, _, _ in bars])))
    fig.legend(loc="outside upper center", ncol=2, fontsize=8, frameon=False)
    return fig


def _fig5_panels(ds: xr.Dataset) -> dict[tuple[float, float], list[str]]:
    """Cases grouped into panels: one per target density and nose (CRH), in case order."""
    panels: dict[tuple[float, float], list[str]] = {}
    dens = ds["target_density"].values if "target_density" in ds.coords else None
    for k, c in enumerate(ds["case"].values):
        rho = float(dens[k]) if dens is not None else float("nan")
        key = (round(rho, 6), round(float(ds["crh"].values[k]), 6))
        panels.setdefault(key, []).append(str(c))
    return panels


_LAW_LABELS = {
    "concrete": "paper's Table 1 law",
    "soil": "paper's Table 1 law",
    "aluminium": "paper's Table 1 law",
    "aluminium_3term": "source's three-term law",
}


@styled
def plot_fig5(ds: xr.Dataset) -> Figure:
    """Depth against impact velocity, one panel per target and nose (paper Fig. 5).

    Colour: the target's law; line style: the projectile. Lines with dots: pencore; wide
    pale lines: the closed form with exact nose entry; dotted: the closed form with the
    full nose force from first contact (the sources' Eq. 1). Measured shots: filled when
    the projectile stayed rigid by its authors' limits, open when it deformed or eroded.
    """
    from matplotlib.lines import Line2D

    panels = _fig5_panels(ds)
    ncol = 2 if len(panels) > 1 else 1
    nrow = -(-len(panels) // ncol)
    fig = new_figure(5.2 * ncol, 3.9 * nrow + 0.9)
    axes = fig.subplots(nrow, ncol, squeeze=False).ravel()
    v = ds["velocity"].values
    n_exp = ds.sizes.get("experiment", 0)
    targets = list(dict.fromkeys(str(t) for t in ds["target"].values))
    projectiles = list(dict.fromkeys(str(p) for p in ds["projectile"].values))
    colour = {t: _c(k) for k, t in enumerate(targets)}
    style = {p: _LINESTYLES[k % len(_LINESTYLES)] for k, p in enumerate(projectiles)}
    marker = {p: _MARKERS[k % len(_MARKERS)] for k, p in enumerate(projectiles)}
    for ax in axes[len(panels) :]:
        ax.set_visible(False)
    for ax, cases in zip(axes, panels.values(), strict=False):
        shown = []
        for c in cases:
            sub = ds.sel(case=c)
            tgt, prj = str(sub["target"].item()), str(sub["projectile"].item())
            col, ls = colour[tgt], style[prj]
            ok = np.isfinite(sub["pencore_depth"].values)
            ax.plot(v[ok], sub["closedform_depth"].values[ok], "-", color=col, lw=5.0,
                    alpha=0.22, solid_capstyle="round")  # fmt: skip
            if "cavity_form_depth" in sub:
                ax.plot(v[ok], sub["cavity_form_depth"].values[ok], ":", color=col, lw=1.2)
            ax.plot(v[ok], sub["pencore_depth"].values[ok], ls, marker=".", ms=4, color=col,
                    lw=1.0)  # fmt: skip
            if prj not in shown:
                shown.append(prj)
        if n_exp:
            for prj in shown:
                e = ds["experiment_projectile"].values.astype(str) == prj
                rigid = ds["experiment_rigid"].values.astype(bool)
                for keep, fill in ((e & rigid, "k"), (e & ~rigid, "none")):
                    ax.plot(ds["experiment_velocity"].values[keep],
                            ds["experiment_depth"].values[keep], marker[prj], mfc=fill,
                            mec="k", ms=5, ls="none")  # fmt: skip
        first = ds.sel(case=cases[0])
        tgt = str(first["target"].item())
        title = _TARGET_TITLES.get(tgt, tgt)
        crh = _crh_label(float(first["crh"]))
        ax.set_title(f"{title}\n{crh}", fontsize=9)
        ax.set_xlabel(_VI)
        ax.set_ylabel(_DEPTH)
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        handles = [
            Line2D([], [], color=colour[t], lw=1.2, label=_LAW_LABELS.get(t, t))
            for t in dict.fromkeys(str(ds.sel(case=c)["target"].item()) for c in cases)
        ]
        handles += [
            Line2D(
                [], [], color="0.3", ls=style[p], marker=marker[p], ms=5, mfc="0.3", label=_pname(p)
            )  # fmt: skip
            for p in shown
        ]
        ax.legend(handles=handles, fontsize=7, frameon=False, loc="upper left")
    key = [
        Line2D([], [], color="0.3", marker=".", lw=1.0, label="pencore (normal, no yaw)"),
        Line2D([], [], color="0.3", lw=5.0, alpha=0.22, label="closed form, exact nose entry"),
        Line2D(
            [],
            [],
            color="0.3",
            ls=":",
            lw=1.2,
            label="closed form, full nose force from contact (sources' Eq. 1)",
        ),  # fmt: skip
        Line2D([], [], color="k", marker="o", ls="none", label="measured, rigid"),
        Line2D(
            [],
            [],
            color="k",
            marker="o",
            mfc="none",
            ls="none",
            label="measured, deformed or eroded",
        ),  # fmt: skip
    ]
    fig.legend(handles=key, loc="outside lower center", ncol=3, fontsize=7, frameon=False)
    return fig


@styled
def plot_verification(ds: xr.Dataset, cases: Sequence[str] | None = None) -> Figure:
    """pencore (symbols) against the closed form (lines), and their relative difference."""
    fig = new_figure(6.4, 6.0)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[2, 1])
    v = ds["velocity"].values
    for k, c in enumerate(cases or [str(c) for c in ds["case"].values]):
        sub = ds.sel(case=c)
        col = _c(k)
        lab = f"{sub['projectile'].item()} into {sub['target'].item()}"
        ok = np.isfinite(sub["pencore_depth"].values)
        ax1.plot(v[ok], sub["closedform_depth"].values[ok], "-", color=col, lw=1.0)
        ax1.plot(v[ok], sub["pencore_depth"].values[ok], "o", mfc="none", color=col, label=lab)
        ax2.plot(v[ok], 100.0 * sub["rel_diff"].values[ok], "o-", color=col, ms=3, lw=0.8)
    ax1.set_yscale("log")
    ax1.set_ylabel(_DEPTH)
    ax1.grid(alpha=0.3, which="both")
    ax1.plot([], [], "-", color="k", lw=1.0, label="closed form (lines)")
    ax1.legend(fontsize=7, frameon=False, ncol=2)
    ax1.set_title(
        "Normal frictionless impact: pencore (symbols) and closed form (lines)", fontsize=10
    )
    ax2.axhline(0.0, color="k", lw=0.6)
    ax2.set_xlabel(_VI)
    ax2.set_ylabel("(pencore − closed form) /\nclosed form (%)")
    ax2.grid(alpha=0.3)
    mx = float(ds["max_abs_rel_diff"]) if "max_abs_rel_diff" in ds else np.nan
    if np.isfinite(mx):
        ax2.set_title(f"largest |difference| = {100 * mx:.2g} %", fontsize=9)
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
