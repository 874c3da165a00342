"""Input checking: the valid range of every quantity a user gives pencore, and strict
readers for numbers, integers and mappings.

Text is read as a number only where a reader allows it (YAML files, mappings of a
projectile or target, the command line) and only in the input gate's plain decimal
notation (:data:`pencore.inputs.gate.DECIMAL`); the ranges then judge the value like any
other (only a range that reaches infinity, such as ``max_wall``'s, admits ``inf``).

Every user-facing entry point (the API, YAML files, the CLI) checks its inputs here, so
a bad value stops with one :class:`~pencore.InputError` whose message names the value, its unit
and what is allowed, before any computation.

The ranges are data: one entry a quantity in ``inputs/data/limits.yaml``
(:data:`LIMITS_FILE`: its valid range and kind, its plausible range, unit and likely slip,
with the file's provenance), read once on import into :data:`LIMITS` and
:data:`PLAUSIBLE`; this module is the gate that applies them.

Each range in :data:`~pencore.inputs.limits.LIMITS` is of one of two kinds:

``physical``
    the model means nothing outside it (a negative diameter, CRH < 0.5, an obliquity of
    90 deg or more, a negative resistance coefficient);
``guard``
    the model could be evaluated, but a value this far out is almost certainly a typo
    (a 10 km/s impact, a 100-m diameter, a 1000-s run); the bound is generous and says so.

The docs' table of valid ranges (user guide, "Projectiles, targets and numerics") is
generated from :data:`~pencore.inputs.limits.LIMITS` by :func:`limits_markdown` at every build.

Beside each valid range, :data:`~pencore.inputs.limits.PLAUSIBLE` holds the *plausible*
range of every quantity that carries a unit, with the slip of unit a value outside it
most likely is (a speed of 1.4 m/s: km/s meant). A valid but implausible value is run,
with one :class:`~pencore.PlausibilityWarning` naming the value and the slip
(:func:`plausible`); the docs' errors page lists the ranges
(:func:`plausible_markdown`).
"""

from __future__ import annotations

import contextlib
import dataclasses
import difflib
import math
import numbers
import os
import re
import sys
import warnings
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from pencore.errors import InputError, PlausibilityWarning, hint_keywords
from pencore.inputs.gate import DECIMAL_WORDS, brief, brief_path, decimal, read_yaml

__all__ = [
    "Limit",
    "LIMITS",
    "LIMITS_FILE",
    "load_limits",
    "count",
    "number",
    "as_float",
    "flag",
    "integer",
    "check_keys",
    "limits_markdown",
    "Plausible",
    "PLAUSIBLE",
    "plausible",
    "looks_like_radians",
    "plausible_markdown",
    "one_line_warnings",
    "half_space_plates",
]


@dataclass(frozen=True)
class Limit:
    """The valid range of one input quantity.

    Attributes
    ----------
    label : str
        How messages name the quantity.
    unit : str
        SI unit (``""`` for dimensionless, ``"deg"`` at the edges).
    lo, hi : float
        Bounds; ``lo_open``/``hi_open`` make them strict.
    kind : str
        ``"physical"``, ``"guard"`` (see the module docstring), or ``"physical / guard"``
        for a physical lower bound and a guard upper bound.
    why : str
        One line on where the bounds come from.
    group : str
        ``"core"`` (the main table of valid ranges) or ``"models"`` (the shank contact
        models and paper-emulation numerics of :mod:`pencore.inputs.models`).
    """

    label: str
    unit: str
    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False
    kind: str = "physical"
    why: str = ""
    group: str = "core"

    def contains(self, v: float) -> bool:
        above = v > self.lo if self.lo_open else v >= self.lo
        below = v < self.hi if self.hi_open else v <= self.hi
        return above and below

    def describe(self) -> str:
        u = f" {self.unit}" if self.unit else ""
        lo_b = "(" if self.lo_open else "["
        hi_b = ")" if self.hi_open else "]"
        return f"in {lo_b}{_fmt(self.lo)}, {_fmt(self.hi)}{hi_b}{u}"


def _fmt(x: float) -> str:
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return f"{x:g}"


def _type_name(value: Any) -> str:
    return type(value).__name__


