"""The concrete record's figure: measured against predicted, the error against diameter
and speed (:mod:`pencore.studies.validation.record`)."""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import InputError, hint_keywords
from pencore.inputs.record import DEFAULT_RECORD_LAW
from pencore.plotting.style import _c, new_figure, styled

__all__ = ["plot_concrete_record"]

#: Bin edges of the error panels: diameter (mm), speed (m/s).
_EDGES = {
    "diameter": (np.array([5, 10, 15, 20, 30, 45, 60, 80, 100, 160, 250.0]), 1e3, "mm"),
    "velocity": (np.array([0, 200, 300, 400, 500, 600, 700, 800, 900, 1000, 1600.0]), 1.0, "m/s"),
}
_NEEDS = ("diameter", "velocity", "measured", "predicted", "held_out_predicted", "held_out")


@styled
def plot_concrete_record(ds: xr.Dataset) -> Figure:
    """Measured against predicted for the default law (left; filled: held-out sources, open:
    a source a law was fitted to; crosses: rows set aside as eroding), and each law's median
    error per bin of diameter (middle) and striking speed (right) over the clean rows, with
    held-out predictions (the size term refitted without the row's source; the ``S(fc)``
    forms were built on the Sandia/WES rows, which the 60-100 mm bins hold).

    Parameters
    ----------
    ds : xarray.Dataset
        :func:`pencore.studies.validation.record.gather_record`'s dataset.
    """
    missing = [k for k in _NEEDS if k not in ds]
    if missing or "model" not in ds.dims:
        raise InputError(
            f"plot_concrete_record needs the concrete record's dataset; missing {missing}"
        )
    models = [str(m) for m in ds["model"].values]
    kinds = [str(k) for k in ds["kind"].values]
    law = DEFAULT_RECORD_LAW if DEFAULT_RECORD_LAW in models else models[0]
    fig = new_figure(16.0, 5.4)
    ax = fig.add_subplot(1, 3, 1)
    m = ds["measured"].values
    p = ds["held_out_predicted"].sel(model=law).values
    held = ds["held_out"].values.astype(bool)
    eroding = ds["group"].values.astype(str) == "eroding"
    clean = ~eroding
    ok = np.isfinite(p) & (p > 0)
    lo, hi = 0.5 * float(np.nanmin(m[ok])), 2.0 * float(np.nanmax(m[ok]))
    x = np.geomspace(lo, hi, 50)
    ax.plot(x, x, "-", color="0.3", lw=0.8, label="predicted = measured")
    ax.fill_between(x, 0.75 * x, 1.25 * x, color="0.5", alpha=0.15, lw=0, label="±25 %")
    ax.plot(m[ok & held], p[ok & held], "o", ms=3.5, color=_c(0), ls="none",
            label=f"held-out sources ({int((ok & held).sum())})")  # fmt: skip
    fitted = ok & ~held & ~eroding
    ax.plot(m[fitted], p[fitted], "o", ms=3.5, mfc="none", color=_c(1), ls="none",
            label=f"sources a law was fitted to ({int(fitted.sum())})")  # fmt: skip
    ax.plot(m[ok & eroding], p[ok & eroding], "x", ms=3.5, color=_c(3), ls="none",
            label=f"set aside as eroding ({int((ok & eroding).sum())})")  # fmt: skip
    ax.set(xscale="log", yscale="log", xlabel="measured depth (m)",
           ylabel="predicted depth (m)",
           title=f"law {law!r}, {ds.sizes['shot']} shots")  # fmt: skip
    ax.legend(fontsize=7, loc="upper left")
    for k, (var, title) in enumerate((("diameter", "diameter"), ("velocity", "striking speed"))):
        ax = fig.add_subplot(1, 3, k + 2)
        edges, scale, unit = _EDGES[var]
        xv = ds[var].values * scale
        mid = np.sqrt(np.maximum(edges[:-1], 1.0) * edges[1:])
        for i, name in enumerate(models):
            e = ds["held_out_rel_error"].sel(model=name).values
            med = [
                np.median(e[s]) if (s := clean & np.isfinite(e) & (xv >= a) & (xv < b)).sum() >= 3
                else np.nan
                for a, b in zip(edges[:-1], edges[1:], strict=True)
            ]  # fmt: skip
            style = "-o" if kinds[i] == "solver" else ":s"
            ax.plot(mid, med, style, ms=3, lw=1.2 if name == law else 0.8, color=_c(i),
                    label=name)  # fmt: skip
        ax.axhline(0.0, color="0.3", lw=0.8)
        ax.axhspan(-0.25, 0.25, color="0.5", alpha=0.12, lw=0)
        ax.set(xscale="log", xlabel=f"{title} ({unit})",
               ylabel="median relative error (predicted / measured - 1)",
               title=f"error against {title}, clean rows (bins of >= 3 shots)")  # fmt: skip
        ax.legend(fontsize=6.5, ncol=2)
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
