"""The generated configuration reference (pencore.workflowconfig.config_reference) lists every
key of the shipped configurations, and every range it prints is the one the schema or
the configuration check enforces, found by probing them at and beside each bound."""

from __future__ import annotations

import copy
import math
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import jsonschema
import pytest
import yaml

from pencore.errors import ConfigError
from pencore.inputs.limits import LIMITS
from pencore.workflowconfig.config_check import KEY_RULES, LIMITED_KEYS, check_config
from pencore.workflowconfig.config_reference import (
    config_key_paths,
    config_reference,
    named_map_paths,
    reference_rows,
)

REPO = Path(__file__).resolve().parents[2]
SHIPPED = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
SCHEMA = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())
MARKDOWN = config_reference(REPO)
ROWS = reference_rows(REPO)

#: ``| `key` | type | default | valid range | description |``
_ROW = re.compile(r"^\| `([^`]+)` \| (.*?) \| (.*?) \| (.*?) \| (.*) \|$")
#: ``in (0, 10000] m/s``
_INTERVAL = re.compile(r"in ([\[(])([^,\]\[()]+), ([^,\]\[()]+)([\])])")


def _table() -> dict[str, tuple[str, str]]:
    """key path -> (type, valid-range cell) as printed."""
    out = {}
    for line in MARKDOWN.splitlines():
        m = _ROW.match(line)
        if m and m.group(1) != "key":
            out[m.group(1)] = (m.group(2), m.group(4).replace("\\|", "|"))
    return out


TABLE = _table()


@pytest.mark.parametrize(
    "name", ["config/config.yaml", "config/ensemble_large.yaml", ".test/config.yaml"]
)
def test_every_key_of_the_shipped_configs_is_in_the_reference(name):
    config = yaml.safe_load((REPO / name).read_text())
    missing = sorted(config_key_paths(config, named=named_map_paths(REPO)) - set(TABLE))
    assert not missing, missing


def test_every_key_has_a_type_and_a_description():
    assert len(TABLE) == len(ROWS) > 100
    assert [r.path for r in ROWS if not r.description] == []
    assert [r.path for r in ROWS if r.type == "any"] == []


