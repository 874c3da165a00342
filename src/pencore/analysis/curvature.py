"""Path geometry of a trajectory: slope, curvature and inflection points.

Part of :mod:`pencore.analysis` (see its docstring for the conventions and the
definitions chosen where the paper leaves a choice open). Derivatives along a path are
taken in parametric form, ``x(p)``, ``y(p)``, with ``p`` the time when it is known and
the cumulative chord length otherwise; ``np.gradient`` gives second-order differences on
the non-uniform grids of an adaptive integrator. Angles come out in degrees.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import InputError, hint_keywords
from pencore.io.runs import check_run

#: Default noise threshold of :func:`inflection_points`, relative to the peak abs(curvature).
#: A sign change counts only when the curvature reaches this fraction of its peak on both
#: sides. Saved solver states are accurate to about ``rtol`` (1e-6); differencing them
#: twice on the adaptive grid leaves curvature noise around 1e-10 of the peak on straight
#: stretches, and exit through the free surface or the approach to the stop adds wiggles
#: of order 1e-3 of the peak. 1 % of the peak ignores all of these and keeps the
#: inflections of the turning part, whose lobes are several percent of the peak or more.
DEFAULT_REL_THRESHOLD = 1e-2

#: Default fraction of the peak abs(curvature) that marks Points 1 and 2 of Eq. 12.
DEFAULT_BRACKET_FRACTION = 0.05

#: Default fraction of the impact speed below which the end of a run is not analysed.
DEFAULT_SPEED_FRACTION = 0.1

#: A path whose peak abs(curvature) times its chord length is below this is straight.
STRAIGHT_TOL = 1e-9


# ------------------------------------------------------------------ helpers


def _as_1d(name: str, a: Any) -> np.ndarray:
    arr = np.asarray(a, dtype=float)
    if arr.ndim != 1:
        raise InputError(f"{name} must be a 1-D array, got shape {arr.shape}")
    return arr


def _check_same(**arrays: np.ndarray) -> int:
    sizes = {k: v.size for k, v in arrays.items()}
    n = next(iter(sizes.values()))
    if any(s != n for s in sizes.values()):
        raise InputError(f"arrays must have the same length, got {sizes}")
    return n


def _parameter(x: np.ndarray, y: np.ndarray, t: np.ndarray | None) -> np.ndarray:
    """Path parameter: ``t`` if given (must increase strictly), else chord length."""
    if t is not None:
        d = np.diff(t)
        if np.any(~(d > 0.0)):
            raise InputError("t must be strictly increasing (no repeated or NaN times)")
        return t
    s = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))))
    if np.any(~(np.diff(s) > 0.0)):
        raise InputError(
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
        raise InputError("give both vx and vy, or neither")
    if vx is None:
        return _grad(x, p), _grad(y, p)
    xd, yd = _as_1d("vx", vx), _as_1d("vy", vy)
    _check_same(x=x, vx=xd, vy=yd)
    return xd, yd


def _point_arrays(ds: xr.Dataset, point: str) -> tuple[np.ndarray, np.ndarray]:
    if point not in ("cm", "tip"):
        raise InputError(f"point must be 'cm' or 'tip', got {point!r}")
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
        For solver output :func:`~pencore.slope_ds` uses the saved velocities, which are
        exact.

    Raises
    ------
    InputError
        Arrays that are not 1-D or of different lengths, fewer than 2 points, or a time
        that does not increase.

    Examples
    --------
    The parabola ``y = x^2`` has slope ``2 x``:

    >>> import numpy as np
    >>> from pencore import slope
    >>> x = np.linspace(0.0, 1.0, 5)
    >>> slope(x, x**2, t=x).round(3)
    array([0. , 0.5, 1. , 1.5, 2. ])
    """
    x, y = _as_1d("x", x), _as_1d("y", y)
    tt = None if t is None else _as_1d("t", t)
    n = _check_same(x=x, y=y) if tt is None else _check_same(x=x, y=y, t=tt)
    if n < 2:
        raise InputError(f"need at least 2 points, got {n}")
    p = _parameter(x, y, tt)
    with np.errstate(divide="ignore", invalid="ignore"):
        return _grad(y, p) / _grad(x, p)


