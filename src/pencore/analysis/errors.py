"""Error statistics of predictions against measurements.

The relative error of a prediction ``p`` of a measured value ``m > 0`` is
``e = p / m - 1`` (dimensionless; a measured 0, e.g. a shot that did not perforate, has
only an absolute error). :func:`error_statistics` gives the mean, RMS and largest ``|e|``
of a sample with the 95 % Student-t interval of the mean; :func:`summary_statistics` the
count, mean ``|e|``, bias (mean ``e``) and the ``e`` of largest magnitude, the columns of
the validation summary (:func:`pencore.studies.validation.measurements.summary`).

Examples
--------
>>> from pencore.analysis.errors import error_statistics, relative_errors
>>> relative_errors([2.0, 0.0], [2.2, 0.1]).round(3).tolist()
[0.1, nan]
>>> st = error_statistics([1.0, 2.0], [1.1, 1.8])
>>> round(st["mean_rel_error"], 3), round(st["max_abs_rel_error"], 3)
(0.0, 0.1)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from pencore.errors import InputError

__all__ = [
    "ERROR_STATISTICS",
    "t_half_width",
    "relative_errors",
    "error_statistics",
    "sample_statistics",
    "summary_statistics",
]

#: The keys of :func:`error_statistics`.
ERROR_STATISTICS = (
    "n",
    "n_relative",
    "mean_abs_error",
    "mean_rel_error",
    "rms_rel_error",
    "max_abs_rel_error",
    "ci95_lo",
    "ci95_hi",
)


def t_half_width(x: Any, level: float = 0.95) -> float:
    """Half-width of the Student-t interval (``level``) of the mean of the sample ``x``,
    in the units of ``x``; NaN for fewer than two values."""
    x = np.asarray(x, dtype=float)
    n = x.size
    if n < 2:
        return math.nan
    from scipy import stats  # here: reading and plotting results loads no scipy

    return float(stats.t.ppf(0.5 + level / 2, n - 1) * x.std(ddof=1) / math.sqrt(n))


def relative_errors(measured: Any, predicted: Any) -> np.ndarray:
    """``predicted / measured - 1`` per value (dimensionless); NaN where the measured value
    is 0 or NaN (no printed value)."""
    measured, predicted = np.asarray(measured, float), np.asarray(predicted, float)
    rel = np.full(measured.shape, np.nan)
    pos = measured > 0  # False for NaN (no printed value)
    rel[pos] = predicted[pos] / measured[pos] - 1.0
    return rel


def error_statistics(measured: Sequence[float], predicted: Sequence[float]) -> dict[str, float]:
    """Error statistics of predicted against measured values.

    Returns ``n`` (rows), ``n_relative`` (rows with a measured value > 0, the only ones
    with a relative error: a measured residual velocity of 0 m/s is a shot that did not
    perforate), ``mean_abs_error`` (mean abs(predicted - measured), in the measured units),
    and over the relative errors ``e = predicted / measured - 1`` (dimensionless):
    ``mean_rel_error``, ``rms_rel_error``, ``max_abs_rel_error`` and the 95 % Student-t
    interval of the mean (``ci95_lo``, ``ci95_hi``; NaN for fewer than two values).

    Raises
    ------
    InputError
        Unequal lengths, no values, or a measured value negative or not finite.
    """
    m, p = np.asarray(measured, float), np.asarray(predicted, float)
    if m.shape != p.shape or m.size == 0 or np.any(m < 0) or not np.all(np.isfinite(m)):
        raise InputError("error_statistics needs equal-length, finite, non-negative values")
    pos = m > 0
    e = p[pos] / m[pos] - 1.0
    n = e.size
    nan = math.nan
    mean = float(e.mean()) if n else nan
    half = t_half_width(e)
    return {
        "n": float(m.size),
        "n_relative": float(n),
        "mean_abs_error": float(np.mean(np.abs(p - m))),
        "mean_rel_error": mean,
        "rms_rel_error": float(np.sqrt(np.mean(e**2))) if n else nan,
        "max_abs_rel_error": float(np.max(np.abs(e))) if n else nan,
        "ci95_lo": mean - half,
        "ci95_hi": mean + half,
    }


def sample_statistics(measured: np.ndarray, predicted: np.ndarray) -> dict[str, float]:
    """:func:`error_statistics` of the values given, or ``n = 0`` and NaN for none (a group
    whose every projectile deformed has no rigid shot to compare)."""
    if measured.size:
        return error_statistics(measured, predicted)
    return {k: (0.0 if k in ("n", "n_relative") else math.nan) for k in ERROR_STATISTICS}


def summary_statistics(e: Any) -> dict[str, float]:
    """Count ``n``, mean ``|e|`` (``mean_abs_rel_error``), ``bias`` (mean ``e``) and
    ``worst`` (the ``e`` of largest magnitude, signed) of the finite relative errors ``e``;
    NaN statistics for none.

    Examples
    --------
    >>> st = summary_statistics([0.1, -0.3, float("nan")])
    >>> st["n"], round(st["mean_abs_rel_error"], 6), round(st["bias"], 6), st["worst"]
    (2, 0.2, -0.1, -0.3)
    """
    e = np.asarray(e, dtype=float)
    e = e[np.isfinite(e)]
    if not e.size:
        return {"n": 0, "mean_abs_rel_error": math.nan, "bias": math.nan, "worst": math.nan}
    return {
        "n": int(e.size),
        "mean_abs_rel_error": float(np.mean(np.abs(e))),
        "bias": float(np.mean(e)),
        "worst": float(e[np.argmax(np.abs(e))]),
    }
