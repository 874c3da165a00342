"""Attribution figure: one panel per disputed paper number, the value under
every setting, the paper's value, and the band that counts as reproducing it."""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator, NullFormatter

from pencore.errors import hint_keywords
from pencore.plotting.style import _COLOURS, _MARKERS, _c, new_figure, styled

__all__ = ["plot_attribution"]

_PANELS = [
    ("alpha_5", r"$\varphi$, #2, 5 rad/s (deg)", True),
    ("alpha_20", r"$\varphi$, #2, 20 rad/s (deg)", True),
    ("turn_back_25", "#2 turns back at 25 rad/s", False),
    ("vcr", r"$V_{cr}$, #2, 45° (m/s)", False),
    ("depth_280", "Table 2 test 2 depth (m)", False),
    ("phi_p4_280", r"$\varphi$, #4, 280 m/s (deg)", True),
    ("phi_p4_1000", r"$\varphi$, #4, 1000 m/s (deg)", True),
    ("fig12_falls", "Fig. 12: $V_{cr}$ (#2, 30°)\nfalls, yaw 0→2°", False),
]


@styled
def plot_attribution(ds: xr.Dataset) -> Figure:
    """Dot plot per paper number: settings down the page (grouped as configured), the
    default model's row shaded, the paper's value as a red line (Vcr: its bracket) and the
    3 % band around it in pink; open markers are attribution-only knobs, filled ones
    physically argued readings. Deviation panels switch to a log axis when the values span
    more than a factor 20 (they reach 150 deg where the projectile tumbles).
    """
    labels = [str(s) for s in ds["label"].values]
    groups = [str(g) for g in ds["group"].values]
    argued = ds["argued"].values.astype(bool)
    names = [str(s) for s in ds["setting"].values]
    n = len(labels)
    y = np.arange(n)[::-1]
    tol = float(ds.attrs.get("tolerance", 0.03))
    # a group past the colour cycle takes the next marker, so no two groups look alike
    order = list(dict.fromkeys(groups))
    gcol = {g: _c(i) for i, g in enumerate(order)}
    gmark = {g: _MARKERS[(i // len(_COLOURS)) % len(_MARKERS)] for i, g in enumerate(order)}
    fig = new_figure(17.0, max(2.6, 1.0 + 0.27 * n))
    axes = fig.subplots(1, len(_PANELS), sharey=True, gridspec_kw={"wspace": 0.08})
    for ax, (key, title, log) in zip(axes, _PANELS, strict=True):
        v = ds[f"value_{key}"].values.astype(float)
        p = float(ds[f"paper_{key}"])
        if "default" in names:
            ax.axhspan(y[names.index("default")] - 0.5, y[names.index("default")] + 0.5,
                       color="0.9", zorder=0)  # fmt: skip
        if key in ("turn_back_25", "fig12_falls"):
            ax.axvline(p, color="crimson", lw=1.5)
            ax.set_xlim(-0.5, 1.5)
            ax.set_xticks([0, 1], ["no", "yes"])
        elif key == "vcr":
            lo, hi = ds.attrs.get("paper_vcr_lo", np.nan), ds.attrs.get("paper_vcr_hi", np.nan)
            mid = p
            ax.axvspan(mid * (1 - tol), mid * (1 + tol), color="pink", alpha=0.5, lw=0)
            if np.isfinite(lo):
                ax.axvspan(lo, hi, color="crimson", alpha=0.6, lw=0)
            else:
                ax.axvline(mid, color="crimson", lw=1.5)
        else:
            ax.axvspan(p * (1 - tol), p * (1 + tol), color="pink", alpha=0.5, lw=0)
            ax.axvline(p, color="crimson", lw=1.5)
        for i in range(n):
            c = gcol[groups[i]]
            ax.plot(
                v[i], y[i], gmark[groups[i]], ms=5, mfc=c if argued[i] else "white", mec=c, mew=1.3
            )
        finite = v[np.isfinite(v) & (v > 0)]
        if log and finite.size and max(finite.max(), p) / min(finite.min(), p) > 20:
            ax.set_xscale("log")
            ax.xaxis.set_minor_formatter(NullFormatter())
        elif key not in ("turn_back_25", "fig12_falls"):
            ax.xaxis.set_major_locator(MaxNLocator(4))
        ax.set_title(title, fontsize=8)
        ax.grid(alpha=0.3, axis="x")
        ax.tick_params(labelsize=7)
    axes[0].set_yticks(y, labels, fontsize=7)
    axes[0].set_ylim(-0.7, n - 0.3)
    fig.suptitle(
        "Which reading moves which paper number: red = the paper, pink = within "
        f"{tol:.0%}; filled = physically argued reading, open = attribution knob; "
        "grey row = the model as written",
        fontsize=9,
    )
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