def number(
    value: Any,
    key: str,
    what: str = "",
    *,
    allow_str: bool = False,
    label: str = "",
    plausibility: bool = True,
) -> float:
    """``value`` as a float within ``LIMITS[key]``, else :class:`~pencore.InputError`.

    Booleans are not numbers. Strings are refused unless ``allow_str`` (YAML reads
    ``1e6`` without a decimal point as a string, and a quoted ``"0.5"`` is a string too;
    YAML readers and the command line pass ``allow_str=True``); then a string must be
    plain decimal (:func:`pencore.inputs.gate.decimal`).

    Parameters
    ----------
    value : Any
        The value given.
    key : str
        Key into :data:`~pencore.inputs.limits.LIMITS`.
    what : str
        Prefix naming where the value came from (``"projectile 'x'"``).
    allow_str : bool
        Accept a string in plain decimal notation.
    label : str
        How messages name the value, for a quantity that has the range of ``key`` but
        is not it (a search tolerance in m/s); default: the label of ``key``.
    plausibility : bool
        Warn (:func:`plausible`) when the value is valid but outside its plausible range
        (:data:`PLAUSIBLE`); never for a value given a ``label`` (it is not the quantity).

    Returns
    -------
    float
    """
    lim = LIMITS[key]
    if label:
        lim = replace(lim, label=label)
    where = f"{what}: " if what else ""
    unit = f" {lim.unit}" if lim.unit and lim.unit != "SI" else ""
    v = as_float(value, allow_str)
    if v is None:
        if allow_str and isinstance(value, str):
            raise InputError(
                f"{where}{lim.label} must be a number{unit and ' of' + unit} {DECIMAL_WORDS}, "
                f"got {brief(value)}"
            )
        raise InputError(
            f"{where}{lim.label} must be a number of{unit or ' (dimensionless)'}, "
            f"got {brief(value)} ({_type_name(value)})"
        )
    if math.isnan(v) or (math.isinf(v) and v != lim.hi) or not lim.contains(v):
        raise InputError(f"{where}{lim.label} must be {lim.describe()}, got {brief(value)}")
    if plausibility and not label and key in PLAUSIBLE:
        plausible(v, key, what)
    return v


def as_float(value: Any, allow_str: bool) -> float | None:
    """``value`` as a float when it is a real number (not a bool; a 0-d numeric array;
    with ``allow_str``, a string in plain decimal notation,
    :func:`pencore.inputs.gate.decimal`), else None."""
    if isinstance(value, bool) or _is_time(value):
        return None
    if isinstance(value, numbers.Real):
        try:
            return float(value)
        except OverflowError:  # an integer no float can hold: out of every range
            return math.inf if value > 0 else -math.inf
    if allow_str and isinstance(value, str):
        return decimal(value)
    if isinstance(value, numbers.Integral):  # numpy integers are Integral, not always Real
        try:
            return float(value)
        except OverflowError:
            return math.inf if value > 0 else -math.inf
    try:  # 0-d numpy arrays
        import numpy as np

        if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
            return float(value)
    except ImportError:  # pragma: no cover
        pass
    return None


def flag(value: Any, what: str) -> bool:
    """``value`` as a bool when it is one (Python's or numpy's ``bool_``, a 0-d boolean
    array), else :class:`~pencore.InputError`: ``1``, ``"yes"`` and None are not flags.

    Examples
    --------
    >>> import numpy as np
    >>> flag(np.bool_(True), "stop_at_reversal")
    True
    """
    kind = getattr(getattr(value, "dtype", None), "kind", "")
    if isinstance(value, bool) or (kind == "b" and getattr(value, "ndim", 1) == 0):
        return bool(value)
    raise InputError(f"{what} must be True or False, got {brief(value)}")


def _is_time(value: Any) -> bool:
    """True for numpy's time values (``np.timedelta64(300)`` is an integer to Python, but
    a duration, not a speed or a length), scalars and 0-d arrays alike."""
    kind = getattr(getattr(value, "dtype", None), "kind", "")
    return kind in ("m", "M")


def integer(value: Any, key: str, what: str = "") -> int:
    """``value`` as an int within ``LIMITS[key]``; floats must be whole numbers."""
    lim = LIMITS[key]
    where = f"{what}: " if what else ""
    v = as_float(value, allow_str=False)
    huge = v is not None and math.isinf(v) and isinstance(value, numbers.Integral)
    if v is None or not (math.isfinite(v) or huge) or (not huge and v != math.floor(v)):
        raise InputError(f"{where}{lim.label} must be a whole number, got {brief(value)}")
    if not lim.contains(v):
        raise InputError(f"{where}{lim.label} must be {lim.describe()}, got {brief(value)}")
    return int(v)


