"""Shared pieces of the Section 4 studies: the paper's projectiles, axes,
start points, and attribute helpers.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np
import xarray as xr

from pencore.analysis.errors import t_half_width
from pencore.errors import InputError
from pencore.inputs.library import get_projectile
from pencore.inputs.numerics import Numerics
from pencore.search.threshold import STATUSES

__all__ = [
    "PROJECTILES",
    "TRAJECTORY_VARIABLES",
    "projectile_coords",
    "start_from_height",
    "combine",
    "t_half_width",
    "STRING_DTYPE",
    "var_attrs",
    "axis_values",
    "MAX_AXIS_POINTS",
    "MAX_SEARCHES",
    "search_grid",
    "start_point",
    "PARAMETER_ATTRS",
    "search_variables",
    "numerics_record",
    "signed_deviation",
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


#: dtype of string variables (netCDF variable-length strings)
STRING_DTYPE = object


def var_attrs(units: str, long_name: str, **extra: Any) -> dict[str, Any]:
    """A variable's attributes: ``units``, ``long_name`` and any ``extra``."""
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
            np.array(names, dtype=STRING_DTYPE),
            {"long_name": "projectile (paper Table 3)", "units": "1"},
        ),
        "lc_over_l": (
            "projectile",
            np.array(lcl),
            var_attrs(
                "1", "nose tip to centre of mass over total length, L_c/L (pencore geometry)"
            ),
        ),
        "mass": ("projectile", np.array(mass), var_attrs("kg", "projectile mass")),
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


#: Most points of one axis of a study or sweep (one run or one search each): the
#: workflow configuration's bound on a grid (``pencore.workflowconfig.config_check.MAX_GRID``)
#: for the Python and command-line doors too; a typo guard (1e4 runs of about 0.1 s are
#: about 20 minutes).
MAX_AXIS_POINTS = 10_000
#: Most threshold searches of one table (each is some 10-25 runs): 1000 cells are
#: hours of work on one core, seven times the largest the workflow computes (140); a
#: larger grid is split into several calls.
MAX_SEARCHES = 1_000


def axis_values(values: Iterable[float], what: str) -> np.ndarray:
    """The values of a dataset axis as floats; one line naming ``what`` if empty, not
    finite, repeated or longer than :data:`MAX_AXIS_POINTS`."""
    values = list(values)
    if len(values) > MAX_AXIS_POINTS:
        raise InputError(
            f"{what} has {len(values)} values; at most {MAX_AXIS_POINTS} are allowed in one "
            "call (a typo guard: split the grid into several calls)"
        )
    v = np.asarray(values, dtype=float).ravel()
    if v.size == 0 or not np.all(np.isfinite(v)):
        raise InputError(f"{what} must be a non-empty list of numbers, got {list(v)}")
    if np.unique(v).size != v.size:
        raise InputError(f"{what} has repeated values: {list(v)}")
    return v


def search_grid(shape: tuple[int, ...], what: str) -> np.ndarray:
    """An empty object array of ``shape`` for the results of a table of searches, refused
    (one line naming ``what`` and its size) when it has more than :data:`MAX_SEARCHES`
    cells, before any search is run."""
    n = math.prod(shape)
    if n > MAX_SEARCHES:
        dims = " x ".join(str(k) for k in shape)
        raise InputError(
            f"{what} is a grid of {dims} = {n} searches; at most {MAX_SEARCHES} are allowed "
            "in one call (each search is some 10-25 runs): split it into several calls"
        )
    return np.empty(shape, dtype=object)


def start_point(start: Sequence[float] | None) -> tuple[float, float, float] | None:
    """A start point of the nose tip (m) as 3 floats, or None (touching the surface)."""
    if start is None:
        return None
    s = tuple(float(x) for x in start)
    if len(s) != 3 or not all(math.isfinite(x) for x in s):
        raise InputError(f"start must be 3 finite coordinates (m), got {start!r}")
    return s


def signed_deviation(ds: xr.Dataset) -> np.ndarray:
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


#: Attributes of the impact parameters when they are a dataset's coordinates (SI units,
#: angles in degrees as at the edges).
PARAMETER_ATTRS = {
    "velocity": var_attrs("m s-1", "impact velocity V_i"),
    "obliquity": var_attrs("degree", "angle of obliquity phi_1 (axis from the target normal)"),
    "yaw": var_attrs("degree", "yaw angle phi_2 (velocity angle minus axis angle)"),
    "omega": var_attrs("rad s-1", "initial angular velocity about the centre of mass (+z)"),
}


def search_variables(
    results: np.ndarray, name: str, units: str, long_name: str, dims: tuple[str, ...]
) -> dict[str, Any]:
    """Variables ``name``, ``name_lo``, ``name_hi``, ``status``, ``n_evals``,
    ``monotone``, ``message``, ``history`` from an object array of CriticalResult."""

    def arr(f, dtype=float):
        out = np.empty(results.shape, dtype=dtype)
        for idx in np.ndindex(results.shape):
            out[idx] = f(results[idx])
        return out

    return {
        name: (
            dims,
            arr(lambda r: r.value),
            var_attrs(
                units,
                long_name,
                note="midpoint of the final bracket; NaN unless status is ok or non_monotone",
            ),
        ),
        f"{name}_lo": (
            dims,
            arr(lambda r: r.lo),
            var_attrs(
                units, f"{long_name}: largest value evaluated without the event (bracket low)"
            ),
        ),
        f"{name}_hi": (
            dims,
            arr(lambda r: r.hi),
            var_attrs(
                units, f"{long_name}: smallest value evaluated with the event (bracket high)"
            ),
        ),
        "status": (
            dims,
            arr(lambda r: r.status, STRING_DTYPE),
            # the statuses a search ends with by bisecting ("solver_error": see message)
            {"units": "1", "long_name": "search status: " + ", ".join(STATUSES[:5])},
        ),
        "n_evals": (
            dims,
            arr(lambda r: r.n_evals, np.int64),
            var_attrs("1", "number of trajectories run by the search"),
        ),
        "monotone": (
            dims,
            arr(lambda r: int(r.monotone), np.int8),
            var_attrs("1", "0 if the coarse scan found the verdict not monotone"),
        ),
        "message": (
            dims,
            arr(lambda r: r.message, STRING_DTYPE),
            {"units": "1", "long_name": "search report"},
        ),
        "history": (
            dims,
            arr(lambda r: json.dumps(r.to_dict()["history"]), STRING_DTYPE),
            {"units": "1", "long_name": "every value evaluated and its verdict (JSON)"},
        ),
    }


def numerics_record(num: Numerics) -> dict[str, Any]:
    """The fields of ``num`` as a plain dict (the ``numerics_json`` attribute of a dataset)."""
    return {f: getattr(num, f) for f in Numerics.__dataclass_fields__}
