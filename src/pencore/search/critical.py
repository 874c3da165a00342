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
  yaw": :func:`normal_impact_angles` maps the two readings (:data:`YAW_CONVENTIONS`)
  onto ``simulate``'s obliquity and yaw.

:func:`find_threshold` does the search on any verdict: it checks both ends of the
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
from pencore.errors import InputError
from pencore.inputs.conventions import normal_impact_angles
from pencore.inputs.gate import brief
from pencore.inputs.limits import as_float, number
from pencore.run.impact import prepare, run_impact, simulate
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
        :mod:`pencore.inputs.models`).
    """
    check_search_args(lo, hi, tol, max_iter, scan, "velocity")
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
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
    check_search_args(lo, hi, tol, max_iter, scan, "omega")
    number(velocity, "velocity", "omega_c")
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
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
    (:func:`pencore.analysis.deviation.final_deviation` with ``fraction``: the velocity angle from
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
    check_search_args(lo, hi, tol, max_iter, scan, "velocity")
    thr = as_float(threshold_deg, allow_str=False)
    if thr is None or not (math.isfinite(thr) and thr > 0.0):
        raise InputError(f"threshold_deg must be a positive angle, got {brief(threshold_deg)}")
    frac = as_float(fraction, allow_str=False)
    if frac is None or not 0.0 < frac <= 1.0:
        raise InputError(f"fraction (of the impact speed) must be in (0, 1], got {brief(fraction)}")
    obl, yaw_sim = normal_impact_angles(yaw, convention)
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
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
