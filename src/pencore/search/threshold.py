"""The threshold search behind every critical value, and its result.

:func:`find_threshold` finds the lowest value of one input at which a yes/no verdict
switches from False to True: it checks both ends of the bracket, optionally scans it
coarsely to detect a non-monotone verdict, and bisects to a caller-given tolerance.
Every verdict evaluated is returned in :class:`CriticalResult`, so a workflow can
archive the evidence behind each number. The verdicts themselves (a run that turns back,
deviates or perforates) are in :mod:`pencore.search.critical` and
:mod:`pencore.search.perforation`.
"""

from __future__ import annotations

import difflib
import logging
import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from pencore.errors import InputError, SolverError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.limits import as_float, number
from pencore.inputs.numerics import Numerics

#: Progress of the searches (bracket, evaluations, verdicts) at INFO; the workflow
#: scripts route it to the rule's log file.
log = logging.getLogger("pencore.search")

__all__ = [
    "check_search_args",
    "MAX_SCAN",
    "MAX_ITER",
    "VELOCITY_TOL",
    "OMEGA_TOL",
    "DEFAULT_SCAN",
    "STATUSES",
    "CriticalResult",
    "find_threshold",
    "FIXED_BY_SEARCH",
    "split_search_kwargs",
]

#: Default (and widest recommended) bracket width for critical velocities (m/s).
VELOCITY_TOL = 5.0
#: Default (and widest recommended) bracket width for critical angular velocities (rad/s).
OMEGA_TOL = 0.5
#: Scan points used by :func:`~pencore.vcr`, :func:`~pencore.omega_c` and :func:`~pencore.vci`
#: before bisecting.
DEFAULT_SCAN = 5

#: Possible values of ``CriticalResult.status`` (:class:`~pencore.CriticalResult`).
STATUSES = ("ok", "non_monotone", "below_range", "above_range", "max_iter", "solver_error")


@dataclass(frozen=True)
class CriticalResult:
    """Outcome of a threshold search.

    Attributes
    ----------
    value : float
        Midpoint of the final bracket ``[lo, hi]``; NaN for ``below_range`` and
        ``above_range``.
    lo : float
        Largest value evaluated with verdict False below the threshold (NaN if none,
        i.e. ``below_range``).
    hi : float
        Smallest value evaluated with verdict True above ``lo`` (NaN if none, i.e.
        ``above_range``). For ``below_range`` it is the lower end of the search range.
    n_evals : int
        Number of verdict evaluations (each value is evaluated once).
    monotone : bool
        False if the coarse scan saw a True followed later by a False. True otherwise,
        which without a scan means "not contradicted", not "proven".
    status : str
        ``"ok"``: converged, ``hi - lo <= tol``. ``"non_monotone"``: converged on the
        first False -> True transition of a non-monotone verdict (the lowest threshold
        found). ``"below_range"``: the verdict is already True at the lower end.
        ``"above_range"``: it is still False at the upper end. ``"max_iter"``: the bracket
        is still wider than ``tol`` after ``max_iter`` bisections. ``"solver_error"``: a
        run of the verdict could not finish (:class:`~pencore.SolverError`: the steps
        stalled, a budget ran out); ``value``, ``lo`` and ``hi`` are NaN, ``message`` is
        the solver's reason and ``history`` the verdicts found before it.
    message : str
        Human-readable explanation, naming the flips of a non-monotone verdict.
    history : tuple of (float, bool)
        Every evaluated value and its verdict, in evaluation order.
    tol : float
        The tolerance asked for.

    Examples
    --------
    >>> from pencore import find_threshold
    >>> r = find_threshold(lambda x: x >= 0.3, 0.0, 1.0, 0.01, scan=5)
    >>> print(r.status, r.converged, r.monotone, r.n_evals, f"{r.value:.3f}")
    ok True True 10 0.301
    >>> r.history[:3]
    ((0.0, False), (1.0, True), (0.25, False))
    """

    value: float
    lo: float
    hi: float
    n_evals: int
    monotone: bool
    status: str
    message: str
    history: tuple[tuple[float, bool], ...] = ()
    tol: float = math.nan

    @property
    def converged(self) -> bool:
        """True when ``value`` is a threshold located to within ``tol``."""
        return self.status in ("ok", "non_monotone")

    def to_dict(self) -> dict[str, Any]:
        """Plain-Python dict (history as a list of [value, verdict]) for JSON/netCDF attrs."""
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        d["history"] = [[float(v), bool(b)] for v, b in self.history]
        return d


