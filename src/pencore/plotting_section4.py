"""Figures of the Section 4 studies (paper Figs 7-18).

Same rules as :mod:`pencore.plotting` (object-oriented matplotlib on an Agg canvas, no
pyplot): every ``plot_*`` function takes the study's dataset (from
:mod:`pencore.studies.section4`) and returns a :class:`matplotlib.figure.Figure`; save it
with :func:`pencore.plotting.save_figure`.

The paper's figures plot what it calls "dx/dy"; it is the slope ``dy/dx`` of the path
``y(x)`` (target below ``y = 0``, motion towards ``+x``), and is labelled so here. For
normal impact the slope is near infinite, so Figs 14 and 17 show the same information as
the deviation from the normal, ``phi = 90 deg + atan(dy/dx)``, signed (positive towards
``+x``).
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from .plotting import new_figure, save_figure

__all__ = [
    "save_figure",
    "plot_fig7",
    "plot_fig8",
    "plot_fig9",
    "plot_fig11",
    "plot_fig12",
    "plot_fig13",
    "plot_fig15",
    "plot_fig16",
    "plot_start_height",
    "plot_fig18",
    "PLOTS",
]

_COLOURS = [
    "tab:blue",
    "tab:orange",
    "tab:green",
    "tab:red",
    "tab:purple",
    "tab:brown",
    "tab:pink",
    "tab:gray",
    "tab:olive",
    "tab:cyan",
]
_MARKERS = ["o", "s", "^", "D", "v", "P"]
_VI = r"Impact velocity $V_i$ (m/s)"
_LCL = r"$L_c/L$"


def _c(k: int) -> str:
    return _COLOURS[k % len(_COLOURS)]


def _pname(p: object) -> str:
    s = str(p)
    return f"#{s[1:]}" if s.startswith("p") and s[1:].isdigit() else s


def _finite(*arrays: np.ndarray) -> np.ndarray:
    ok = np.ones(np.shape(arrays[0]), dtype=bool)
    for a in arrays:
        ok &= np.isfinite(a)
    return ok


def _surface(ax) -> None:
    ax.axhline(0.0, color="0.3", lw=0.8)


def _path(ax, sub: xr.Dataset, point: str = "tip", **kw) -> None:
    x, y = sub[f"{point}_x"].values, sub[f"{point}_y"].values
    ok = _finite(x, y)
    ax.plot(x[ok], y[ok], **kw)


def _search_errorbars(
    ax,
    x: np.ndarray,
    sub: xr.Dataset,
    name: str,
    colour: str,
    marker: str,
    label: str,
    jitter: float = 0.0,
) -> None:
    """Converged values with their brackets; out-of-range searches as open triangles at
    the edge of the search range, shifted by ``jitter`` along x so that several
    projectiles stay visible."""
    status = sub["status"].values.astype(str)
    val = sub[name].values
    lo, hi = sub[f"{name}_lo"].values, sub[f"{name}_hi"].values
    ok = np.isin(status, ["ok", "non_monotone"]) & np.isfinite(val)
    if ok.any():
        ax.errorbar(
            x[ok],
            val[ok],
            yerr=[val[ok] - lo[ok], hi[ok] - val[ok]],
            color=colour,
            marker=marker,
            ms=4,
            lw=1.0,
            capsize=2,
            label=label,
        )
    else:
        ax.plot([], [], marker=marker, color=colour, label=label)
    nm = status == "non_monotone"
    if nm.any():
        ax.plot(x[nm], val[nm], marker=marker, ms=10, mfc="none", color=colour, ls="none")
    above = status == "above_range"
    if above.any():
        ax.plot(x[above] + jitter, lo[above], marker="^", ms=7, mfc="none", color=colour, ls="none")
    below = status == "below_range"
    if below.any():
        ax.plot(x[below] + jitter, hi[below], marker="v", ms=7, mfc="none", color=colour, ls="none")


def _jitter(x: np.ndarray, k: int, n: int) -> float:
    span = float(np.ptp(x)) if np.size(x) > 1 else 1.0
    return (k - 0.5 * (n - 1)) * 0.012 * span


def _legend_search(ax) -> None:
    ax.plot([], [], "^", mfc="none", color="0.3", label="above the search range")
    ax.plot([], [], "o", ms=10, mfc="none", color="0.3", label="verdict not monotone")


# ----------------------------------------------------------------------------- Fig. 7


def plot_fig7(ds: xr.Dataset) -> Figure:
    """(a) nose-tip trajectories, (b) slope dy/dx of the centre-of-mass path, against x."""
    fig = new_figure(11.0, 4.4)
    ax1, ax2 = fig.subplots(1, 2)
    for k, v in enumerate(ds["velocity"].values):
        sub = ds.sel(velocity=v)
        rev = int(sub["reversed"])
        lab = f"$V_i$ = {v:g} m/s" + (" (turns back)" if rev else "")
        ls = "--" if rev else "-"
        _path(ax1, sub, "tip", color=_c(k), ls=ls, lw=1.2, label=lab)
        x, s = sub["cm_x"].values, sub["slope"].values
        ok = _finite(x, s)
        ax2.plot(x[ok], s[ok], color=_c(k), ls=ls, lw=1.2, label=lab)
    _surface(ax1)
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title(
        f"(a) nose-tip trajectories, {_pname(ds.attrs.get('projectile'))}, "
        f"$\\varphi_1$ = {ds.attrs.get('obliquity_fixed', 45):g}°",
        fontsize=10,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, frameon=False)
    ax2.axhline(0.0, color="0.3", lw=0.8)
    ax2.set_xlabel("centre of mass x (m)")
    ax2.set_ylabel("slope dy/dx (paper: 'dx/dy')")
    ax2.set_ylim(-1.6, 1.6)
    ax2.set_title("(b) slope of the centre-of-mass path; > 0: moving back up", fontsize=10)
    ax2.grid(alpha=0.3)
    return fig


# ----------------------------------------------------------------------------- Fig. 8


def plot_fig8(ds: xr.Dataset) -> Figure:
    """Vcr against obliquity, one line per projectile, with the search brackets."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    obl = ds["obliquity"].values
    n = ds.sizes["projectile"]
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        _search_errorbars(
            ax,
            obl,
            sub,
            "vcr",
            _c(k),
            _MARKERS[k % len(_MARKERS)],
            f"{_pname(p)}, $L_c/L$ = {float(sub['lc_over_l']):.3f}",
            _jitter(obl, k, n),
        )
    ax.errorbar(
        [45.0],
        [1645.5],
        yerr=[[4.5], [4.5]],
        fmt="*",
        ms=11,
        color="k",
        label="paper, #2 at 45° (1641 < $V_{cr}$ ≤ 1650)",
    )
    _legend_search(ax)
    ax.set_xlabel(r"Angle of obliquity $\varphi_1$ (deg)")
    ax.set_ylabel(r"Critical reverse velocity $V_{cr}$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, frameon=False)
    rng = ds.attrs.get("search_range_m_s")
    if rng is not None:
        ax.set_title(
            f"search {float(rng[0]):g}-{float(rng[1]):g} m/s, bracket ≤ "
            f"{float(ds.attrs.get('tolerance_m_s', np.nan)):g} m/s",
            fontsize=9,
        )
    return fig


# ----------------------------------------------------------------------------- Fig. 9


def plot_fig9(ds: xr.Dataset) -> Figure:
    """(a) trajectories with Points 1 and 2, (b) turning angle against Lc/L."""
    fig = new_figure(11.0, 4.4)
    ax1, ax2 = fig.subplots(1, 2)
    f0 = float(ds.attrs.get("primary_bracket_fraction", 0.05))
    fr = ds["bracket_fraction"].values
    j0 = int(np.argmin(np.abs(fr - f0)))
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        _path(ax1, sub, "cm", color=_c(k), lw=1.2, label=_pname(p))
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
            marker="o" if j == j0 else ".",
            lw=1.5 if j == j0 else 0.6,
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


# ----------------------------------------------------------------------------- Figs 11-12


def plot_fig11(ds: xr.Dataset) -> Figure:
    """(a) trajectories for yaw -1 and +1 deg, (b) axis angle theta along the path."""
    fig = new_figure(11.0, 4.4)
    ax1, ax2 = fig.subplots(1, 2)
    for k, y in enumerate(ds["yaw"].values):
        sub = ds.sel(yaw=y)
        lab = (
            f"$\\varphi_2$ = {y:g}°, ends {sub['outcome'].item()}, nose "
            f"{sub['nose_direction'].item()}"
        )
        _path(ax1, sub, "tip", color=_c(k), lw=1.2, label=lab)
        x, th = sub["cm_x"].values, sub["theta"].values
        ok = _finite(x, th)
        ax2.plot(x[ok], th[ok], color=_c(k), lw=1.2, label=lab)
    _surface(ax1)
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title(
        f"(a) nose-tip paths, {_pname(ds.attrs.get('projectile'))}, $V_i$ = "
        f"{ds.attrs.get('velocity_fixed', 1000):g} m/s, $\\varphi_1$ = "
        f"{ds.attrs.get('obliquity_fixed', 30):g}°",
        fontsize=10,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, frameon=False)
    ax2.axhline(90.0, color="0.5", lw=0.6, ls=":")
    ax2.axhline(180.0, color="0.5", lw=0.6, ls=":")
    ax2.set_xlabel("centre of mass x (m)")
    ax2.set_ylabel(r"axis angle from the normal $\theta$ (deg)")
    ax2.set_title("(b) > 90°: nose above horizontal; > 180°: nose towards −x", fontsize=10)
    ax2.grid(alpha=0.3)
    return fig


def plot_fig12(ds: xr.Dataset) -> Figure:
    """Vcr against yaw, one panel per obliquity; filled: nose +x at Vcr, cross: -x."""
    obls = ds["obliquity"].values
    fig = new_figure(5.0 * len(obls) + 0.5, 4.6)
    axes = fig.subplots(1, len(obls), squeeze=False)[0]
    yaw = ds["yaw"].values
    for ax, ob in zip(axes, obls, strict=True):
        for k, p in enumerate(ds["projectile"].values):
            sub = ds.sel(projectile=p, obliquity=ob)
            _search_errorbars(
                ax,
                yaw,
                sub,
                "vcr",
                _c(k),
                _MARKERS[k % len(_MARKERS)],
                f"{_pname(p)}, $L_c/L$ = {float(sub['lc_over_l']):.3f}",
                _jitter(yaw, k, ds.sizes["projectile"]),
            )
            if "nose_direction" in sub:
                nd = sub["nose_direction"].values.astype(str)
                m = nd == "-x"
                if m.any():
                    ax.plot(yaw[m], sub["vcr"].values[m], "x", ms=10, mew=2, color=_c(k), ls="none")
        ax.plot([], [], "x", ms=8, mew=2, color="0.3", label="nose ends pointing −x")
        _legend_search(ax)
        ax.set_xlabel(r"Yaw angle $\varphi_2$ (deg)")
        ax.set_ylabel(r"$V_{cr}$ (m/s)")
        ax.set_title(f"$\\varphi_1$ = {ob:g}°", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, frameon=False)
    return fig


# ----------------------------------------------------------------------------- Figs 13-15


def plot_fig13(ds: xr.Dataset) -> Figure:
    """(a) nose-tip paths, (b) signed deviation phi against depth; both yaw conventions."""
    fig = new_figure(11.0, 4.6)
    ax1, ax2 = fig.subplots(1, 2)
    styles = {"axis_tilted": "-", "velocity_tilted": ":"}
    for k, v in enumerate(ds["velocity"].values):
        for c in ds["convention"].values:
            sub = ds.sel(velocity=v, convention=c)
            lab = f"$V_i$ = {v:g} m/s, {c}: $\\varphi$ = {float(sub['final_deviation']):.3g}°"
            _path(ax1, sub, "tip", color=_c(k), ls=styles.get(str(c), "--"), lw=1.2, label=lab)
            y, d = sub["tip_y"].values, sub["deviation_signed"].values
            ok = _finite(y, d)
            ax2.plot(d[ok], y[ok], color=_c(k), ls=styles.get(str(c), "--"), lw=1.2)
    _surface(ax1)
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title(
        f"(a) {_pname(ds.attrs.get('projectile'))}, yaw "
        f"{ds.attrs.get('yaw_deg', 0.1):g}°; paper $\\varphi$: 0.16° (280), "
        "0.24° (1000), large (2200)",
        fontsize=9,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=6.5, frameon=False)
    ax2.set_xscale("symlog", linthresh=0.1)
    ax2.set_xlabel(r"deviation from the normal $\varphi$ = 90° + atan(dy/dx) (deg, signed)")
    ax2.set_ylabel("nose-tip y (m)")
    ax2.set_title("(b) solid: axis tilted (velocity normal); dotted: velocity tilted", fontsize=9)
    ax2.grid(alpha=0.3, which="both")
    return fig


def plot_fig15(ds: xr.Dataset, threshold: float | None = None) -> Figure:
    """Vci against Lc/L, one line per yaw, at each deviation threshold."""
    ths = ds["threshold"].values
    t0 = float(ds.attrs.get("primary_threshold_deg", 5.0) if threshold is None else threshold)
    j0 = int(np.argmin(np.abs(ths - t0)))
    fig = new_figure(6.6, 4.8)
    ax = fig.add_subplot()
    lcl = ds["lc_over_l"].values
    for k, y in enumerate(ds["yaw"].values):
        for j, t in enumerate(ths):
            sub = ds.sel(yaw=y, threshold=t)
            if j == j0:
                _search_errorbars(
                    ax,
                    lcl,
                    sub,
                    "vci",
                    _c(k),
                    _MARKERS[k % len(_MARKERS)],
                    f"$\\varphi_2$ = {y:g}°, threshold {t:g}°",
                    _jitter(lcl, k, ds.sizes["yaw"]),
                )
            else:
                v = sub["vci"].values
                ok = np.isfinite(v)
                ax.plot(lcl[ok], v[ok], ls=":" if t < ths[j0] else "--", lw=0.8, color=_c(k))
    for j, t in enumerate(ths):
        if j != j0:
            ax.plot(
                [],
                [],
                ls=":" if t < ths[j0] else "--",
                lw=0.8,
                color="0.3",
                label=f"threshold {t:g}°",
            )
    _legend_search(ax)
    for p, x in zip(ds["projectile"].values, lcl, strict=True):
        ax.annotate(
            _pname(p),
            (x, 0),
            xycoords=("data", "axes fraction"),
            xytext=(0, 3),
            textcoords="offset points",
            ha="center",
            fontsize=8,
        )
    ax.set_xlabel(_LCL)
    ax.set_ylabel(r"Critical impact velocity $V_{ci}$ (m/s)")
    ax.set_title(
        f"normal impact with yaw ({ds.attrs.get('yaw_convention', '?')}); "
        "unstable: reverses or final deviation > threshold",
        fontsize=9,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, frameon=False)
    return fig


# ----------------------------------------------------------------------------- Figs 16-18


def plot_fig16(ds: xr.Dataset) -> Figure:
    """(a) nose-tip paths for each omega, (b) signed deviation alpha against depth."""
    fig = new_figure(11.0, 4.6)
    ax1, ax2 = fig.subplots(1, 2)
    paper = {5.0: "0.14°", 20.0: "2.86°", 25.0: "turns back"}
    for k, w in enumerate(ds["omega"].values):
        sub = ds.sel(omega=w)
        lab = (
            f"ω = {w:g} rad/s: α = {float(sub['final_deviation']):.3g}°"
            + (", turns back" if int(sub["reversed"]) else "")
            + (f" (paper {paper[float(w)]})" if float(w) in paper else "")
        )
        _path(ax1, sub, "tip", color=_c(k), lw=1.2, label=lab)
        y, d = sub["tip_y"].values, sub["deviation_signed"].values
        ok = _finite(y, d)
        ax2.plot(d[ok], y[ok], color=_c(k), lw=1.2, label=lab)
    _surface(ax1)
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title(
        f"(a) {_pname(ds.attrs.get('projectile'))}, $V_i$ = "
        f"{ds.attrs.get('velocity_fixed', 1000):g} m/s, tip starting "
        f"{ds.attrs.get('start_height_m', 0):g} m above",
        fontsize=10,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, frameon=False)
    ax2.set_xlabel(r"deviation from the normal α (deg, signed)")
    ax2.set_ylabel("nose-tip y (m)")
    ax2.set_title("(b) deviation along the path", fontsize=10)
    ax2.grid(alpha=0.3)
    return fig


def plot_start_height(ds: xr.Dataset) -> Figure:
    """alpha against the start height of the nose tip, one line per omega."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    h = ds["start_height"].values
    paper = {5.0: 0.14, 20.0: 2.86}
    for k, w in enumerate(ds["omega"].values):
        sub = ds.sel(omega=w)
        a = sub["alpha"].values
        rev = sub["reversed"].values.astype(bool)
        ax.plot(h, a, marker="o", color=_c(k), label=f"ω = {w:g} rad/s")
        if rev.any():
            ax.plot(h[rev], a[rev], "*", ms=12, color=_c(k), ls="none")
        if float(w) in paper:
            ax.axhline(paper[float(w)], color=_c(k), ls="--", lw=0.8)
    ax.plot([], [], "--", color="0.3", lw=0.8, label="paper (start height not stated)")
    ax.plot([], [], "*", ms=10, color="0.3", ls="none", label="turns back (paper: at ω = 25 rad/s)")
    ax.set_yscale("log")
    ax.set_xlabel("nose-tip height above the surface at the start (m)")
    ax.set_ylabel("deviation α (deg)")
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile'))}, $V_i$ = "
        f"{ds.attrs.get('velocity_m_s', 1000):g} m/s, normal impact with spin",
        fontsize=10,
    )
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, frameon=False)
    return fig


def plot_fig18(ds: xr.Dataset) -> Figure:
    """omega_c against impact velocity, one line per projectile."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    v = ds["velocity"].values
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        _search_errorbars(
            ax,
            v,
            sub,
            "omega_c",
            _c(k),
            _MARKERS[k % len(_MARKERS)],
            f"{_pname(p)}, $L_c/L$ = {float(sub['lc_over_l']):.3f}",
            _jitter(v, k, ds.sizes["projectile"]),
        )
    ax.errorbar(
        [1000.0],
        [22.5],
        yerr=[[2.5], [2.5]],
        fmt="*",
        ms=11,
        color="k",
        label="paper, #2 at 1000 m/s (20 < ω_c ≤ 25)",
    )
    _legend_search(ax)
    ax.set_xlabel(_VI)
    ax.set_ylabel(r"Critical angular velocity $\omega_c$ (rad/s)")
    rng = ds.attrs.get("search_range_rad_s")
    if rng is not None:
        ax.set_title(
            f"search {float(rng[0]):g}-{float(rng[1]):g} rad/s; tip starting "
            f"{float(ds.attrs.get('start_height_m', 0)):g} m above",
            fontsize=9,
        )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, frameon=False)
    return fig


#: Figure kind (as used by the workflow) -> plotting function.
PLOTS = {
    "fig7": plot_fig7,
    "fig8": plot_fig8,
    "fig9": plot_fig9,
    "fig11": plot_fig11,
    "fig12": plot_fig12,
    "fig13": plot_fig13,
    "fig15": plot_fig15,
    "fig16": plot_fig16,
    "start_height": plot_start_height,
    "fig18": plot_fig18,
}
