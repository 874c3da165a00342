"""Critical-value searches: Vcr, Vci and omega_c as thresholds of a yes/no verdict.

Each critical value of the paper is the lowest value of one input at which a run's
verdict switches from False to True:

* ``vcr`` (Section 4.2, Figs 8 and 12): the lowest impact speed at which the projectile
  turns back towards the surface (``reversed``) for a given obliquity and yaw;
* ``omega_c`` (Figs 16-18): the lowest initial angular velocity about the centre of mass
  at which a normal impact turns back;
* ``vci`` (Figs 13-15): the lowest normal-impact speed at which, for a small yaw, the
  final deviation (:func:`pencore.analysis.deviation.final_deviation`) exceeds a chosen threshold
  or the projectile turns back. The paper does not state its threshold; the caller must.
  Nor does it say which of the velocity or the axis is normal in a "normal impact with
  yaw": :func:`~pencore.inputs.conventions.normal_impact_angles` maps the two readings
  (:data:`~pencore.inputs.conventions.YAW_CONVENTIONS`)
  onto ``simulate``'s obliquity and yaw.

:func:`~pencore.find_threshold` does the search on any verdict: it checks both ends of the
bracket, optionally scans it coarsely to detect a non-monotone verdict, and bisects to a
caller-given tolerance. Every verdict evaluated is returned, so a workflow can archive
the evidence behind each number. The ballistic limit of a finite target
(``ballistic_limit``, lowest speed that perforates) is the same search, in
:mod:`pencore.search.perforation`.
"""

from __future__ import annotations

import math
from typing import Any

from pencore.analysis.curvature import DEFAULT_SPEED_FRACTION
from pencore.analysis.deviation import final_deviation
from pencore.errors import InputError, hint_keywords
from pencore.inputs.conventions import normal_impact_angles
from pencore.inputs.gate import brief
from pencore.inputs.limits import as_float, number
from pencore.inputs.numerics import keywords_checked
from pencore.run.impact import prepare, run_impact, simulate
from pencore.search.regime import quiet, warn_at_answer
from pencore.search.threshold import (
    DEFAULT_SCAN,
    FIXED_BY_SEARCH,
    OMEGA_TOL,
    VELOCITY_TOL,
    CriticalResult,
    check_search_args,
    find_threshold,
    split_search_kwargs,
)

__all__ = [
    "vcr",
    "omega_c",
    "vci",
]


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


@keywords_checked
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
    """Critical reverse velocity Vcr (m/s): the lowest impact speed that turns back.

    Verdict at speed ``v``: ``simulate(projectile, target, v, obliquity, yaw, omega,
    stop_at_reversal=True)`` has ``attrs['reversed'] == 1`` (the centre-of-mass velocity
    turned towards the surface while in the target). The paper's Section 4.2, Figs 8 and 12.

    Parameters
    ----------
    projectile, target
        As for :func:`~pencore.simulate` (names, YAML paths or objects).
    obliquity : float
        Axis angle from the target normal (deg).
    yaw : float, default 0
        Velocity angle minus axis angle (deg).
    lo, hi : float, default 100, 4000
        Speed range searched (m/s), ``0 < lo < hi``. Low speeds at grazing obliquity can
        ricochet (reverse) too; the default scan flags that as ``non_monotone``.
    tol : float, default 5
        Final bracket width (m/s), > 0.
    omega : float, default 0
        Initial angular velocity (rad/s).
    scan : int or None, default 5
        Points of a coarse scan of ``[lo, hi]`` before bisecting, that detects a
        non-monotone verdict; None: no scan (:func:`~pencore.find_threshold`).
    max_iter : int, default 60
        Most bisections.
    **simulate_kwargs
        ``numerics=``, numerics overrides (``rtol=``, ``eps=``, ...), ``start=``, and the
        shank contact model and paper-emulation numerics (``shank=``, ``emulation=``).

    Returns
    -------
    CriticalResult
        ``lo`` (m/s) did not turn back, ``hi`` did; ``value`` is their midpoint and
        ``status`` says whether the search converged (``"ok"``), the verdict was already
        True at ``lo`` (``"below_range"``) or still False at ``hi`` (``"above_range"``).

    Raises
    ------
    InputError
        A bad search argument (``lo >= hi``, ``tol <= 0``, a scan of fewer than 2 points)
        or a bad input of :func:`~pencore.simulate`; the message names it.

    Examples
    --------
    The speed above which #2 turns back at 45 deg obliquity, bracketed to 100 m/s (the
    paper's Fig. 7 starts the nose 1 m above the surface):

    >>> import pencore
    >>> r = pencore.vcr("p2", "soil", 45.0, lo=1000.0, hi=2500.0, tol=100.0, scan=None,
    ...                 start=(-1.0, 1.0, 0.0))
    >>> print(r.status, r.lo < r.hi <= r.lo + 100.0)
    ok True
    >>> print(f"{r.lo:.0f} < Vcr <= {r.hi:.0f} m/s")
    1562 < Vcr <= 1656 m/s
    """
    check_search_args(lo, hi, tol, max_iter, scan, "velocity")
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
    pr = quiet(prepare(projectile, target, numerics, **overrides))

    def verdict(v: float) -> bool:
        return _turns_back(pr, sim, v, obliquity, yaw, omega)

    result = find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="Vcr")
    return warn_at_answer(pr, result)


