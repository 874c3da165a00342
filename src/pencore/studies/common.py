"""Shared pieces of the Section 4 studies: the paper's projectiles, axes,
start points, and attribute helpers.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np
import xarray as xr
from scipy import stats

from pencore.errors import InputError
from pencore.inputs.library import get_projectile

__all__ = [
    "PROJECTILES",
    "TRAJECTORY_VARIABLES",
    "projectile_coords",
    "start_from_height",
    "combine",
]


#: The paper's projectiles (Table 3), in order of rising Lc/L.
PROJECTILES = ("p1", "p2", "p3", "p4")


#: Time histories kept in trajectory datasets (all written by :func:`pencore.simulate`,
#: plus ``deviation_signed``).
TRAJECTORY_VARIABLES = (
    "tip_x",
    "tip_y",
    "cm_x",
    "cm_y",
    "vel_x",
    "vel_y",
    "slope",
    "deviation",
    "deviation_signed",
    "theta",
    "axis_x",
    "speed",
)


_STR = object  # dtype of string variables (netCDF variable-length strings)


def t_half_width(x: Any, level: float = 0.95) -> float:
    """Half-width of the Student-t interval (``level``) of the mean of the sample ``x``,
    in the units of ``x``; NaN for fewer than two values."""
    x = np.asarray(x, dtype=float)
    n = x.size
    if n < 2:
        return math.nan
    return float(stats.t.ppf(0.5 + level / 2, n - 1) * x.std(ddof=1) / math.sqrt(n))


def _attrs(units: str, long_name: str, **extra: Any) -> dict[str, Any]:
    return {"units": units, "long_name": long_name, **extra}


def projectile_coords(projectiles: Sequence[str]) -> dict[str, Any]:
    """Coordinates on dimension ``projectile``: names, ``lc_over_l`` and ``mass``."""
    names = list(projectiles)
    if not names:
        raise InputError("need at least one projectile")
    lcl, mass = [], []
    for p in names:
        proj = get_projectile(p)
        mp = proj.mass_properties()
        lcl.append(mp.lc / proj.length)
        mass.append(mp.mass)
    return {
        "projectile": (
            "projectile",
            np.array(names, dtype=_STR),
            {"long_name": "projectile (paper Table 3)", "units": "1"},
        ),
        "lc_over_l": (
            "projectile",
            np.array(lcl),
            _attrs("1", "nose tip to centre of mass over total length, L_c/L (pencore geometry)"),
        ),
        "mass": ("projectile", np.array(mass), _attrs("kg", "projectile mass")),
    }


def start_from_height(height: float) -> tuple[float, float, float] | None:
    """Nose-tip start for a normal impact whose tip starts ``height`` (m) above y = 0.

    ``0`` gives ``None``: :func:`pencore.simulate`'s default, the lowest point of the body
    just touching the surface at x = 0.
    """
    h = float(height)
    if not (math.isfinite(h) and h >= 0.0):
        raise InputError(f"start height must be >= 0 m, got {height!r}")
    return None if h == 0.0 else (0.0, h, 0.0)


def _axis(values: Iterable[float], what: str) -> np.ndarray:
    v = np.asarray(list(values), dtype=float).ravel()
    if v.size == 0 or not np.all(np.isfinite(v)):
        raise InputError(f"{what} must be a non-empty list of numbers, got {list(v)}")
    if np.unique(v).size != v.size:
        raise InputError(f"{what} has repeated values: {list(v)}")
    return v


def _start(start: Sequence[float] | None) -> tuple[float, float, float] | None:
    if start is None:
        return None
    s = tuple(float(x) for x in start)
    if len(s) != 3 or not all(math.isfinite(x) for x in s):
        raise InputError(f"start must be 3 finite coordinates (m), got {start!r}")
    return s


def _signed_deviation(ds: xr.Dataset) -> np.ndarray:
    """In-plane velocity angle from -y, positive towards +x, unwrapped (degree)."""
    return np.degrees(np.unwrap(np.arctan2(ds["vel_x"].values, -ds["vel_y"].values)))


def combine(parts: Sequence[xr.Dataset], dim: str = "projectile") -> xr.Dataset:
    """Concatenate per-job parts of a study along ``dim`` (attributes of the first)."""
    parts = list(parts)
    if not parts:
        raise InputError("nothing to combine")
    return xr.concat(
        parts,
        dim=dim,
        data_vars="minimal",
        coords="minimal",
        compat="override",
        combine_attrs="override",
    )
