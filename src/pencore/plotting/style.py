"""Shared figure style: one rcParams dict (:data:`~pencore.plotting.style.STYLE`, applied with
:func:`matplotlib.rc_context`), colours, markers, axis labels, and the Agg figure/save helpers.

Figures are built with the object-oriented API on an Agg canvas, never through pyplot, so
plotting works headless, keeps no global state, and can run in parallel jobs. PDF and PS
fonts are embedded as TrueType (Type 42), so the text stays editable and searchable.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Iterable
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
    """Decorator of every ``plot_*`` function: check its Dataset, and run it inside
    ``matplotlib.rc_context(STYLE)``.

    Artists read rcParams when they are created, so the style has to be active while the
    figure is built, not only when it is saved. The first argument must be an
    :class:`xarray.Dataset` (:func:`pencore.io.runs.check_run`); each function checks
    the variables and attributes it reads. A Dataset of another kind or a tampered one
    that gets past those checks, and so fails while it is drawn (a missing name, a value
    of the wrong kind, an empty axis), is one :class:`~pencore.InputError` line naming
    the function and the failure, never a traceback from deep inside xarray or matplotlib.
    """
    import inspect

    signature = inspect.signature(plot)
    name = plot.__name__

    @functools.wraps(plot)
    def wrapper(*args: Any, **kwargs: Any) -> Figure:
        from pencore.errors import InputError
        from pencore.inputs.gate import brief
        from pencore.io.runs import check_run

        bound = signature.bind(*args, **kwargs)  # a wrong argument is Python's own TypeError
        first = next(iter(bound.arguments.values()), None)
        check_run(first, name, made_by="the pencore study or run it draws")
        try:
            with matplotlib.rc_context(STYLE):
                return plot(*args, **kwargs)
        except InputError:
            raise
        except (KeyError, ValueError, TypeError, IndexError, ZeroDivisionError) as exc:
            raise InputError(
                f"{name} cannot draw this Dataset ({type(exc).__name__}: {brief(str(exc))}): "
                f"is it the Dataset {name} takes, unedited? (see help(pencore.plotting.{name}))"
            ) from None

    return wrapper


def new_figure(width: float = 6.4, height: float = 4.4) -> Figure:
    """An empty figure on an Agg canvas (size in inches)."""
    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def save_figure(
    fig: Figure,
    *paths: str | os.PathLike[str],
    dpi: int = 150,
    fmt: str | None = None,
    protect: Iterable[str | os.PathLike[str]] = (),
) -> list[Path]:
    """Save ``fig`` to every path, each written atomically through the output gate.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    *paths : path-like
        Destinations; the format comes from the suffix, one of
        :data:`pencore.io.outputs.FIGURE_SUFFIXES` (``.png``, ``.pdf``, ``.svg``), or
        ``fmt`` when given. Parent directories are created. Each path obeys the output
        gate (:mod:`pencore.io.outputs`: not a directory, a read-only file, an input of
        the open call or one of ``protect``).
    dpi : int
        Resolution of raster formats (dots per inch).
    fmt : str, optional
        The format, for a path without a suffix.
    protect : iterable of path-like
        Files no path may be (the inputs the figure was drawn from).

    Returns
    -------
    list of pathlib.Path
        The paths written.

    Raises
    ------
    pencore.errors.WriteError
        A path the gate refuses (before anything is written) or a failed write (nothing
        left of it); one line naming the path and the cause.
    """
    from pencore.errors import WriteError
    from pencore.io.atomic import atomic_path
    from pencore.io.outputs import FIGURE_SUFFIXES, check_destination, describe_os_error

    if not paths:
        raise ValueError("save_figure needs at least one path")
    protect = tuple(protect)
    suffixes = None if fmt else FIGURE_SUFFIXES
    checked = [check_destination(p, suffixes, protect) for p in paths]  # all before any
    out = []
    for p in checked:
        try:
            p.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise WriteError(
                f"cannot write {str(p)!r}: its folder {str(p.parent)!r} cannot be made "
                f"({describe_os_error(exc)})",
                exc.errno,
            ) from None
        kind = fmt or p.suffix[1:].lower()
        with atomic_path(p, protect=protect, suffixes=suffixes) as tmp:
            with matplotlib.rc_context(STYLE):
                fig.savefig(tmp, dpi=dpi, metadata=_metadata(Path(f"x.{kind}")), format=kind)
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
