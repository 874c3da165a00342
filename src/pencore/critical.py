"""Critical-value searches: Vcr, Vci and omega_c as thresholds of a yes/no verdict.

Each critical value of the paper is the lowest value of one input at which a run's
verdict switches from False to True:

* ``vcr`` (Section 4.2, Figs 8 and 12): the lowest impact speed at which the projectile
  turns back towards the surface (``reversed``) for a given obliquity and yaw;
* ``omega_c`` (Figs 16-18): the lowest initial angular velocity about the centre of mass
  at which a normal impact turns back;
* ``vci`` (Figs 13-15): the lowest normal-impact speed at which, for a small yaw, the
  final deviation (:func:`pencore.analysis.final_deviation`) exceeds a chosen threshold
  or the projectile turns back. The paper does not state its threshold; the caller must.
  Nor does it say which of the velocity or the axis is normal in a "normal impact with
  yaw": :func:`normal_impact_angles` maps the two readings (:data:`YAW_CONVENTIONS`)
  onto ``simulate``'s obliquity and yaw.

:func:`find_threshold` does the search on any verdict: it checks both ends of the
bracket, optionally scans it coarsely to detect a non-monotone verdict, and bisects to a
caller-given tolerance. Every verdict evaluated is returned, so a workflow can archive
the evidence behind each number. The ballistic limit of a finite target
(``ballistic_limit``, lowest speed that perforates) is the same search, in
:mod:`pencore.perforation` and re-exported here.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from .analysis import DEFAULT_SPEED_FRACTION, final_deviation
from .conventions import YAW_CONVENTIONS, normal_impact_angles
from .library import InputError
from .solver import Numerics, prepare, run_impact, simulate

#: Progress of the searches (bracket, evaluations, verdicts) at INFO; the workflow
#: scripts route it to the rule's log file.
log = logging.getLogger("pencore.critical")

__all__ = [
    "VELOCITY_TOL",
    "OMEGA_TOL",
    "DEFAULT_SCAN",
    "STATUSES",
    "CriticalResult",
    "find_threshold",
    "vcr",
    "omega_c",
    "vci",
    "YAW_CONVENTIONS",
    "normal_impact_angles",
    "ballistic_limit",  # noqa: F822 - lazy, see __getattr__
]

#: Default (and widest recommended) bracket width for critical velocities (m/s).
VELOCITY_TOL = 5.0
#: Default (and widest recommended) bracket width for critical angular velocities (rad/s).
OMEGA_TOL = 0.5
#: Scan points used by :func:`vcr`, :func:`omega_c` and :func:`vci` before bisecting.
DEFAULT_SCAN = 5

#: Possible values of :attr:`CriticalResult.status`.
STATUSES = ("ok", "non_monotone", "below_range", "above_range", "max_iter")


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
        is still wider than ``tol`` after ``max_iter`` bisections.
    message : str
        Human-readable explanation, naming the flips of a non-monotone verdict.
    history : tuple of (float, bool)
        Every evaluated value and its verdict, in evaluation order.
    tol : float
        The tolerance asked for.
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
    INFO through ``logging.getLogger("pencore.critical")``, prefixed with ``name``.

    Parameters
    ----------
    verdict : callable
        ``verdict(value) -> bool``; True means "reverses" / "unstable". Called once per
        distinct value.
    lo, hi : float
        Search range, ``lo < hi`` (units of the searched quantity).
    tol : float
        Required width of the final bracket (same units), > 0. No default on purpose:
        use :data:`VELOCITY_TOL` or :data:`OMEGA_TOL` or tighter.
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
    """
    lo, hi, tol = float(lo), float(hi), float(tol)
    if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
        raise InputError(f"need finite lo < hi, got lo={lo!r}, hi={hi!r}")
    if not (math.isfinite(tol) and tol > 0.0):
        raise InputError(f"tol must be a positive number, got {tol!r}")
    if int(max_iter) < 0:
        raise InputError(f"max_iter must be >= 0, got {max_iter!r}")
    if scan is not None and int(scan) < 2:
        raise InputError(f"scan must be None or >= 2 points, got {scan!r}")

    seen: dict[float, bool] = {}
    history: list[tuple[float, bool]] = []

    bracket = [float(lo), float(hi)]  # current bracket, for the progress log only
    log.info("%s: search in [%s, %s], tol %s", name, _fmt(lo), _fmt(hi), _fmt(tol))

    def ev(v: float) -> bool:
        v = float(v)
        if v not in seen:
            seen[v] = bool(verdict(v))
            history.append((v, seen[v]))
            log.info(
                "%s: evaluation %d at %s -> %s (bracket [%s, %s])",
                name,
                len(history),
                _fmt(v),
                seen[v],
                _fmt(bracket[0]),
                _fmt(bracket[1]),
            )
        return seen[v]

    def result(
        value: float, a: float, b: float, monotone: bool, status: str, message: str
    ) -> CriticalResult:
        log.info(
            "%s: %s after %d evaluations, value %s in [%s, %s]",
            name,
            status,
            len(history),
            _fmt(value),
            _fmt(a),
            _fmt(b),
        )
        return CriticalResult(
            value, a, b, len(history), monotone, status, message, tuple(history), tol
        )

    nan = math.nan
    if ev(lo):
        return result(
            nan,
            nan,
            lo,
            True,
            "below_range",
            f"verdict is already True at the lower end {_fmt(lo)}: the threshold "
            f"is at or below {_fmt(lo)}; lower lo",
        )
    if not ev(hi):
        return result(
            nan,
            hi,
            nan,
            True,
            "above_range",
            f"verdict is still False at the upper end {_fmt(hi)}: the threshold "
            f"is above {_fmt(hi)} (or does not exist); raise hi",
        )

    monotone = True
    notes = []
    a, b = lo, hi
    if scan is not None:
        grid = np.linspace(lo, hi, int(scan))
        grid[0], grid[-1] = lo, hi
        verdicts = [ev(v) for v in grid]
        flips = [
            (grid[i], verdicts[i], grid[i + 1], verdicts[i + 1])
            for i in range(len(grid) - 1)
            if verdicts[i] != verdicts[i + 1]
        ]
        first = next(i for i in range(len(grid) - 1) if not verdicts[i] and verdicts[i + 1])
        a, b = float(grid[first]), float(grid[first + 1])
        bracket[:] = [a, b]
        if any(v1 and not v2 for _, v1, _, v2 in flips):
            monotone = False
            desc = "; ".join(
                f"{str(v1)}->{str(v2)} between {_fmt(x1)} and {_fmt(x2)}"
                for x1, v1, x2, v2 in flips
            )
            notes.append(
                f"verdict is not monotone on the {len(grid)}-point scan of "
                f"[{_fmt(lo)}, {_fmt(hi)}]: flips {desc}; bisected only the first "
                f"False->True transition [{_fmt(a)}, {_fmt(b)}], so the value is the "
                "lowest threshold found"
            )
        else:
            notes.append(f"{len(grid)}-point scan of [{_fmt(lo)}, {_fmt(hi)}] is monotone")
    else:
        notes.append("monotonicity not checked (no scan)")

    n_iter = 0
    while b - a > tol and n_iter < max_iter:
        mid = 0.5 * (a + b)
        if mid <= a or mid >= b:  # floating-point resolution reached
            break
        if ev(mid):
            b = mid
        else:
            a = mid
        bracket[:] = [a, b]
        n_iter += 1
    value = 0.5 * (a + b)
    if b - a > tol:
        status = "max_iter"
        notes.insert(
            0, f"bracket width {_fmt(b - a)} is still > tol {_fmt(tol)} after {n_iter} bisections"
        )
    else:
        status = "ok" if monotone else "non_monotone"
        notes.insert(0, f"threshold in [{_fmt(a)}, {_fmt(b)}] after {n_iter} bisections")
    return result(value, a, b, monotone, status, "; ".join(notes))


