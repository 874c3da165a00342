"""The reference of the workflow's configuration keys, generated as Markdown.

Every key of ``config/config.yaml`` with its type, its default (the value in
``config/config.yaml``; the schema's default for keys that file leaves out), its valid
range and its description. Nothing is typed here: the types, descriptions and schema
bounds come from ``workflow/schemas/config.schema.yaml``, the ranges the workflow checks
beyond the schema from :mod:`pencore.studies.config_check`
(:data:`~pencore.studies.config_check.KEY_RULES`,
:data:`~pencore.studies.config_check.GRID_POINTS`,
:data:`~pencore.studies.config_check.GRID_STEP`), the very objects the check enforces.

Command line (from the repository root; the documentation build includes its output)::

    python -m pencore.studies.config_reference > config_keys.md
    python -m pencore.studies.config_reference --root /path/to/pencore

Key paths are dotted; ``[]`` stands for every entry of a list (``validation.fig5.cases[].name``).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pencore.inputs.limits import LIMITS, Limit
from pencore.studies.config_check import (
    GRID_POINTS,
    GRID_STEP,
    LIMITED_KEYS,
    MAX_GRID,
    KeyRule,
    key_rule,
)

__all__ = [
    "SCHEMA",
    "CONFIG",
    "Row",
    "NAME",
    "config_key_paths",
    "named_map_paths",
    "config_reference",
    "reference_rows",
    "schema_limit",
    "main",
]

#: The schema and the default configuration, relative to the repository root.
SCHEMA = Path("workflow/schemas/config.schema.yaml")
CONFIG = Path("config/config.yaml")

#: Schema keyword naming another schema node whose keys a free mapping takes (for example
#: the attribution's ``choices.numerics``, which takes the keys of ``numerics``).
KEYS_OF = "x-keys-of"


@dataclass(frozen=True)
class Row:
    """One configuration key of the reference.

    Attributes
    ----------
    path : str
        Dotted key path; ``[]`` for the entries of a list.
    type : str
        The schema's type (``number``, ``array of string``, ``one of: a, b``...).
    default : str
        The value in ``config/config.yaml`` (compact JSON), or the schema default marked
        ``(schema)``, or ``""``.
    schema_range : pencore.inputs.limits.Limit or None
        Bounds the schema puts on the value (or on each entry of a list of numbers).
    check : pencore.studies.config_check.KeyRule or None
        The range :func:`pencore.studies.config_check.check_config` enforces on every
        number of the value, by the unit in the key's name.
    limited : pencore.inputs.limits.Limit or None
        The :data:`pencore.inputs.limits.LIMITS` entry the configuration check applies to
        the value (:data:`pencore.studies.config_check.LIMITED_KEYS`).
    constraints : tuple of str
        Further schema rules (allowed values, list length, pattern, required keys).
    description : str
        From the schema (``""`` if it has none; a test keeps that from happening).
    """

    path: str
    type: str
    default: str
    schema_range: Limit | None
    check: KeyRule | None
    limited: Limit | None
    constraints: tuple[str, ...]
    description: str

    def range_text(self) -> str:
        """The valid range as the reference prints it."""
        parts = []
        if self.schema_range is not None:
            parts.append(self.schema_range.describe())
        parts += self.constraints
        if self.check is not None:
            parts.append(f"every number {self.check.limit.describe()} (checked)")
        if self.limited is not None:
            parts.append(f"{self.limited.describe()} (checked)")
        if self.path.rsplit(".", 1)[-1] == "n" and self.type == "integer":
            parts.append(f"{GRID_POINTS.describe()} (checked)")
        if self.path.rsplit(".", 1)[-1] == "step":
            parts.append(f"{GRID_STEP.describe()} (checked)")
        return "; ".join(parts)


#: How the reference names a key the user chooses (the name of an option set).
NAME = "<name>"


def _load_yaml(path: Path) -> Any:
    import yaml

    with open(path, encoding="utf-8") as f:
        return yaml.safe_load(f)


def _pointer(schema: Mapping[str, Any], ref: str) -> Mapping[str, Any]:
    if not ref.startswith("#/"):
        raise ValueError(f"only local schema references are supported, got {ref!r}")
    node: Any = schema
    for part in ref[2:].split("/"):
        node = node[part]
    return node


def _resolve(schema: Mapping[str, Any], node: Mapping[str, Any]) -> dict[str, Any]:
    """``node`` with its ``$ref`` merged in (the node's own keys win)."""
    out = dict(node)
    while "$ref" in out:
        ref = out.pop("$ref")
        out = {**_resolve(schema, _pointer(schema, ref)), **out}
    return out


def schema_limit(node: Mapping[str, Any], unit: str = "") -> Limit | None:
    """The bounds of a numeric schema node (``minimum``, ``exclusiveMaximum``...), if any."""
    keys = ("minimum", "exclusiveMinimum", "maximum", "exclusiveMaximum")
    if not any(k in node for k in keys):
        return None
    lo, lo_open = -math.inf, True
    hi, hi_open = math.inf, True
    if "minimum" in node:
        lo, lo_open = float(node["minimum"]), False
    if "exclusiveMinimum" in node:
        lo, lo_open = float(node["exclusiveMinimum"]), True
    if "maximum" in node:
        hi, hi_open = float(node["maximum"]), False
    if "exclusiveMaximum" in node:
        hi, hi_open = float(node["exclusiveMaximum"]), True
    return Limit("value", unit, lo, hi, lo_open, hi_open, kind="schema")


def _types(node: Mapping[str, Any]) -> list[str]:
    t = node.get("type", [])
    return [t] if isinstance(t, str) else list(t)


def _type_text(schema: Mapping[str, Any], node: Mapping[str, Any]) -> str:
    types = _types(node)
    if "array" in types:
        items = _resolve(schema, node.get("items", {}))
        inner = _type_text(schema, items) or "any"
        return f"array of {inner}" + (" or null" if "null" in types else "")
    if types:
        return " or ".join(types)
    return "object" if "properties" in node else "any"


def _constraints(schema: Mapping[str, Any], node: Mapping[str, Any]) -> tuple[str, ...]:
    out = []
    enum = [e for e in node.get("enum", []) if e is not None]
    if enum:
        out.append("one of " + ", ".join(f"`{e}`" for e in enum))
    if "array" in _types(node):
        items = _resolve(schema, node.get("items", {}))
        item_enum = [e for e in items.get("enum", []) if e is not None]
        if item_enum:
            out.append("entries one of " + ", ".join(f"`{e}`" for e in item_enum))
        lim = schema_limit(items)
        if lim is not None:
            out.append(f"entries {lim.describe()}")
        lo, hi = node.get("minItems"), node.get("maxItems")
        if lo is not None and lo == hi:
            out.append(f"exactly {lo} entries")
        elif lo:
            out.append(f"at least {lo} {'entry' if lo == 1 else 'entries'}")
        if node.get("uniqueItems"):
            out.append("entries unique")
    if "pattern" in node:
        out.append(f"matches `{node['pattern']}`")
    if node.get("required"):
        out.append("needs " + ", ".join(f"`{k}`" for k in node["required"]))
    return tuple(out)


def _unit(key: str) -> str:
    rule = key_rule(key)
    return rule.limit.unit if rule is not None else ""


def _compact(value: Any) -> str:
    return json.dumps(value, separators=(", ", ": "), ensure_ascii=False)


def _default(path: str, config: Any, node: Mapping[str, Any]) -> str:
    """The value at ``path`` in ``config`` (first entry of lists for ``[]``), or the
    schema default, as a Markdown cell; ``""`` for mappings too long to print (their keys
    have rows of their own)."""
    value: Any = config
    found = True
    for part in path.split("."):
        key, is_list = (part[:-2], True) if part.endswith("[]") else (part, False)
        if not (isinstance(value, Mapping) and key in value):
            found = False
            break
        value = value[key]
        if is_list:
            if not (isinstance(value, Sequence) and not isinstance(value, str) and value):
                found = False
                break
            value = value[0]
    source = ""
    if not found:
        if "default" not in node:
            return ""
        value, source = node["default"], " (schema)"
    elif "[]" in path:
        source = " (first entry)"
    if isinstance(value, list) and value and isinstance(value[0], Mapping):
        where = "the schema" if source == " (schema)" else f"`{CONFIG}`"
        return f"{len(value)} {'entry' if len(value) == 1 else 'entries'} in {where}"
    if not _is_small(value):
        return ""
    return f"`{_compact(value)}`{source}"


def _is_small(value: Any) -> bool:
    return not isinstance(value, Mapping | list) or len(_compact(value)) <= 80


def _walk(
    schema: Mapping[str, Any],
    node: Mapping[str, Any],
    path: str,
    config: Any,
    validated: bool = True,
) -> Iterator[Row]:
    """The rows of ``node`` and the keys below it. ``validated`` is False below an
    :data:`KEYS_OF` reference: the schema describes those keys but does not validate
    them there, so their schema bounds are not printed (the configuration check's are)."""
    node = _resolve(schema, node)
    if path:
        key = path.rsplit(".", 1)[-1].removesuffix("[]")
        rule = key_rule(key)
        yield Row(
            path=path,
            type=_type_text(schema, node),
            default=_default(path, config, node),
            schema_range=schema_limit(node, _unit(key)) if validated else None,
            check=rule,
            limited=LIMITS[LIMITED_KEYS[path]] if path in LIMITED_KEYS else None,
            constraints=_constraints(schema, node),
            description=" ".join(str(node.get("description", "")).split()),
        )
    if KEYS_OF in node:
        target = _resolve(schema, _pointer(schema, node[KEYS_OF]))
        for name, sub in target.get("properties", {}).items():
            yield from _walk(schema, sub, f"{path}.{name}", config, validated=False)
    for name, sub in node.get("properties", {}).items():
        yield from _walk(schema, sub, f"{path}.{name}" if path else name, config, validated)
    named = node.get("additionalProperties")
    if isinstance(named, Mapping) and path:
        # a mapping of user-chosen names to entries of one schema (option sets)
        yield from _walk(schema, named, f"{path}.{NAME}", config, validated)
    if "array" in _types(node):
        items = _resolve(schema, node.get("items", {}))
        if "properties" in items:
            for name, sub in items["properties"].items():
                yield from _walk(schema, sub, f"{path}[].{name}", config, validated)


def reference_rows(root: str | Path = ".") -> list[Row]:
    """Every key the schema defines, in schema order, as :class:`Row` objects.

    Parameters
    ----------
    root : path-like
        The repository root (holding ``workflow/schemas/`` and ``config/``).
    """
    root = Path(root)
    schema = _load_yaml(root / SCHEMA)
    config = _load_yaml(root / CONFIG)
    return list(_walk(schema, schema, "", config))


def named_map_paths(root: str | Path = ".") -> frozenset[str]:
    """The key paths whose keys are names the user chooses (a schema's mapping-valued
    ``additionalProperties``), as the reference names them."""
    return frozenset(
        r.path.removesuffix(f".{NAME}") for r in reference_rows(root) if r.path.endswith(NAME)
    )


def config_key_paths(
    config: Any, prefix: str = "", named: frozenset[str] = frozenset()
) -> set[str]:
    """The key paths of a configuration as the reference names them: ``[]`` for every
    entry of a list of mappings, :data:`NAME` for a user-chosen key of a path in
    ``named`` (:func:`named_map_paths`)."""
    out: set[str] = set()
    if isinstance(config, Mapping):
        for key, value in config.items():
            name = NAME if prefix in named else str(key)
            path = f"{prefix}.{name}" if prefix else name
            out.add(path)
            out |= config_key_paths(value, path, named)
    elif isinstance(config, Sequence) and not isinstance(config, str):
        for item in config:
            if isinstance(item, Mapping):
                out |= config_key_paths(item, f"{prefix}[]", named)
    return out


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def config_reference(root: str | Path = ".") -> str:
    """The configuration reference as Markdown: one table per top-level key.

    Parameters
    ----------
    root : path-like
        The repository root (holding ``workflow/schemas/`` and ``config/``).

    Returns
    -------
    str
        Markdown (a heading, notes, and the tables).
    """
    root = Path(root)
    schema = _load_yaml(root / SCHEMA)
    rows = reference_rows(root)
    lines = [
        "# Workflow configuration keys",
        "",
        f"Generated from `{SCHEMA}` (types, descriptions, schema bounds), `{CONFIG}` "
        "(defaults) and `pencore.studies.config_check` (the ranges checked beyond the "
        "schema) by `python -m pencore.studies.config_reference`; do not edit by hand.",
        "",
        "Key paths are dotted; `[]` stands for every entry of a list and `<name>` for a "
        "name you choose (an option set). A configuration "
        "given with `--configfile` is merged over the defaults. Ranges marked *(checked)* "
        "apply to every number of the value: a scalar, each entry of a list, and the "
        "`min` and `max` of a range, grid or distribution; unmarked ranges are the "
        "schema's. Across keys, the workflow also "
        "checks that a range's `min` is not above its `max`, that no grid has more than "
        f"{MAX_GRID} points, that the largest `|obliquity| + |yaw|` of a study stays "
        "below 90 deg, that `projectiles` and `cases` names are unique, that the "
        "Table 2 CSV has rows, that each case's speed window `[v_min, v_max]` meets its "
        "study's velocities, and each ensemble case and attribution setting as a whole "
        "(`pencore.studies.ensemble_cases.check_case`, "
        "`pencore.paper.choices.check_settings`).",
        "",
    ]
    for top, node in schema.get("properties", {}).items():
        node = _resolve(schema, node)
        lines += [f"## `{top}`", "", " ".join(str(node.get("description", "")).split()), ""]
        lines += [
            "| key | type | default | valid range | description |",
            "| --- | --- | --- | --- | --- |",
        ]
        for row in rows:
            if row.path == top or row.path.startswith((f"{top}.", f"{top}[]")):
                lines.append(
                    "| "
                    + " | ".join(
                        _cell(x)
                        for x in (
                            f"`{row.path}`",
                            row.type,
                            row.default,
                            row.range_text(),
                            row.description,
                        )
                    )
                    + " |"
                )
        lines.append("")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m pencore.studies.config_reference [--root DIR]``: print the reference."""
    parser = argparse.ArgumentParser(
        prog="python -m pencore.studies.config_reference",
        description="Print the workflow configuration reference (Markdown).",
    )
    parser.add_argument("--root", default=".", help="repository root (default: .)")
    args = parser.parse_args(argv)
    sys.stdout.write(config_reference(args.root))
    return 0


if __name__ == "__main__":
    sys.exit(main())
