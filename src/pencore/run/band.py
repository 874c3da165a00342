"""The depth band a run into a concrete given by a law carries (:mod:`pencore.inputs.record`).

A run whose target is one medium built by :func:`pencore.concrete_law` from ``fc`` with a
law the record scores (``Medium.record_law``) gets, when it stops in the target, the band
of its tip's path length below the face from the law's comparable measured shots
(:func:`pencore.inputs.record.depth_band`): the Dataset variable ``depth_band`` (m, on
``band_end``: ``lo``, ``hi``) and the attributes ``depth_band_*``. Where the record holds
no comparable shot the run warns (:class:`~pencore.errors.PlausibilityWarning`: the answer
has no measured error) and ``depth_band`` says why there is none. The comparable shots are
normal impacts: an oblique or yawed run's band is that of its speed at normal incidence,
and says so.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import xarray as xr

from pencore.errors import PlausibilityWarning, hint_keywords
from pencore.inputs.geometry import OgiveNose, Projectile
from pencore.inputs.record import MIN_SHOTS, WINDOWS, depth_band, scores_of
from pencore.inputs.target import Target

__all__ = ["attach_depth_band"]


def _law_medium(target: Target):
    solid = target.solid_layers
    if len(solid) != 1 or not solid[0].medium.record_law:
        return None
    return solid[0].medium


def attach_depth_band(
    ds: xr.Dataset,
    projectile: Projectile,
    target: Target,
    velocity: float,
    oblique: bool,
) -> xr.Dataset:
    """Add the depth band to a run's Dataset (module notes); the Dataset unchanged for a
    target that is not one medium of a scored concrete law.

    Parameters
    ----------
    ds : xarray.Dataset
        The run (:func:`pencore.simulate`).
    projectile : Projectile
        Its body (diameter, nose).
    target : Target
        Its target.
    velocity : float
        Impact speed (m/s).
    oblique : bool
        Whether the impact is oblique or yawed.
    """
    medium = _law_medium(target)
    if medium is None:
        return ds
    law = medium.record_law
    scores = scores_of(law)
    crh = projectile.nose.crh if isinstance(projectile.nose, OgiveNose) else math.nan
    where = (
        f"d = {projectile.diameter * 1e3:.3g} mm, fc = {medium.fc / 1e6:.3g} MPa, "
        f"V = {velocity:.4g} m/s, CRH {crh:.3g}"
    )
    ds.attrs["depth_band_law"] = law
    if ds.attrs.get("outcome") != "stopped":
        ds.attrs["depth_band"] = (
            f"none: the run did not stop in the target ({ds.attrs.get('outcome')})"
        )
        return ds
    band = (
        None
        if scores is None
        else depth_band(
            scores,
            float(ds["path_length"]),
            diameter=projectile.diameter,
            fc=medium.fc,
            velocity=velocity,
            crh=crh,
        )
    )
    if band is None:
        why = (
            f"none: fewer than {MIN_SHOTS} scored shots of law {law!r} are comparable "
            f"({where}; comparable: diameter and fc within a factor {WINDOWS['diameter']:g} and "
            f"{WINDOWS['fc']:g}, speed within a factor {WINDOWS['velocity']:g}, CRH within "
            f"{WINDOWS['crh']:g})"
        )
        ds.attrs["depth_band"] = why
        warnings.warn(
            f"concrete law {law!r}: no measured error for this answer, {why[6:]}",
            PlausibilityWarning,
            stacklevel=3,
        )
        return ds
    ds["depth_band"] = xr.DataArray(
        np.array([band.lo, band.hi]),
        dims="band_end",
        coords={"band_end": ["lo", "hi"]},
        attrs={
            "units": "m",
            "long_name": f"{band.level:.0%} band of the tip's path length below the face from "
            "comparable measured shots (one source left out to calibrate)",
        },
    )
    ds.attrs.update(
        {
            "depth_band": band.describe() + ("; the shots are normal impacts" if oblique else ""),
            "depth_band_level": band.level,
            "depth_band_nominal_level": band.nominal_level,
            "depth_band_held_out_coverage": band.held_out_coverage,
            "depth_band_n_shots": band.n_shots,
            "depth_band_n_sources": band.n_sources,
        }
    )
    return ds


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
