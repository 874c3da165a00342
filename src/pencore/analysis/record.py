"""Statistics of a law scored on a record of measured shots, and its band's calibration.

For each shot the relative error ``e = predicted / measured - 1`` and the ratio ``r =
measured / predicted`` (the factor the band multiplies a prediction by). :func:`binned`
gives per bin of one quantity the count, median ``e``, mean ``|e|`` and the share of shots
within 25 %. :func:`calibrate_level` calibrates a law's depth band
(:mod:`pencore.inputs.record`) one source left out at a time: every shot's band is made
from the comparable shots of the *other* sources, and the nominal quantile level is the
smallest of a grid whose bands held the stated share of the shots.

Examples
--------
>>> import numpy as np
>>> b = binned(np.array([0.1, -0.3, 0.0, 0.2]), np.array([10.0, 12.0, 50.0, 80.0]),
...            [0.0, 15.0, 100.0])
>>> [int(n) for n in b["n"]], [round(float(x), 2) for x in b["median_error"]]
([2, 2], [-0.1, 0.1])
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from pencore.errors import InputError, hint_keywords
from pencore.inputs.record import MIN_SHOTS, STATED_LEVEL, Scores, band_factors, comparable

__all__ = [
    "STATISTICS",
    "WITHIN",
    "LEVELS",
    "binned",
    "Calibration",
    "calibrate_level",
    "held_out_bands",
]

#: The statistics of :func:`binned`.
STATISTICS = ("n", "median_error", "median_abs_error", "mean_abs_error", "within")

#: The error band of the "within" share: ``|e| <= 0.25``.
WITHIN = 0.25

#: Nominal levels tried by :func:`calibrate_level`, in order (1: the comparable shots'
#: smallest and largest ratio).
LEVELS = (0.8, 0.82, 0.84, 0.86, 0.88, 0.9, 0.92, 0.94, 0.96, 0.98, 1.0)


def _summary(e: np.ndarray) -> dict[str, float]:
    if e.size == 0:
        return {
            "n": 0,
            "median_error": np.nan,
            "median_abs_error": np.nan,
            "mean_abs_error": np.nan,
            "within": np.nan,
        }
    return {
        "n": int(e.size),
        "median_error": float(np.median(e)),
        "median_abs_error": float(np.median(np.abs(e))),
        "mean_abs_error": float(np.mean(np.abs(e))),
        "within": float(np.mean(np.abs(e) <= WITHIN)),
    }


def binned(e: np.ndarray, x: np.ndarray, edges: Sequence[float]) -> dict[str, np.ndarray]:
    """Statistics of the errors ``e`` per bin ``[edges[i], edges[i+1])`` of ``x``.

    Returns
    -------
    dict
        :data:`STATISTICS`: ``n``, ``median_error``, ``median_abs_error``,
        ``mean_abs_error`` and ``within`` (the share with ``|e| <=`` :data:`WITHIN`), one
        entry per bin; NaN for an empty bin.
    """
    e, x = np.asarray(e, dtype=float), np.asarray(x, dtype=float)
    if e.shape != x.shape:
        raise InputError(f"binned: e and x differ in shape, {e.shape} and {x.shape}")
    edges = np.asarray(edges, dtype=float)
    if edges.ndim != 1 or edges.size < 2 or np.any(np.diff(edges) <= 0):
        raise InputError(f"binned: edges must increase, got {edges.tolist()}")
    out: dict[str, list] = {k: [] for k in STATISTICS}
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        s = _summary(e[(x >= lo) & (x < hi) & np.isfinite(e)])
        for k, v in s.items():
            out[k].append(v)
    return {k: np.asarray(v, dtype=float) for k, v in out.items()}


def held_out_bands(
    scores: Scores, level: float, min_shots: int = MIN_SHOTS
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every shot's band factors from the comparable shots of the other sources.

    Returns
    -------
    lo, hi : ndarray
        The band's factors (NaN where fewer than ``min_shots`` are comparable).
    n : ndarray of int
        The comparable shots of the other sources.
    """
    k = scores.ratio.size
    lo, hi, n = np.full(k, np.nan), np.full(k, np.nan), np.zeros(k, dtype=int)
    for i in range(k):
        m = comparable(
            scores, scores.diameter[i], scores.fc[i], scores.velocity[i], scores.crh[i]
        ) & (scores.source != scores.source[i])
        n[i] = int(m.sum())
        if n[i] >= min_shots:
            lo[i], hi[i] = band_factors(scores.ratio[m], level)
    return lo, hi, n


@dataclass(frozen=True)
class Calibration:
    """The held-out calibration of a law's band.

    Attributes
    ----------
    nominal_level : float
        The smallest of :data:`LEVELS` whose held-out bands held ``stated_level`` of the
        shots (1 where none did: the band is then the comparable shots' whole range).
    held_out_coverage : float
        The share of shots with a band whose held-out band at ``nominal_level`` held them.
    coverage_at_stated : float
        The same at the nominal level equal to the stated one (uncalibrated).
    n_with_band : int
        Shots with at least :data:`~pencore.inputs.record.MIN_SHOTS` comparable shots of other
        sources.
    n_shots : int
        All the law's shots.
    stated_level : float
        :data:`~pencore.inputs.record.STATED_LEVEL`.
    """

    nominal_level: float
    held_out_coverage: float
    coverage_at_stated: float
    n_with_band: int
    n_shots: int
    stated_level: float = STATED_LEVEL


def calibrate_level(
    scores: Scores,
    levels: Sequence[float] = LEVELS,
    stated: float = STATED_LEVEL,
    min_shots: int = MIN_SHOTS,
) -> Calibration:
    """The nominal level whose bands hold ``stated`` of shots one source left out at a time.

    Examples
    --------
    Ratios that do not depend on the source: the stated level needs no widening.

    >>> import numpy as np
    >>> rng = np.random.default_rng(1)
    >>> n = 400
    >>> s = Scores("demo", np.repeat(np.arange(20).astype(str), 20), np.full(n, 0.03),
    ...            np.full(n, 40e6), np.full(n, 500.0), np.full(n, 3.0),
    ...            np.exp(rng.normal(0, 0.2, n)), np.nan, np.nan)
    >>> c = calibrate_level(s)
    >>> c.nominal_level <= 0.84, round(c.held_out_coverage, 2) >= 0.8
    (True, True)
    """
    cov: dict[float, float] = {}
    n_band = 0
    for level in sorted(set(levels) | {stated}):
        lo, hi, _ = held_out_bands(scores, level, min_shots)
        has = np.isfinite(lo)
        n_band = int(has.sum())
        r = scores.ratio[has]
        cov[level] = float(np.mean((r >= lo[has]) & (r <= hi[has]))) if n_band else np.nan
    chosen = next((lv for lv in levels if cov[lv] >= stated), max(levels))
    return Calibration(
        nominal_level=float(chosen),
        held_out_coverage=cov[chosen],
        coverage_at_stated=cov[stated],
        n_with_band=n_band,
        n_shots=int(scores.ratio.size),
        stated_level=stated,
    )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
