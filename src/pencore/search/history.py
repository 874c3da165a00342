"""A threshold search as a Dataset: every value evaluated, its verdict, and the result.

:func:`search_dataset` turns a :class:`~pencore.CriticalResult` (from
:func:`~pencore.vcr`, :func:`~pencore.vci`, :func:`~pencore.omega_c` or
:func:`~pencore.ballistic_limit`) into an :class:`xarray.Dataset` on the dimension
``evaluation`` (in the order the search made them), for a file or a plot
(:func:`pencore.plotting.search.plot_search`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from pencore.search.threshold import CriticalResult

__all__ = ["search_dataset"]


def search_dataset(
    result: CriticalResult, name: str, units: str, long_name: str, **attrs: Any
) -> xr.Dataset:
    """The evaluations of a threshold search and its result.

    Parameters
    ----------
    result : CriticalResult
        The search.
    name : str
        The searched quantity (``"vcr"``, ``"vci"``, ``"omega_c"``, ``"v_bl"``).
    units : str
        Its units (``"m s-1"``, ``"rad s-1"``).
    long_name : str
        What it is, in words.
    **attrs
        More attributes (the inputs of the search; numbers in SI units, angles in deg).

    Returns
    -------
    xarray.Dataset
        ``value`` (``units``) and ``verdict`` (1: the threshold is at or below the value)
        on ``evaluation``; the scalars ``name`` (the midpoint of the final bracket, NaN
        when not found), ``name_lo`` and ``name_hi`` (the bracket); attributes ``status``,
        ``converged`` (0/1), ``monotone``, ``message``, ``tol``, ``quantity``.

    Examples
    --------
    >>> from pencore import find_threshold
    >>> from pencore.search.history import search_dataset
    >>> r = find_threshold(lambda x: x >= 0.3, 0.0, 1.0, 0.01, scan=None)
    >>> ds = search_dataset(r, "x", "1", "a threshold")
    >>> ds.sizes["evaluation"], ds.attrs["status"], f"{float(ds.x):.3f}"
    (9, 'ok', '0.301')
    """
    values = np.array([v for v, _ in result.history], dtype=float)
    verdicts = np.array([int(b) for _, b in result.history], dtype=np.int8)

    def scalar(v: float, what: str) -> tuple:
        return ((), float(v), {"units": units, "long_name": what})

    return xr.Dataset(
        {
            "value": ("evaluation", values, {"units": units, "long_name": f"{name} tried"}),
            "verdict": (
                "evaluation",
                verdicts,
                {"units": "1", "long_name": "verdict of the run (1: at or above the threshold)"},
            ),
            name: scalar(result.value, f"{long_name} (midpoint of the final bracket)"),
            f"{name}_lo": scalar(result.lo, f"{long_name}: largest value below"),
            f"{name}_hi": scalar(result.hi, f"{long_name}: smallest value above"),
        },
        coords={
            "evaluation": (
                "evaluation",
                np.arange(values.size, dtype=np.int32),
                {"units": "1", "long_name": "order of evaluation"},
            )
        },
        attrs={
            "title": f"pencore search for {name}",
            "quantity": name,
            "status": result.status,
            "converged": int(result.converged),
            "monotone": int(result.monotone),
            "message": result.message,
            "tol": float(result.tol) if math.isfinite(result.tol) else -1.0,
            "n_evals": int(result.n_evals),
            "Conventions": "CF-1.8",
            **attrs,
        },
    )
