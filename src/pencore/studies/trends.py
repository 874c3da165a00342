"""Trend verdicts: does a quantity rise or fall along a parameter, within the numerical
brackets of the searches.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["TrendResult", "trend"]


@dataclass(frozen=True)
class TrendResult:
    """Verdict on a claimed trend along one parameter.

    Each consecutive pair (a at the smaller parameter, b at the larger) compares the
    intervals ``[lo, hi]`` that hold the two values: b *falls* when ``b.hi < a.lo``,
    *rises* when ``b.lo > a.hi``, is *flat* when the intervals overlap (equal within the
    search tolerance), *undetermined* when either is unknown.

    ``verdict`` for the claim "falls" (mirror for "rises"): ``holds`` (no pair against
    the claim and at least one with it), ``partly holds`` (pairs both ways), ``does not
    hold`` (pairs against it, none with it, or all flat), ``undetermined`` (no pair could
    be compared).
    """

    claim: str
    verdict: str
    n_with: int
    n_flat: int
    n_against: int
    n_undetermined: int
    against: tuple[str, ...] = ()

    def note(self) -> str:
        s = (
            f"{self.n_with} step(s) {self.claim}, {self.n_flat} flat within the "
            f"tolerance, {self.n_against} against, {self.n_undetermined} undetermined"
        )
        if self.against:
            s += "; against: " + "; ".join(self.against[:6])
            if len(self.against) > 6:
                s += f"; ... ({len(self.against) - 6} more)"
        return s


def _interval(lo: float, hi: float) -> tuple[float, float]:
    lo = -math.inf if not np.isfinite(lo) else float(lo)
    hi = math.inf if not np.isfinite(hi) else float(hi)
    return lo, hi


def trend(
    lines: Iterable[tuple[str, Sequence[float], Sequence[float], Sequence[float]]],
    claim: str = "falls",
) -> TrendResult:
    """Check a claimed monotone trend on several lines of bracketed values.

    Parameters
    ----------
    lines : iterable of (label, parameter, lo, hi)
        One line per fixed setting of the other parameters: the parameter values
        (sorted here), and the bracket ``[lo, hi]`` of the quantity at each. For an exact
        value give ``lo = hi = value``. NaN in ``lo`` means "unbounded below" and in
        ``hi`` "unbounded above" (e.g. a search that ended ``above_range`` gives
        ``[range_hi, NaN]``); both NaN means unknown.
    claim : {"falls", "rises"}
    """
    if claim not in ("falls", "rises"):
        raise ValueError(f"claim must be 'falls' or 'rises', got {claim!r}")
    n_w = n_f = n_a = n_u = 0
    against = []
    for label, par, lo, hi in lines:
        par = np.asarray(par, float)
        order = np.argsort(par)
        par = par[order]
        lo = np.asarray(lo, float)[order]
        hi = np.asarray(hi, float)[order]
        for i in range(par.size - 1):
            if (np.isnan(lo[i]) and np.isnan(hi[i])) or (
                np.isnan(lo[i + 1]) and np.isnan(hi[i + 1])
            ):
                n_u += 1
                continue
            a_lo, a_hi = _interval(lo[i], hi[i])
            b_lo, b_hi = _interval(lo[i + 1], hi[i + 1])
            falls, rises = b_hi < a_lo, b_lo > a_hi
            if falls or rises:
                if (falls and claim == "falls") or (rises and claim == "rises"):
                    n_w += 1
                else:
                    n_a += 1
                    against.append(
                        f"{label}: {par[i]:g}->{par[i + 1]:g} "
                        f"[{a_lo:.4g}, {a_hi:.4g}] -> [{b_lo:.4g}, {b_hi:.4g}]"
                    )
            elif math.isinf(a_lo) and math.isinf(b_lo) or math.isinf(a_hi) and math.isinf(b_hi):
                n_u += 1  # both unbounded the same way: cannot compare
            else:
                n_f += 1
    if n_w + n_f + n_a == 0:
        verdict = "undetermined"
    elif n_a == 0 and n_w > 0:
        verdict = "holds"
    elif n_a > 0 and n_w > 0:
        verdict = "partly holds"
    else:
        verdict = "does not hold"
    return TrendResult(claim, verdict, n_w, n_f, n_a, n_u, tuple(against))