def count(items: Any, key: str, what: str = "") -> int:
    """The length of ``items`` when it is within ``LIMITS[key]`` (a count: layers, rows),
    else :class:`~pencore.InputError` naming the count and the limit. Checked before any item is
    read, so a huge input is refused at once."""
    lim = LIMITS[key]
    where = f"{what}: " if what else ""
    n = len(items)
    if not lim.contains(n):
        raise InputError(f"{where}{lim.label} must be {lim.describe()}, got {n}")
    return n


def check_keys(mapping: Mapping[str, Any], allowed: Iterable[str], what: str) -> None:
    """Refuse keys of ``mapping`` not in ``allowed``, with a "did you mean" hint."""
    allowed = list(allowed)
    for key in mapping:
        if key not in allowed:
            hint = difflib.get_close_matches(str(key), allowed, n=1, cutoff=0.6)
            tip = f"; did you mean {brief(hint[0])}?" if hint else ""
            raise InputError(
                f"{what}: unknown key {brief(key)}{tip} (allowed: {', '.join(allowed)})"
            )


def limits_markdown(group: str = "core") -> str:
    """A Markdown table of valid ranges, one row per entry of :data:`~pencore.inputs.limits.LIMITS`
    in ``group``
    (``"core"``: the main table; ``"models"``: the shank models and emulation numerics)."""
    rows = ["| input | valid range | kind | why |", "|---|---|---|---|"]
    for key, lim in LIMITS.items():
        if lim.group != group:
            continue
        rows.append(f"| `{key}` | {lim.describe()[3:]} | {lim.kind} | {lim.why} |")
    return "\n".join(rows)


# ---------------------------------------------------------------- plausible ranges


@dataclass(frozen=True)
class Plausible:
    """The plausible range of one quantity, and the slip of unit a value outside it
    most likely is.

    A value ``v`` is plausible when it is 0 (a quantity switched off) or its magnitude
    lies in ``[lo, hi]`` (rule ``"range"``); rule ``"radians"`` (angles in degrees) flags the
    likely reading of a common angle in radians instead (:func:`looks_like_radians`).

    Attributes
    ----------
    label, unit : str
        How messages name the quantity, and its unit.
    lo, hi : float
        Plausible bounds of ``|v|`` (rule ``"range"``).
    below, above : str
        The likely slip of a value below ``lo`` / above ``hi``.
    rule : str
        ``"range"`` or ``"radians"``.
    valid : str
        For a quantity checked under another key's valid range (a resistance
        coefficient, a measured depth), how the docs' table words its valid range;
        ``""`` when :data:`LIMITS` has its own.
    """

    label: str
    unit: str
    lo: float
    hi: float
    below: str = ""
    above: str = ""
    rule: str = "range"
    valid: str = ""

    def fits(self, v: float) -> bool:
        if v == 0.0 or math.isnan(v):
            return True
        if self.rule == "radians":
            return not looks_like_radians(v)
        return self.lo <= abs(v) <= self.hi

    def slip(self, v: float) -> str:
        if self.rule == "radians":
            return self.below.format(deg=math.degrees(v))
        return self.below if abs(v) < self.lo else self.above

    def describe(self) -> str:
        if self.rule == "radians":
            return "not a common angle read in radians"
        u = f" {self.unit}" if self.unit else ""
        if self.lo == 0.0:
            return f"magnitude at most {_fmt(self.hi)}{u}"
        if math.isinf(self.hi):
            return f"at least {_fmt(self.lo)}{u}"
        return f"[{_fmt(self.lo)}, {_fmt(self.hi)}]{u}"


def looks_like_radians(angle_deg: float) -> bool:
    """Whether an angle given in degrees is likely a common angle typed in radians.

    The rule: ``0 < |a| < pi/2`` (a radian value of an angle below 90 deg), ``a`` not a
    multiple of 0.5 deg (the small angles people type in degrees: 0.5, 1, 1.5), and ``a``
    read as radians is a multiple of 5 deg, at least 5 deg: exactly (``math.radians(30)``
    passed on), or within 0.5 deg when ``a`` has at most 4 significant digits (typed in:
    0.52 or 0.5236 for 30 deg, 0.785 for 45 deg, 0.26 for 15 deg). A computed angle with
    more digits (a measured angle of attack, an ensemble's draw) is not flagged.

    Examples
    --------
    >>> [looks_like_radians(a) for a in (0.5236, 0.785, math.radians(30), 0.79056, 1.0, 30.0)]
    [True, True, True, False, False, False]
    """
    a = abs(angle_deg)
    if not 0.0 < a < 0.5 * math.pi or (2.0 * a).is_integer():
        return False
    deg = math.degrees(a)
    nearest = 5.0 * round(deg / 5.0)
    if nearest < 5.0:
        return False
    if abs(deg - nearest) < 1e-6:  # math.radians(30), np.deg2rad(45): converted in full
        return True
    typed = float(f"{a:.4g}") == a  # a value typed in: at most 4 significant digits
    return typed and abs(deg - nearest) <= 0.5