def slope_ds(ds: xr.Dataset, point: str = "cm") -> np.ndarray:
    """Slope ``dy/dx`` of the path of a run.

    Parameters
    ----------
    ds : xarray.Dataset
        A run of :func:`~pencore.simulate`.
    point : {"cm", "tip"}, default "cm"
        The centre-of-mass path (from the saved velocity, exact) or the nose-tip path
        (:func:`~pencore.slope` in time).

    Returns
    -------
    numpy.ndarray
        ``dy/dx`` (dimensionless) at each saved time; ``+-inf`` or NaN on a vertical path.

    Raises
    ------
    InputError
        ``point`` is neither ``"cm"`` nor ``"tip"``.

    Examples
    --------
    At 45 deg obliquity the path starts at slope -1 (the paper's Fig. 7b):

    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    >>> print(f"{pencore.slope_ds(ds)[0]:.3f}")
    -1.000
    """
    if point not in ("cm", "tip"):
        raise InputError(f"point must be 'cm' or 'tip', got {point!r}")
    check_run(ds, "slope_ds", ["vel_x", "vel_y"] if point == "cm" else ["time", "tip_x", "tip_y"])
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

    Raises
    ------
    InputError
        Arrays that are not 1-D or of different lengths, fewer than 3 points, a time that
        does not increase, or ``vx``, ``vy`` without ``t`` (or one without the other).

    Examples
    --------
    A circle of radius 2 m run counter-clockwise has curvature 1/2 1/m:

    >>> import numpy as np
    >>> from pencore import signed_curvature
    >>> a = np.linspace(0.0, np.pi, 400)
    >>> k = signed_curvature(2.0 * np.cos(a), 2.0 * np.sin(a), a)
    >>> print(f"{k[1:-1].min():.4f} {k[1:-1].max():.4f}")
    0.5000 0.5000
    """
    x, y = _as_1d("x", x), _as_1d("y", y)
    tt = None if t is None else _as_1d("t", t)
    n = _check_same(x=x, y=y) if tt is None else _check_same(x=x, y=y, t=tt)
    if n < 3:
        raise InputError(f"need at least 3 points, got {n}")
    if tt is None and vx is not None:
        raise InputError("vx, vy are time derivatives: give t as well")
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
        Peak abs(curvature) (1/m) over the samples considered.
    threshold : float
        abs(curvature) (1/m) that a lobe had to exceed to count.

    Examples
    --------
    >>> import numpy as np
    >>> from pencore import inflection_points
    >>> x = np.linspace(-1.0, 1.0, 201)
    >>> found = inflection_points(x, x**3)
    >>> len(found), found.direction.tolist(), f"{found.x[0]:.3f}"
    (1, [1], '0.000')
    """

    index: np.ndarray
    param: np.ndarray
    x: np.ndarray
    y: np.ndarray
    direction: np.ndarray
    peak: float
    threshold: float

    def __len__(self) -> int:
        """The number of inflection points."""
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
        Noise threshold relative to the peak abs(curvature) (default
        :data:`~pencore.analysis.curvature.DEFAULT_REL_THRESHOLD` = 1e-2): a sign change counts
        only when the
        curvature exceeds ``rel_threshold * peak`` on both sides of it, so wiggles below
        that level (differencing noise, exit or stop transients) are ignored. A path whose
        peak abs(curvature) times its chord length is below
        :data:`~pencore.analysis.curvature.STRAIGHT_TOL` is straight
        and has none.
    vx, vy : (n,) array_like, optional
        Exact ``dx/dt``, ``dy/dt`` (m/s) if known; needs ``t``.

    Returns
    -------
    Inflections
        Possibly empty.

    Raises
    ------
    InputError
        ``rel_threshold`` outside [0, 1), arrays that are not 1-D or of different
        lengths, fewer than 3 points, or a time that does not increase.

    Examples
    --------
    ``y = sin(x)`` on ``[0.5, 6]`` changes its curvature's sign at ``x = pi``:

    >>> import numpy as np
    >>> from pencore import inflection_points
    >>> x = np.linspace(0.5, 6.0, 500)
    >>> found = inflection_points(x, np.sin(x))
    >>> print(len(found), f"{found.x[0]:.3f}", found.direction[0])
    1 3.142 1
    """
    if not (0.0 <= rel_threshold < 1.0):
        raise InputError(f"rel_threshold must be in [0, 1), got {rel_threshold!r}")
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
        raise InputError(f"speed_fraction must be in [0, 1), got {speed_fraction!r}")
    ok = np.flatnonzero(speed >= speed_fraction * impact_speed)
    return int(ok[-1]) if ok.size else -1


def inflection_points_ds(
    ds: xr.Dataset,
    *,
    point: str = "cm",
    rel_threshold: float = DEFAULT_REL_THRESHOLD,
    speed_fraction: float = DEFAULT_SPEED_FRACTION,
) -> Inflections:
    """Inflection points of a run's path (``d2y/dx2 = 0``).

    :func:`~pencore.inflection_points` of the centre-of-mass path (with the exact saved
    velocities) or of the nose-tip path, over the samples up to the last one with speed
    >= ``speed_fraction`` x impact speed (the curvature of a nearly stopped projectile is
    not part of the trajectory).

    Parameters
    ----------
    ds : xarray.Dataset
        A run of :func:`~pencore.simulate`.
    point : {"cm", "tip"}, default "cm"
        Which path.
    rel_threshold : float, default 0.01
        Noise threshold relative to the peak abs(curvature), in [0, 1)
        (:func:`~pencore.inflection_points`).
    speed_fraction : float, default 0.1
        Part of the run analysed, as a fraction of the impact speed, in [0, 1).

    Returns
    -------
    Inflections
        Times (``param``, s) and positions (``x``, ``y``, m) of the sign changes.

    Raises
    ------
    InputError
        ``point`` other than ``"cm"`` or ``"tip"``, ``rel_threshold`` or
        ``speed_fraction`` out of range.

    Examples
    --------
    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, start=(-1.0, 1.0, 0.0))
    >>> found = pencore.inflection_points_ds(ds)
    >>> print(len(found), [f"{1e3 * t:.2f} ms" for t in found.param])
    3 ['1.56 ms', '1.70 ms', '2.32 ms']
    """
    if point not in ("cm", "tip"):
        raise InputError(f"point must be 'cm' or 'tip', got {point!r}")
    need = ["time", "speed", f"{point}_x", f"{point}_y"] + (["vel_x", "vel_y"] * (point == "cm"))
    check_run(ds, "inflection_points_ds", need)
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


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
