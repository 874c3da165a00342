"""Trajectory figures of Section 4: Figs 7, 11, 13-14, 16-17 and the start-height study.

The paper's figures plot what it calls "dx/dy"; it is the slope ``dy/dx`` of the path
``y(x)`` (target below ``y = 0``, motion towards ``+x``), and is labelled so here. For
normal impact the slope is near infinite, so Figs 14 and 17 show the same information as
the deviation from the normal, ``phi = 90 deg + atan(dy/dx)``, signed (positive towards
``+x``).
"""

from __future__ import annotations

import xarray as xr
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter

from pencore.errors import hint_keywords
from pencore.plotting.style import _c, _finite, _pname, convention_label, new_figure, styled

__all__ = ["plot_fig7", "plot_fig11", "plot_fig13", "plot_fig16", "plot_start_height"]


def _surface(ax) -> None:
    ax.axhline(0.0, color="0.3", lw=0.8)


def _path(ax, sub: xr.Dataset, point: str = "tip", **kw) -> None:
    x, y = sub[f"{point}_x"].values, sub[f"{point}_y"].values
    ok = _finite(x, y)
    ax.plot(x[ok], y[ok], **kw)


@styled
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


@styled
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


@styled
def plot_fig13(ds: xr.Dataset) -> Figure:
    """(a) nose-tip paths, (b) signed deviation phi against depth; both yaw conventions."""
    fig = new_figure(11.0, 4.6)
    ax1, ax2 = fig.subplots(1, 2)
    styles = {"axis_tilted": "-", "velocity_tilted": ":"}
    for k, v in enumerate(ds["velocity"].values):
        for c in ds["convention"].values:
            sub = ds.sel(velocity=v, convention=c)
            y, d = sub["tip_y"].values, sub["deviation_signed"].values
            ok = _finite(y, d)
            # the legend carries the sign that panel (b) shows (final_deviation is |phi|)
            sign = -1.0 if ok.any() and d[ok][-1] < 0 else 1.0
            phi = sign * float(sub["final_deviation"])
            lab = f"$V_i$ = {v:g} m/s, {convention_label(c)}: $\\varphi$ = {phi:.3g}°"
            _path(ax1, sub, "tip", color=_c(k), ls=styles.get(str(c), "--"), lw=1.2, label=lab)
            ax2.plot(d[ok], y[ok], color=_c(k), ls=styles.get(str(c), "--"), lw=1.2)
    _surface(ax1)
    ax1.set_xlabel("x (m)")
    ax1.set_ylabel("y (m)")
    ax1.set_title(
        f"(a) {_pname(ds.attrs.get('projectile'))}, yaw "
        f"{ds.attrs.get('yaw_deg', 0.1):g}°; paper $\\varphi$: {_paper_fig13()}",
        fontsize=9,
    )
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=6.5, frameon=False)
    ax2.set_xscale("symlog", linthresh=0.1)
    # plain signed numbers: the default symlog labels read "-10^0" for -1
    ax2.xaxis.set_major_formatter(FuncFormatter(lambda x, _pos: f"{x:g}".replace("-", "\u2212")))
    ax2.set_xlabel(r"deviation from the normal $\varphi$ = 90° + atan(dy/dx) (deg, signed)")
    ax2.set_ylabel("nose-tip y (m)")
    ax2.set_title("(b) solid: axis tilted (velocity normal); dotted: velocity tilted", fontsize=9)
    ax2.grid(alpha=0.3, which="both")
    return fig


@styled
def plot_fig16(ds: xr.Dataset) -> Figure:
    """(a) nose-tip paths for each omega, (b) signed deviation alpha against depth."""
    fig = new_figure(11.0, 4.6)
    ax1, ax2 = fig.subplots(1, 2)
    pv = _paper_values()
    paper = {w: f"{a:g}°" for w, a in pv["fig16_alpha_deg"].items()}
    paper[pv["fig16_reverses_at"]] = "turns back"
    for k, w in enumerate(ds["omega"].values):
        sub = ds.sel(omega=w)
        lab = (
            f"ω = {w:g} rad/s: $\\varphi$ = {float(sub['final_deviation']):.3g}°"
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
    ax2.set_xlabel(r"deviation from the normal $\varphi$ (deg, signed)")
    ax2.set_ylabel("nose-tip y (m)")
    ax2.set_title("(b) deviation along the path", fontsize=10)
    ax2.grid(alpha=0.3)
    return fig


@styled
def plot_start_height(ds: xr.Dataset) -> Figure:
    """alpha against the start height of the nose tip, one line per omega."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    h = ds["start_height"].values
    pv = _paper_values()
    paper = pv["fig16_alpha_deg"]
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
    ax.plot(
        [],
        [],
        "*",
        ms=10,
        color="0.3",
        ls="none",
        label=f"turns back (paper: at ω = {pv['fig16_reverses_at']:g} rad/s)",
    )
    ax.set_yscale("log")
    ax.set_xlabel("nose-tip height above the surface at the start (m)")
    ax.set_ylabel(r"deviation $\varphi$ (deg)")
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile'))}, $V_i$ = "
        f"{ds.attrs.get('velocity_m_s', 1000):g} m/s, normal impact with spin",
        fontsize=10,
    )
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, frameon=False)
    return fig


def _paper_values() -> dict:
    """The paper's numbers of Sect. 4.3 from the claims file (:mod:`pencore.paper.claims`)."""
    from pencore.paper.claims import paper_values

    return paper_values()


def _paper_fig13() -> str:
    """The paper's final deviations of Figs 13-14 as a title fragment:
    ``"0.16° (280), 0.24° (1000), large (2200)"`` (speeds in m/s)."""
    pv = _paper_values()
    phis = [f"{phi:g}° ({v:g})" for v, phi in sorted(pv["fig13_phi_deg"].items())]
    return ", ".join([*phis, f"large ({pv['fig13_large_at']:g})"])


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
