"""Critical-value figures of Section 4: Vcr (Figs 8, 12), Vci (Fig. 15), omega_c (Fig. 18),
with the search brackets as error bars.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import hint_keywords
from pencore.plotting.style import (
    _LCL,
    _MARKERS,
    _VI,
    _c,
    _pname,
    convention_label,
    new_figure,
    styled,
)

__all__ = ["plot_fig8", "plot_fig12", "plot_fig15", "plot_fig18"]


def _search_errorbars(
    ax,
    x: np.ndarray,
    sub: xr.Dataset,
    name: str,
    colour: str,
    marker: str,
    label: str,
    jitter: float = 0.0,
) -> set[str]:
    """Converged values with their brackets; out-of-range searches as open triangles at
    the edge of the search range, shifted by ``jitter`` along x so that several
    projectiles stay visible. Returns the search outcomes drawn besides the converged
    values (keys of :data:`_SEARCH_MARKS`), for :func:`_legend_search`."""
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
    else:  # no value converged: the legend keys the colour alone (its markers are open)
        ax.plot([], [], color=colour, label=label)
    drawn = {k for k in _SEARCH_MARKS if (status == k).any()}
    nm = status == "non_monotone"
    if nm.any():
        ax.plot(x[nm], val[nm], marker=marker, ms=10, mfc="none", color=colour, ls="none")
    above = status == "above_range"
    if above.any():
        ax.plot(x[above] + jitter, lo[above], marker="^", ms=7, mfc="none", color=colour, ls="none")
    below = status == "below_range"
    if below.any():
        ax.plot(x[below] + jitter, hi[below], marker="v", ms=7, mfc="none", color=colour, ls="none")
    return drawn


def _jitter(x: np.ndarray, k: int, n: int) -> float:
    span = float(np.ptp(x)) if np.size(x) > 1 else 1.0
    return (k - 0.5 * (n - 1)) * 0.012 * span


def _ordered_legend(ax, fig: Figure, order: list[str], ncols: int = 2) -> None:
    """Legend below the axes (outside the data), entries in ``order``.

    Matplotlib lists plain lines before errorbar containers, whatever the order they were
    drawn in; this puts them back in the order given (labels not in ``order`` go last).
    """
    handles, labels = ax.get_legend_handles_labels()
    rank = {label: i for i, label in enumerate(order)}
    pairs = sorted(zip(handles, labels, strict=True), key=lambda hl: rank.get(hl[1], len(rank)))
    fig.legend(
        [h for h, _ in pairs],
        [lab for _, lab in pairs],
        loc="outside lower center",
        ncols=ncols,
        fontsize=7,
        frameon=False,
    )


def _paper_vcr() -> tuple[float, float, float]:
    """The paper's Vcr bracket of #2 (lo, hi in m/s) and its obliquity (deg), from the
    claims file (claim ``vcr_p2_45``)."""
    from pencore.paper.claims import at, claim, paper_values

    lo, hi = paper_values()["vcr_p2_45_bracket"]
    return lo, hi, float(at(claim("vcr_p2_45")["at"])[0]["obliquity"])


def _paper_omega_c() -> tuple[float, float, float]:
    """The paper's omega_c bracket of #2 (lo, hi in rad/s) and its impact speed (m/s),
    from the claims file (claim ``omega_c_p2_1000``)."""
    from pencore.paper.claims import at, claim, paper_values

    lo, hi = paper_values()["omega_c_p2_1000_bracket"]
    return lo, hi, float(at(claim("omega_c_p2_1000")["at"])[0]["velocity"])


#: Search outcome -> (legend label, marker, marker size) of its open marker.
_SEARCH_MARKS = {
    "above_range": ("above the search range", "^", 7),
    "below_range": ("below the search range", "v", 7),
    "non_monotone": ("verdict not monotone", "o", 10),
}
_SEARCH_LABELS = [label for label, _, _ in _SEARCH_MARKS.values()]


def _legend_search(ax, drawn: set[str]) -> None:
    """Legend entries for the search outcomes drawn (only those: a legend lists no marker
    the figure does not show)."""
    for key, (label, marker, ms) in _SEARCH_MARKS.items():
        if key in drawn:
            ax.plot([], [], marker, ms=ms, mfc="none", color="0.3", ls="none", label=label)


def _paper_star(ax, x: float, lo: float, hi: float, ds: xr.Dataset, label: str) -> None:
    """The paper's bracket for projectile #2 as a star in #2's colour, named beside it:
    it can sit on another projectile's curve, and must not read as that one's."""
    names = [str(p) for p in ds["projectile"].values]
    colour = _c(names.index("p2")) if "p2" in names else "k"
    mid, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    ax.errorbar(
        [x], [mid], yerr=[[half], [half]], fmt="*", ms=13, color=colour, mec="k", mew=0.8,
        ecolor=colour, label=label, zorder=5,
    )  # fmt: skip
    ax.annotate(
        "paper, #2",
        (x, mid),
        xytext=(10, 14),
        textcoords="offset points",
        fontsize=8,
        color=colour,
        arrowprops={"arrowstyle": "-", "color": colour, "lw": 0.8},
    )


@styled
def plot_fig8(ds: xr.Dataset) -> Figure:
    """Vcr against obliquity, one line per projectile, with the search brackets."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    obl = ds["obliquity"].values
    n = ds.sizes["projectile"]
    drawn: set[str] = set()
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        drawn |= _search_errorbars(
            ax,
            obl,
            sub,
            "vcr",
            _c(k),
            _MARKERS[k % len(_MARKERS)],
            f"{_pname(p)}, $L_c/L$ = {float(sub['lc_over_l']):.3f}",
            _jitter(obl, k, n),
        )
    lo, hi, obliquity = _paper_vcr()
    _paper_star(
        ax, obliquity, lo, hi, ds, f"paper, #2 at {obliquity:g}° ({lo:g} < $V_{{cr}}$ ≤ {hi:g})"
    )
    _legend_search(ax, drawn)
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


