"""Checks of the workflow configuration that a JSON schema cannot express, and short
messages for the ones it can.

The Snakefile validates ``config`` against ``workflow/schemas/config.schema.yaml`` and
then calls :func:`check_config`, so a bad configuration stops when the workflow is parsed,
with one line that names the key path and the value, instead of late in a job (or never).

Checked here, by the unit in the key's name (``*_m_s``, ``*_deg``, ``*_rad_s``, ``*_m``;
the ranges are the data :data:`KEY_RULES`, :data:`GRID_POINTS` and :data:`GRID_STEP`, which
:mod:`pencore.workflowconfig.config_reference` prints for the configuration reference):

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
* the Table 2 CSV has at least one row;
* every ``numerics`` mapping passes :func:`pencore.inputs.numerics.resolve_numerics`
  (the limits the solver enforces: ``rtol: 0.5`` stops here, not in a job);
* every projectile, target and medium named (the keys :data:`NAMING_KEYS`: ``projectile``,
  ``projectiles``, ``target``, ``targets``, ``medium``, ``media``) is in the library or an
  existing YAML file (read through the input gate), and so is every one a measurement
  table's rows name (its columns :data:`NAMING_COLUMNS`); every set of a Fig. 5 body shot
  table (``validation.fig5.body_shots``) is in its file, and the projectile it is drawn
  with is known; every data table named (the keys :data:`TABLE_KEYS`) is a readable table;
* layer thicknesses (``thickness*_m``) are finite and > 0 (``LIMITS["thickness"]``);
* search scans (``scan_points``) are whole numbers in ``[2, MAX_SCAN]``;
* a case's speed window ``[v_min, v_max]`` (m/s) has ``v_min < v_max`` and meets its
  study's velocity grid (else the job would write a dataset of NaN);
* ensemble distributions stay, over their whole support, within the ranges the solver
  accepts (speed, yaw, angular velocity, azimuth, and obliquity + yaw below 90 deg); a
  normal without ``min``/``max`` counts as reaching 8 standard deviations from its mean
  (a draw beyond has probability < 1e-15), see
  :func:`pencore.workflowconfig.ensemble_cases.check_case`.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pencore.errors import ConfigError, InputError
from pencore.inputs.gate import brief, load_yaml_text, read_text, read_yaml
from pencore.inputs.limits import LIMITS, Limit, as_float, number, one_line_warnings, plausible
from pencore.inputs.numerics import NUMERIC_FIELDS, resolve_numerics
from pencore.paper.choices import check_settings
from pencore.search.threshold import MAX_SCAN
from pencore.workflowconfig.ensemble_cases import check_case

__all__ = [
    "read_config",
    "strict_schema_error",
    "GRID_POINTS",
    "GRID_STEP",
    "KEY_RULES",
    "LIMITED_KEYS",
    "MAX_GRID",
    "NAMING_KEYS",
    "NAMING_COLUMNS",
    "TABLE_KEYS",
    "KeyRule",
    "check_config",
    "one_line_warnings",
    "table_text",
    "key_rule",
    "schema_error_message",
]

#: Largest number of points a configured grid may have (typo guard).
MAX_GRID = 10_000


@dataclass(frozen=True)
class KeyRule:
    """The range :func:`check_config` enforces on every number of the keys it matches.

    Attributes
    ----------
    pattern : str
        The keys matched, as a glob on the key's own name (``*_m_s``, ``obliquity*_deg``);
        without ``*`` the name itself.
    label : str
        How messages name the quantity.
    limit : pencore.inputs.limits.Limit
        The valid range (unit and bounds).
    """

    pattern: str
    label: str
    limit: Limit

    def matches(self, key: str) -> bool:
        """Whether the rule applies to a key of this name."""
        head, star, tail = self.pattern.partition("*")
        if not star:
            return key == self.pattern
        return key.startswith(head) and key.endswith(tail) and len(key) >= len(head + tail)


#: Ranges by the unit in the key's name, first match wins. Each applies to every number of
#: the key's value: a scalar, each entry of a list, the ``min`` and ``max`` of a range or
#: grid (and of an ensemble distribution).
KEY_RULES: tuple[KeyRule, ...] = (
    KeyRule("*_m_s", "velocity", LIMITS["velocity"]),
    KeyRule("*_rad_s", "angular velocity", LIMITS["omega"]),
    KeyRule(
        "obliquity*_deg",
        "obliquity",
        Limit("obliquity", "deg", 0.0, 90.0, hi_open=True, why="the axis points into +x"),
    ),
    KeyRule("yaw*_deg", "yaw", LIMITS["yaw"]),
    KeyRule(
        "threshold*_deg",
        "threshold",
        Limit("threshold", "deg", 0.0, 180.0, True, True, why="an angle between directions"),
    ),
    KeyRule("start_m", "start coordinate", LIMITS["start"]),
    KeyRule(
        "start_height*_m",
        "start height",
        Limit("start height", "m", 0.0, LIMITS["start"].hi, kind="physical / guard"),
    ),
)

#: Number of points ``n`` of a grid ``{min, max, n}`` (also the largest grid by step).
GRID_POINTS = Limit("grid points", "", 1.0, float(MAX_GRID), kind="physical / guard")
#: Step of a grid ``{min, max, step}``.
GRID_STEP = Limit("step", "", 0.0, math.inf, lo_open=True, hi_open=True)


def key_rule(key: str) -> KeyRule | None:
    """The :data:`KEY_RULES` entry that applies to a key of this name, if any."""
    return next((rule for rule in KEY_RULES if rule.matches(key)), None)


_SETTING = "attribution.settings[].choices"

#: Keys whose values pencore checks against :data:`pencore.inputs.limits.LIMITS` under the
#: given name when the configuration is checked: the numerics overrides (every numeric
#: field of :class:`pencore.inputs.numerics.Numerics` is checked by its own name), the
#: perforation slab's depth windows, and the choices of an attribution setting
#: (:func:`pencore.paper.choices.check_choices`). ``[]`` stands for every entry of a list.
LIMITED_KEYS: dict[str, str] = {
    **{f"numerics.{name}": name for name in NUMERIC_FIELDS},
    "perforation.crater_depth": "crater_depth",
    "perforation.free_surface_depth": "free_surface_depth",
    **{f"{_SETTING}.numerics.{name}": name for name in NUMERIC_FIELDS},
    f"{_SETTING}.shank.factor": "shank_factor",
    f"{_SETTING}.shank.delta_ref": "delta_ref",
    f"{_SETTING}.emulation.n_circumferential": "n_circumferential",
    f"{_SETTING}.emulation.dt": "dt",
    f"{_SETTING}.start_height": "start_height",
    f"{_SETTING}.friction": "friction",
}


def _fail(path: str, message: str) -> None:
    raise ConfigError(f"config {path}: {message}")


def _numbers(value: Any) -> list[float]:
    """Every number in a scalar, a list, or a range/grid mapping (its min and max); an
    integer no float can hold counts as infinite."""
    if isinstance(value, bool):
        return []
    if isinstance(value, int | float):
        return [_float(value)]
    if isinstance(value, Mapping):
        return [_float(value[k]) for k in ("min", "max") if _is_num(value.get(k))]
    if isinstance(value, Sequence) and not isinstance(value, str):
        return [_float(v) for v in value if _is_num(v)]
    return []


def _float(value: int | float) -> float:
    v = as_float(value, allow_str=False)
    return math.nan if v is None else v


def _is_num(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


def _check_range(path: str, value: Mapping[str, Any]) -> None:
    lo, hi = value.get("min"), value.get("max")
    if _is_num(lo) and _is_num(hi) and lo > hi:
        _fail(path, f"min {brief(lo)} is larger than max {brief(hi)}")
    step, n = value.get("step"), value.get("n")
    if _is_num(step):
        if not GRID_STEP.contains(step):
            _fail(path, f"step must be > 0, got {brief(step)}")
        if _is_num(lo) and _is_num(hi):
            span = (_float(hi) - _float(lo)) / _float(step)
            points = math.floor(span + 1e-9) + 1 if math.isfinite(span) else math.inf
            if not GRID_POINTS.contains(points):
                _fail(
                    path,
                    f"the grid has {points} points (min {brief(lo)}, max {brief(hi)}, "
                    f"step {brief(step)}); at most {MAX_GRID} are allowed (typo guard)",
                )
    if _is_num(n) and not GRID_POINTS.contains(n):
        _fail(path, f"n must be {GRID_POINTS.describe()} points, got {brief(n)}")


#: Plausible range (:data:`pencore.inputs.limits.PLAUSIBLE`) of the numbers of the keys a
#: :data:`KEY_RULES` pattern matches (tolerances excepted: a 2 m/s tolerance is no speed).
PLAUSIBLE_KEYS = {"*_m_s": "velocity", "*_rad_s": "omega", "obliquity*_deg": "obliquity",
                  "yaw*_deg": "yaw"}  # fmt: skip


def _warn_implausible(path: str, key: str, value: Any, nums: list[float]) -> None:
    """A :class:`~pencore.PlausibilityWarning` for each implausible number of the key (an
    ensemble distribution's ``mean`` and ``value`` included)."""
    rule = key_rule(key)
    which = PLAUSIBLE_KEYS.get(rule.pattern) if rule is not None else None
    if key.startswith("thickness") and key.endswith("_m"):
        which = "thickness"
    if which is None or "tol" in key:
        return
    if isinstance(value, Mapping):
        nums = nums + [_float(value[k]) for k in ("mean", "value") if _is_num(value.get(k))]
    for v in nums:
        if math.isfinite(v):
            plausible(v, which, f"config {path}")


def _check_leaf(path: str, key: str, value: Any) -> None:
    if isinstance(value, Sequence) and not isinstance(value, str) and len(value) > MAX_GRID:
        _fail(
            path,
            f"the list has {len(value)} entries; at most {MAX_GRID} are allowed, as for a "
            "grid {min, max, step} (typo guard)",
        )
    if isinstance(value, Mapping):
        _check_range(path, value)
    nums = _numbers(value)
    rule = key_rule(key)
    if rule is not None and not (rule.pattern == "start_m" and value is None):
        lim = rule.limit
        if rule.pattern == "start_m" and not (
            isinstance(value, Sequence) and len(value) == 3 and len(nums) == 3
        ):
            _fail(path, f"must be three numbers [x, y, z] in m, got {brief(value)}")
        for v in nums:
            if not (math.isfinite(v) and lim.contains(v)):
                _fail(path, f"{rule.label} {v!r} {lim.unit} is not {lim.describe()}")
    if key.startswith("thickness") and key.endswith("_m"):
        lim = LIMITS["thickness"]
        if isinstance(value, Mapping | Sequence) and not isinstance(value, str):
            items = list(value.values()) if isinstance(value, Mapping) else list(value)
        else:
            items = [value]
        for v in items:
            if v is None or isinstance(v, str | Mapping):
                continue
            f = as_float(v, allow_str=False)
            if f is None or not (math.isfinite(f) and lim.contains(f)):
                _fail(path, f"layer thickness {brief(v)} m is not {lim.describe()}")
    elif key == "scan_points" and value is not None:
        f = as_float(value, allow_str=False)
        if f is None or not math.isfinite(f) or f != math.floor(f) or not 2 <= f <= MAX_SCAN:
            _fail(
                path, f"scan_points must be a whole number in [2, {MAX_SCAN}], got {brief(value)}"
            )
    elif key == "numerics" and isinstance(value, Mapping):
        try:
            resolve_numerics(value)
        except InputError as exc:
            _fail(path, str(exc))
    _warn_implausible(path, key, value, nums)
    if key in TABLE_KEYS and value is not None:  # data tables: readable, a table
        for i, name in enumerate([value] if isinstance(value, str) else value):
            if isinstance(name, str):
                _csv_rows(name, path if isinstance(value, str) else f"{path}[{i}]")
    kind = NAMING_KEYS.get(key)
    if kind is not None and isinstance(value, str):
        _check_name(path, kind, value)
    elif kind is not None and isinstance(value, Sequence):
        for i, name in enumerate(value):
            if isinstance(name, str):
                _check_name(f"{path}[{i}]", kind, name)
    if key in ("projectiles", "cases") and isinstance(value, Sequence):
        names = [c.get("name") if isinstance(c, Mapping) else c for c in value]
        dupes = sorted({str(x) for x in names if names.count(x) > 1})
        if dupes:
            _fail(path, f"duplicate names {', '.join(dupes)}")


#: Keys whose value names a thing of the library (a name, a YAML file, or a list of
#: them), and what it names: each is looked up when the configuration is checked.
NAMING_KEYS = {
    "projectile": "projectile",
    "projectiles": "projectile",
    "target": "target",
    "targets": "target",
    "medium": "medium",
    "media": "medium",
}

#: Keys whose value names a data table (a CSV file, or a list of them): each is read
#: through the input gate when the configuration is checked.
TABLE_KEYS = ("csv", "shots")

#: Columns of a measurement table (``validation.measurements[].csv``) that name a library
#: projectile or target for their row.
NAMING_COLUMNS = {"projectile": "projectile", "target": "target"}


#: The root that relative file names start from, while :func:`check_config` runs.
_ROOT: list[Path] = [Path(".")]


def _check_name(path: str, kind: str, name: str) -> None:
    """A projectile, target or medium name the library knows, or a YAML file."""
    from pencore.inputs.library import MEDIA, get_projectile, get_target

    if kind == "medium":
        if name not in MEDIA:
            _fail(path, f"unknown medium {brief(name)}; known: {', '.join(MEDIA)}")
        return
    spec = name
    if name.endswith((".yaml", ".yml")) or "/" in name:
        spec = str(_ROOT[0] / name)
    try:
        (get_projectile if kind == "projectile" else get_target)(spec)
    except InputError as exc:
        _fail(path, str(exc))


def _check_window(path: str, study: Mapping[str, Any]) -> None:
    """Each case's ``[v_min, v_max]`` is a window that meets the study's velocity grid."""
    grid = _numbers(study.get("velocities_m_s"))
    for i, case in enumerate(study.get("cases") or []):
        if not isinstance(case, Mapping):
            continue
        lo, hi = case.get("v_min"), case.get("v_max")
        where = f"{path}.cases[{i}]" if path else f"cases[{i}]"
        for key, v in (("v_min", lo), ("v_max", hi)):
            if v is not None and not (_is_num(v) and math.isfinite(v) and v >= 0.0):
                _fail(f"{where}.{key}", f"must be a speed >= 0 m/s, got {brief(v)}")
        a = 0.0 if lo is None else float(lo)
        b = math.inf if hi is None else float(hi)
        if not a < b:
            _fail(where, f"v_min {a:g} m/s is not below v_max {b:g} m/s: no speed would run")
        if grid and (b < min(grid) or a > max(grid)):
            _fail(
                where,
                f"[v_min, v_max] = [{a:g}, {b:g}] m/s misses the study's velocities "
                f"[{min(grid):g}, {max(grid):g}] m/s: the case would be all NaN",
            )


def _check_study(path: str, study: Mapping[str, Any]) -> None:
    """Obliquity and yaw together keep the velocity pointing into the target; speed
    windows of cases meet the velocity grid."""
    if isinstance(study.get("cases"), Sequence):
        _check_window(path, study)
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
    """Raise :class:`~pencore.ConfigError` for the first problem in ``config`` (see the module).

    Parameters
    ----------
    config : mapping
        The workflow configuration, after schema validation.
    root : path-like
        Directory that relative file names in the configuration start from.
    """
    _ROOT[0] = Path(root)
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
    _check_tables(config.get("validation"))
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
    perforation = config.get("perforation")
    if isinstance(perforation, Mapping):
        for key in ("crater_depth", "free_surface_depth"):
            if key in perforation:
                try:
                    number(perforation[key], LIMITED_KEYS[f"perforation.{key}"])
                except InputError as exc:
                    _fail(f"perforation.{key}", str(exc))


def _csv_rows(path: str, where: str) -> list[dict[str, str]]:
    """The rows of a data table (CSV with ``#`` comments) named in the configuration,
    read through the input gate without the data stack; one line naming ``where`` if it
    cannot be read."""
    import csv

    try:
        text = table_text(_ROOT[0] / path, "data table")
    except InputError as exc:
        _fail(where, str(exc))
    lines = [ln for ln in text.splitlines() if not ln.lstrip().startswith("#")]
    return list(csv.DictReader(lines))


def _check_tables(validation: Any) -> None:
    """The names in the validation's data tables: each library projectile or target a
    measurement table's rows name (its ``projectile`` and ``target`` columns), and each
    set of a Fig. 5 body shot table with the projectile it is drawn with."""
    if not isinstance(validation, Mapping):
        return
    for i, m in enumerate(validation.get("measurements") or []):
        if not isinstance(m, Mapping) or not isinstance(m.get("csv"), str):
            continue
        where = f"validation.measurements[{i}].csv"
        rows = _csv_rows(m["csv"], where)
        for column, kind in NAMING_COLUMNS.items():
            for name in sorted({r.get(column) or "" for r in rows} - {""}):
                row = next(k for k, r in enumerate(rows) if r.get(column) == name)
                _check_name(f"{where} (row {row + 1}, column {column})", kind, name.strip())
    fig5 = validation.get("fig5")
    body = fig5.get("body_shots") if isinstance(fig5, Mapping) else None
    if not isinstance(body, Mapping):
        return
    for path, sets in body.items():
        where = f"validation.fig5.body_shots.{path}"
        if not isinstance(sets, Mapping):
            continue
        known = {r.get("set") for r in _csv_rows(str(path), where)}
        for name, projectile in sets.items():
            if name not in known:
                hint = difflib.get_close_matches(str(name), sorted(k for k in known if k), n=1)
                tip = f"; did you mean {hint[0]!r}?" if hint else ""
                _fail(f"{where}.{name}", f"no set {brief(name)} in {str(path)!r}{tip}")
            if isinstance(projectile, str):
                _check_name(f"{where}.{name}", "projectile", projectile)


def table_text(path: str | Path, what: str) -> str:
    """The text of a data table (CSV with ``#`` comments) the workflow checks at parse
    time, through the input gate (:func:`pencore.inputs.gate.read_text`), without the
    data stack: a missing, empty, comments-only, Latin-1 or binary file is one
    :class:`~pencore.InputError` line naming it (pandas would raise its own traceback)."""
    name = f"{what} file {str(path)!r}"
    text = read_text(path, name, "CSV")
    if "\x00" in text:
        raise InputError(f"{name} is a binary file, not a CSV text file")
    if not any(ln.strip() and not ln.lstrip().startswith("#") for ln in text.splitlines()):
        raise InputError(f"{name} holds no table (it is empty or only comments)")
    return text


def read_config(
    files: Sequence[str | Path],
    overrides: Mapping[str, Any] | Sequence[str] | None = None,
) -> dict[str, Any]:
    """The workflow configuration read through the input gate, as Snakemake merges it.

    Snakemake reads configuration files with its own YAML reader, which takes ``23:20``
    for the base-60 number 1400, keeps the last of two sections of the same name, and
    reads text such as ``1_0`` as a number. The Snakefile calls this function on the same
    files and replaces what Snakemake read, so the configuration meets the gate of every
    other input (:mod:`pencore.inputs.gate`: plain decimal numbers, repeated keys refused,
    bounded size, depth and count, control characters refused with line and column).

    Parameters
    ----------
    files : sequence of path-like
        Configuration files in the order Snakemake applies them (the Snakefile's
        ``configfile:`` first, then each ``--configfile``); later files update earlier
        ones, mapping by mapping.
    overrides : mapping or sequence of str, optional
        ``--config`` entries on top: ``KEY=VALUE`` strings (each value read as YAML
        through the gate), or a mapping of values already read.

    Returns
    -------
    dict

    Raises
    ------
    ConfigError
        One line naming the file (and line and column) or the entry.
    """
    merged: dict[str, Any] = {}
    for path in files:
        try:
            data = read_yaml(path, "config")
        except InputError as exc:
            raise ConfigError(str(exc)) from None
        if data is None:
            continue
        if not isinstance(data, Mapping):
            raise ConfigError(
                f"config file {str(path)!r} must hold a mapping of sections, "
                f"got {type(data).__name__}"
            )
        _update(merged, data)
    if isinstance(overrides, Mapping):
        _update(merged, overrides)
    elif overrides:
        for entry in overrides:
            key, sep, text = str(entry).partition("=")
            if not sep:
                raise ConfigError(f"--config entry must be KEY=VALUE, got {brief(entry)}")
            try:
                value = load_yaml_text(text, f"--config value of {brief(key)}") if text else None
            except InputError as exc:
                raise ConfigError(str(exc)) from None
            _update(merged, {key: value})
    return merged


def _update(config: dict[str, Any], new: Mapping[str, Any]) -> None:
    """Update ``config`` with ``new`` in place, mapping by mapping (Snakemake's rule)."""
    for key, value in new.items():
        if isinstance(value, Mapping) and isinstance(config.get(key), dict):
            _update(config[key], value)
        else:
            config[key] = dict(value) if isinstance(value, Mapping) else value


def strict_schema_error(config: Mapping[str, Any], schema: Mapping[str, Any]) -> str | None:
    """One line for the first value of ``config`` whose type the schema states and
    JSON Schema's own check lets through, else None.

    JSON Schema counts a float with no fraction as an integer (``seed: -0.0``,
    ``n_chunks: 4.0``) and a boolean as neither; here an ``integer`` is a whole number
    written without a fraction (a Python ``int``, not a ``bool``), and a ``number`` is
    not a ``bool``.
    """
    import jsonschema

    base = jsonschema.validators.validator_for(schema)
    checker = base.TYPE_CHECKER.redefine_many(
        {
            "integer": lambda _c, x: isinstance(x, int) and not isinstance(x, bool),
            "number": lambda _c, x: isinstance(x, (int, float)) and not isinstance(x, bool),
        }
    )
    strict = jsonschema.validators.extend(base, type_checker=checker)(schema)
    for error in strict.iter_errors(config):
        if error.validator != "type":
            continue  # the Snakefile's own validation reports every other violation
        path = ".".join(str(p) for p in error.absolute_path) or "(top level)"
        wanted = error.validator_value
        wanted = " or ".join(wanted) if isinstance(wanted, list) else wanted
        return f"config {path}: must be of type {wanted}, got {brief(error.instance)}"
    return None


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