# ------------------------------------------------------------------ solver-backed searches

_FIXED = {"velocity", "obliquity", "yaw", "omega", "prepared", "stop_at_reversal"}


def _split(kwargs: dict[str, Any], fixed: set[str]) -> tuple[Numerics | None, dict, dict]:
    """Split keyword arguments into (numerics, numerics overrides, simulate kwargs)."""
    bad = set(kwargs) & fixed
    if bad:
        raise InputError(f"argument(s) {', '.join(sorted(bad))} are set by the search itself")
    numerics = kwargs.pop("numerics", None)
    # numerics overrides and the models (shank=, emulation=) all go to prepare()
    to_prepare = set(Numerics.__dataclass_fields__) | {"shank", "emulation"}
    overrides = {k: kwargs.pop(k) for k in list(kwargs) if k in to_prepare}
    unknown = set(kwargs) - {"start"}
    if unknown:
        raise InputError(f"unknown argument(s): {', '.join(sorted(unknown))}")
    return numerics, overrides, kwargs


def _turns_back(
    pr: Any, sim: dict[str, Any], velocity: float, obliquity: float, yaw: float, omega: float
) -> bool:
    """Run to the first reversal (or the end) and say whether the projectile turned back
    (the raw run: the verdict needs no Dataset)."""
    run = run_impact(
        pr.projectile,
        pr.target,
        velocity,
        obliquity,
        yaw,
        omega,
        stop_at_reversal=True,
        prepared=pr,
        **sim,
    )
    return bool(run.reversed)


