"""Input checking: the valid range of every quantity a user gives pencore, and strict
readers for numbers, integers and mappings.

Text is read as a number only where a reader allows it (YAML files, mappings of a
projectile or target, the command line) and only in the input gate's plain decimal
notation (:data:`pencore.inputs.gate.DECIMAL`); the ranges then judge the value like any
other (only a range that reaches infinity, such as ``max_wall``'s, admits ``inf``).

Every user-facing entry point (the API, YAML files, the CLI) checks its inputs here, so
a bad value stops with one :class:`~pencore.InputError` whose message names the value, its unit
and what is allowed, before any computation.

Each range in :data:`~pencore.inputs.limits.LIMITS` is of one of two kinds:

``physical``
    the model means nothing outside it (a negative diameter, CRH < 0.5, an obliquity of
    90 deg or more, a negative resistance coefficient);
``guard``
    the model could be evaluated, but a value this far out is almost certainly a typo
    (a 10 km/s impact, a 100-m diameter, a 1000-s run); the bound is generous and says so.

The docs' table of valid ranges (user guide, "Projectiles, targets and numerics") is
generated from :data:`~pencore.inputs.limits.LIMITS` by :func:`limits_markdown` at every build.
"""

from __future__ import annotations

import difflib
import math
import numbers
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from typing import Any

from pencore.errors import InputError
from pencore.inputs.gate import DECIMAL_WORDS, brief, decimal