@keywords_checked
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
    """Critical angular velocity omega_c (rad/s): the lowest initial spin that turns back.

    Verdict at ``w``: ``simulate(projectile, target, velocity, obliquity, yaw, omega=w,
    stop_at_reversal=True)`` has ``attrs['reversed'] == 1``. Normal impact by default (the
    paper's Figs 16-18).

    Parameters
    ----------
    projectile, target
        As for :func:`~pencore.simulate` (names, YAML paths or objects).
    velocity : float
        Impact speed (m/s), > 0.
    lo, hi : float
        Range of initial angular velocity searched (rad/s), ``lo < hi``.
    tol : float, default 0.5
        Final bracket width (rad/s), > 0.
    obliquity, yaw : float, default 0
        Angles of the impact (deg).
    scan, max_iter
        As for :func:`~pencore.vcr`.
    **simulate_kwargs
        As for :func:`~pencore.vcr`.

    Returns
    -------
    CriticalResult
        ``lo`` (rad/s) did not turn back, ``hi`` did.

    Raises
    ------
    InputError
        A bad search argument or velocity, or a bad input of :func:`~pencore.simulate`.

    Examples
    --------
    #2 at 1500 m/s, normal impact, bracketed to 25 rad/s:

    >>> import pencore
    >>> r = pencore.omega_c("p2", "soil", 1500.0, lo=0.0, hi=500.0, tol=25.0, scan=None)
    >>> print(r.status, f"{r.lo:.0f} < omega_c <= {r.hi:.0f} rad/s")
    ok 156 < omega_c <= 172 rad/s
    """
    check_search_args(lo, hi, tol, max_iter, scan, "omega")
    number(velocity, "velocity", "omega_c")
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
    pr = prepare(projectile, target, numerics, **overrides)

    def verdict(w: float) -> bool:
        return _turns_back(pr, sim, velocity, obliquity, yaw, w)

    return find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="omega_c")


@keywords_checked
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
    """Critical impact velocity for instability Vci (m/s): normal impact with a small yaw.

    Verdict at speed ``v``: the run ``simulate(projectile, target, v, obliquity, yaw',
    omega, stop_at_reversal=True)``, with ``(obliquity, yaw') =``
    :func:`~pencore.inputs.conventions.normal_impact_angles` ``(yaw, convention)``,
    reversed, or its final deviation (:func:`~pencore.final_deviation` with ``fraction``:
    the velocity angle from the normal at the last state with speed >= ``fraction`` x
    impact speed) exceeds ``threshold_deg``. The paper (Figs 13-15) gives no threshold (it
    calls 0.16-0.24 deg "not really affected" and 2200 m/s for #4 "large"): report how Vci
    moves with it.

    Parameters
    ----------
    projectile, target
        As for :func:`~pencore.simulate` (names, YAML paths or objects).
    yaw : float
        Initial yaw (deg), e.g. 0.1.
    lo, hi : float
        Speed range searched (m/s), ``0 < lo < hi``.
    threshold_deg : float
        Deviation (deg) above which the run counts as unstable, > 0.
    tol : float, default 5
        Final bracket width (m/s).
    omega : float, default 0
        Initial angular velocity (rad/s).
    fraction : float, default 0.1
        Speed fraction of the final-deviation definition, in (0, 1].
    convention : {"axis_tilted", "velocity_tilted"}, default "axis_tilted"
        Which of the axis or the velocity is tilted by ``yaw`` (the other is normal);
        ``"axis_tilted"`` (velocity normal) reproduces the paper's Fig. 13 deviations.
    scan, max_iter
        As for :func:`~pencore.vcr`.
    shared_runs : dict, optional
        ``{speed: (reversed, final deviation in deg)}`` of runs already made with the
        same projectile, target, yaw, ``fraction`` and numerics; read before running and
        filled after. Searches for several thresholds of one case pass the same dict and
        so share their runs (a run does not depend on the threshold; results identical).
    **simulate_kwargs
        As for :func:`~pencore.vcr`.

    Returns
    -------
    CriticalResult
        ``lo`` (m/s) stayed within ``threshold_deg``, ``hi`` did not.

    Raises
    ------
    InputError
        ``threshold_deg`` not a positive angle, ``fraction`` outside (0, 1], an unknown
        ``convention``, a bad search argument, or a bad input of :func:`~pencore.simulate`.

    Examples
    --------
    #4 of the paper with 0.1 deg of yaw: the speed above which its deviation exceeds
    1 deg, bracketed to 200 m/s:

    >>> import pencore
    >>> r = pencore.vci("p4", "soil", 0.1, lo=1000.0, hi=3000.0, threshold_deg=1.0,
    ...                 tol=200.0, scan=None)
    >>> print(r.status, f"{r.lo:.0f} < Vci <= {r.hi:.0f} m/s")
    ok 2000 < Vci <= 2125 m/s
    """
    check_search_args(lo, hi, tol, max_iter, scan, "velocity")
    thr = as_float(threshold_deg, allow_str=False)
    if thr is None or not (math.isfinite(thr) and thr > 0.0):
        raise InputError(f"threshold_deg must be a positive angle, got {brief(threshold_deg)}")
    frac = as_float(fraction, allow_str=False)
    if frac is None or not 0.0 < frac <= 1.0:
        raise InputError(f"fraction (of the impact speed) must be in (0, 1], got {brief(fraction)}")
    obl, yaw_sim = normal_impact_angles(yaw, convention)
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
    pr = quiet(prepare(projectile, target, numerics, **overrides))

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
                loads=False,  # the verdict reads the path only
                **sim,
            )
            rev = int(ds.attrs["reversed"]) == 1
            runs[v] = (rev, math.nan if rev else float(final_deviation(ds, fraction)))
        rev, dev = runs[v]
        return rev or bool(dev > threshold_deg)

    result = find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="Vci")
    return warn_at_answer(pr, result)


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