def _fmt(v: float) -> str:
    return f"{v:.6g}"


def find_threshold(
    verdict: Callable[[float], bool],
    lo: float,
    hi: float,
    tol: float,
    *,
    max_iter: int = 60,
    scan: int | None = None,
    name: str = "threshold",
) -> CriticalResult:
    """Lowest value in ``[lo, hi]`` where ``verdict`` switches from False to True.

    Progress (the bracket, each evaluation and its verdict, the outcome) is logged at
    INFO through ``logging.getLogger("pencore.search")``, prefixed with ``name``.

    Parameters
    ----------
    verdict : callable
        ``verdict(value) -> bool``; True means "reverses" / "unstable". Called once per
        distinct value.
    lo, hi : float
        Search range, ``lo < hi`` (units of the searched quantity).
    tol : float
        Required width of the final bracket (same units), > 0. No default on purpose:
        use :data:`~pencore.search.threshold.VELOCITY_TOL` or
        :data:`~pencore.search.threshold.OMEGA_TOL` or tighter.
    max_iter : int
        Largest number of bisection steps.
    scan : int, optional
        Number of equally spaced points (ends included, >= 2) evaluated across
        ``[lo, hi]`` before bisecting. If they show a True followed later by a False the
        verdict is not monotone: ``monotone`` is False, ``status`` is
        ``"non_monotone"``, ``message`` names the values where it flips, and only the
        FIRST False -> True transition of the scan is bisected, so the result is the
        lowest threshold found (a flip narrower than the scan spacing can still be
        missed). Default None: only the ends are checked.
    name : str, optional
        What is searched (``"Vcr"``, ``"Vci"``, ``"omega_c"``), for the progress log.

    Returns
    -------
    CriticalResult
        The bracket ends are checked first: if ``verdict(lo)`` is True the status is
        ``"below_range"`` (``value`` NaN, ``hi = lo``, ``lo`` NaN); if ``verdict(hi)`` is
        False it is ``"above_range"`` (``value`` NaN, ``lo = hi``, ``hi`` NaN). Otherwise
        ``lo`` has verdict False, ``hi`` True, ``hi - lo <= tol`` (unless ``max_iter``),
        and ``value = (lo + hi) / 2``.

    Raises
    ------
    InputError
        ``lo >= hi``, a bound or ``tol`` that is not a finite number, ``tol <= 0``,
        ``max_iter`` or ``scan`` not a whole number in its range, a ``verdict`` that is
        not callable or returns anything but True or False (``"no"``, None, NaN, 0, an
        array): the message names it.

    Examples
    --------
    Any yes/no question of one number: here where ``x**2`` exceeds 2.

    >>> from pencore import find_threshold
    >>> r = find_threshold(lambda x: x * x > 2.0, 0.0, 2.0, 1e-6)
    >>> print(r.status, f"{r.value:.5f}", r.lo < 2**0.5 <= r.hi)
    ok 1.41421 True
    >>> find_threshold(lambda x: x > 5.0, 0.0, 2.0, 0.1).status
    'above_range'
    """
    if not callable(verdict):
        raise InputError(
            f"verdict must be a function value -> bool, got {type(verdict).__name__} "
            f"{brief(verdict)}"
        )
    lo, hi, tol, max_iter, scan = check_search_args(lo, hi, tol, max_iter, scan)
    search = _Search(verdict, name, tol, [lo, hi])
    log.info("%s: search in [%s, %s], tol %s", name, _fmt(lo), _fmt(hi), _fmt(tol))
    try:
        return _search(search, lo, hi, tol, max_iter, scan)
    except SolverError as exc:
        # a run that cannot finish (steps stalled, a budget spent) is this search's
        # verdict, with its reason: the caller's table keeps every other cell
        return search.result(math.nan, math.nan, math.nan, True, "solver_error", str(exc))


