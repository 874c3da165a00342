"""Shared figure style: one rcParams dict (:data:`~pencore.plotting.style.STYLE`, applied with
:func:`matplotlib.rc_context`), colours, markers, axis labels, and the Agg figure/save helpers.

Figures are built with the object-oriented API on an Agg canvas, never through pyplot, so
plotting works headless, keeps no global state, and can run in parallel jobs. PDF and PS
fonts are embedded as TrueType (Type 42), so the text stays editable and searchable.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pencore.errors import hint_keywords

__all__ = ["STYLE", "styled", "new_figure", "save_figure", "convention_label"]

#: Reader-facing names of the yaw conventions (config names stay out of titles/legends).
CONVENTION_LABELS = {
    "axis_tilted": "axis tilted, velocity normal",
    "velocity_tilted": "velocity tilted, axis normal",
}


def convention_label(convention: object) -> str:
    """Words for a yaw-convention config name, e.g. ``axis_tilted`` -> "axis tilted, ..."."""
    c = str(convention)
    return CONVENTION_LABELS.get(c, c.replace("_", " "))


#: The one place for figure style: matplotlib rcParams applied (with
#: :func:`matplotlib.rc_context`) while a figure is built and while it is saved.
#: Type 42 embeds TrueType fonts in PDF/PS (editable text; journals ask for it).
STYLE: dict[str, Any] = {
    "pdf.fonttype": 42,
    "ps.fonttype": 42,
    "svg.fonttype": "none",
    "savefig.dpi": 150,
    "legend.frameon": False,
    "axes.titlesize": "medium",
}


def styled(plot: Callable[..., Figure]) -> Callable[..., Figure]:
    """Decorator: run a ``plot_*`` function inside ``matplotlib.rc_context(STYLE)``.

    Artists read rcParams when they are created, so the style has to be active while the
    figure is built, not only when it is saved.
    """

    @functools.wraps(plot)
    def wrapper(*args: Any, **kwargs: Any) -> Figure:
        with matplotlib.rc_context(STYLE):
            return plot(*args, **kwargs)

    return wrapper


def new_figure(width: float = 6.4, height: float = 4.4) -> Figure:
    """An empty figure on an Agg canvas (size in inches)."""
    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def save_figure(
    fig: Figure, *paths: str | os.PathLike[str], dpi: int = 150, fmt: str | None = None
) -> list[Path]:
    """Save ``fig`` to every path (format from the suffix, e.g. ``.png``, ``.pdf``, or
    ``fmt`` when given: a temporary file without a suffix).

    Parent directories are created. Returns the paths written.
    """
    if not paths:
        raise ValueError("save_figure needs at least one path")
    out = []
    for p in paths:
        p = Path(p)
        p.parent.mkdir(parents=True, exist_ok=True)
        with matplotlib.rc_context(STYLE):
            kind = Path(f"x.{fmt}") if fmt else p
            fig.savefig(p, dpi=dpi, metadata=_metadata(kind), format=fmt)
        out.append(p)
    return out


def _metadata(p: Path) -> dict[str, str | None]:
    # no creation dates: identical inputs give identical PDFs
    if p.suffix.lower() == ".pdf":
        return {"Creator": "pencore", "CreationDate": None}
    if p.suffix.lower() == ".png":
        return {"Software": "pencore"}
    return {}


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
_LINESTYLES = ["-", "--", "-.", ":"]


def _c(k: int) -> str:
    return _COLOURS[k % len(_COLOURS)]


_VI = r"Impact velocity $V_i$ (m/s)"


_LCL = r"$L_c/L$"


_DEPTH = "Penetration depth (m)"


def _pname(p: object) -> str:
    s = str(p)
    return f"#{s[1:]}" if s.startswith("p") and s[1:].isdigit() else s


def _finite(*arrays: np.ndarray) -> np.ndarray:
    ok = np.ones(np.shape(arrays[0]), dtype=bool)
    for a in arrays:
        ok &= np.isfinite(a)
    return ok


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
