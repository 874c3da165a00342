"""Checks of the workflow configuration that a JSON schema cannot express, and short
messages for the ones it can.

The Snakefile validates ``config`` against ``workflow/schemas/config.schema.yaml`` and
then calls :func:`check_config`, so a bad configuration stops when the workflow is parsed,
with one line that names the key path and the value, instead of late in a job (or never).

Checked here, by the unit in the key's name (``*_m_s``, ``*_deg``, ``*_rad_s``, ``*_m``):

* velocities (``*_m_s``) are > 0 and within the velocity guard of
  :data:`pencore.inputs.limits.LIMITS`; angular velocities (``*_rad_s``) within theirs;
* obliquities are in [0, 90) deg, yaws in (-90, 90) deg, and within one study the largest
  ``|obliquity| + |yaw|`` stays below 90 deg (the velocity must point into the target);
  thresholds (``threshold*_deg``) are > 0;
* ranges ``{min, max}`` have ``min <= max``; grids ``{min, max, step}`` a step > 0 and
  ``{min, max, n}`` an ``n`` >= 1, and no grid has more than :data:`MAX_GRID` points
  (a typo guard: the largest grid of the paper's studies has 9 points);
* start positions (``start_m``) are three numbers within the start guard, start heights
  (``start_height*_m``) are >= 0;
* names of ``cases`` and entries of ``projectiles`` lists are unique;
* the Table 2 CSV has at least one row.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from pencore.errors import ConfigError, InputError
from pencore.inputs.limits import LIMITS
from pencore.paper.choices import check_settings
from pencore.studies.ensemble_cases import check_case

__all__ = ["MAX_GRID", "check_config", "schema_error_message"]

#: Largest number of points a configured grid may have (typo guard).
MAX_GRID = 10_000


def _fail(path: str, message: str) -> None:
    raise ConfigError(f"config {path}: {message}")


def _numbers(value: Any) -> list[float]:
    """Every number in a scalar, a list, or a range/grid mapping (its min and max)."""
    if isinstance(value, bool):
        return []
    if isinstance(value, int | float):
        return [float(value)]
    if isinstance(value, Mapping):
        return [float(value[k]) for k in ("min", "max") if _is_num(value.get(k))]
    if isinstance(value, Sequence) and not isinstance(value, str):
        return [float(v) for v in value if _is_num(v)]
    return []


def _is_num(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


def _check_range(path: str, value: Mapping[str, Any]) -> None:
    lo, hi = value.get("min"), value.get("max")
    if _is_num(lo) and _is_num(hi) and lo > hi:
        _fail(path, f"min {lo!r} is larger than max {hi!r}")
    step, n = value.get("step"), value.get("n")
    if _is_num(step):
        if not step > 0:
            _fail(path, f"step must be > 0, got {step!r}")
        if _is_num(lo) and _is_num(hi):
            points = math.floor((hi - lo) / step + 1e-9) + 1
            if points > MAX_GRID:
                _fail(path, f"the grid has {points} points (min {lo}, max {hi}, step {step}); "
                      f"at most {MAX_GRID} are allowed (typo guard)")  # fmt: skip
    if _is_num(n) and not 1 <= n <= MAX_GRID:
        _fail(path, f"n must be in [1, {MAX_GRID}] points, got {n!r}")


def _check_leaf(path: str, key: str, value: Any) -> None:
    if isinstance(value, Mapping):
        _check_range(path, value)
    nums = _numbers(value)
    if key.endswith("_m_s"):
        lim = LIMITS["velocity"]
        for v in nums:
            if not (math.isfinite(v) and lim.contains(v)):
                _fail(path, f"velocity {v!r} m/s is not {lim.describe()}")
    elif key.endswith("_rad_s"):
        lim = LIMITS["omega"]
        for v in nums:
            if not (math.isfinite(v) and lim.contains(v)):
                _fail(path, f"angular velocity {v!r} rad/s is not {lim.describe()}")
    elif key.startswith("obliquity") and key.endswith("_deg"):
        for v in nums:
            if not 0.0 <= v < 90.0:
                _fail(path, f"obliquity {v!r} deg is not in [0, 90) deg")
    elif key.startswith("yaw") and key.endswith("_deg"):
        for v in nums:
            if not -90.0 < v < 90.0:
                _fail(path, f"yaw {v!r} deg is not in (-90, 90) deg")
    elif key.startswith("threshold") and key.endswith("_deg"):
        for v in nums:
            if not 0.0 < v < 180.0:
                _fail(path, f"threshold {v!r} deg is not in (0, 180) deg")
    elif key == "start_m" and value is not None:
        lim = LIMITS["start"]
        if not (isinstance(value, Sequence) and len(value) == 3 and len(nums) == 3):
            _fail(path, f"must be three numbers [x, y, z] in m, got {value!r}")
        for v in nums:
            if not lim.contains(v):
                _fail(path, f"start coordinate {v!r} m is not {lim.describe()}")
    elif key.startswith("start_height") and key.endswith("_m"):
        for v in nums:
            if not 0.0 <= v <= LIMITS["start"].hi:
                _fail(path, f"start height {v!r} m is not in [0, {LIMITS['start'].hi:g}] m")
    if key in ("projectiles", "cases") and isinstance(value, Sequence):
        names = [c.get("name") if isinstance(c, Mapping) else c for c in value]
        dupes = sorted({str(x) for x in names if names.count(x) > 1})
        if dupes:
            _fail(path, f"duplicate names {', '.join(dupes)}")


def _check_study(path: str, study: Mapping[str, Any]) -> None:
    """Obliquity and yaw together keep the velocity pointing into the target."""
    ob = [abs(v) for v in _numbers(study.get("obliquity_deg"))]
    yw = [abs(v) for v in _numbers(study.get("yaw_deg"))]
    if ob and yw and max(ob) + max(yw) >= 90.0:
        _fail(path, f"obliquity {max(ob):g} deg + yaw {max(yw):g} deg reaches 90 deg: the "
              "velocity would not point into the target")  # fmt: skip


def _walk(path: str, node: Any) -> None:
    if isinstance(node, Mapping):
        for key, value in node.items():
            sub = f"{path}.{key}" if path else str(key)
            _check_leaf(sub, str(key), value)
            _walk(sub, value)
        _check_study(path, node)
    elif isinstance(node, Sequence) and not isinstance(node, str):
        for i, item in enumerate(node):
            _walk(f"{path}[{i}]", item)


def check_config(config: Mapping[str, Any], root: str | Path = ".") -> None:
    """Raise :class:`ConfigError` for the first problem in ``config`` (see the module).

    Parameters
    ----------
    config : mapping
        The workflow configuration, after schema validation.
    root : path-like
        Directory that relative file names in the configuration start from.
    """
    _walk("", config)
    table2 = config.get("validation", {}).get("table2", {})
    csv = table2.get("csv") if isinstance(table2, Mapping) else None
    if csv:
        path = Path(root) / csv
        try:
            lines = [ln for ln in path.read_text().splitlines() if ln.strip()]
        except OSError as exc:
            _fail("validation.table2.csv", f"cannot read {str(path)!r}: {exc.strerror}")
        if len(lines) < 2:
            _fail("validation.table2.csv", f"{str(path)!r} has a header but no rows")
    cases = config.get("ensemble", {}).get("cases") or []
    names = [c.get("name") for c in cases if isinstance(c, Mapping)]
    if len(set(names)) != len(names):
        _fail("ensemble.cases", f"duplicate case names {sorted(names)}")
    for i, case in enumerate(cases):
        try:
            check_case(case)
        except InputError as exc:
            _fail(f"ensemble.cases[{i}]", str(exc))
    settings = config.get("attribution", {}).get("settings")
    if settings:
        try:
            check_settings(settings)
        except InputError as exc:
            _fail("attribution.settings", str(exc))


def schema_error_message(config: Mapping[str, Any], schema: Mapping[str, Any]) -> str:
    """One line for the first schema violation of ``config``: the key path, what is wrong,
    and for an unknown key the closest allowed one (instead of the whole schema)."""
    import jsonschema

    validator = jsonschema.validators.validator_for(schema)(schema)
    error = jsonschema.exceptions.best_match(validator.iter_errors(config))
    if error is None:
        return "config: does not match the schema"
    path = ".".join(str(p) for p in error.absolute_path) or "(top level)"
    if error.validator == "additionalProperties":
        allowed = list(error.schema.get("properties", {}))
        unknown = [k for k in error.instance if k not in allowed]
        key = unknown[0] if unknown else "?"
        hint = difflib.get_close_matches(str(key), allowed, n=1, cutoff=0.6)
        tip = f"; did you mean {hint[0]!r}?" if hint else ""
        where = "" if path == "(top level)" else f"{path}."
        return f"config {where}{key}: unknown key{tip} (allowed: {', '.join(allowed)})"
    message = " ".join(error.message.split())
    if len(message) > 300:
        message = message[:300] + " ..."
    return f"config {path}: {message}"
