"""Penetration-depth figures of Section 3: Table 2 bars, Fig. 5 and the verification runs.

Notation follows the paper: impact velocity ``V_i``, calibre radius head ``CRH``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.plotting.style import _DEPTH, _VI, _c, new_figure, styled

__all__ = ["plot_table2", "plot_fig5", "plot_verification"]


_TARGET_TITLES = {
    "concrete": "Concrete (Forrestal et al. 1994)",
    "aluminium": "Aluminium 6061-T6511 (Piekutowski et al. 1999)",
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


@styled
def plot_fig5(ds: xr.Dataset) -> Figure:
    """Depth against impact velocity, one panel per target (paper Fig. 5).

    Thin lines with dots: pencore; wide pale lines: the closed form; open symbols: experiments
    (from the dataset's ``experiment`` dimension, when it has points).
    """
    targets = list(dict.fromkeys(str(t) for t in ds["target"].values))
    fig = new_figure(4.0 * len(targets) + 0.6, 4.2)
    axes = fig.subplots(1, len(targets), squeeze=False)[0]
    colours = ["tab:blue", "tab:red", "tab:green", "tab:purple", "tab:brown", "tab:olive"]
    markers = ["o", "s", "^", "D", "v", "P"]
    n_exp = ds.sizes.get("experiment", 0)
    for ax, tgt in zip(axes, targets, strict=True):
        sel = [
            str(c)
            for c, t in zip(ds["case"].values, ds["target"].values, strict=True)
            if str(t) == tgt
        ]
        for k, c in enumerate(sel):
            sub = ds.sel(case=c)
            col, mk = colours[k % len(colours)], markers[k % len(markers)]
            lab = _crh_label(float(sub["crh"])) or str(sub["label"].item())
            v = ds["velocity"].values
            # the two agree to a fraction of a percent: closed form as a wide pale band
            # underneath, pencore as a thin line with dots on top
            ok = np.isfinite(sub["closedform_depth"].values)
            ax.plot(
                v[ok],
                sub["closedform_depth"].values[ok],
                "-",
                color=col,
                lw=5.0,
                alpha=0.25,
                solid_capstyle="round",
                label=f"{lab}, closed form",
            )
            ok = np.isfinite(sub["pencore_depth"].values)
            ax.plot(
                v[ok],
                sub["pencore_depth"].values[ok],
                "-",
                marker=".",
                color=col,
                lw=1.0,
                label=f"{lab}, pencore",
            )
            if n_exp:
                e = ds["experiment_case"].values.astype(str) == c
                if e.any():
                    ax.plot(
                        ds["experiment_velocity"].values[e],
                        ds["experiment_depth"].values[e],
                        mk,
                        mfc="none",
                        color=col,
                        ls="none",
                        label=f"{lab}, experiment",
                    )
        ax.set_title(_TARGET_TITLES.get(tgt, tgt), fontsize=10)
        ax.set_xlabel(_VI)
        ax.set_ylabel(_DEPTH)
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, frameon=False)
        if not n_exp:
            ax.text(
                0.98,
                0.02,
                "no experimental points supplied",
                transform=ax.transAxes,
                ha="right",
                va="bottom",
                fontsize=7,
                color="0.4",
            )
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
