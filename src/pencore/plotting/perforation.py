"""Perforation figures (beyond the paper, issue 11): ballistic limit against slab thickness
and obliquity, and residual velocity against impact velocity with the Recht-Ipson fit."""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from .critical import _search_errorbars
from .style import _MARKERS, _VI, _c, _pname, new_figure, styled

__all__ = ["plot_ballistic_limit", "plot_residual_velocity"]


@styled
def plot_ballistic_limit(ds: xr.Dataset) -> Figure:
    """v_bl against slab thickness, one line per obliquity, with the search brackets."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    th = ds["thickness"].values
    for k, o in enumerate(ds["obliquity"].values):
        sub = ds.sel(obliquity=o)
        _search_errorbars(
            ax, th, sub, "v_bl", _c(k), _MARKERS[k % len(_MARKERS)], f"obliquity {o:g}°"
        )
    ax.set_xlabel("Slab thickness (m)")
    ax.set_ylabel(r"Ballistic limit $v_{bl}$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile', ''))} into {ds.attrs.get('medium', '')} "
        f"(model prediction; bracket ≤ {float(ds.attrs.get('search_tol_m_s', np.nan)):g} m/s)",
        fontsize=9,
    )
    return fig


@styled
def plot_residual_velocity(ds: xr.Dataset) -> Figure:
    """Residual speed of the runs and the fitted Recht-Ipson curve."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    v = ds["velocity"].values
    a, p = ds.attrs["recht_ipson_a"], ds.attrs["recht_ipson_p"]
    vb = ds.attrs["v_bl_m_s"]
    ax.plot(v, ds["residual_velocity"].values, "o", color=_c(0), label="pencore runs")
    if np.isfinite(a) and np.isfinite(vb):
        vf = np.linspace(min(v.min(), vb), v.max(), 400)
        vr = a * np.maximum(vf**p - vb**p, 0.0) ** (1.0 / p)
        ax.plot(
            vf,
            vr,
            "-",
            color=_c(1),
            label=rf"Recht-Ipson, $a$ = {a:.3f}, $p$ = {p:.3f}, $v_{{bl}}$ = {vb:.1f} m/s",
        )
    ax.plot(v, v, ":", color="0.5", lw=0.8, label="$v_r = v_i$")
    ax.set_xlabel(_VI)
    ax.set_ylabel(r"Residual velocity $v_r$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile', ''))}, {ds.attrs.get('medium', '')} slab "
        f"{ds.attrs.get('thickness_m', np.nan):g} m, obliquity "
        f"{ds.attrs.get('obliquity_deg', 0.0):g}° (model prediction)",
        fontsize=9,
    )
    return fig