def vcr(
    projectile: Any,
    target: Any,
    obliquity: float,
    yaw: float = 0.0,
    lo: float = 100.0,
    hi: float = 4000.0,
    tol: float = VELOCITY_TOL,
    *,
    omega: float = 0.0,
    scan: int | None = DEFAULT_SCAN,
    max_iter: int = 60,
    **simulate_kwargs: Any,
) -> CriticalResult:
    """Critical reverse velocity Vcr (m/s): lowest impact speed that turns back.

    Verdict at speed ``v``: ``simulate(projectile, target, v, obliquity, yaw, omega,
    stop_at_reversal=True)`` has ``attrs['reversed'] == 1`` (the centre-of-mass velocity
    turned towards the surface while in the target).

    Parameters
    ----------
    projectile, target
        As for :func:`pencore.simulate` (names, YAML paths or objects).
    obliquity, yaw : float
        Degrees.
    lo, hi : float
        Speed range searched (m/s). Low speeds at grazing obliquity can ricochet
        (reverse) too; the default scan flags that as ``non_monotone``.
    tol : float
        Final bracket width (m/s).
    omega : float
        Initial angular velocity (rad/s).
    scan, max_iter
        See :func:`find_threshold`; by default a 5-point scan guards against a
        non-monotone verdict.
    **simulate_kwargs
        ``numerics=``, numerics overrides (``rtol=``, ``eps=``, ...), ``start=``, and the
        shank contact model and paper-emulation numerics (``shank=``, ``emulation=``;
        :mod:`pencore.models`).
    """
    numerics, overrides, sim = _split(dict(simulate_kwargs), _FIXED)
    pr = prepare(projectile, target, numerics, **overrides)

    def verdict(v: float) -> bool:
        return _turns_back(pr, sim, v, obliquity, yaw, omega)

    return find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="Vcr")


