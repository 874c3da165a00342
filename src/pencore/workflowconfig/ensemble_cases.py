"""Checks of an ensemble case (:mod:`pencore.studies.ensemble`): its keys, sample counts,
seed, and the distribution of each impact variable, spelt out.

Apart from :mod:`pencore.studies.ensemble` (standard library and :mod:`pencore.inputs.limits`
only) so that the workflow's configuration check, run at every Snakemake start, names a
bad case without loading scipy and the solver.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from pencore.errors import InputError
from pencore.inputs.conventions import YAW_CONVENTIONS
from pencore.inputs.gate import brief
from pencore.inputs.limits import LIMITS, as_float, check_keys, integer

__all__ = ["VARIABLES", "CASE_KEYS", "YAW_READINGS", "check_case"]

#: Impact variables: config key -> (simulate argument, units, long name).
VARIABLES: dict[str, tuple[str, str, str]] = {
    "velocity_m_s": ("velocity", "m s-1", "impact velocity"),
    "obliquity_deg": ("obliquity", "degree", "obliquity (axis from the target normal)"),
    "yaw_deg": ("yaw", "degree", "yaw (velocity angle minus axis angle)"),
    "omega_rad_s": ("omega", "rad s-1", "initial angular velocity"),
    "azimuth_deg": ("azimuth", "degree", "azimuth of the impact plane about the normal"),
}
CASE_KEYS = (
    "name",
    "projectile",
    "target",
    "n_samples",
    "n_chunks",
    "seed",
    "yaw_convention",
    *VARIABLES,
)

#: What a case's ``obliquity_deg`` and ``yaw_deg`` draw, by its ``yaw_convention``
#: (:func:`pencore.inputs.conventions.impact_angles`); the default is ``velocity_tilted``.
YAW_READINGS: dict[str, str] = {
    "velocity_tilted": (
        "velocity yaw: obliquity_deg is the axis's angle from the normal and yaw_deg tilts "
        "the velocity from the axis (simulate's obliquity and yaw as drawn)"
    ),
    "axis_tilted": (
        "angle of attack: obliquity_deg is the velocity's angle from the normal and "
        "yaw_deg tilts the axis from the velocity (simulate's obliquity = obliquity_deg + "
        "yaw_deg, yaw = -yaw_deg, drawn tied)"
    ),
}


def _num(value: Any, where: str) -> float:
    v = as_float(value, allow_str=False)
    if v is None or not math.isfinite(v):
        raise InputError(f"{where} must be a finite number, got {value!r}")
    return v


def _int(value: Any, where: str) -> int:
    v = as_float(value, allow_str=False)
    if v is None or not math.isfinite(v) or v != math.floor(v) or abs(v) > 2**62:
        raise InputError(f"{where} must be a whole number, got {value!r}")
    return int(v)


def _dist(spec: Any, where: str) -> dict[str, float | str]:
    if isinstance(spec, bool):
        raise InputError(f"{where} must be a number or a distribution, got {spec!r}")
    if isinstance(spec, (int, float)):
        return {"dist": "fixed", "value": _num(spec, where)}
    if not isinstance(spec, Mapping):
        raise InputError(f"{where} must be a number or a distribution, got {spec!r}")
    kind = spec.get("dist")
    keys = {"fixed": ("value",), "uniform": ("min", "max"), "normal": ("mean", "sd")}
    if not isinstance(kind, str) or kind not in keys:
        raise InputError(f"{where}: dist must be one of fixed, uniform, normal, got {brief(kind)}")
    allowed = ("dist", *keys[kind], *(("min", "max") if kind == "normal" else ()))
    check_keys(spec, allowed, where)
    d: dict[str, float | str] = {"dist": kind}
    for k in allowed[1:]:
        if k in spec:
            d[k] = _num(spec[k], f"{where}.{k}")
        elif k in keys[kind]:
            raise InputError(f"{where}: {kind} needs {k!r}")
    lo, hi = d.get("min", -math.inf), d.get("max", math.inf)
    if kind == "uniform" and not lo < hi:
        raise InputError(f"{where}: uniform needs min < max, got {lo} and {hi}")
    if kind == "normal":
        if not d["sd"] > 0:
            raise InputError(f"{where}: normal needs sd > 0, got {d['sd']}")
        if not lo < hi:
            raise InputError(f"{where}: min must be below max, got {lo} and {hi}")
    return d


def check_case(case: Mapping[str, Any]) -> dict[str, Any]:
    """One ensemble case, checked, with every variable's distribution spelt out.

    ``yaw_convention`` (default ``"velocity_tilted"``) says what ``obliquity_deg`` and
    ``yaw_deg`` are (:data:`YAW_READINGS`): the axis's angle and a velocity yaw, or the
    velocity's angle and an angle of attack (the axis tilted). Either way
    ``|obliquity| + |yaw|`` stays below 90 deg, which keeps simulate's obliquity and
    ``obliquity + yaw`` inside (-90, 90) deg.

    Raises
    ------
    InputError
        One line naming the key: unknown keys (with a hint), N < 1, chunks outside
        1..N, a bad distribution, an unknown ``yaw_convention``, or ranges the solver
        refuses (speed <= 0, obliquity outside [0, 90) deg).
    """
    if not isinstance(case, Mapping):
        raise InputError(f"ensemble case must be a mapping, got {case!r}")
    name = case.get("name", "?")
    where = f"ensemble {name}"
    check_keys(case, CASE_KEYS, where)
    for k in ("name", "projectile", "target"):
        if not isinstance(case.get(k), str) or not case[k]:
            raise InputError(f"{where}: {k} must be a non-empty string, got {case.get(k)!r}")
    # counts within the limits table, so that sampling and planning stay bounded
    n = integer(case.get("n_samples", 100), "n_samples", where)
    chunks = integer(case.get("n_chunks", 1), "n_chunks", where)
    if n < 1 or not 1 <= chunks <= n:
        raise InputError(f"{where}: need n_samples >= 1 and 1 <= n_chunks <= n_samples")
    out: dict[str, Any] = {
        "name": name,
        "projectile": case["projectile"],
        "target": case["target"],
        "n_samples": n,
        "n_chunks": chunks,
        "seed": _int(case.get("seed", 0), f"{where}.seed"),
        "yaw_convention": _convention(case.get("yaw_convention", "velocity_tilted"), where),
    }
    defaults = {"velocity_m_s": None, "obliquity_deg": 0.0, "yaw_deg": 0.0,
                "omega_rad_s": 0.0, "azimuth_deg": 0.0}  # fmt: skip
    for k, default in defaults.items():
        if case.get(k, default) is None:
            raise InputError(f"{where}: {k} is required")
        out[k] = _dist(case.get(k, default), f"{where}.{k}")
    # every draw must be a run the solver accepts (one refused draw fails a whole chunk)
    v_hi = LIMITS["velocity"].hi
    _check_support(out["velocity_m_s"], 0.0, v_hi, f"{where}.velocity_m_s", open_lo=True)
    _check_support(out["obliquity_deg"], 0.0, 90.0, f"{where}.obliquity_deg", open_hi=True)
    _check_support(out["yaw_deg"], -90.0, 90.0, f"{where}.yaw_deg", open_lo=True, open_hi=True)
    for key, lim in (("omega_rad_s", LIMITS["omega"]), ("azimuth_deg", LIMITS["azimuth"])):
        _check_support(out[key], lim.lo, lim.hi, f"{where}.{key}")
    obl, yaw = _support(out["obliquity_deg"]), _support(out["yaw_deg"])
    reach = max(abs(obl[0]), abs(obl[1])) + max(abs(yaw[0]), abs(yaw[1]))
    if reach >= 90.0:
        raise InputError(
            f"{where}: obliquity and yaw together reach {reach:g} deg; |obliquity + yaw| "
            "must stay below 90 deg for every draw (narrow the distributions)"
        )
    return out


def _convention(value: Any, where: str) -> str:
    if not isinstance(value, str) or value not in YAW_CONVENTIONS:
        raise InputError(
            f"{where}.yaw_convention must be one of {', '.join(YAW_CONVENTIONS)}, got "
            f"{brief(value)}"
        )
    return value


#: Standard deviations from the mean that a normal without min/max is taken to reach:
#: a draw beyond has probability < 1.3e-15.
NORMAL_REACH_SD = 8.0


def _support(d: Mapping[str, Any]) -> tuple[float, float]:
    """Where draws of ``d`` can fall (a normal without bounds: within
    :data:`NORMAL_REACH_SD` standard deviations of its mean)."""
    if d["dist"] == "fixed":
        return float(d["value"]), float(d["value"])
    if d["dist"] == "uniform":
        return float(d["min"]), float(d["max"])
    mean, sd = float(d["mean"]), float(d["sd"])
    lo = max(float(d.get("min", -math.inf)), mean - NORMAL_REACH_SD * sd)
    hi = min(float(d.get("max", math.inf)), mean + NORMAL_REACH_SD * sd)
    return lo, hi


def _check_support(d, lo, hi, where, open_lo=False, open_hi=False) -> None:  # noqa: ANN001
    a, b = _support(d)
    bad_lo = a <= lo if open_lo else a < lo
    bad_hi = b >= hi if open_hi else b > hi
    if bad_lo or bad_hi:
        lo_s, hi_s = ("(" if open_lo else "[") + f"{lo:g}", f"{hi:g}" + (")" if open_hi else "]")
        raise InputError(
            f"{where}: values must lie in {lo_s}, {hi_s}; the distribution reaches "
            f"[{a:g}, {b:g}] (set min/max)"
        )
