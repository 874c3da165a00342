"""Perforation of finite targets: the verdict, the ballistic limit, the Recht-Ipson curve.

A run on a finite target (:class:`pencore.inputs.target.Target` whose last layer has a
thickness) ends ``perforated`` when every surface element is below the rear face of the
last plate and the centre of mass moves away from it
(:func:`pencore.kernels.state.perforated`); the trajectory Dataset then carries the residual
velocity (``attrs['residual_velocity']``, m/s) and the exit attitude
(:func:`pencore.run.dataset.exit_attributes`).

The ballistic limit ``v_bl`` (m/s) is the lowest impact speed that perforates:
:func:`ballistic_limit` searches it with :func:`pencore.search.threshold.find_threshold`, the
search behind Vcr, Vci and omega_c, and returns the same :class:`~pencore.CriticalResult`
(bracket, every evaluation, monotonicity flag).

Recht-Ipson curve (Recht & Ipson, J. Appl. Mech. 30 (1963) 384-390, energy and momentum
balance of a rigid projectile perforating a plate; the generalised exponent ``p`` is the
form of Lambert & Jonas, BRL-R-1852 (1976))::

    v_r = a (v^p - v_bl^p)^(1/p)   for v > v_bl,   0 otherwise

with ``a = 1`` and ``p = 2`` for a rigid projectile whose resisting work does not depend on
the impact speed. :func:`fit_recht_ipson` fits ``a`` and ``p`` (``v_bl`` given, e.g. from
:func:`ballistic_limit`, or fitted too).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import InputError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.limits import as_float, plausible
from pencore.inputs.numerics import keywords_checked
from pencore.io.runs import check_run
from pencore.run.impact import prepare, run_impact
from pencore.search.regime import quiet, warn_at_answer
from pencore.search.threshold import (
    DEFAULT_SCAN,
    FIXED_BY_SEARCH,
    VELOCITY_TOL,
    CriticalResult,
    check_search_args,
    find_threshold,
    split_search_kwargs,
)

__all__ = [
    "perforates",
    "residual_velocity",
    "ballistic_limit",
    "recht_ipson",
    "fit_recht_ipson",
]


def perforates(ds: xr.Dataset) -> bool:
    """Whether a run perforated its target.

    Parameters
    ----------
    ds : xarray.Dataset
        A run of :func:`~pencore.simulate`.

    Returns
    -------
    bool
        True when the run ended with outcome ``perforated`` (every surface band behind
        the rear face of the last layer, moving away from it).

    Examples
    --------
    >>> import pencore
    >>> slab = pencore.Target("slab", (pencore.Layer(pencore.get_target("concrete").medium, 0.8),))
    >>> pencore.perforates(pencore.simulate("p2", slab, 500.0))
    True
    >>> pencore.perforates(pencore.simulate("p2", "soil", 500.0))
    False
    """
    check_run(ds, "perforates", attrs=("outcome",))
    return ds.attrs["outcome"] == "perforated"


def residual_velocity(ds: xr.Dataset) -> float:
    """Residual speed of a run: the centre-of-mass speed once clear of the target.

    Parameters
    ----------
    ds : xarray.Dataset
        A run of :func:`~pencore.simulate`.

    Returns
    -------
    float
        The speed (m/s) when the run perforated (attribute ``residual_velocity``); 0 when
        it did not (stopped, reversed or ricocheted).

    Examples
    --------
    >>> import pencore
    >>> slab = pencore.Target("slab", (pencore.Layer(pencore.get_target("concrete").medium, 0.8),))
    >>> print(f"{pencore.residual_velocity(pencore.simulate('p2', slab, 500.0)):.0f} m/s")
    306 m/s
    >>> pencore.residual_velocity(pencore.simulate("p2", "soil", 500.0))
    0.0
    """
    check_run(ds, "residual_velocity", attrs=("outcome",))
    if ds.attrs["outcome"] != "perforated":
        return 0.0
    check_run(ds, "residual_velocity", attrs=("residual_velocity",))
    return float(ds.attrs["residual_velocity"])


@keywords_checked
def ballistic_limit(
    projectile: Any,
    target: Any,
    obliquity: float = 0.0,
    yaw: float = 0.0,
    lo: float = 50.0,
    hi: float = 3000.0,
    tol: float = VELOCITY_TOL,
    *,
    omega: float = 0.0,
    scan: int | None = DEFAULT_SCAN,
    max_iter: int = 60,
    **simulate_kwargs: Any,
) -> CriticalResult:
    """Ballistic limit v_bl (m/s): lowest impact speed that perforates a finite target.

    Verdict at speed ``v``: ``simulate(projectile, target, v, obliquity, yaw, omega)``
    ends with outcome ``perforated``. A ricochet (``exited``) or an embedded projectile
    (``stopped``) is "no perforation". At oblique incidence a low-speed ricochet and a
    higher-speed embedding can both precede perforation; the scan flags a verdict that
    goes True then False as ``non_monotone``.

    Parameters
    ----------
    projectile, target
        As for :func:`~pencore.simulate`; the target must be finite (last layer with a
        thickness).
    obliquity, yaw : float, default 0
        Angles of the impact (deg).
    lo, hi : float, default 50, 3000
        Speed range searched (m/s), ``0 < lo < hi``.
    tol : float, default 5
        Final bracket width (m/s), > 0.
    omega : float, default 0
        Initial angular velocity (rad/s).
    scan, max_iter
        As for :func:`~pencore.vcr` (:func:`~pencore.find_threshold`).
    **simulate_kwargs
        ``numerics=``, numerics overrides (``rtol=``, ``eps=``, ...) and ``start=``.

    Returns
    -------
    CriticalResult
        ``value`` is the midpoint of the bracket ``[lo, hi]`` (m/s): ``lo`` did not
        perforate, ``hi`` did.

    Raises
    ------
    InputError
        A semi-infinite target, a bad search argument, or a bad input of
        :func:`~pencore.simulate`.

    Examples
    --------
    #2 against an 0.8 m concrete slab, bracketed to 20 m/s:

    >>> import pencore
    >>> slab = pencore.Target("slab", (pencore.Layer(pencore.get_target("concrete").medium, 0.8),))
    >>> r = pencore.ballistic_limit("p2", slab, lo=50.0, hi=1000.0, tol=20.0, scan=None)
    >>> print(r.status, f"{r.lo:.0f} < v_bl <= {r.hi:.0f} m/s")
    ok 377 < v_bl <= 391 m/s
    """
    check_search_args(lo, hi, tol, max_iter, scan, "velocity")
    numerics, overrides, sim = split_search_kwargs(dict(simulate_kwargs), FIXED_BY_SEARCH)
    pr = quiet(prepare(projectile, target, numerics, **overrides))
    if not pr.target.finite:
        raise InputError(
            f"target {pr.target.name!r} is semi-infinite: the ballistic limit needs a "
            "finite last layer (give it a thickness)"
        )
    for k, layer in enumerate(pr.target.layers):  # a plate in mm given for m
        if not layer.is_gap:
            where = f"target {brief(pr.target.name)} layer {k}"
            plausible(layer.thickness, "plate_thickness", where)

    def verdict(v: float) -> bool:
        run = run_impact(pr.projectile, pr.target, v, obliquity, yaw, omega, prepared=pr, **sim)
        return run.outcome == "perforated"

    result = find_threshold(verdict, lo, hi, tol, max_iter=max_iter, scan=scan, name="v_bl")
    return warn_at_answer(pr, result)


def recht_ipson(v: np.ndarray | float, v_bl: float, a: float = 1.0, p: float = 2.0) -> np.ndarray:
    """Recht-Ipson residual speed ``a (v^p - v_bl^p)^(1/p)``, 0 for ``v <= v_bl``.

    Recht & Ipson, J. Appl. Mech. 30 (1963) 384 (``a = 1``, ``p = 2``); the free ``a`` and
    ``p`` as in Lambert & Jonas, BRL-R-1852 (1976).

    Parameters
    ----------
    v : float or array_like
        Impact speed (m/s).
    v_bl : float
        Ballistic limit (m/s).
    a : float, default 1
        Scale (dimensionless).
    p : float, default 2
        Exponent (dimensionless).

    Returns
    -------
    numpy.ndarray
        Residual speed (m/s), the shape of ``v``.

    Raises
    ------
    InputError
        ``v`` not finite speeds >= 0, ``v_bl`` not a finite number >= 0, ``a`` or ``p``
        not a finite number > 0.

    Examples
    --------
    >>> from pencore import recht_ipson
    >>> recht_ipson([200.0, 500.0, 340.0], v_bl=300.0)
    array([  0., 400., 160.])
    """
    v = _speeds(v, "recht_ipson impact speed v")
    v_bl = _positive(v_bl, "recht_ipson v_bl", zero=True)
    a, p = _positive(a, "recht_ipson a"), _positive(p, "recht_ipson p")
    return a * np.maximum(v**p - v_bl**p, 0.0) ** (1.0 / p)


def _positive(value: Any, what: str, zero: bool = False) -> float:
    """``value`` as a finite number > 0 (>= 0 with ``zero``), else one InputError line."""
    v = as_float(value, allow_str=False)
    if v is None or not math.isfinite(v) or not (v >= 0.0 if zero else v > 0.0):
        raise InputError(
            f"{what} must be a finite number {'>=' if zero else '>'} 0, got {brief(value)}"
        )
    return v


def _speeds(values: Any, what: str) -> np.ndarray:
    """``values`` as a float array of finite speeds >= 0 (m/s), else one InputError
    line naming the first bad entry."""
    try:
        raw = np.asarray(values)
        if raw.dtype.kind not in "iuf":  # text, booleans, objects: not speeds
            raise TypeError
        arr = raw.astype(float)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be numbers (m/s), got {brief(values)}") from None
    if arr.ndim > 1:
        raise InputError(f"{what} must be a number or a 1-D array, got shape {arr.shape}")
    bad = ~(np.isfinite(arr) & (arr >= 0.0))
    if bad.any():
        i = int(np.flatnonzero(np.ravel(bad))[0])
        raise InputError(
            f"{what} must be finite speeds >= 0 m/s, got {float(np.ravel(arr)[i]):g} (entry {i})"
        )
    return arr


def fit_recht_ipson(v: np.ndarray, v_r: np.ndarray, v_bl: float | None = None) -> dict[str, float]:
    """Least-squares fit of :func:`recht_ipson` to perforating runs.

    Parameters
    ----------
    v, v_r : array
        Impact and residual speeds (m/s); only rows with ``v_r > 0`` are fitted.
    v_bl : float, optional
        Ballistic limit (m/s), held fixed; fitted too when None.

    Returns
    -------
    dict
        ``a``, ``p``, ``v_bl`` (m/s) and ``rms`` (m/s, RMS residual of the fit).

    Raises
    ------
    InputError
        Speeds that are not finite numbers >= 0, arrays of unequal length, a residual
        speed above its impact speed, fewer than 3 perforating runs (2 with ``v_bl``
        given).

    Examples
    --------
    Recovering the curve from exact points:

    >>> import numpy as np
    >>> from pencore import fit_recht_ipson, recht_ipson
    >>> v = np.array([450.0, 500.0, 600.0, 700.0, 800.0])
    >>> fit = fit_recht_ipson(v, recht_ipson(v, 400.0, a=0.9, p=2.5))
    >>> print({k: round(x, 3) for k, x in fit.items()})
    {'a': 0.9, 'p': 2.5, 'v_bl': 400.0, 'rms': 0.0}
    """
    from scipy.optimize import least_squares

    v = np.atleast_1d(_speeds(v, "fit_recht_ipson impact speeds v"))
    v_r = np.atleast_1d(_speeds(v_r, "fit_recht_ipson residual speeds v_r"))
    if v.shape != v_r.shape:
        raise InputError(
            f"fit_recht_ipson needs one residual speed per impact speed, got {v.size} "
            f"impact and {v_r.size} residual speeds"
        )
    above = np.flatnonzero(v_r > v)
    if above.size:
        i = int(above[0])
        raise InputError(
            f"fit_recht_ipson: residual speed {v_r[i]:g} m/s above its impact speed "
            f"{v[i]:g} m/s (entry {i}); a rigid projectile leaves a plate slower than it hit it"
        )
    if v_bl is not None:
        v_bl = _positive(v_bl, "fit_recht_ipson v_bl", zero=True)
    keep = v_r > 0.0
    v, v_r = v[keep], v_r[keep]
    if v.size < (3 if v_bl is None else 2):
        raise InputError(f"need at least 3 perforating runs to fit Recht-Ipson, got {v.size}")
    vmin = float(v.min())

    def unpack(x: np.ndarray) -> tuple[float, float, float]:
        return x[0], x[1], (float(v_bl) if v_bl is not None else x[2])

    def resid(x: np.ndarray) -> np.ndarray:
        a, p, vb = unpack(x)
        return recht_ipson(v, vb, a, p) - v_r

    x0 = [1.0, 2.0] + ([] if v_bl is not None else [0.9 * vmin])
    lower = [1e-3, 1.0] + ([] if v_bl is not None else [0.0])
    upper = [10.0, 10.0] + ([] if v_bl is not None else [vmin * (1 - 1e-9)])
    sol = least_squares(resid, x0, bounds=(lower, upper))
    a, p, vb = unpack(sol.x)
    return {
        "a": float(a),
        "p": float(p),
        "v_bl": float(vb),
        "rms": float(math.sqrt(np.mean(sol.fun**2))),
    }


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