#: The data file of the ranges: one entry a quantity, with its valid range and kind, its
#: plausible range, unit and likely slip; the file's header gives the format and provenance.
LIMITS_FILE = Path(__file__).parent / "data" / "limits.yaml"

#: An interval of the data file: ``(`` / ``)`` exclude a bound, ``[`` / ``]`` include it.
_INTERVAL = re.compile(r"([\[(])\s*([^,\s]+)\s*,\s*([^,\s]+)\s*([\])])")
#: The fields an entry of :data:`LIMITS_FILE` may hold.
_FIELDS = (
    "label",
    "unit",
    "valid",
    "kind",
    "why",
    "group",
    "plausible",
    "below",
    "above",
    "valid_as",
    "valid_text",
)


def _bound(text: str, where: str) -> float:
    """A bound of an interval: an integer when written as one (a count), else a float
    in plain decimal (``inf`` allowed)."""
    if re.fullmatch(r"[+-]?[0-9]+", text):
        return int(text)
    v = decimal(text)
    if v is None or math.isnan(v):
        raise InputError(f"{where}: bound must be a number, got {brief(text)}")
    return v


def _interval(text: Any, where: str) -> tuple[float, float, bool, bool]:
    """``(lo, hi, lo_open, hi_open)`` of an interval such as ``"(0, 1e4]"``."""
    m = _INTERVAL.fullmatch(text) if isinstance(text, str) else None
    if m is None:
        raise InputError(f"{where} must be an interval such as '(0, 1e4]', got {brief(text)}")
    lo, hi = _bound(m[2], where), _bound(m[3], where)
    if not lo <= hi:
        raise InputError(f"{where}: the interval {brief(text)} is empty")
    return lo, hi, m[1] == "(", m[4] == ")"


def _text(entry: Mapping[str, Any], key: str, where: str, default: str = "") -> str:
    value = entry.get(key, default)
    if not isinstance(value, str):
        raise InputError(f"{where}: {key} must be text, got {brief(value)}")
    return value


def load_limits(
    path: str | os.PathLike[str] = LIMITS_FILE,
) -> tuple[dict[str, Limit], dict[str, Plausible]]:
    """The valid and the plausible ranges of the data file ``path`` (default
    :data:`LIMITS_FILE`, which gives :data:`LIMITS` and :data:`PLAUSIBLE`).

    Returns
    -------
    (dict of str to Limit, dict of str to Plausible)
        By key, in the file's order: the entries with a ``valid`` range, and those with a
        ``plausible`` one.

    Raises
    ------
    InputError
        An entry that is not in the format the file's header describes (named).
    """
    data = read_yaml(path, "limits")
    if not isinstance(data, dict):
        raise InputError(f"limits file {brief_path(path)} must map each quantity to its ranges")
    limits: dict[str, Limit] = {}
    plausibles: dict[str, Plausible] = {}
    for key, entry in data.items():
        where = f"limits file {brief_path(path)}, {key}"
        if not isinstance(entry, dict):
            raise InputError(f"{where} must be a mapping of {', '.join(_FIELDS)}")
        check_keys(entry, _FIELDS, where)
        label, unit = _text(entry, "label", where), _text(entry, "unit", where)
        if "valid" in entry:
            lo, hi, lo_open, hi_open = _interval(entry["valid"], f"{where}: valid")
            limits[key] = Limit(
                label,
                unit,
                lo,
                hi,
                lo_open,
                hi_open,
                kind=_text(entry, "kind", where, "physical"),
                why=_text(entry, "why", where),
                group=_text(entry, "group", where, "core"),
            )
        if "plausible" not in entry:
            continue
        rule = "radians" if entry["plausible"] == "radians" else "range"
        lo, hi = 0.0, math.inf
        if rule == "range":
            lo, hi, *_ = _interval(entry["plausible"], f"{where}: plausible")
        if "valid" in entry:
            valid = ""
        elif "valid_as" in entry:
            valid = limits[_text(entry, "valid_as", where)].describe()[3:]
        else:
            valid = _text(entry, "valid_text", where)
        plausibles[key] = Plausible(
            label,
            unit,
            lo,
            hi,
            below=_text(entry, "below", where),
            above=_text(entry, "above", where),
            rule=rule,
            valid=valid,
        )
    return limits, plausibles