def test_command_line_prints_the_reference():
    out = subprocess.run(
        [sys.executable, "-m", "pencore.workflowconfig.config_reference", "--root", str(REPO)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert out == MARKDOWN


def _intervals(cell: str, checked: bool) -> list[tuple[float, float, bool, bool]]:
    """The intervals of a valid-range cell, the checked or the schema's."""
    out = []
    for part in cell.split("; "):
        if part.endswith("(checked)") != checked or part.startswith("entries"):
            continue
        m = _INTERVAL.search(part)
        if m:
            lo, hi = float(m.group(2)), float(m.group(3))
            out.append((lo, hi, m.group(1) == "(", m.group(4) == ")"))
    return out


def _probes(lo, hi, lo_open, hi_open, integer) -> list[tuple[float, bool]]:
    """(value, inside) at and on both sides of each finite bound."""
    out = []
    for bound, is_open, outward in ((lo, lo_open, -math.inf), (hi, hi_open, math.inf)):
        if not math.isfinite(bound):
            continue
        inward = -outward
        near_out = bound + math.copysign(1, outward) if integer else math.nextafter(bound, outward)
        near_in = bound + math.copysign(1, inward) if integer else math.nextafter(bound, inward)
        out += [(bound, not is_open), (near_out, False), (near_in, True)]
    return out


def _node(cfg: Any, path: str, create: bool = False) -> tuple[Any, str]:
    """The mapping holding the last key of ``path`` (first entry for ``[]``) and that key."""
    parts = path.split(".")
    node = cfg
    for part in parts[:-1]:
        key = part.removesuffix("[]")
        if key not in node and create:
            node[key] = {}
        node = node[key]
        if part.endswith("[]"):
            node = node[0]
    return node, parts[-1]


def _zero_like(value: Any) -> Any:
    if isinstance(value, dict):
        return {**value, **{k: 0.0 for k in ("min", "max") if k in value}}
    if isinstance(value, list):
        return [0.0]
    return 0.0


def _probe_config(path: str, value: float) -> dict | None:
    """The shipped configuration with ``value`` at ``path``: the scalar, every entry of a
    list, the min and max of a range (for its step or n: the entry itself)."""
    cfg = copy.deepcopy(SHIPPED)
    holder, key = _node(cfg, path, create=True)
    current = holder.get(key)
    if key in ("step", "n") and isinstance(current, int | float):
        holder[key] = value
        if key == "step":  # one point, so that a small step is not a huge grid
            holder["max"] = holder["min"]
        return cfg
    # obliquity + yaw of one study stay below 90 deg: the probed key alone sets the angle
    for other in list(holder):
        if other != key and other.endswith("_deg") and other.startswith(("obliquity", "yaw")):
            holder[other] = _zero_like(holder[other])
    # a case's speed window must meet the study's velocities (a check across keys): the
    # probed velocities alone decide
    for case in holder.get("cases", []) if key == "velocities_m_s" else []:
        case.pop("v_min", None)
        case.pop("v_max", None)
    # v_stop >= 10 eps when eps > 0 (a check across keys): the probed key alone decides
    if key == "v_stop":
        holder["eps"] = 0.0
    elif key == "eps":
        holder["v_stop"] = LIMITS["v_stop"].hi
    if isinstance(current, dict):
        if "dist" in current:
            return None  # distributions are checked as a whole (min < max, sd > 0)
        holder[key] = {**current, "min": value, "max": value}
    elif isinstance(current, list):
        holder[key] = [value] * (3 if key == "start_m" else 1)
    else:
        holder[key] = value
    return cfg


def _accepted_by_check(cfg: dict) -> bool:
    try:
        check_config(cfg, REPO)
    except ConfigError:
        return False
    return True


def _accepted_by_schema(cfg: dict) -> bool:
    return jsonschema.Draft202012Validator(SCHEMA).is_valid(cfg)


CHECKED = [(p, t, c) for p, (t, c) in TABLE.items() if _intervals(c, checked=True)]
SCHEMA_BOUNDED = [(p, t, c) for p, (t, c) in TABLE.items() if _intervals(c, checked=False)]


@pytest.mark.parametrize(("path", "type_", "cell"), CHECKED, ids=[p for p, _, _ in CHECKED])
def test_checked_range_is_what_the_configuration_check_enforces(path, type_, cell):
    probed = 0
    for lo, hi, lo_open, hi_open in _intervals(cell, checked=True):
        for value, inside in _probes(lo, hi, lo_open, hi_open, type_.startswith("integer")):
            cfg = _probe_config(path, value)
            if cfg is None:
                continue
            assert _accepted_by_check(cfg) == inside, f"{path} = {value!r}: printed {cell!r}"
            probed += 1
    if "[]" not in path or "choices" in path:
        assert probed, f"{path}: no probe"


@pytest.mark.parametrize(
    ("path", "type_", "cell"), SCHEMA_BOUNDED, ids=[p for p, _, _ in SCHEMA_BOUNDED]
)
def test_schema_range_is_what_the_schema_enforces(path, type_, cell):
    for lo, hi, lo_open, hi_open in _intervals(cell, checked=False):
        for value, inside in _probes(lo, hi, lo_open, hi_open, type_.startswith("integer")):
            cfg = copy.deepcopy(SHIPPED)
            holder, key = _node(cfg, path, create=True)
            holder[key] = value
            assert _accepted_by_schema(cfg) == inside, f"{path} = {value!r}: printed {cell!r}"


def test_every_rule_of_the_check_is_printed_and_probed():
    """Each range of KEY_RULES and LIMITED_KEYS is printed on a key the probes reach."""
    probed_paths = {p for p, _, _ in CHECKED}
    for rule in KEY_RULES:
        text = f"every number {rule.limit.describe()} (checked)"
        assert any(text in TABLE[p][1] for p in probed_paths), rule.pattern
    for path, name in LIMITED_KEYS.items():
        assert path in probed_paths, path
        assert f"{LIMITS[name].describe()} (checked)" in TABLE[path][1], path


def test_config_readme_is_the_generated_reference():
    """config/README.md is the generator's output (regenerate it with
    ``python -m pencore.workflowconfig.config_reference > config/README.md``)."""
    assert (REPO / "config" / "README.md").read_text() == MARKDOWN
