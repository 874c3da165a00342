"""The rigid regime of a search: judged at its answer, not at every speed it tries.

A speed search runs far outside the rigid regime at the top of its bracket (a ballistic
limit bracketed up to 3000 m/s) while its answer lies well inside. The runs of a search
therefore do not warn (:func:`quiet`), and the search warns once when the speed it finds
is outside the regime (:func:`warn_at_answer`, :func:`pencore.inputs.regime.warn_outside`):
where a rigid body's threshold is not to be trusted.
"""

from __future__ import annotations

import math

from pencore.errors import hint_keywords
from pencore.inputs.regime import warn_outside
from pencore.integrators.problem import Problem
from pencore.search.threshold import CriticalResult

__all__ = ["quiet", "warn_at_answer"]


def quiet(pr: Problem) -> Problem:
    """The prepared problem with its runs' regime warning spent: a search's runs do not
    warn (the search judges its answer)."""
    pr.regime_warned = True
    return pr


def warn_at_answer(pr: Problem, result: CriticalResult) -> CriticalResult:
    """Warn when a speed search's answer (the upper end of its final bracket, m/s) is
    outside the rigid regime; the result unchanged."""
    if result.status in ("ok", "non_monotone") and math.isfinite(result.hi):
        warn_outside(pr.projectile, pr.target, result.hi)
    return result


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
