"""Checks of the workflow configuration that the JSON schema cannot express.

The schema (``workflow/schemas/config.schema.yaml``) checks types and signs. This module
adds the relations between values: ranges with ``min > max``, obliquities of 90 deg or
more (alone or with the yaw), negative velocities inside lists, grids so large they are
surely a typo, duplicate case names and a Table 2 file without rows. It also turns a
schema error into one short line (key path, value, a "did you mean" for unknown keys)
instead of Snakemake's dump of the whole schema.

Every error is a :class:`ConfigError` whose message is one line naming the key path and
the offending value. The Snakefile calls :func:`validate_config` right after loading the
configuration.
"""

from __future__ import annotations

import csv
import difflib
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["ConfigError", "MAX_GRID_POINTS", "check_config", "schema_error_line", "validate_config"]

#: Largest grid a range may describe: a typo guard (``step: 0.001`` for ``1.0``).
MAX_GRID_POINTS = 10_000


class ConfigError(ValueError):
    """A bad configuration value; the message is one line with the key path and value."""


def _fail(path: str, value: Any, why: str) -> None:
    raise ConfigError(f"config {path} = {value!r}: {why}")


def _walk(node: Any, path: str = "") -> Iterator[tuple[str, Any]]:
    yield path, node
    if isinstance(node, Mapping):
        for k, v in node.items():
            yield from _walk(v, f"{path}.{k}" if path else str(k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _walk(v, f"{path}[{i}]")


def _is_num(x: Any) -> bool:
    return isinstance(x, int | float) and not isinstance(x, bool)


def _values(node: Any) -> list[float]:
    """Numbers a config entry stands for: a number, a list, or a min/max range."""
    if _is_num(node):
        return [float(node)]
    if isinstance(node, list):
        return [float(v) for v in node if _is_num(v)]
    if isinstance(node, Mapping):
        return [float(node[k]) for k in ("min", "max") if _is_num(node.get(k))]
    return []


def _check_range(path: str, node: Mapping[str, Any]) -> None:
    lo, hi = node.get("min"), node.get("max")
    if _is_num(lo) and _is_num(hi) and lo > hi:
        _fail(path, dict(node), f"min {lo} > max {hi}")
    n = node.get("n")
    if _is_num(n) and n > MAX_GRID_POINTS:
        _fail(f"{path}.n", n, f"more than {MAX_GRID_POINTS} grid points (a typo?)")
    step = node.get("step")
    if _is_num(lo) and _is_num(hi) and _is_num(step) and step > 0:
        points = int(np.floor((hi - lo) / step + 1e-9)) + 1
        if points > MAX_GRID_POINTS:
            _fail(f"{path}.step", step, f"{points} grid points > {MAX_GRID_POINTS} (a typo?)")


def _leaf(path: str) -> str:
    return path.rsplit(".", 1)[-1].split("[", 1)[0]


def _check_table2_csv(path: str, value: Any, base: Path) -> None:
    f = Path(value) if Path(value).is_absolute() else base / value
    if not f.is_file():
        return  # missing files are Snakemake's to report (missing input)
    with f.open(newline="") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    if len(rows) < 2:
        _fail(path, value, "the table has a header but no data rows")


def check_config(config: Mapping[str, Any], base: str | Path = ".") -> None:
    """Raise :class:`ConfigError` at the first relation between values that is wrong.

    Parameters
    ----------
    config
        The configuration after schema validation (defaults filled or not).
    base
        Directory relative file names (``validation.table2.csv``) are resolved against.

    Raises
    ------
    ConfigError
        One line: ``config <key path> = <value>: <reason>``.
    """
    base = Path(base)
    for path, node in _walk(config):
        leaf = _leaf(path)
        if isinstance(node, Mapping):
            _check_range(path, node)
            vmin, vmax = node.get("v_min"), node.get("v_max")
            if _is_num(vmin) and _is_num(vmax) and vmin > vmax:
                _fail(f"{path}.v_min", vmin, f"v_min > v_max {vmax}")
        if isinstance(node, list) and node and all(isinstance(c, Mapping) for c in node):
            names = [c.get("name") for c in node if "name" in c]
            dup = sorted({n for n in names if names.count(n) > 1}, key=str)
            if dup:
                _fail(path, dup[0], "duplicate case name")
        if "velocit" in leaf and isinstance(node, list):
            for i, v in enumerate(node):
                if _is_num(v) and v < 0:
                    _fail(f"{path}[{i}]", v, "velocities must be >= 0")
        if leaf.startswith("obliquity"):
            for v in _values(node):
                if abs(v) >= 90:
                    _fail(path, node, "obliquity must be below 90 deg (90 is grazing)")
        if isinstance(node, Mapping) and "obliquity_deg" in node and "yaw_deg" in node:
            obl, yaw = _values(node["obliquity_deg"]), _values(node["yaw_deg"])
            if obl and yaw and max(map(abs, obl)) + max(map(abs, yaw)) >= 90:
                total = max(map(abs, obl)) + max(map(abs, yaw))
                _fail(
                    f"{path}.obliquity_deg+yaw_deg",
                    total,
                    "obliquity + |yaw| reaches 90 deg: the velocity would not enter the target",
                )
    csv_path = config.get("validation", {}).get("table2", {}).get("csv")
    if isinstance(csv_path, str):
        _check_table2_csv("validation.table2.csv", csv_path, base)


def schema_error_line(exc: BaseException) -> str:
    """One line for a schema validation error: key path, value, and a suggestion.

    ``exc`` is Snakemake's ``WorkflowError`` (wrapping a ``jsonschema`` error) or the
    ``jsonschema.ValidationError`` itself; anything else gives ``str(exc)``'s first line.
    """
    err = exc
    if not hasattr(err, "absolute_path"):
        chained = [*getattr(exc, "args", ()), exc.__cause__, exc.__context__]
        err = next((a for a in chained if hasattr(a, "absolute_path")), None)
    if err is None:
        return f"config: {str(exc).splitlines()[0] if str(exc) else type(exc).__name__}"
    path = ".".join(str(p) for p in err.absolute_path) or "<top level>"
    if err.validator == "additionalProperties" and isinstance(err.instance, Mapping):
        known = list(err.schema.get("properties", {}))
        unknown = [k for k in err.instance if k not in known]
        parts = []
        for k in unknown:
            close = difflib.get_close_matches(str(k), known, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            parts.append(f"config {path}.{k}: unknown key{hint}")
        if parts:
            return "; ".join(parts) + f"; known keys: {', '.join(known)}"
    value = err.instance
    shown = repr(value) if len(repr(value)) <= 80 else repr(value)[:77] + "..."
    return f"config {path} = {shown}: {err.message.splitlines()[0][:200]}"


def validate_config(
    config: dict[str, Any],
    schema_validate: Callable[[dict[str, Any]], Any],
    base: str | Path = ".",
) -> None:
    """Schema validation (via ``schema_validate``), then :func:`check_config`.

    A schema error is re-raised as :class:`ConfigError` with :func:`schema_error_line`.
    """
    try:
        schema_validate(config)
    except Exception as exc:  # Snakemake's WorkflowError or jsonschema's error
        raise ConfigError(schema_error_line(exc)) from None
    check_config(config, base)