#: The valid range of every quantity a user can give, by key: a :class:`Limit` each,
#: read from :data:`LIMITS_FILE`.
LIMITS: dict[str, Limit]
#: The plausible range of every quantity that carries a unit, by key (the keys of
#: :data:`LIMITS` where the quantity is one of them): a :class:`Plausible` each, read from
#: :data:`LIMITS_FILE`.
PLAUSIBLE: dict[str, Plausible]
LIMITS, PLAUSIBLE = load_limits()


#: Files of this package: a warning is reported at the first caller outside them.
_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def _caller_level() -> int:
    """The ``stacklevel`` of the first frame outside pencore (the user's call)."""
    frame, level = sys._getframe(2), 2
    while frame is not None and (
        frame.f_code.co_filename.startswith(_PACKAGE)
        or (frame.f_code.co_filename == "<string>" and frame.f_code.co_name == "__init__")
        or frame.f_code.co_filename == dataclasses.__file__
    ):  # a dataclass's generated __init__ is pencore's code too, and so is the
        # dataclasses.replace that pencore calls (Projectile.with_mass, numerics overrides)
        caller = frame.f_back
        if caller is not None and not isinstance(caller.f_globals.get("__name__"), str):
            # code run without a module name (a Snakefile): Python drops a warning
            # attributed to it, so it stays with pencore's frame
            return level
        frame, level = caller, level + 1
    return level


def plausible(value: float, key: str, what: str = "") -> bool:
    """Warn (:class:`~pencore.PlausibilityWarning`) when ``value`` is outside the
    plausible range ``PLAUSIBLE[key]``; True when it is within.

    The warning is one line naming the value, the plausible range and the likely slip;
    it never stops a run (unless a filter turns warnings into errors).

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     plausible(1.4, "velocity")
    False
    >>> print(w[0].message)
    velocity 1.4 m/s is implausible (plausible: [10, 5000] m/s): a speed in km/s given for m/s? (1.4 km/s = 1400 m/s)
    """  # noqa: E501
    p = PLAUSIBLE[key]
    v = float(value)
    if p.fits(v):
        return True
    where = f"{what}: " if what else ""
    unit = f" {p.unit}" if p.unit else ""
    warnings.warn(
        f"{where}{p.label} {v:g}{unit} is implausible (plausible: {p.describe()}): {p.slip(v)}",
        PlausibilityWarning,
        stacklevel=_caller_level(),
    )
    return False


@contextlib.contextmanager
def half_space_plates() -> Iterator[None]:
    """Within the block, a thin plate on the half-space law is intended (a study that
    compares the near-surface options with none): its ``"plate"`` warning is not given.
    Every other plausibility warning is."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", r".*: plate thickness ", PlausibilityWarning)
        yield


@contextlib.contextmanager
def one_line_warnings(prog: str = "pencore") -> Iterator[None]:
    """Within the block, print each :class:`~pencore.PlausibilityWarning` as one line,
    ``<prog>: warning: <message>``, on standard error (other warnings as before); the
    command line and the workflow show them so. Filters apply as always."""
    previous = warnings.showwarning

    def show(message, category, filename, lineno, file=None, line=None):  # noqa: ANN001, ANN202
        if not issubclass(category, PlausibilityWarning):
            return previous(message, category, filename, lineno, file, line)
        stream = sys.stderr if file is None else file
        try:
            print(f"{prog}: warning: {' '.join(str(message).split())}", file=stream)
        except (OSError, ValueError):  # no usable standard error: nothing to tell
            pass

    warnings.showwarning = show
    try:
        yield
    finally:
        warnings.showwarning = previous


def plausible_markdown() -> str:
    """A Markdown table of the plausible ranges (:data:`PLAUSIBLE`) beside the valid
    ones, with the slip each points to."""
    rows = [
        "| input | valid range | plausible range | likely slip outside it |",
        "|---|---|---|---|",
    ]
    for key, p in PLAUSIBLE.items():
        valid = p.valid or LIMITS[key].describe()[3:]
        slips = "; ".join(x.format(deg=30.0) if p.rule == "radians" else x for x in
                          (p.below, p.above) if x)  # fmt: skip
        rows.append(f"| `{key}` | {valid} | {p.describe()} | {slips} |")
    return "\n".join(rows)


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