def _search(
    search: _Search, lo: float, hi: float, tol: float, max_iter: int, scan: int | None
) -> CriticalResult:
    """The search of :func:`find_threshold` on checked arguments."""
    nan = math.nan
    if search.ev(lo):
        return search.result(
            nan,
            nan,
            lo,
            True,
            "below_range",
            f"verdict is already True at the lower end {_fmt(lo)}: the threshold "
            f"is at or below {_fmt(lo)}; lower lo",
        )
    if not search.ev(hi):
        return search.result(
            nan,
            hi,
            nan,
            True,
            "above_range",
            f"verdict is still False at the upper end {_fmt(hi)}: the threshold "
            f"is above {_fmt(hi)} (or does not exist); raise hi",
        )
    if scan is not None:
        a, b, monotone, note = _scan(search, lo, hi, int(scan))
    else:
        a, b, monotone, note = lo, hi, True, "monotonicity not checked (no scan)"
    a, b, n_iter = _bisect(search, a, b, tol, max_iter)
    if b - a > tol:
        status = "max_iter"
        first = f"bracket width {_fmt(b - a)} is still > tol {_fmt(tol)} after {n_iter} bisections"
    else:
        status = "ok" if monotone else "non_monotone"
        first = f"threshold in [{_fmt(a)}, {_fmt(b)}] after {n_iter} bisections"
    return search.result(0.5 * (a + b), a, b, monotone, status, f"{first}; {note}")


#: Most points of a coarse scan (each is a run) and most bisection steps a search takes.
MAX_SCAN = 1000
MAX_ITER = 1000


def _real(value: Any, what: str) -> float:
    """``value`` as a finite float; refuses booleans, text and anything else."""
    v = as_float(value, allow_str=False)
    if v is None or not math.isfinite(v):
        raise InputError(f"{what} must be a finite number, got {brief(value)}")
    return v


def _whole(value: Any, what: str, lo: int, hi: int) -> int:
    v = as_float(value, allow_str=False)
    if v is None or not math.isfinite(v) and not isinstance(value, numbers.Integral):
        raise InputError(f"{what} must be a whole number in [{lo}, {hi}], got {brief(value)}")
    if (math.isfinite(v) and v != math.floor(v)) or not lo <= v <= hi:
        raise InputError(f"{what} must be a whole number in [{lo}, {hi}], got {brief(value)}")
    return int(v)


def check_search_args(
    lo: Any,
    hi: Any,
    tol: Any,
    max_iter: Any,
    scan: Any,
    quantity: str | None = None,
) -> tuple[float, float, float, int, int | None]:
    """The arguments of a search, checked before any run, or
    :class:`~pencore.errors.InputError` naming the bad one.

    ``lo < hi`` finite numbers (within ``LIMITS[quantity]`` when given, e.g.
    ``"velocity"``, ``"omega"``), ``tol`` a positive finite number, ``max_iter`` a whole
    number in ``[0, MAX_ITER]``, ``scan`` None or a whole number in ``[2, MAX_SCAN]``.
    Returns them as ``(float, float, float, int, int or None)``.
    """
    if quantity is not None:
        lo_f = number(lo, quantity, "search lower bound lo")
        hi_f = number(hi, quantity, "search upper bound hi")
    else:
        lo_f, hi_f = _real(lo, "search lower bound lo"), _real(hi, "search upper bound hi")
    if not lo_f < hi_f:
        raise InputError(f"need lo < hi, got lo={brief(lo)}, hi={brief(hi)}")
    tol_f = _real(tol, "tol")
    if not tol_f > 0.0:
        raise InputError(f"tol must be a positive number, got {brief(tol)}")
    n_iter = _whole(max_iter, "max_iter", 0, MAX_ITER)
    n_scan = None if scan is None else _whole(scan, "scan", 2, MAX_SCAN)
    return lo_f, hi_f, tol_f, n_iter, n_scan


def _check_search(lo: float, hi: float, tol: float, max_iter: int, scan: int | None) -> None:
    """The arguments of :func:`find_threshold`, or :class:`~pencore.errors.InputError`."""
    check_search_args(lo, hi, tol, max_iter, scan)


class _Search:
    """One search's verdicts: each value evaluated once, every evaluation logged and kept
    in order, and the current bracket (for the log)."""

    def __init__(
        self, verdict: Callable[[float], bool], name: str, tol: float, bracket: list[float]
    ) -> None:
        self.verdict, self.name, self.tol, self.bracket = verdict, name, tol, bracket
        self.seen: dict[float, bool] = {}
        self.history: list[tuple[float, bool]] = []

    def ev(self, v: float) -> bool:
        v = float(v)
        if v not in self.seen:
            answer = self.verdict(v)
            if not isinstance(answer, bool | np.bool_):
                # "no", None, NaN, 0/1 or an array would pass bool() as an answer
                raise InputError(
                    f"{self.name}: verdict({_fmt(v)}) must return True or False, got "
                    f"{type(answer).__name__} {brief(answer)}"
                )
            self.seen[v] = bool(answer)
            self.history.append((v, self.seen[v]))
            log.info(
                "%s: evaluation %d at %s -> %s (bracket [%s, %s])",
                self.name,
                len(self.history),
                _fmt(v),
                self.seen[v],
                _fmt(self.bracket[0]),
                _fmt(self.bracket[1]),
            )
        return self.seen[v]

    def result(
        self, value: float, a: float, b: float, monotone: bool, status: str, message: str
    ) -> CriticalResult:
        log.info(
            "%s: %s after %d evaluations, value %s in [%s, %s]",
            self.name,
            status,
            len(self.history),
            _fmt(value),
            _fmt(a),
            _fmt(b),
        )
        return CriticalResult(
            value, a, b, len(self.history), monotone, status, message, tuple(self.history),
            self.tol,
        )  # fmt: skip