def omega_c(
    projectile: Any,
    target: Any,
    velocity: float,
    lo: float,
    hi: float,
    tol: float = OMEGA_TOL,
    *,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    scan: int | None = DEFAULT_SCAN,
    max_iter: int = 60,
    **simulate_kwargs: Any,
) -> CriticalResult:
    """Critical angular velocity omega_c (rad/s): lowest initial omega that turns back.

    Verdict at ``w``: ``simulate(projectile, target, velocity, obliquity, yaw, omega=w,
    stop_at_reversal=True)`` has ``attrs['reversed'] == 1``. Normal impact by default
    (paper Figs 16-18). ``lo``, ``hi`` and ``tol`` in rad/s; other arguments as
    :func:`vcr`.
    """
    numerics, overrides, sim = _split(dict(simulate_kwargs), _FIXED)
    pr = prepare(projectile, target, numerics, **overrides)

    def verdict(w: float) -> bool:
        return _turns_back(pr, sim, velocity, obliquity, yaw, w)

    return find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="omega_c")


def vci(
    projectile: Any,
    target: Any,
    yaw: float,
    lo: float,
    hi: float,
    threshold_deg: float,
    tol: float = VELOCITY_TOL,
    *,
    omega: float = 0.0,
    fraction: float = DEFAULT_SPEED_FRACTION,
    convention: str = "axis_tilted",
    scan: int | None = DEFAULT_SCAN,
    max_iter: int = 60,
    shared_runs: dict[float, tuple[bool, float]] | None = None,
    **simulate_kwargs: Any,
) -> CriticalResult:
    """Critical impact velocity for instability Vci (m/s), normal impact with small yaw.

    Verdict at speed ``v``: the run ``simulate(projectile, target, v, obliquity, yaw',
    omega, stop_at_reversal=True)``, with ``(obliquity, yaw') =``
    :func:`normal_impact_angles` ``(yaw, convention)``, reversed, OR its final deviation
    (:func:`pencore.analysis.final_deviation` with ``fraction``: the velocity angle from
    the normal at the last state with speed >= ``fraction`` x impact speed) exceeds
    ``threshold_deg``. The paper gives no threshold (it calls 0.16-0.24 deg "not really
    affected" and 2200 m/s for #4 "large"); report how Vci moves with it.

    Parameters
    ----------
    yaw : float
        Initial yaw (deg), e.g. 0.1.
    lo, hi, tol : float
        Speed range and final bracket width (m/s).
    threshold_deg : float
        Deviation (deg) above which the run counts as unstable, > 0.
    fraction : float
        Speed fraction of the final-deviation definition.
    convention : {"axis_tilted", "velocity_tilted"}
        Which of the axis or the velocity is tilted by ``yaw`` (the other is normal); see
        :func:`normal_impact_angles`. Default ``"axis_tilted"`` (velocity normal), the
        reading that reproduces the paper's Fig. 13 deviations.
    shared_runs : dict, optional
        ``{speed: (reversed, final deviation in deg)}`` of runs already made with the
        same projectile, target, yaw, ``fraction`` and numerics; read before running and
        filled after. Searches for several thresholds of one case pass the same dict and
        so share their runs (a run does not depend on the threshold; results identical).
    Other arguments as :func:`vcr`.
    """
    if not (math.isfinite(threshold_deg) and threshold_deg > 0.0):
        raise InputError(f"threshold_deg must be a positive angle, got {threshold_deg!r}")
    obl, yaw_sim = normal_impact_angles(yaw, convention)
    numerics, overrides, sim = _split(dict(simulate_kwargs), _FIXED)
    pr = prepare(projectile, target, numerics, **overrides)

    runs = {} if shared_runs is None else shared_runs

    def verdict(v: float) -> bool:
        if v not in runs:
            ds = simulate(
                pr.projectile,
                pr.target,
                v,
                obl,
                yaw_sim,
                omega,
                stop_at_reversal=True,
                prepared=pr,
                **sim,
            )
            rev = int(ds.attrs["reversed"]) == 1
            runs[v] = (rev, math.nan if rev else float(final_deviation(ds, fraction)))
        rev, dev = runs[v]
        return rev or bool(dev > threshold_deg)

    return find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="Vci")


def __getattr__(name: str) -> Any:
    # ballistic_limit lives in pencore.perforation (which imports this module)
    if name == "ballistic_limit":
        from .perforation import ballistic_limit

        return ballistic_limit
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
