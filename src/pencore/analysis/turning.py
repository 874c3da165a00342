"""Total turning angle of a trajectory (paper Eq. 12): Points 1 and 2 and theta_2 - theta_1.

Part of :mod:`pencore.analysis`; the definition of Points 1 and 2 chosen where the paper
leaves it open is stated there and in :func:`turning_angle`. Angles in degrees.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

from pencore.analysis.curvature import (
    DEFAULT_BRACKET_FRACTION,
    DEFAULT_REL_THRESHOLD,
    DEFAULT_SPEED_FRACTION,
    STRAIGHT_TOL,
    _as_1d,
    _check_same,
    _first_derivs,
    _impact_speed,
    _parameter,
    _window_end,
    inflection_points,
    signed_curvature,
)
from pencore.errors import InputError, hint_keywords


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

    Examples
    --------
    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, start=(-1.0, 1.0, 0.0))
    >>> ta = pencore.turning_angle(ds)
    >>> print(ta.ok, ta.method, f"{float(ta):.1f} deg")
    True bracket 1.2 deg
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
        """True when ``delta_theta`` is defined (``reason`` is empty)."""
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
        raise InputError(f"method must be 'bracket' or 'sign_change', got {method!r}")
    if not (0.0 < fraction < 1.0):
        raise InputError(f"fraction must be in (0, 1), got {fraction!r}")
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
                f"abs(curvature) is already >= {fraction:g} of its peak at the first sample: "
                "no straight approach, so Point 1 is not in the record"
            )
        w1 = (thr - a[i1 - 1]) / (a[i1] - a[i1 - 1])
        p1 = point(i1 - 1, float(w1))
        if i2 == a.size - 1:
            return fail(
                f"abs(curvature) is still >= {fraction:g} of its peak at the last sample "
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
        abs(curvature) first rises through ``fraction`` (default 0.05) of its peak, Point 2
        where it last falls through it; both crossings are interpolated linearly between
        samples. NaN when the path is straight, when it is already curved at the first
        sample, or when it is still curved at the last sample analysed (the run stopped
        or was cut while turning).
    ``method="sign_change"``
        The first and the last significant sign changes of the curvature
        (:func:`~pencore.inflection_points` with ``rel_threshold``). In solver runs these lie inside
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
        Fraction of the peak abs(curvature) that marks Points 1 and 2 (bracket method).
    speed_fraction : float
        Part of the run analysed, as a fraction of the impact speed (default 0.1).
    rel_threshold : float
        Noise threshold of the sign-change method.

    Returns
    -------
    TurningAngle
        ``delta_theta`` (degree) with the two points, or NaN and ``reason``.

    Raises
    ------
    InputError
        An unknown ``method``, a ``fraction`` outside (0, 1), a ``speed_fraction`` outside
        [0, 1), a mapping without the keys ``t``, ``x``, ``y``, ``theta``, or arrays of
        different lengths or a time that does not increase.

    Examples
    --------
    #2 at 45 deg obliquity and 1000 m/s, the nose starting 1 m above the surface (the
    paper's Figs 7 and 9):

    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, start=(-1.0, 1.0, 0.0))
    >>> ta = pencore.turning_angle(ds)
    >>> print(f"{ta.delta_theta:.1f} deg between t = {1e3 * ta.t_1:.2f} and {1e3 * ta.t_2:.2f} ms")
    1.2 deg between t = 1.42 and 2.33 ms
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
        raise InputError(f"mapping needs keys t, x, y, theta; missing {sorted(missing)}")
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


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