def _scan(search: _Search, lo: float, hi: float, n: int) -> tuple[float, float, bool, str]:
    """Evaluate ``n`` equally spaced points of ``[lo, hi]`` (ends known: False at ``lo``,
    True at ``hi``); the first False -> True interval, whether the verdict is monotone,
    and a note naming the flips of a non-monotone one."""
    grid = np.linspace(lo, hi, n)
    grid[0], grid[-1] = lo, hi
    verdicts = [search.ev(v) for v in grid]
    flips = [
        (grid[i], verdicts[i], grid[i + 1], verdicts[i + 1])
        for i in range(len(grid) - 1)
        if verdicts[i] != verdicts[i + 1]
    ]
    first = next(i for i in range(len(grid) - 1) if not verdicts[i] and verdicts[i + 1])
    a, b = float(grid[first]), float(grid[first + 1])
    search.bracket[:] = [a, b]
    if not any(v1 and not v2 for _, v1, _, v2 in flips):
        return a, b, True, f"{len(grid)}-point scan of [{_fmt(lo)}, {_fmt(hi)}] is monotone"
    desc = "; ".join(
        f"{str(v1)}->{str(v2)} between {_fmt(x1)} and {_fmt(x2)}" for x1, v1, x2, v2 in flips
    )
    note = (
        f"verdict is not monotone on the {len(grid)}-point scan of "
        f"[{_fmt(lo)}, {_fmt(hi)}]: flips {desc}; bisected only the first "
        f"False->True transition [{_fmt(a)}, {_fmt(b)}], so the value is the "
        "lowest threshold found"
    )
    return a, b, False, note


def _bisect(
    search: _Search, a: float, b: float, tol: float, max_iter: int
) -> tuple[float, float, int]:
    """Halve the bracket ``[a, b]`` (verdict False at ``a``, True at ``b``) until it is at
    most ``tol`` wide, ``max_iter`` steps were taken, or floating point cannot split it;
    the final bracket and the number of steps."""
    n_iter = 0
    while b - a > tol and n_iter < max_iter:
        mid = 0.5 * (a + b)
        if mid <= a or mid >= b:  # floating-point resolution reached
            break
        if search.ev(mid):
            b = mid
        else:
            a = mid
        search.bracket[:] = [a, b]
        n_iter += 1
    return a, b, n_iter


#: Arguments of a run that a solver-backed search sets itself.
FIXED_BY_SEARCH = {"velocity", "obliquity", "yaw", "omega", "prepared", "stop_at_reversal"}


def split_search_kwargs(
    kwargs: dict[str, Any], fixed: set[str]
) -> tuple[Numerics | None, dict, dict]:
    """Split a search's keyword arguments into (numerics, numerics overrides, simulate
    kwargs); arguments in ``fixed`` (set by the search itself) and unknown ones raise
    :class:`~pencore.errors.InputError`."""
    bad = set(kwargs) & fixed
    if bad:
        raise InputError(f"argument(s) {', '.join(sorted(bad))} are set by the search itself")
    numerics = kwargs.pop("numerics", None)
    # numerics overrides and the models (shank=, emulation=) all go to prepare()
    to_prepare = set(Numerics.__dataclass_fields__) | {"shank", "emulation"}
    overrides = {k: kwargs.pop(k) for k in list(kwargs) if k in to_prepare}
    unknown = sorted(set(kwargs) - {"start"}, key=str)
    if unknown:
        known = sorted(fixed | to_prepare | {"start", "numerics"})
        hint = difflib.get_close_matches(str(unknown[0]), known, n=1, cutoff=0.6)
        tip = f" (did you mean {hint[0]!r}?)" if hint else ""
        raise InputError(f"unknown argument(s): {', '.join(map(str, unknown))}{tip}")
    return numerics, overrides, kwargs


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
