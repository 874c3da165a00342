"""The ring-mesh check of a ballistic-limit map: the same searches on a finer ring mesh.

A map (:func:`pencore.studies.perforation.obliquity.ballistic_map`) is run on the ring mesh
of its numerics (``n_nose``, ``n_shank``); :func:`finer_rings` gives the same numerics on
``factor`` times the rings, and :func:`mesh_check` compares the two maps cell by cell. A
cell is *converged* when both searches found a limit and the two differ by no more than
the search's own tolerance (the width of its final bracket): a finer mesh then cannot be
told from the default by the search. Every other cell carries its reason (the move on the
finer rings, or the failed search and its message), which the archive keeps and the
map's figure and table show.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import InputError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.studies.common import var_attrs

__all__ = ["finer_rings", "mesh_check"]


def finer_rings(numerics: Numerics | Mapping[str, Any] | None, factor: float) -> Numerics:
    """``numerics`` with ``factor`` times its nose and shank rings (rounded), the rest kept.

    Parameters
    ----------
    numerics : Numerics, mapping or None
        As :func:`pencore.inputs.numerics.resolve_numerics` takes them.
    factor : float
        Ring-mesh factor (dimensionless), > 0.

    Returns
    -------
    Numerics
    """
    if not (isinstance(factor, int | float) and np.isfinite(factor) and factor > 0.0):
        raise InputError(f"ring-mesh factor must be a number > 0, got {factor!r}")
    num = resolve_numerics(numerics)
    return resolve_numerics(
        num,
        {"n_nose": round(factor * num.n_nose), "n_shank": round(factor * num.n_shank)},
    )


def _reason(v1: float, v2: float, s1: str, s2: str, m1: str, m2: str, factor: float,
            tol: float) -> str:  # fmt: skip
    """Why a cell is not converged ('' when it is)."""
    if s1 != "ok" or not np.isfinite(v1):
        return f"the search on the default rings ended {s1}: {m1}"
    if s2 != "ok" or not np.isfinite(v2):
        return f"the search on {factor:g}x the rings ended {s2}: {m2}"
    if abs(v2 - v1) > tol:
        return (
            f"V_bl moves {v2 - v1:+.1f} m/s on {factor:g}x the rings "
            f"({v1:.1f} -> {v2:.1f}), more than the search tolerance {tol:g} m/s"
        )
    return ""


def mesh_check(coarse: xr.Dataset, fine: xr.Dataset, factor: float) -> xr.Dataset:
    """Cell by cell agreement of a map with the same map on a finer ring mesh.

    Parameters
    ----------
    coarse, fine : xarray.Dataset
        Maps of :func:`~pencore.studies.perforation.obliquity.ballistic_map` (or joined by
        :func:`~pencore.studies.perforation.obliquity.combine_maps`) on the same grid and
        search, on the default rings and on ``factor`` times them.
    factor : float
        The finer map's ring-mesh factor (dimensionless), for the record.

    Returns
    -------
    xarray.Dataset
        On ``(option, t_over_d, obliquity)``: ``v_bl`` and ``v_bl_fine`` (m/s), their
        ``status`` and ``status_fine``, ``difference`` (m/s, fine minus default),
        ``converged`` (1 when both searches found a limit within the search tolerance of
        each other, else 0) and ``reason`` (empty when converged). Attributes: the factor,
        both meshes' rings, the tolerance and the count of converged cells.

    Raises
    ------
    InputError
        Maps on different grids, searches or media.
    """
    keys = ("projectile", "medium", "search_tol_m_s", "options_json")
    for key in keys:
        if coarse.attrs.get(key) != fine.attrs.get(key):
            raise InputError(f"mesh_check: the two maps differ in {key}")
    for dim in ("option", "t_over_d", "obliquity"):
        if not np.array_equal(coarse[dim].values, fine[dim].values):
            raise InputError(f"mesh_check: the two maps differ in their {dim} values")
    tol = float(coarse.attrs["search_tol_m_s"])
    v1, v2 = coarse["v_bl"], fine["v_bl"]
    s1, s2 = coarse["status"].values, fine["status"].values
    m1, m2 = coarse["message"].values, fine["message"].values
    reason = np.empty(v1.shape, dtype=object)
    for idx in np.ndindex(v1.shape):
        reason[idx] = _reason(
            float(v1.values[idx]), float(v2.values[idx]), str(s1[idx]), str(s2[idx]),
            str(m1[idx]), str(m2[idx]), factor, tol,
        )  # fmt: skip
    dims = v1.dims
    out = xr.Dataset(
        {
            "v_bl": (dims, v1.values, var_attrs("m s-1", "ballistic limit, default rings")),
            "v_bl_fine": (
                dims,
                v2.values,
                var_attrs("m s-1", f"ballistic limit, {factor:g}x the rings"),
            ),  # fmt: skip
            "status": (dims, s1.astype(str), {"long_name": "search status, default rings"}),
            "status_fine": (
                dims,
                s2.astype(str),
                {"long_name": f"search status, {factor:g}x the rings"},
            ),  # fmt: skip
            "difference": (
                dims,
                (v2 - v1).values,
                var_attrs("m s-1", "v_bl_fine - v_bl"),
            ),  # fmt: skip
            "converged": (
                dims,
                (reason == "").astype(np.int8),
                var_attrs("1", "1: both searches found V_bl within the search tolerance"),
            ),  # fmt: skip
            "reason": (dims, reason.astype(str), {"long_name": "why a cell is not converged"}),
        },
        coords={d: coarse[d] for d in dims},  # with their units and long names
    )
    num1 = _rings(coarse)
    num2 = _rings(fine)
    out.attrs = {
        "title": "ring-mesh check of the ballistic-limit map",
        "projectile": coarse.attrs["projectile"],
        "medium": coarse.attrs["medium"],
        "mesh_factor": float(factor),
        "n_nose": num1[0],
        "n_shank": num1[1],
        "n_nose_fine": num2[0],
        "n_shank_fine": num2[1],
        "search_tol_m_s": tol,
        "n_cells": int(reason.size),
        "n_converged": int((reason == "").sum()),
    }
    return out


def _rings(bl_map: xr.Dataset) -> tuple[int, int]:
    """``(n_nose, n_shank)`` of a map's numerics (``numerics_json``), -1 when unrecorded."""
    num = json.loads(bl_map.attrs.get("numerics_json", "{}"))
    return int(num.get("n_nose", -1)), int(num.get("n_shank", -1))