@styled
def plot_fig12(ds: xr.Dataset) -> Figure:
    """Vcr against yaw, one panel per obliquity; filled: nose +x at Vcr, cross: -x."""
    obls = ds["obliquity"].values
    fig = new_figure(5.0 * len(obls) + 0.5, 4.6)
    axes = fig.subplots(1, len(obls), squeeze=False)[0]
    yaw = ds["yaw"].values
    for ax, ob in zip(axes, obls, strict=True):
        drawn: set[str] = set()
        flipped = False
        for k, p in enumerate(ds["projectile"].values):
            sub = ds.sel(projectile=p, obliquity=ob)
            drawn |= _search_errorbars(
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
                    flipped = True
        if flipped:
            ax.plot(
                [], [], "x", ms=10, mew=2, color="0.3", ls="none", label="nose ends pointing −x"
            )
        _legend_search(ax, drawn)
        ax.set_xlabel(r"Yaw angle $\varphi_2$ (deg)")
        ax.set_ylabel(r"$V_{cr}$ (m/s)")
        ax.set_title(f"$\\varphi_1$ = {ob:g}°", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, frameon=False)
    return fig


@styled
def plot_fig15(ds: xr.Dataset, threshold: float | None = None) -> Figure:
    """Vci against Lc/L, one line per yaw, at each deviation threshold."""
    ths = ds["threshold"].values
    t0 = float(ds.attrs.get("primary_threshold_deg", 5.0) if threshold is None else threshold)
    j0 = int(np.argmin(np.abs(ths - t0)))
    fig = new_figure(6.6, 4.8)
    ax = fig.add_subplot()
    lcl = ds["lc_over_l"].values
    drawn: set[str] = set()
    for k, y in enumerate(ds["yaw"].values):
        for j, t in enumerate(ths):
            sub = ds.sel(yaw=y, threshold=t)
            if j == j0:
                drawn |= _search_errorbars(
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
    _legend_search(ax, drawn)
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
        f"normal impact with yaw ({convention_label(ds.attrs.get('yaw_convention', '?'))}); "
        "unstable: reverses or final deviation > threshold",
        fontsize=9,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, frameon=False)
    return fig


@styled
def plot_fig18(ds: xr.Dataset) -> Figure:
    """omega_c against impact velocity, one line per projectile."""
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    v = ds["velocity"].values
    order: list[str] = []
    drawn: set[str] = set()
    for k, p in enumerate(ds["projectile"].values):
        sub = ds.sel(projectile=p)
        label = f"{_pname(p)}, $L_c/L$ = {float(sub['lc_over_l']):.3f}"
        order.append(label)
        drawn |= _search_errorbars(
            ax,
            v,
            sub,
            "omega_c",
            _c(k),
            _MARKERS[k % len(_MARKERS)],
            label,
            _jitter(v, k, ds.sizes["projectile"]),
        )
    lo, hi, velocity = _paper_omega_c()
    paper_label = rf"paper, #2 at {velocity:g} m/s (${lo:g} < \omega_c \leq {hi:g}$ rad/s)"
    _paper_star(ax, velocity, lo, hi, ds, paper_label)
    names = [str(p) for p in ds["projectile"].values]
    if "p2" in names and velocity in v:
        # pencore's #2 at the paper's speed, named too: the star is compared with it
        at2 = ds.sel(projectile="p2", velocity=velocity)
        if str(at2["status"].values) == "above_range":
            ax.annotate(
                f"pencore, #2: > {float(at2['omega_c_lo']):g} rad/s",
                (velocity, float(at2["omega_c_lo"])),
                xytext=(10, -16),
                textcoords="offset points",
                fontsize=8,
                color=_c(names.index("p2")),
            )
    order += [paper_label, *_SEARCH_LABELS]
    _legend_search(ax, drawn)
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
    _ordered_legend(ax, fig, order)
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
