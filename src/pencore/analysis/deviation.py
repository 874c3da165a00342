"""Deviation of a trajectory from the target normal, its final value, nose direction, reversal.

Part of :mod:`pencore.analysis`; the final deviation is read at the last saved state whose
speed is still a fraction of the impact speed (see :func:`final_deviation`). Degrees out.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from pencore.analysis.curvature import (
    DEFAULT_SPEED_FRACTION,
    _as_1d,
    _check_same,
    _impact_speed,
    _window_end,
)
from pencore.errors import InputError, hint_keywords
from pencore.io.runs import check_run

_NAN = float("nan")


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
        Degrees; a float for scalar input; NaN where the velocity is zero (it has no
        direction).

    Raises
    ------
    InputError
        Components that are not numbers, or arrays of shapes that do not broadcast.

    Examples
    --------
    >>> from pencore import deviation_from_normal
    >>> deviation_from_normal(0.0, -100.0), deviation_from_normal(100.0, -100.0)
    (0.0, 45.0)
    >>> deviation_from_normal([-100.0, 100.0], [-100.0, 100.0], signed=True)
    array([-45., 135.])
    """
    try:
        vx, vy, vz = np.asarray(vx, float), np.asarray(vy, float), np.asarray(vz, float)
        np.broadcast_shapes(vx.shape, vy.shape, vz.shape)
    except (TypeError, ValueError):
        raise InputError(
            "deviation_from_normal needs velocity components as numbers or arrays of one "
            f"shape (m/s), got vx={str(vx)[:30]!r}, vy={str(vy)[:30]!r}, vz={str(vz)[:30]!r}"
        ) from None
    with np.errstate(invalid="ignore"):
        if signed:
            out = np.degrees(np.arctan2(vx, -vy))
        else:
            out = np.degrees(np.arctan2(np.hypot(vx, vz), -vy))
        # a velocity of zero has no direction (atan2 would say 0 or 180 by the signs of 0)
        out = np.where((vx == 0.0) & (vy == 0.0) & (vz == 0.0), np.nan, out)
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
    signed : bool, default False
        Signed in-plane angle (positive towards +x) instead of the unsigned one.

    Returns
    -------
    float
        The deviation (deg), in [0, 180] (signed: in (-180, 180]); NaN when no saved
        state is fast enough.

    Examples
    --------
    The path of #2 at 45 deg obliquity and 1000 m/s curves away from the normal:

    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    >>> print(f"{pencore.final_deviation(ds):.0f} deg")
    46 deg
    """
    check_run(ds, "final_deviation", ("vel_x", "vel_y", "vel_z", "speed"))
    return final_deviation_arrays(
        ds["vel_x"].values,
        ds["vel_y"].values,
        ds["vel_z"].values,
        fraction=fraction,
        impact_speed=_impact_speed(ds),
        signed=signed,
    )


def nose_direction(data: xr.Dataset | Any) -> str:
    """The side the nose points to at the end of the run: ``'+x'`` or ``'-x'``.

    The sign of the axis component ``axis_x`` at the last saved state (Figs 11-12);
    ``axis_x == 0`` (a nose pointing straight down) counts as ``'+x'``.

    Parameters
    ----------
    data : xarray.Dataset or array_like
        A :func:`~pencore.simulate` dataset or an ``axis_x`` history.

    Returns
    -------
    str
        ``'+x'`` or ``'-x'``.

    Raises
    ------
    InputError
        Not a run's Dataset nor a 1-D array of numbers; ``axis_x`` at the end is NaN.

    Examples
    --------
    >>> import pencore
    >>> pencore.nose_direction(pencore.simulate("p2", "soil", 1000.0, obliquity=45.0))
    '+x'
    >>> pencore.nose_direction([0.5, 0.1, -0.2])
    '-x'
    """
    if isinstance(data, xr.Dataset):
        check_run(data, "nose_direction", ("axis_x",))
        ax = data["axis_x"].values
    else:
        try:
            ax = np.asarray(data, float)
        except (TypeError, ValueError):
            ax = np.empty((0, 0))
        if ax.ndim != 1 or ax.size == 0:
            shown = repr(data) if len(repr(data)) <= 40 else repr(data)[:37] + "..."
            raise InputError(
                "nose_direction needs a Dataset made by pencore.simulate or an axis_x "
                f"history (a 1-D array of numbers), got {type(data).__name__} {shown}"
            )
    last = float(np.ravel(ax)[-1])
    if math.isnan(last):
        raise InputError("axis_x at the end is NaN")
    return "+x" if last >= 0.0 else "-x"


def reversed_in_target(ds: xr.Dataset) -> bool:
    """Whether the run turned back towards the surface while in the target.

    Reads the ``reversed`` attribute written by :func:`~pencore.simulate` (set when the
    centre-of-mass velocity gets ``vel_y >= 0`` while part of the body is below the
    surface and the speed is >= ``v_stop``): the verdict of :func:`~pencore.vcr`.

    Parameters
    ----------
    ds : xarray.Dataset
        A run of :func:`~pencore.simulate`.

    Returns
    -------
    bool

    Raises
    ------
    InputError
        ``ds`` is not a Dataset with a ``reversed`` attribute (not made by ``simulate``).

    Examples
    --------
    #2 at 45 deg obliquity turns back at 1800 m/s, not at 1000 m/s (the paper's Fig. 7):

    >>> import pencore
    >>> start = (-1.0, 1.0, 0.0)  # the nose 1 m above the surface
    >>> for v in (1000.0, 1800.0):
    ...     ds = pencore.simulate("p2", "soil", v, obliquity=45.0, start=start)
    ...     print(v, pencore.reversed_in_target(ds))
    1000.0 False
    1800.0 True
    """
    check_run(ds, "reversed_in_target", attrs=("reversed",))
    return bool(int(ds.attrs["reversed"]))


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
