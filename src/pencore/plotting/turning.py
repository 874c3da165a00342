"""Fig. 9: the total turning angle d(theta)_12 against Lc/L."""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import hint_keywords
from pencore.plotting.style import _LCL, _LINESTYLES, _MARKERS, _c, _pname, new_figure, styled
from pencore.plotting.trajectories import _path, _surface

__all__ = ["plot_fig9"]


@styled
def plot_fig9(ds: xr.Dataset) -> Figure:
    """(a) trajectories with Points 1 and 2, (b) turning angle against Lc/L."""
    fig = new_figure(11.0, 4.4)
    ax1, ax2 = fig.subplots(1, 2)
    f0 = float(ds.attrs.get("primary_bracket_fraction", 0.05))
    fr = ds["bracket_fraction"].values
    j0 = int(np.argmin(np.abs(fr - f0)))
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        # the four paths nearly coincide: colour, line style and marker each tell them apart
        _path(
            ax1,
            sub,
            "cm",
            color=_c(k),
            lw=1.2,
            ls=_LINESTYLES[k % len(_LINESTYLES)],
            marker=_MARKERS[k % len(_MARKERS)],
            markevery=(0.1 + 0.05 * k, 0.2),
            ms=5,
            label=_pname(p),
        )
        ax1.plot(
            [float(sub["x_1"][j0]), float(sub["x_2"][j0])],
            [float(sub["y_1"][j0]), float(sub["y_2"][j0])],
            "o",
            mfc="none",
            color=_c(k),
        )
    _surface(ax1)
    ax1.set_xlabel("centre of mass x (m)")
    ax1.set_ylabel("centre of mass y (m)")
    ax1.set_title(
        f"(a) $\\varphi_1$ = {ds.attrs.get('obliquity_deg', 45):g}°, $V_i$ = "
        f"{ds.attrs.get('velocity_m_s', 1000):g} m/s; ○ Points 1 and 2",
        fontsize=10,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, frameon=False)
    lcl = ds["lc_over_l"].values
    for j, f in enumerate(fr):
        ax2.plot(
            lcl,
            ds["delta_theta"].values[:, j],
            # the fractions give nearly the same angles: distinct markers, sizes and styles
            marker=_MARKERS[j % len(_MARKERS)],
            ms=9 - 1.5 * j,
            mfc="none" if j != j0 else None,
            ls=_LINESTYLES[j % len(_LINESTYLES)],
            lw=1.5 if j == j0 else 0.9,
            color="k" if j == j0 else _c(j),
            label=f"Points at {f:g} of peak curvature" + (" (primary)" if j == j0 else ""),
        )
    ax2.plot(
        lcl,
        ds["delta_theta_sign_change"].values,
        "s--",
        mfc="none",
        color="0.4",
        lw=0.8,
        label="first/last sign change of $d^2y/dx^2$",
    )
    for p, x, y in zip(ds["projectile"].values, lcl, ds["delta_theta"].values[:, j0], strict=True):
        ax2.annotate(_pname(p), (x, y), xytext=(3, 3), textcoords="offset points", fontsize=8)
    ax2.set_xlabel(_LCL)
    ax2.set_ylabel(r"Total turning angle $\Delta\theta_{12}$ (deg)")
    ax2.set_title(r"(b) $\Delta\theta_{12} = \theta_2 - \theta_1$ (Eq. 12)", fontsize=10)
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=7, frameon=False)
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