__all__ = [
    "Limit",
    "LIMITS",
    "count",
    "number",
    "as_float",
    "integer",
    "check_keys",
    "limits_markdown",
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


_INF = math.inf
#: Densest element at room conditions: osmium, 22 590 kg/m^3.
_RHO_MAX = 23_000.0

#: The valid range of every quantity a user can give, by key: a :class:`Limit` each.
LIMITS: dict[str, Limit] = {
    # impact
    "velocity": Limit(
        "velocity",
        "m/s",
        0.0,
        1e4,
        lo_open=True,
        kind="physical / guard",
        why="> 0; above 10 km/s the rigid-body DAFL does not apply (typo guard)",
    ),
    "obliquity": Limit(
        "obliquity", "deg", -90.0, 90.0, True, True, why="the axis must point into the target"
    ),
    "yaw": Limit(
        "yaw",
        "deg",
        -90.0,
        90.0,
        True,
        True,
        why="abs(obliquity + yaw) < 90 deg: the velocity must point into the target",
    ),
    "omega": Limit("omega", "rad/s", -1e4, 1e4, kind="guard", why="typo guard"),
    "azimuth": Limit("azimuth", "deg", -360.0, 360.0, kind="guard", why="one turn either way"),
    "start": Limit(
        "start coordinate",
        "m",
        -1e3,
        1e3,
        kind="guard",
        why="typo guard; the start must also reach the target within t_max",
    ),
    # projectile
    "diameter": Limit("diameter", "m", 1e-4, 10.0, kind="guard", why="0.1 mm to 10 m"),
    "length": Limit(
        "segment length",
        "m",
        0.0,
        100.0,
        lo_open=True,
        kind="physical / guard",
        why="> 0; 100 m is a typo guard",
    ),
    "density": Limit(
        "density",
        "kg/m^3",
        0.0,
        _RHO_MAX,
        lo_open=True,
        why="> 0 and at most osmium's 22 590 kg/m^3",
    ),
    "crh": Limit(
        "ogive CRH",
        "",
        0.5,
        100.0,
        kind="physical / guard",
        why="0.5 is the hemisphere; above 100 the nose is > 20 m per m of diameter",
    ),
    "half_angle_deg": Limit(
        "cone half-angle", "deg", 0.0, 90.0, True, True, why="a cone must close"
    ),
    "mass": Limit(
        "mass",
        "kg",
        0.0,
        1e5,
        lo_open=True,
        kind="physical / guard",
        why="> 0 (measured mass); 100 t is a typo guard; also at most the outline full of osmium",
    ),
    "centre_of_mass": Limit(
        "centre of mass (tip distance Lc)",
        "m",
        0.0,
        100.0,
        lo_open=True,
        kind="physical / guard",
        why="> 0 and inside the body's length",
    ),
    "inertia": Limit(
        "moment of inertia",
        "kg m^2",
        0.0,
        1e6,
        lo_open=True,
        kind="physical / guard",
        why="> 0; a body of revolution also has I_axial <= m a^2 and I_axial <= 2 I_transverse",
    ),
    # target
    "coefficient": Limit(
        "resistance coefficient",
        "SI",
        0.0,
        1e12,
        kind="physical / guard",
        why=">= 0 (the stress must resist); 1e12 is a typo guard",
    ),
    "friction": Limit(
        "friction coefficient",
        "",
        0.0,
        2.0,
        kind="physical / guard",
        why=">= 0; above 2 is a typo guard",
    ),
    "friction_speed": Limit(
        "friction table speed", "m/s", 0.0, 1e4, kind="physical / guard", why=">= 0, increasing"
    ),
    "thickness": Limit(
        "layer thickness",
        "m",
        0.0,
        1e4,
        lo_open=True,
        kind="physical / guard",
        why="> 0; leave it out for a semi-infinite last layer",
    ),
    "crater_depth": Limit(
        "crater depth",
        "calibers",
        0.0,
        100.0,
        kind="physical / guard",
        why=">= 0 (0: off); Forrestal's crater region (F = c z), k = 2 there",
    ),
    "free_surface_depth": Limit(
        "free-surface depth",
        "calibers",
        0.0,
        100.0,
        kind="physical / guard",
        why=">= 0 (0: off); resistance ramp next to a free face",
    ),
    "plastic_zone_ratio": Limit(
        "plastic-zone ratio",
        "",
        0.0,
        1e3,
        kind="physical / guard",
        why="0 (off) or > 1: plastic-zone over cavity radius, (E / (3 (1 - nu) Y))^(1/3)",
    ),
    # laws from material properties (pencore.inputs.laws)
    "fc": Limit(
        "unconfined compressive strength fc",
        "Pa",
        1e6,
        5e8,
        kind="physical / guard",
        why="in Pa (40 MPa is 4e7); below 1 MPa is no concrete, above 500 MPa a typo guard",
    ),
    "s_factor": Limit(
        "Forrestal's S",
        "",
        0.0,
        1e3,
        lo_open=True,
        kind="physical / guard",
        why="> 0 (the static resistance is S fc); 1000 is a typo guard",
    ),
    "youngs_modulus": Limit(
        "Young's modulus E",
        "Pa",
        1e8,
        1e12,
        kind="guard",
        why="in Pa (69 GPa is 6.9e10): 0.1 GPa to 1000 GPa",
    ),
    "poisson_ratio": Limit("Poisson's ratio", "", 0.0, 0.5, why="0 to 1/2 (1/2: incompressible)"),
    "yield_strength": Limit(
        "yield strength Y",
        "Pa",
        1e5,
        1e10,
        kind="guard",
        why="in Pa (276 MPa is 2.76e8): 0.1 MPa to 10 GPa",
    ),
    "hardening_exponent": Limit(
        "hardening exponent n",
        "",
        0.0,
        1.0,
        hi_open=True,
        why="0 (elastic-perfectly plastic) to below 1 (1 would be linear elastic)",
    ),
    "soil_factor": Limit(
        "Forrestal-Luk factor",
        "",
        0.0,
        1e3,
        lo_open=True,
        kind="physical / guard",
        why="> 0 (A or B of A tau0 + B rho Vn^2); 1000 is a typo guard",
    ),
    "shear_strength": Limit(
        "shear strength tau0",
        "Pa",
        0.0,
        1e9,
        lo_open=True,
        kind="physical / guard",
        why="> 0, in Pa (10 MPa is 1e7); 1 GPa is a typo guard",
    ),
    "medium_density": Limit(
        "medium density", "kg/m^3", 0.0, _RHO_MAX, lo_open=True, why="> 0 (for reference only)"
    ),
    # numerics
    "n_nose": Limit("n_nose", "", 1, 10_000, kind="physical / guard", why="rings on the nose"),
    "n_shank": Limit("n_shank", "", 1, 10_000, kind="physical / guard", why="rings per 5 calibres"),
    "n_face": Limit("n_face", "", 1, 1_000, kind="physical / guard", why="rings per flat face"),
    "eps": Limit(
        "eps",
        "m/s",
        0.0,
        0.1,
        kind="physical / guard",
        why="0 is the pure step (may fail as chatter); at most the default v_stop "
        "(1 m/s) over 10, so that every eps in range runs with the default v_stop",
    ),
    "rtol": Limit("rtol", "", 1e-12, 0.1, kind="guard", why="round-off to 10 %"),
    "max_travel": Limit(
        "max_travel",
        "m",
        0.0,
        10.0,
        lo_open=True,
        kind="physical / guard",
        why="> 0; largest move per step",
    ),
    "v_stop": Limit("v_stop", "m/s", 0.0, 1e3, lo_open=True, kind="physical / guard", why="> 0"),
    "t_max": Limit(
        "t_max",
        "s",
        0.0,
        100.0,
        lo_open=True,
        kind="physical / guard",
        why="> 0; a penetration lasts milliseconds to a second",
    ),
    "max_steps": Limit("max_steps", "", 1, 1e9, kind="physical / guard", why="step budget"),
    "max_wall": Limit("max_wall", "s", 0.0, _INF, lo_open=True, why="wall-time budget"),
    "h_min": Limit(
        "h_min",
        "s",
        0.0,
        1e-3,
        lo_open=True,
        kind="physical / guard",
        why="smallest step before the run fails as stiff or chattering",
    ),
    "n_gauss": Limit(
        "n_gauss", "", 1, 64, kind="physical / guard", why="Gauss points per friction arc"
    ),
    "jacobian_age": Limit(
        "jacobian_age",
        "",
        1,
        1000,
        kind="physical / guard",
        why="accepted steps a Jacobian is held for (1: every step)",
    ),
    "gravity": Limit(
        "gravity",
        "m/s^2",
        0.0,
        1e3,
        kind="physical / guard",
        why=">= 0 along -y; 100 g is a typo guard",
    ),
    # counts: how many of a thing an input may hold, so that every parse and every
    # plan is decided in seconds (benchmarks/bench_parse.py measures the largest)
    "layers": Limit(
        "number of layers",
        "",
        1,
        1_000,
        kind="physical / guard",
        why="layers and gaps of a target; real targets have a few (guard)",
    ),
    "shank_segments": Limit(
        "number of shank segments",
        "",
        0,
        1_000,
        kind="guard",
        why="cylindrical segments of a projectile; real bodies have a few (guard)",
    ),
    "friction_rows": Limit(
        "friction table rows",
        "",
        1,
        10_000,
        kind="physical / guard",
        why="(speed, mu) rows of a friction table; 10 000 is 1 m/s steps to 10 km/s",
    ),
    "n_samples": Limit(
        "ensemble n_samples",
        "",
        1,
        1_000_000,
        kind="physical / guard",
        why="impacts of an ensemble case: 10^6 runs are hours of CPU (guard)",
    ),
    "n_chunks": Limit(
        "ensemble n_chunks",
        "",
        1,
        1_000,
        kind="physical / guard",
        why="jobs an ensemble case is split into (at most n_samples); each is a "
        "Snakemake job, planned before the first runs",
    ),
    # shank contact models and paper-emulation numerics (pencore.inputs.models)
    "shank_factor": Limit(
        "shank load factor",
        "",
        0.0,
        10.0,
        kind="physical / guard",
        why=">= 0 (0 removes the shank load); above 10 is a typo guard",
        group="models",
    ),
    "delta_ref": Limit(
        "cavity delta_ref",
        "m",
        0.0,
        1.0,
        lo_open=True,
        kind="physical / guard",
        why="> 0 (wall intrusion at full load); 1 m is a typo guard",
        group="models",
    ),
    "n_phi": Limit(
        "cavity n_phi",
        "",
        8,
        4096,
        kind="physical / guard",
        why="quadrature points around a shank ring (cavity model on rings)",
        group="models",
    ),
    "n_circumferential": Limit(
        "n_circumferential",
        "",
        3,
        10_000,
        kind="physical / guard",
        why="flat panels around the body (3 is the coarsest closed facet ring)",
        group="models",
    ),
    "dt": Limit(
        "explicit dt",
        "s",
        0.0,
        1e-3,
        lo_open=True,
        kind="physical / guard",
        why="> 0; fixed step of the explicit integrator",
        group="models",
    ),
    "start_height": Limit(
        "start height",
        "m",
        0.0,
        100.0,
        kind="physical / guard",
        why=">= 0 (0: touching); tip height of the attribution's normal impacts",
        group="models",
    ),
}


def _type_name(value: Any) -> str:
    return type(value).__name__


def number(
    value: Any, key: str, what: str = "", *, allow_str: bool = False, label: str = ""
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
