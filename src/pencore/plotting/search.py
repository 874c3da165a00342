"""The history of one threshold search (:func:`pencore.search.history.search_dataset`):
each value tried in the order of evaluation, marked by its verdict, and the final
bracket."""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import hint_keywords
from pencore.io.runs import check_run
from pencore.plotting.style import _c, _pname, new_figure, styled

__all__ = ["plot_search"]

_LABELS = {
    "m s-1": "m/s",
    "rad s-1": "rad/s",
}


@styled
def plot_search(ds: xr.Dataset) -> Figure:
    """Draw a threshold search: value against evaluation number, verdicts as filled
    (above the threshold) or open (below) markers, the final bracket shaded.

    Parameters
    ----------
    ds : xarray.Dataset
        :func:`pencore.search.history.search_dataset` (``pencore vcr --out``...).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> from pencore import find_threshold
    >>> from pencore.search.history import search_dataset
    >>> ds = search_dataset(find_threshold(lambda v: v >= 300.0, 100.0, 900.0, 5.0),
    ...                     "vcr", "m s-1", "critical reverse velocity")
    >>> plot_search(ds).axes[0].get_ylabel()
    'vcr tried (m/s)'
    """
    made_by = "pencore.search.history.search_dataset (pencore vcr --out ...)"
    check_run(ds, "plot_search", ("value", "verdict", "evaluation"), ("quantity", "status"),
              made_by)  # fmt: skip
    name = str(ds.attrs["quantity"])
    check_run(ds, "plot_search", ("value", name, f"{name}_lo", f"{name}_hi"), (), made_by,
              numeric=True)  # fmt: skip
    units = ds["value"].attrs.get("units", "")
    fig = new_figure(6.4, 4.4)
    ax = fig.add_subplot()
    n = ds["evaluation"].values + 1
    v = ds["value"].values
    yes = ds["verdict"].values == 1
    ax.plot(n, v, "-", color="0.7", lw=0.8)
    ax.plot(n[yes], v[yes], "o", color=_c(3), label="at or above the threshold")
    ax.plot(n[~yes], v[~yes], "o", mfc="none", color=_c(0), label="below the threshold")
    lo, hi = float(ds[f"{name}_lo"]), float(ds[f"{name}_hi"])
    if math.isfinite(lo) and math.isfinite(hi):
        ax.axhspan(lo, hi, color=_c(2), alpha=0.2, label=f"final bracket [{lo:.4g}, {hi:.4g}]")
    ax.set_xlabel("Evaluation")
    ax.set_ylabel(f"{name} tried ({_LABELS.get(units, units)})")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    a = ds.attrs
    value = float(ds[name])
    found = f"{name} = {value:.4g}" if np.isfinite(value) else "no threshold in the range"
    ax.set_title(
        f"{_pname(a.get('projectile', ''))} into {a.get('target', '')}: {found} ({a['status']})",
        fontsize=9,
    )
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
