"""Ensemble (Monte Carlo) studies: N impacts drawn from stated distributions, run in
chunks that are separate jobs, gathered with outcome probabilities and distributions.

An ensemble *case* names a projectile and a target, ``n_samples``, ``n_chunks``, a
``seed``, and a distribution for each impact variable (config units at the edge):

=================  =========  ==========================================================
key                units      meaning (as in :func:`pencore.simulate`)
=================  =========  ==========================================================
``velocity_m_s``   m/s        impact speed
``obliquity_deg``  degree     angle of the projectile axis from the target normal
``yaw_deg``        degree     velocity angle minus axis angle (a velocity yaw)
``omega_rad_s``    rad/s      initial angular velocity about the in-plane normal
``azimuth_deg``    degree     rotation of the whole impact about the target normal
=================  =========  ==========================================================

The table's ``obliquity_deg`` and ``yaw_deg`` are the case's default reading,
``yaw_convention: velocity_tilted``. With ``yaw_convention: axis_tilted`` the case draws an
angle of attack instead: ``obliquity_deg`` is the velocity's angle from the normal and
``yaw_deg`` tilts the axis from the velocity, so each run has simulate's obliquity
``obliquity_deg + yaw_deg`` and yaw ``-yaw_deg``, tied
(:func:`pencore.inputs.conventions.impact_angles`). Every output says which it drew
(attributes ``yaw_convention`` and ``yaw_reading``), and an ``axis_tilted`` case records
the draws as ``velocity_obliquity`` and ``angle_of_attack`` beside simulate's
``obliquity`` and ``yaw``.

A distribution is ``{dist: fixed, value}``, ``{dist: uniform, min, max}`` or
``{dist: normal, mean, sd}`` with optional ``min`` / ``max`` (a truncated normal, drawn by
inverse CDF); a bare number means ``fixed``. All N samples are drawn at once from
``numpy.random.default_rng(seed)``, one row of uniforms per sample (a column per variable
in the order of the table), so sample ``i`` is the same whatever the chunking and
whatever N (:func:`sample_conditions`): a larger ensemble extends a smaller one.

Per sample (:func:`run_chunk`): outcome, reversed, perforated (outcome ``perforated``;
always 0 for a semi-infinite target), penetration depth and path length of the tip, the
tip's horizontal travel in the impact plane (``downrange``) and across it
(``cross_range``; zero by the model's symmetry, a check), and the final attitude
(deviation of the velocity from the normal, angle of the axis from the normal).
:func:`gather` adds probabilities with Wilson 95 % intervals, means with Student-t 95 %
intervals, quantiles with distribution-free (binomial order-statistic) 95 % intervals
(both intervals scipy's: :func:`wilson_interval`, :func:`quantile_interval`), and the
running estimates against N for the convergence plot.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr
from scipy import stats

from pencore.errors import InputError
from pencore.inputs.conventions import impact_angles
from pencore.run.impact import prepare, simulate
from pencore.studies.common import t_half_width
from pencore.workflowconfig.ensemble_cases import VARIABLES, YAW_READINGS, check_case

__all__ = [
    "sample_conditions",
    "run_angles",
    "chunk_indices",
    "run_chunk",
    "gather",
    "wilson_interval",
    "quantile_interval",
]

QUANTILES = (0.05, 0.5, 0.95)
#: Results with distributions (variable, units, long name).
RESULTS = (
    ("penetration_depth", "m", "deepest point of the nose tip below the surface"),
    ("path_length", "m", "length of the nose-tip path below the surface"),
    ("downrange", "m", "horizontal travel of the tip in the impact plane"),
    ("final_deviation", "degree", "final deviation of the velocity from the normal"),
    ("final_axis_angle", "degree", "final angle of the axis from the normal"),
)


def _transform(d: Mapping[str, Any], u: np.ndarray) -> np.ndarray:
    """Uniform(0, 1) draws -> the distribution, by inverse CDF."""
    if d["dist"] == "fixed":
        return np.full(u.shape, float(d["value"]))
    if d["dist"] == "uniform":
        return float(d["min"]) + (float(d["max"]) - float(d["min"])) * u
    mu, sd = float(d["mean"]), float(d["sd"])
    a = stats.norm.cdf((float(d.get("min", -math.inf)) - mu) / sd)
    b = stats.norm.cdf((float(d.get("max", math.inf)) - mu) / sd)
    return mu + sd * stats.norm.ppf(a + (b - a) * u)


def sample_conditions(case: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """All N impact conditions of a case (config units), identical for any chunking."""
    c = check_case(case)
    rng = np.random.default_rng(c["seed"])
    n = c["n_samples"]
    # row i holds sample i's uniforms (one per variable, also for fixed ones): the
    # generator fills the (n, 5) array row by row, so sample i does not depend on n
    u = rng.random((n, len(VARIABLES)))
    return {k: _transform(c[k], u[:, j]) for j, k in enumerate(VARIABLES)}


def run_angles(cond: Mapping[str, np.ndarray], convention: str) -> tuple[np.ndarray, np.ndarray]:
    """simulate's obliquity and yaw (deg) of drawn conditions (:func:`sample_conditions`)
    read by the case's ``yaw_convention``: the draws themselves for
    ``velocity_tilted``; ``obliquity_deg + yaw_deg`` and ``-yaw_deg`` (the axis tilted
    from the velocity by the drawn angle of attack) for ``axis_tilted``."""
    obl = np.asarray(cond["obliquity_deg"], float)
    yaw = np.asarray(cond["yaw_deg"], float)
    if convention == "axis_tilted":
        return obl + yaw, -yaw
    impact_angles(0.0, 0.0, convention)  # refuses an unknown convention
    return obl, yaw


def chunk_indices(n_samples: int, n_chunks: int, chunk: int) -> np.ndarray:
    """Sample indices of chunk ``chunk`` (0-based) of ``n_chunks`` nearly equal chunks."""
    if not 0 <= chunk < n_chunks:
        raise InputError(f"ensemble chunk {chunk} outside 0..{n_chunks - 1}")
    return np.array_split(np.arange(n_samples), n_chunks)[chunk]


def _one(pr: Any, cond: Mapping[str, float], convention: str) -> dict[str, Any]:
    kw = {VARIABLES[k][0]: float(v) for k, v in cond.items()}
    kw["obliquity"], kw["yaw"] = impact_angles(kw["obliquity"], kw["yaw"], convention)
    ds = simulate(pr.projectile, pr.target, prepared=pr, **kw)  # checked once, at prepare
    az = math.radians(kw["azimuth"])
    dx = float(ds["tip_x"][-1] - ds["tip_x"][0])
    dz = float(ds["tip_z"][-1] - ds["tip_z"][0])
    ax, ay = float(ds["axis_x"][-1]), float(ds["axis_y"][-1])
    az_ = float(ds["axis_z"][-1])
    outcome = str(ds.attrs["outcome"])
    return {
        "outcome": outcome,
        "reversed": int(ds.attrs["reversed"]),
        "perforated": int(outcome == "perforated"),
        "penetration_depth": float(ds["penetration_depth"]),
        "path_length": float(ds["path_length"]),
        # the azimuth rotation maps +x to (cos az, 0, -sin az) and +z to (sin az, 0, cos az)
        "downrange": dx * math.cos(az) - dz * math.sin(az),
        "cross_range": dx * math.sin(az) + dz * math.cos(az),
        "final_deviation": float(ds["final_deviation"]),
        "final_axis_angle": math.degrees(math.acos(_clip(-ay / math.hypot(ax, ay, az_)))),
    }


def _clip(c: float) -> float:
    return max(-1.0, min(1.0, c))


def run_chunk(case: Mapping[str, Any], chunk: int, numerics: Any = None) -> xr.Dataset:
    """Run the samples of one chunk; a Dataset on ``sample`` (global indices)."""
    c = check_case(case)
    idx = chunk_indices(c["n_samples"], c["n_chunks"], chunk)
    cond = sample_conditions(c)
    convention = c["yaw_convention"]
    pr = prepare(c["projectile"], c["target"], numerics)
    runs = [_one(pr, {k: v[i] for k, v in cond.items()}, convention) for i in idx]
    data: dict[str, Any] = {}
    given = dict(cond)
    if convention == "axis_tilted":  # the draws, and simulate's angles beside them
        obl, yaw = run_angles(cond, convention)
        data["velocity_obliquity"] = ("sample", cond["obliquity_deg"][idx], {
            "units": "degree", "long_name": "angle of the velocity from the target normal "
            "(drawn obliquity_deg)"})  # fmt: skip
        data["angle_of_attack"] = ("sample", cond["yaw_deg"][idx], {
            "units": "degree", "long_name": "angle of the axis from the velocity, the axis "
            "tilted (drawn yaw_deg)"})  # fmt: skip
        given.update(obliquity_deg=obl, yaw_deg=yaw)
    for k, (arg, units, long_name) in VARIABLES.items():
        data[arg] = ("sample", given[k][idx], {"units": units, "long_name": long_name})
    units = dict((r[0], (r[1], r[2])) for r in RESULTS)
    units["cross_range"] = ("m", "horizontal travel of the tip across the impact plane")
    for k in runs[0] if runs else ():
        vals = np.array([r[k] for r in runs])
        if k == "outcome":
            data[k] = ("sample", vals.astype(str), {"long_name": "how the run ended"})
        elif k in ("reversed", "perforated"):
            data[k] = ("sample", vals.astype(np.int32), {"long_name": f"1: {k}"})
        else:
            data[k] = ("sample", vals, {"units": units[k][0], "long_name": units[k][1]})
    ds = xr.Dataset(
        data,
        coords={
            "sample": (
                "sample",
                idx.astype(np.int32),
                {"long_name": "sample index (the same draw for any N and chunking)"},
            )
        },
    )
    ds.attrs.update(
        case_json=json.dumps(c, sort_keys=True),
        chunk=chunk,
        n_chunks=c["n_chunks"],
        yaw_convention=convention,
        yaw_reading=YAW_READINGS[convention],
    )
    return ds


def wilson_interval(k: int, n: int, level: float = 0.95) -> tuple[float, float]:
    """Wilson score interval of a probability from ``k`` successes in ``n`` trials.

    scipy's ``scipy.stats.binomtest(k, n).proportion_ci(level, method="wilson")``
    (Wilson, JASA 22 (1927) 209-212; Newcombe, Stat. Med. 17 (1998) 857-872), with the
    ends exactly 0 at ``k = 0`` and 1 at ``k = n``.

    Parameters
    ----------
    k, n : int
        Successes and trials, ``0 <= k <= n``, ``n > 0``.
    level : float, default 0.95
        Confidence level, in (0, 1).

    Returns
    -------
    tuple of float
        Lower and upper end (probabilities, dimensionless).

    Raises
    ------
    InputError
        ``k`` or ``n`` outside those ranges.
    """
    if n <= 0 or not 0 <= k <= n:
        raise InputError(f"wilson_interval needs 0 <= k <= n and n > 0, got k={k}, n={n}")
    ci = stats.binomtest(int(k), int(n)).proportion_ci(level, method="wilson")
    return float(ci.low), float(ci.high)


def quantile_interval(x: np.ndarray, q: float, level: float = 0.95) -> tuple[float, float, float]:
    """Sample quantile and its distribution-free interval from order statistics.

    The number of samples below the true ``q`` quantile is Binomial(n, q), which gives an
    interval between two order statistics with coverage at least ``level`` (Conover,
    *Practical Nonparametric Statistics*, 3rd ed., 1999, Sec. 3.2): scipy's
    ``scipy.stats.quantile_test(x, p=q).confidence_interval(level)``.

    Parameters
    ----------
    x : numpy.ndarray
        The samples (any units).
    q : float
        Probability of the quantile, in (0, 1).
    level : float, default 0.95
        Confidence level, in (0, 1).

    Returns
    -------
    tuple of float
        The sample quantile (``numpy.quantile``, linear), the lower and the upper end of
        the interval (units of ``x``); an end that no order statistic of so few samples
        can give is ``-inf`` or ``+inf`` (scipy's NaN).
    """
    xs = np.asarray(x, float)
    est = float(np.quantile(xs, q))
    ci = stats.quantile_test(xs, q=0.0, p=q).confidence_interval(level)
    lo, hi = float(ci.low), float(ci.high)
    return est, (-math.inf if math.isnan(lo) else lo), (math.inf if math.isnan(hi) else hi)


def gather(parts: Sequence[xr.Dataset]) -> xr.Dataset:
    """Join chunk datasets on ``sample`` (sorted) and add the statistics (module doc)."""
    if not parts:
        raise InputError("ensemble gather: no parts")
    ds = xr.concat(list(parts), dim="sample", data_vars="all").sortby("sample")
    if np.any(np.diff(ds["sample"].values) != 1) or int(ds["sample"][0]) != 0:
        raise InputError("ensemble gather: the parts do not cover samples 0..N-1 once each")
    n = ds.sizes["sample"]
    ds.attrs.pop("chunk", None)
    for k in ("reversed", "perforated"):
        hits = int(ds[k].sum())
        lo, hi = wilson_interval(hits, n)
        ds[f"p_{k}"] = ((), hits / n, {"units": "1", "long_name": f"probability {k}"})
        ds[f"p_{k}_ci95"] = ("bound", [lo, hi], {"units": "1", "long_name": "Wilson 95 % interval"})
    for name, units, long_name in RESULTS:
        x = ds[name].values
        mean, sd = float(np.mean(x)), float(np.std(x, ddof=1)) if n > 1 else math.nan
        half = t_half_width(x)
        ds[f"{name}_mean"] = ((), mean, {"units": units, "long_name": f"mean {long_name}"})
        ds[f"{name}_mean_ci95"] = (
            "bound",
            [mean - half, mean + half],
            {"units": units, "long_name": f"Student-t 95 % interval of the mean {long_name}"},
        )
        ds[f"{name}_sd"] = ((), sd, {"units": units, "long_name": f"standard deviation, {name}"})
        qs = [quantile_interval(x, q) for q in QUANTILES]
        ds[f"{name}_quantile"] = (
            "quantile",
            [q[0] for q in qs],
            {"units": units, "long_name": f"sample quantiles of the {long_name}"},
        )
        ds[f"{name}_quantile_ci95"] = (
            ("quantile", "bound"),
            [q[1:] for q in qs],
            {
                "units": units,
                "long_name": f"order-statistic 95 % interval of the quantiles, {name}",
            },
        )
    # running estimates against N (powers of two, then N)
    ns = sorted({*(2**k for k in range(3, int(math.log2(n)) + 1)), n}) if n >= 8 else [n]
    rev = ds["reversed"].values
    dep = ds["penetration_depth"].values
    run = {"p_reversed": [], "p_lo": [], "p_hi": [], "depth": [], "depth_lo": [], "depth_hi": []}
    for m in ns:
        k = int(rev[:m].sum())
        lo, hi = wilson_interval(k, m)
        run["p_reversed"].append(k / m)
        run["p_lo"].append(lo)
        run["p_hi"].append(hi)
        mu = float(dep[:m].mean())
        h = t_half_width(dep[:m]) if m > 1 else 0.0
        run["depth"].append(mu)
        run["depth_lo"].append(mu - h)
        run["depth_hi"].append(mu + h)
    ds = ds.assign_coords(
        n_used=("n_used", np.array(ns, dtype=np.int32), {"long_name": "first N samples"})
    )
    ds["running_p_reversed"] = (
        "n_used",
        run["p_reversed"],
        {"units": "1", "long_name": "probability reversed from the first N samples"},
    )
    ds["running_p_reversed_ci95"] = (
        ("n_used", "bound"),
        np.c_[run["p_lo"], run["p_hi"]],
        {"units": "1", "long_name": "Wilson 95 % interval of running_p_reversed"},
    )
    ds["running_depth_mean"] = (
        "n_used",
        run["depth"],
        {"units": "m", "long_name": "mean penetration depth from the first N samples"},
    )
    ds["running_depth_mean_ci95"] = (
        ("n_used", "bound"),
        np.c_[run["depth_lo"], run["depth_hi"]],
        {"units": "m", "long_name": "Student-t 95 % interval of running_depth_mean"},
    )
    ds = ds.assign_coords(
        quantile=(
            "quantile",
            np.array(QUANTILES),
            {"units": "1", "long_name": "probability of the quantile"},
        ),
        bound=("bound", np.array(["lower", "upper"]), {"long_name": "end of the interval"}),
    )
    ds.attrs["title"] = "pencore ensemble: impacts drawn from stated distributions"
    case = json.loads(ds.attrs["case_json"])
    ds.attrs.update(projectile=case["projectile"], target=case["target"], ensemble=case["name"])
    ds.attrs["n_samples"] = n
    return ds
