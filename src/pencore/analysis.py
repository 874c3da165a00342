"""Trajectory analysis: slope, inflection points, turning angle, deviation, nose direction.

Conventions (those of :func:`pencore.simulate`): the target is ``y <= 0``, the projectile
moves towards ``+x`` and ``-y``; ``theta`` is the signed angle (degree) from the target
normal ``-y`` to the projectile axis, towards ``+x``. SI units inside; angles come out in
degrees.

The functions are pure: numpy arrays in, floats or arrays out. Those that need several
histories also take an :class:`xarray.Dataset` as written by :func:`pencore.simulate`
(variables ``time``, ``cm_x``, ``cm_y``, ``vel_x``, ``vel_y``, ``vel_z``, ``theta``,
``axis_x``, ``speed``; attributes ``reversed`` and ``impact_velocity_m_s``).

Derivatives along a path are always taken in parametric form, ``x(p)``, ``y(p)``, with
``p`` the time when it is known and the cumulative chord length otherwise, so a path
that is vertical (normal impact, ``dx/dt = 0``) or that turns back in ``x`` is handled;
``np.gradient`` gives second-order differences on the non-uniform grids of an adaptive
integrator. The paper writes "dx/dy" for what is the slope ``dy/dx`` of ``y(x)``; the
code names the quantity correctly.

Definitions chosen here where the paper leaves a choice open:

* **Points 1 and 2 of Eq. 12** (:func:`turning_angle`, default ``method="bracket"``):
  the points where the trajectory curvature rises through, and finally falls back
  through, ``fraction`` (default 5 %) of its peak magnitude. The paper places them where
  ``d2y/dx2 = 0`` on the slope plot of Fig. 7(b): the trajectory is straight before entry
  (slope -1 at 45 deg), curves, and becomes straight again, and Points 1 and 2 bracket
  the curved part. Strict zeros of the second derivative are not usable: it is exactly
  zero in free flight, and a solver run has genuine sign changes inside the nose-entry
  transient (the slope rises, dips slightly, then rises again). A threshold at a small
  fraction of the peak finds the edges of the curved part; ``theta`` hardly changes
  where the curvature is small, so the result barely depends on the fraction (for
  projectile #2 at 45 deg and 1000 m/s, fractions 0.01 to 0.1 change it by less than 0.1 %).
* **Final deviation** (:func:`final_deviation`): the velocity angle from the normal at
  the last saved state whose speed is still at least ``fraction`` (default 0.1) of the
  impact speed. Very near the stop the lateral part of the constant resistance term
  turns the slow projectile quickly, so the direction at the stop itself is not the
  direction of the trajectory.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

__all__ = [
    "DEFAULT_REL_THRESHOLD",
    "DEFAULT_BRACKET_FRACTION",
    "DEFAULT_SPEED_FRACTION",
    "STRAIGHT_TOL",
    "Inflections",
    "TurningAngle",
    "slope",
    "slope_ds",
    "signed_curvature",
    "d2y_dx2",
    "inflection_points",
    "inflection_points_ds",
    "turning_angle",
    "turning_angle_arrays",
    "deviation_from_normal",
    "final_state_index",
    "final_deviation",
    "final_deviation_arrays",
    "nose_direction",
    "reversed_in_target",
]

#: Default noise threshold of :func:`inflection_points`, relative to the peak |curvature|.
#: A sign change counts only when the curvature reaches this fraction of its peak on both
#: sides. Saved solver states are accurate to about ``rtol`` (1e-6); differencing them
#: twice on the adaptive grid leaves curvature noise around 1e-10 of the peak on straight
#: stretches, and exit through the free surface or the approach to the stop adds wiggles
#: of order 1e-3 of the peak. 1 % of the peak ignores all of these and keeps the
#: inflections of the turning part, whose lobes are several percent of the peak or more.
DEFAULT_REL_THRESHOLD = 1e-2

#: Default fraction of the peak |curvature| that marks Points 1 and 2 of Eq. 12.
DEFAULT_BRACKET_FRACTION = 0.05

#: Default fraction of the impact speed below which the end of a run is not analysed.
DEFAULT_SPEED_FRACTION = 0.1

#: A path whose peak |curvature| times its chord length is below this is straight.
STRAIGHT_TOL = 1e-9


# ------------------------------------------------------------------ helpers


def _as_1d(name: str, a: Any) -> np.ndarray:
    arr = np.asarray(a, dtype=float)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array, got shape {arr.shape}")
    return arr


def _check_same(**arrays: np.ndarray) -> int:
    sizes = {k: v.size for k, v in arrays.items()}
    n = next(iter(sizes.values()))
    if any(s != n for s in sizes.values()):
        raise ValueError(f"arrays must have the same length, got {sizes}")
    return n


def _parameter(x: np.ndarray, y: np.ndarray, t: np.ndarray | None) -> np.ndarray:
    """Path parameter: ``t`` if given (must increase strictly), else chord length."""
    if t is not None:
        d = np.diff(t)
        if np.any(~(d > 0.0)):
            raise ValueError("t must be strictly increasing (no repeated or NaN times)")
        return t
    s = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))))
    if np.any(~(np.diff(s) > 0.0)):
        raise ValueError(
            "consecutive points coincide, so the chord-length parameter does not increase; "
            "pass the time array t or remove the repeated points"
        )
    return s


def _grad(f: np.ndarray, p: np.ndarray) -> np.ndarray:
    return np.gradient(f, p, edge_order=2 if f.size >= 3 else 1)


def _first_derivs(
    x: np.ndarray, y: np.ndarray, p: np.ndarray, vx: Any, vy: Any
) -> tuple[np.ndarray, np.ndarray]:
    if (vx is None) != (vy is None):
        raise ValueError("give both vx and vy, or neither")
    if vx is None:
        return _grad(x, p), _grad(y, p)
    xd, yd = _as_1d("vx", vx), _as_1d("vy", vy)
    _check_same(x=x, vx=xd, vy=yd)
    return xd, yd


def _point_arrays(ds: xr.Dataset, point: str) -> tuple[np.ndarray, np.ndarray]:
    if point not in ("cm", "tip"):
        raise ValueError(f"point must be 'cm' or 'tip', got {point!r}")
    return ds[f"{point}_x"].values.astype(float), ds[f"{point}_y"].values.astype(float)


def _impact_speed(ds: xr.Dataset) -> float:
    v0 = ds.attrs.get("impact_velocity_m_s")
    return float(v0) if v0 is not None else float(ds["speed"].values[0])


# ------------------------------------------------------------------ slope and curvature


def slope(x: Any, y: Any, t: Any = None) -> np.ndarray:
    """Trajectory slope ``dy/dx`` along a sampled path.

    Parameters
    ----------
    x, y : (n,) array_like
        Path coordinates (m), ``n >= 2``.
    t : (n,) array_like, optional
        Time (s), strictly increasing, possibly non-uniform. When given the slope is the
        ratio of the parametric derivatives ``(dy/dt) / (dx/dt)``; otherwise the same
        ratio is taken with the cumulative chord length as parameter. Either way the path
        may be non-monotone in ``x`` and the grid non-uniform (second-order differences,
        ``np.gradient``).

    Returns
    -------
    (n,) ndarray
        ``dy/dx`` (dimensionless); ``+-inf`` or NaN where ``dx/dt = 0`` (vertical path).
        For solver output :func:`slope_ds` uses the saved velocities, which are exact.
    """
    x, y = _as_1d("x", x), _as_1d("y", y)
    tt = None if t is None else _as_1d("t", t)
    n = _check_same(x=x, y=y) if tt is None else _check_same(x=x, y=y, t=tt)
    if n < 2:
        raise ValueError(f"need at least 2 points, got {n}")
    p = _parameter(x, y, tt)
    with np.errstate(divide="ignore", invalid="ignore"):
        return _grad(y, p) / _grad(x, p)


def slope_ds(ds: xr.Dataset, point: str = "cm") -> np.ndarray:
    """Slope ``dy/dx`` of the centre-of-mass (``point="cm"``, from the saved velocity,
    exact) or nose-tip (``point="tip"``, from :func:`slope` in time) path of a run."""
    if point == "cm":
        with np.errstate(divide="ignore", invalid="ignore"):
            return ds["vel_y"].values / ds["vel_x"].values
    x, y = _point_arrays(ds, point)
    return slope(x, y, ds["time"].values)


def signed_curvature(
    x: Any, y: Any, t: Any = None, *, vx: Any = None, vy: Any = None
) -> np.ndarray:
    """Signed curvature of a plane path, ``(x' y'' - y' x'') / (x'^2 + y'^2)^(3/2)``.

    Parameters
    ----------
    x, y : (n,) array_like
        Path coordinates (m), ``n >= 3``.
    t : (n,) array_like, optional
        Time (s), strictly increasing; default: cumulative chord length (m).
    vx, vy : (n,) array_like, optional
        Exact first derivatives ``dx/dt``, ``dy/dt`` (m/s) if known (e.g. the saved
        velocities); then only the second derivatives are differenced. Needs ``t``.

    Returns
    -------
    (n,) ndarray
        Curvature (1/m), positive when the path turns counter-clockwise. For motion towards
        ``+x`` (``dx/dt > 0``) its sign is that of ``d2y/dx2``: positive when the slope
        grows, i.e. when a downward path turns back towards the surface. NaN where the
        speed is zero.
    """
    x, y = _as_1d("x", x), _as_1d("y", y)
    tt = None if t is None else _as_1d("t", t)
    n = _check_same(x=x, y=y) if tt is None else _check_same(x=x, y=y, t=tt)
    if n < 3:
        raise ValueError(f"need at least 3 points, got {n}")
    if tt is None and vx is not None:
        raise ValueError("vx, vy are time derivatives: give t as well")
    p = _parameter(x, y, tt)
    xd, yd = _first_derivs(x, y, p, vx, vy)
    xdd, ydd = _grad(xd, p), _grad(yd, p)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (xd * ydd - yd * xdd) / np.hypot(xd, yd) ** 3


def d2y_dx2(x: Any, y: Any, t: Any = None, *, vx: Any = None, vy: Any = None) -> np.ndarray:
    """Second derivative ``d2y/dx2 = (x' y'' - y' x'') / x'^3`` (1/m) in parametric form.

    Same arguments as :func:`signed_curvature`; ``+-inf``/NaN where ``dx/dt = 0``. Use the
    curvature for detection (it stays finite on vertical paths); this is for plots.
    """
    kappa = signed_curvature(x, y, t, vx=vx, vy=vy)
    x, y = _as_1d("x", x), _as_1d("y", y)
    p = _parameter(x, y, None if t is None else _as_1d("t", t))
    xd, yd = _first_derivs(x, y, p, vx, vy)
    with np.errstate(divide="ignore", invalid="ignore"):
        return kappa * np.hypot(xd, yd) ** 3 / xd**3


# ------------------------------------------------------------------ inflection points


@dataclass(frozen=True)
class Inflections:
    """Significant sign changes of the path curvature (``d2y/dx2 = 0``).

    Attributes
    ----------
    index : (k,) int ndarray
        Left sample ``i`` of the interval ``[i, i+1]`` holding each zero crossing.
    param : (k,) ndarray
        Parameter at the crossing: time (s) if ``t`` was given, else chord length (m).
    x, y : (k,) ndarray
        Position of the crossing (m), linearly interpolated.
    direction : (k,) int ndarray
        +1 where the curvature goes from negative to positive, -1 the other way.
    peak : float
        Peak |curvature| (1/m) over the samples considered.
    threshold : float
        |curvature| (1/m) that a lobe had to exceed to count.
    """

    index: np.ndarray
    param: np.ndarray
    x: np.ndarray
    y: np.ndarray
    direction: np.ndarray
    peak: float
    threshold: float

    def __len__(self) -> int:
        return int(self.index.size)


def _crossings(kappa: np.ndarray, floor: float) -> list[tuple[int, float, int]]:
    """(left index, fraction in the interval, direction) of each significant sign change."""
    k = np.where(np.isfinite(kappa), kappa, 0.0)
    sig = np.where(np.abs(k) > floor, np.sign(k), 0.0).astype(int)
    idx = np.flatnonzero(sig)
    out = []
    for a, b in zip(idx[:-1], idx[1:], strict=True):
        if sig[a] == sig[b]:
            continue
        # raw sign changes between the two significant samples; one unless noise
        seg = k[a : b + 1]
        raw = np.flatnonzero((np.sign(seg[:-1]) != np.sign(seg[1:])) | (seg[:-1] == 0.0))
        j = int(raw[(raw.size - 1) // 2]) + a  # the median one if several
        den = k[j] - k[j + 1]
        w = k[j] / den if den != 0.0 else 0.5
        out.append((j, float(min(max(w, 0.0), 1.0)), int(sig[b])))
    return out


def inflection_points(
    x: Any,
    y: Any,
    t: Any = None,
    *,
    rel_threshold: float = DEFAULT_REL_THRESHOLD,
    vx: Any = None,
    vy: Any = None,
) -> Inflections:
    """Points where ``d2y/dx2`` (the path curvature) changes sign.

    The sign of ``d2y/dx2`` is that of the parametric cross product ``x' y'' - y' x''``
    (for ``x' > 0``); the test uses the signed curvature (:func:`signed_curvature`), which
    has that sign and stays finite where ``x' = 0``. Each crossing is located by linear
    interpolation of the curvature between the two samples that bracket it.

    Parameters
    ----------
    x, y : (n,) array_like
        Path coordinates (m).
    t : (n,) array_like, optional
        Time (s), strictly increasing, possibly non-uniform; default chord length.
    rel_threshold : float
        Noise threshold relative to the peak |curvature| (default
        :data:`DEFAULT_REL_THRESHOLD` = 1e-2): a sign change counts only when the
        curvature exceeds ``rel_threshold * peak`` on both sides of it, so wiggles below
        that level (differencing noise, exit or stop transients) are ignored. A path whose
        peak |curvature| times its chord length is below :data:`STRAIGHT_TOL` is straight
        and has none.
    vx, vy : (n,) array_like, optional
        Exact ``dx/dt``, ``dy/dt`` (m/s) if known; needs ``t``.

    Returns
    -------
    Inflections
        Possibly empty.
    """
    if not (0.0 <= rel_threshold < 1.0):
        raise ValueError(f"rel_threshold must be in [0, 1), got {rel_threshold!r}")
    x, y = _as_1d("x", x), _as_1d("y", y)
    tt = None if t is None else _as_1d("t", t)
    kappa = signed_curvature(x, y, tt, vx=vx, vy=vy)
    p = _parameter(x, y, tt)
    chord = float(np.sum(np.hypot(np.diff(x), np.diff(y))))
    finite = np.isfinite(kappa)
    peak = float(np.max(np.abs(kappa[finite]))) if finite.any() else 0.0
    floor = rel_threshold * peak
    empty_i = np.zeros(0, dtype=int)
    if peak * chord <= STRAIGHT_TOL:
        e = np.zeros(0)
        return Inflections(empty_i, e, e, e, empty_i, peak, floor)
    floor = max(floor, STRAIGHT_TOL / chord) if chord > 0 else floor
    cr = _crossings(kappa, floor)
    ii = np.array([c[0] for c in cr], dtype=int)
    w = np.array([c[1] for c in cr], dtype=float)

    def at(f: np.ndarray) -> np.ndarray:
        return f[ii] + w * (f[ii + 1] - f[ii]) if ii.size else np.zeros(0)

    return Inflections(
        ii, at(p), at(x), at(y), np.array([c[2] for c in cr], dtype=int), peak, floor
    )


def _window_end(speed: np.ndarray, impact_speed: float, speed_fraction: float) -> int:
    """Index of the last sample whose speed is >= speed_fraction * impact_speed."""
    if not (0.0 <= speed_fraction < 1.0):
        raise ValueError(f"speed_fraction must be in [0, 1), got {speed_fraction!r}")
    ok = np.flatnonzero(speed >= speed_fraction * impact_speed)
    return int(ok[-1]) if ok.size else -1


def inflection_points_ds(
    ds: xr.Dataset,
    *,
    point: str = "cm",
    rel_threshold: float = DEFAULT_REL_THRESHOLD,
    speed_fraction: float = DEFAULT_SPEED_FRACTION,
) -> Inflections:
    """:func:`inflection_points` of a run's centre-of-mass (exact velocities) or tip path,
    over the samples up to the last one with speed >= ``speed_fraction`` x impact speed
    (the curvature of a nearly stopped projectile is not part of the trajectory)."""
    end = _window_end(ds["speed"].values, _impact_speed(ds), speed_fraction)
    sl = slice(0, end + 1)
    t = ds["time"].values[sl]
    x, y = (a[sl] for a in _point_arrays(ds, point))
    if point == "cm":
        return inflection_points(
            x,
            y,
            t,
            rel_threshold=rel_threshold,
            vx=ds["vel_x"].values[sl],
            vy=ds["vel_y"].values[sl],
        )
    return inflection_points(x, y, t, rel_threshold=rel_threshold)


# ------------------------------------------------------------------ turning angle (Eq. 12)


@dataclass(frozen=True)
class TurningAngle:
    """Total turning angle ``delta_theta = theta_2 - theta_1`` (paper Eq. 12).

    Attributes
    ----------
    delta_theta : float
        ``theta_2 - theta_1`` (degree); NaN when Points 1 and 2 do not both exist.
    theta_1, theta_2 : float
        Axis angle from the normal at Points 1 and 2 (degree; NaN if the point is missing).
    t_1, t_2 : float
        Time (s) of Points 1 and 2 (chord length in m if no time was given).
    x_1, y_1, x_2, y_2 : float
        Positions of Points 1 and 2 on the path (m).
    method : str
        ``"bracket"`` or ``"sign_change"`` (see :func:`turning_angle`).
    reason : str
        Empty when the value is defined, otherwise why it is NaN.
    """

    delta_theta: float
    theta_1: float
    theta_2: float
    t_1: float
    t_2: float
    x_1: float
    y_1: float
    x_2: float
    y_2: float
    method: str
    reason: str = ""

    @property
    def ok(self) -> bool:
        return not self.reason

    def __float__(self) -> float:
        return float(self.delta_theta)


_NAN = float("nan")


def turning_angle_arrays(
    t: Any,
    x: Any,
    y: Any,
    theta: Any,
    *,
    vx: Any = None,
    vy: Any = None,
    impact_speed: float | None = None,
    method: str = "bracket",
    fraction: float = DEFAULT_BRACKET_FRACTION,
    speed_fraction: float = DEFAULT_SPEED_FRACTION,
    rel_threshold: float = DEFAULT_REL_THRESHOLD,
) -> TurningAngle:
    """Turning angle of Eq. 12 from arrays; see :func:`turning_angle` for the definition.

    Parameters
    ----------
    t : (n,) array_like
        Time (s), strictly increasing.
    x, y : (n,) array_like
        Centre-of-mass path (m).
    theta : (n,) array_like
        Axis angle from the target normal (degree, unwrapped).
    vx, vy : (n,) array_like, optional
        Exact centre-of-mass velocity (m/s); default: differenced from ``x``, ``y``.
    impact_speed : float, optional
        Speed (m/s) that ``speed_fraction`` refers to; default: the speed at ``t[0]``.
    method, fraction, speed_fraction, rel_threshold
        As in :func:`turning_angle`.
    """
    if method not in ("bracket", "sign_change"):
        raise ValueError(f"method must be 'bracket' or 'sign_change', got {method!r}")
    if not (0.0 < fraction < 1.0):
        raise ValueError(f"fraction must be in (0, 1), got {fraction!r}")
    tt, x, y, th = (_as_1d(k, a) for k, a in (("t", t), ("x", x), ("y", y), ("theta", theta)))
    _check_same(t=tt, x=x, y=y, theta=th)
    p = _parameter(x, y, tt)
    xd, yd = _first_derivs(x, y, p, vx, vy)
    speed = np.hypot(xd, yd)
    v0 = float(speed[0]) if impact_speed is None else float(impact_speed)
    end = _window_end(speed, v0, speed_fraction)

    def fail(reason: str, **known: float) -> TurningAngle:
        vals = dict(
            theta_1=_NAN, theta_2=_NAN, t_1=_NAN, t_2=_NAN, x_1=_NAN, y_1=_NAN, x_2=_NAN, y_2=_NAN
        )
        vals.update(known)
        return TurningAngle(_NAN, method=method, reason=reason, **vals)

    if end < 2:
        return fail(f"fewer than 3 samples with speed >= {speed_fraction:g} x impact speed")
    sl = slice(0, end + 1)
    tt, x, y, th, xd, yd = tt[sl], x[sl], y[sl], th[sl], xd[sl], yd[sl]

    def point(i: int, w: float) -> dict[str, float]:
        """Interpolated values at fraction w of the interval [i, i+1]."""

        def lerp(f: np.ndarray) -> float:
            return float(f[i] + w * (f[i + 1] - f[i]))

        return dict(t=lerp(tt), x=lerp(x), y=lerp(y), theta=lerp(th))

    if method == "sign_change":
        ip = inflection_points(x, y, tt, rel_threshold=rel_threshold, vx=xd, vy=yd)
        if len(ip) < 2:
            return fail(
                f"{len(ip)} significant inflection point(s) (sign changes of d2y/dx2 above "
                f"{rel_threshold:g} of the peak curvature); need 2"
            )
        pts = []
        for k in (0, len(ip) - 1):
            i = int(ip.index[k])
            w = (ip.param[k] - tt[i]) / (tt[i + 1] - tt[i])
            pts.append(point(i, float(w)))
    else:
        kappa = signed_curvature(x, y, tt, vx=xd, vy=yd)
        a = np.abs(np.where(np.isfinite(kappa), kappa, 0.0))
        chord = float(np.sum(np.hypot(np.diff(x), np.diff(y))))
        peak = float(a.max())
        if chord <= 0.0 or peak * chord <= STRAIGHT_TOL:
            return fail("the path is straight: no curved part, so no Points 1 and 2")
        thr = fraction * peak
        above = np.flatnonzero(a >= thr)
        i1, i2 = int(above[0]), int(above[-1])
        if i1 == 0:
            return fail(
                f"|curvature| is already >= {fraction:g} of its peak at the first sample: "
                "no straight approach, so Point 1 is not in the record"
            )
        w1 = (thr - a[i1 - 1]) / (a[i1] - a[i1 - 1])
        p1 = point(i1 - 1, float(w1))
        if i2 == a.size - 1:
            return fail(
                f"|curvature| is still >= {fraction:g} of its peak at the last sample "
                f"analysed (speed >= {speed_fraction:g} x impact speed): the curved part "
                "does not end, so Point 2 is not in the record",
                theta_1=p1["theta"],
                t_1=p1["t"],
                x_1=p1["x"],
                y_1=p1["y"],
            )
        w2 = (a[i2] - thr) / (a[i2] - a[i2 + 1])
        pts = [p1, point(i2, float(w2))]
    p1, p2 = pts
    return TurningAngle(
        p2["theta"] - p1["theta"],
        p1["theta"],
        p2["theta"],
        p1["t"],
        p2["t"],
        p1["x"],
        p1["y"],
        p2["x"],
        p2["y"],
        method,
    )


def turning_angle(
    data: xr.Dataset | Mapping[str, Any],
    *,
    method: str = "bracket",
    fraction: float = DEFAULT_BRACKET_FRACTION,
    speed_fraction: float = DEFAULT_SPEED_FRACTION,
    rel_threshold: float = DEFAULT_REL_THRESHOLD,
) -> TurningAngle:
    """Total turning angle ``delta_theta_12 = theta_2 - theta_1`` (paper Eq. 12, Fig. 9).

    ``theta`` is the angle from the target normal to the projectile axis (degree), read at
    Points 1 and 2 of the centre-of-mass trajectory, linearly interpolated in time.

    Only the part of the run with speed >= ``speed_fraction`` x impact speed is analysed.

    Definitions of Points 1 and 2:

    ``method="bracket"`` (default)
        The paper's Points 1 and 2 (``d2y/dx2 = 0``, Fig. 7b) bracket the curved part of
        the path: straight before entry, curved, straight again. Point 1 is where
        |curvature| first rises through ``fraction`` (default 0.05) of its peak, Point 2
        where it last falls through it; both crossings are interpolated linearly between
        samples. NaN when the path is straight, when it is already curved at the first
        sample, or when it is still curved at the last sample analysed (the run stopped
        or was cut while turning).
    ``method="sign_change"``
        The first and the last significant sign changes of the curvature
        (:func:`inflection_points` with ``rel_threshold``). In solver runs these lie inside
        the nose-entry transient and miss the start of the turn; offered to show how much
        the choice matters. NaN when there are fewer than two.

    Parameters
    ----------
    data : xarray.Dataset or mapping
        A :func:`pencore.simulate` dataset (uses ``time``, ``cm_x``, ``cm_y``, ``vel_x``,
        ``vel_y``, ``theta`` and the ``impact_velocity_m_s`` attribute), or a mapping with
        keys ``t``, ``x``, ``y``, ``theta`` and optionally ``vx``, ``vy``,
        ``impact_speed``.
    method : {"bracket", "sign_change"}
    fraction : float
        Fraction of the peak |curvature| that marks Points 1 and 2 (bracket method).
    speed_fraction : float
        Part of the run analysed, as a fraction of the impact speed (default 0.1).
    rel_threshold : float
        Noise threshold of the sign-change method.

    Returns
    -------
    TurningAngle
        ``delta_theta`` (degree) with the two points, or NaN and ``reason``.
    """
    kw = dict(
        method=method, fraction=fraction, speed_fraction=speed_fraction, rel_threshold=rel_threshold
    )
    if isinstance(data, xr.Dataset):
        return turning_angle_arrays(
            data["time"].values,
            data["cm_x"].values,
            data["cm_y"].values,
            data["theta"].values,
            vx=data["vel_x"].values,
            vy=data["vel_y"].values,
            impact_speed=_impact_speed(data),
            **kw,
        )
    missing = {"t", "x", "y", "theta"} - set(data)
    if missing:
        raise ValueError(f"mapping needs keys t, x, y, theta; missing {sorted(missing)}")
    return turning_angle_arrays(
        data["t"],
        data["x"],
        data["y"],
        data["theta"],
        vx=data.get("vx"),
        vy=data.get("vy"),
        impact_speed=data.get("impact_speed"),
        **kw,
    )


# ------------------------------------------------------------------ deviation, direction


def deviation_from_normal(vx: Any, vy: Any, vz: Any = 0.0, *, signed: bool = False) -> Any:
    """Angle (degree) between a velocity and the inward target normal ``-y``.

    For motion towards ``+x`` and down (``vx > 0``, ``vy < 0``, ``vz = 0``) this is the
    paper's ``phi = 90 deg + atan(dy/dx)`` with ``dy/dx = vy / vx``, written with
    ``atan2`` so it stays defined for a vertical path (0) and for a path that turns back
    up (> 90).

    Parameters
    ----------
    vx, vy, vz : float or array_like
        Velocity components (m/s).
    signed : bool
        If True, return ``atan2(vx, -vy)`` instead: the in-plane angle, positive towards
        ``+x`` and negative towards ``-x`` (``vz`` ignored). Default: the unsigned 3-D
        angle ``atan2(hypot(vx, vz), -vy)`` in [0, 180].

    Returns
    -------
    float or ndarray
        Degrees; a float for scalar input.
    """
    vx, vy, vz = np.asarray(vx, float), np.asarray(vy, float), np.asarray(vz, float)
    if signed:
        out = np.degrees(np.arctan2(vx, -vy))
    else:
        out = np.degrees(np.arctan2(np.hypot(vx, vz), -vy))
    return float(out) if out.ndim == 0 else out


def final_state_index(
    speed: Any, impact_speed: float | None = None, fraction: float = DEFAULT_SPEED_FRACTION
) -> int:
    """Index of the last saved state whose speed is >= ``fraction`` x impact speed.

    ``impact_speed`` (m/s) defaults to ``speed[0]``; -1 if no state qualifies.
    """
    sp = _as_1d("speed", speed)
    v0 = float(sp[0]) if impact_speed is None else float(impact_speed)
    return _window_end(sp, v0, fraction)


def final_deviation_arrays(
    vx: Any,
    vy: Any,
    vz: Any = None,
    *,
    fraction: float = DEFAULT_SPEED_FRACTION,
    impact_speed: float | None = None,
    signed: bool = False,
) -> float:
    """:func:`final_deviation` from velocity histories (m/s); ``impact_speed`` defaults to
    the first speed. NaN if no state is fast enough."""
    vx, vy = _as_1d("vx", vx), _as_1d("vy", vy)
    vz = np.zeros_like(vx) if vz is None else _as_1d("vz", vz)
    _check_same(vx=vx, vy=vy, vz=vz)
    i = final_state_index(np.sqrt(vx**2 + vy**2 + vz**2), impact_speed, fraction)
    if i < 0:
        return _NAN
    return float(deviation_from_normal(vx[i], vy[i], vz[i], signed=signed))


def final_deviation(
    ds: xr.Dataset, fraction: float = DEFAULT_SPEED_FRACTION, *, signed: bool = False
) -> float:
    """Deviation of the trajectory from the normal at the end of the curved part (degree).

    Defined as :func:`deviation_from_normal` of the centre-of-mass velocity at the last
    saved state whose speed is still >= ``fraction`` (default 0.1) x the impact speed
    (attribute ``impact_velocity_m_s``, else the first saved speed). The direction right at
    the stop is not used: as the speed goes to zero the velocity-independent part of the
    resistance turns the projectile ever more sharply, which is not the trajectory's
    direction. For a run cut at reversal or that exits, the last fast state is the last
    state. This is the paper's phi (Figs 13-14) and alpha (Figs 16-17).

    Parameters
    ----------
    ds : xarray.Dataset
        Output of :func:`pencore.simulate`.
    fraction : float
        Speed fraction in [0, 1).
    signed : bool
        Signed in-plane angle (positive towards +x) instead of the unsigned one.
    """
    return final_deviation_arrays(
        ds["vel_x"].values,
        ds["vel_y"].values,
        ds["vel_z"].values,
        fraction=fraction,
        impact_speed=_impact_speed(ds),
        signed=signed,
    )


def nose_direction(data: xr.Dataset | Any) -> str:
    """``'+x'`` or ``'-x'``: the side the nose points to at the end of the run.

    The sign of the axis component ``axis_x`` at the last saved state (Figs 11-12);
    ``axis_x == 0`` (a nose pointing straight down) counts as ``'+x'``. ``data`` is a
    :func:`pencore.simulate` dataset or an ``axis_x`` history.
    """
    ax = data["axis_x"].values if isinstance(data, xr.Dataset) else np.asarray(data, float)
    last = float(np.ravel(ax)[-1])
    if math.isnan(last):
        raise ValueError("axis_x at the end is NaN")
    return "+x" if last >= 0.0 else "-x"


def reversed_in_target(ds: xr.Dataset) -> bool:
    """True if the run turned back towards the surface while in the target.

    Reads the ``reversed`` attribute written by :func:`pencore.simulate` (set when the
    centre-of-mass velocity gets ``vel_y >= 0`` while part of the body is below the
    surface and the speed is >= ``v_stop``).
    """
    if "reversed" not in ds.attrs:
        raise KeyError("dataset has no 'reversed' attribute; was it made by pencore.simulate?")
    return bool(int(ds.attrs["reversed"]))
