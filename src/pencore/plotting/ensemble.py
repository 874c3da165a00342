"""Ensemble figure: distributions of the outcomes of N drawn impacts, and the
convergence of the estimates against N."""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import hint_keywords
from pencore.plotting.style import _c, _pname, new_figure, styled

__all__ = ["plot_ensemble"]


@styled
def plot_ensemble(ds: xr.Dataset) -> Figure:
    """Four panels: (a) penetration depth, (b) downrange travel and (c) final deviation
    as histograms split by whether the run turned back, with the 5/50/95 % quantiles;
    (d) the running probability of turning back and the running mean depth against N,
    with their 95 % intervals (Wilson; Student t)."""
    fig = new_figure(11.0, 7.0)
    axes = fig.subplots(2, 2)
    rev = ds["reversed"].values.astype(bool)
    for ax, (name, label) in zip(
        axes.flat[:3],
        [
            ("penetration_depth", "Penetration depth of the tip (m)"),
            ("downrange", "Downrange travel of the tip (m)"),
            ("final_deviation", "Final deviation from the normal (deg)"),
        ],
        strict=True,
    ):
        x = ds[name].values
        bins = np.histogram_bin_edges(x[np.isfinite(x)], bins=30)
        ax.hist([x[~rev], x[rev]], bins=bins, stacked=True, color=[_c(0), _c(1)],
                label=["did not turn back", "turned back"])  # fmt: skip
        for q, v in zip(ds["quantile"].values, ds[f"{name}_quantile"].values, strict=True):
            ax.axvline(v, color="0.2", ls=":", lw=1)
            ax.annotate(f"{q:.0%}", (v, 1.0), xycoords=("data", "axes fraction"),
                        ha="center", va="bottom", fontsize=7)  # fmt: skip
        ax.set_xlabel(label)
        ax.set_ylabel("Samples")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8, frameon=False)
    ax = axes[1, 1]
    n = ds["n_used"].values
    ci = ds["running_p_reversed_ci95"].values
    ax.fill_between(n, ci[:, 0], ci[:, 1], color=_c(1), alpha=0.25, lw=0)
    ax.plot(n, ds["running_p_reversed"].values, "o-", color=_c(1), ms=3,
            label="P(turns back), Wilson 95 %")  # fmt: skip
    ax.set_xscale("log", base=2)
    ax.set_xlabel("Number of samples N")
    ax.set_ylabel("Probability of turning back", color=_c(1))
    ax.set_ylim(0, 1)
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    cd = ds["running_depth_mean_ci95"].values
    ax2.fill_between(n, cd[:, 0], cd[:, 1], color=_c(0), alpha=0.2, lw=0)
    ax2.plot(n, ds["running_depth_mean"].values, "s-", color=_c(0), ms=3,
             label="mean depth, t 95 %")  # fmt: skip
    ax2.set_ylabel("Mean penetration depth (m)", color=_c(0))
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8, frameon=False, loc="upper right")
    p, (lo, hi) = float(ds["p_reversed"]), ds["p_reversed_ci95"].values
    fig.suptitle(
        f"{_pname(ds.attrs.get('projectile', ''))} into {ds.attrs.get('target', '')}: "
        f"N = {ds.sizes['sample']}, P(turns back) = {p:.3f} [{lo:.3f}, {hi:.3f}]",
        fontsize=10,
    )
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
