"""Named projectiles and targets, YAML loading, and the Table-3 geometry fit.

The named media and validation projectiles are data files read here
(``inputs/data/media.yaml``, ``inputs/data/projectiles.yaml``; the paper's p1..p4 are
built from ``inputs/data/table3_geometry.yaml``). Provenance of every shipped number is
recorded in its ``source`` string: ``paper`` (Li & Flores-Johnson 2011), ``derived``
(how), or ``assumed`` (why; to be replaced when the published value is at hand).
"""

from __future__ import annotations

import functools
import math
import os
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from pencore.errors import InputError, hint_keywords
from pencore.inputs.gate import brief, brief_path, read_yaml
from pencore.inputs.geometry import ConeNose, Cylinder, FlatNose, OgiveNose, Projectile
from pencore.inputs.laws import medium_from_law
from pencore.inputs.limits import check_keys, count, number
from pencore.inputs.target import Layer, Medium, Target

__all__ = [
    "MEDIA",
    "TABLE3",
    "Table3Fit",
    "table3_fit",
    "table3_mass_bound",
    "shipped_table3_geometry",
    "write_table3_geometry",
    "get_projectile",
    "get_target",
    "projectile_from_dict",
    "target_from_dict",
    "projectile_names",
    "target_names",
]


#: The folder of the library's data files (named media, validation projectiles, the
#: Table-3 geometry), each with its provenance.
LIBRARY_DATA = Path(__file__).parent / "data"

# ---------------------------------------------------------------- Table 3 and its fit

#: Paper Table 3: shank density (kg/m3), mass (kg), Lc/L; nose density 7850 kg/m3, CRH 3.
TABLE3: dict[str, tuple[float, float, float]] = {
    "p1": (4000.0, 19.1, 0.504),
    "p2": (5150.0, 23.1, 0.525),
    "p3": (7850.0, 32.8, 0.553),
    "p4": (11340.0, 45.3, 0.571),
}
TABLE3_NOSE_DENSITY = 7850.0
TABLE3_CRH = 3.0


@dataclass(frozen=True)
class Table3Fit:
    """Least-squares fit of a solid CRH-3 ogive + solid cylinder to Table 3.

    ``diameter`` and ``shank_length`` in m; ``residuals`` maps each projectile to
    (model mass - table mass in kg, model Lc/L - table Lc/L).
    """

    diameter: float
    shank_length: float
    residuals: dict[str, tuple[float, float]]

    def worst_scaled(self) -> float:
        """Largest residual in units of the table's rounding (0.05 kg, 0.0005 in Lc/L);
        <= 1 means every number is reproduced to its rounding."""
        return max(max(abs(dm) / 0.05, abs(dl) / 0.0005) for dm, dl in self.residuals.values())

    def report(self) -> str:
        """The fit and its residuals as text, one line per projectile."""
        lines = [
            f"Table 3 fit: diameter = {self.diameter * 1e3:.2f} mm, "
            f"shank length = {self.shank_length * 1e3:.1f} mm, "
            f"nose length = {_ogive_len(self.diameter) * 1e3:.1f} mm",
            "projectile  mass_residual_kg  LcL_residual",
        ]
        for k, (dm, dl) in self.residuals.items():
            lines.append(f"{k:10s}  {dm:+.4f}            {dl:+.5f}")
        lines.append(
            f"worst residual = {self.worst_scaled():.3f} x rounding; no fixed geometry can "
            f"fit the four masses better than {table3_mass_bound():.4f} kg "
            f"= {table3_mass_bound() / 0.05:.3f} x rounding (mass is affine in shank density)"
        )
        return "\n".join(lines)


def _ogive_len(d: float) -> float:
    return 0.5 * d * math.sqrt(4 * TABLE3_CRH - 1)


def _table3_projectile(key: str, d: float, ls: float, source: str = "") -> Projectile:
    rho_shank = TABLE3[key][0]
    return Projectile(
        key,
        d,
        OgiveNose(TABLE3_CRH, TABLE3_NOSE_DENSITY),
        (Cylinder(ls, rho_shank),),
        source=source,
    )


def table3_mass_bound() -> float:
    """Smallest possible largest mass residual (kg) of ANY fixed geometry.

    For a fixed body the mass is affine in the shank density, ``m = m_nose + rho V_shank``,
    so the four Table-3 masses can be fitted no better than the minimax straight line
    through (shank density, mass). That bound is 0.0525 kg, just above the table's
    rounding (0.05 kg): the table is not exactly self-consistent.
    """
    from scipy.optimize import linprog

    rows_ub: list[list[float]] = []
    rhs_ub: list[float] = []
    for rho, m, _ in TABLE3.values():
        rows_ub += [[-1.0, -rho, -1.0], [1.0, rho, -1.0]]
        rhs_ub += [-m, m]
    sol = linprog([0, 0, 1], A_ub=rows_ub, b_ub=rhs_ub, bounds=[(None, None)] * 3)
    return float(sol.x[2])


@functools.cache
def table3_fit() -> Table3Fit:
    """Fit the diameter and shank length to the eight numbers of Table 3.

    Minimax fit of the residuals scaled by the table's rounding (0.05 kg, 0.0005 in Lc/L):
    the geometry whose worst number is closest to its stated value. Started from the
    least-squares solution. See :func:`pencore.inputs.library.table3_mass_bound` for why
    no geometry reaches the rounding exactly. The library's ``p1``..``p4`` use the shipped
    result of this fit.

    Returns
    -------
    pencore.inputs.library.Table3Fit
        ``diameter`` and ``shank_length`` (m) and the residuals of each projectile.

    Examples
    --------
    >>> import pencore
    >>> fit = pencore.table3_fit()
    >>> print(f"d = {fit.diameter * 1e3:.2f} mm, shank {fit.shank_length * 1e3:.1f} mm")
    d = 94.97 mm, shank 503.5 mm
    """
    from scipy.optimize import least_squares, minimize

    def resid(p: np.ndarray) -> np.ndarray:
        d, ls = p
        out = []
        for key, (_, m, lcl) in TABLE3.items():
            mp = _table3_projectile(key, d, ls).mass_properties()
            out += [(mp.mass - m) / 0.05, (mp.lc_over_l - lcl) / 0.0005]
        return np.asarray(out)

    ls_sol = least_squares(resid, x0=[0.095, 0.5], x_scale=[0.01, 0.05], xtol=1e-14, ftol=1e-14)
    mm = minimize(
        lambda p: float(np.max(np.abs(resid(p)))),
        ls_sol.x,
        method="Nelder-Mead",
        options={"xatol": 1e-10, "fatol": 1e-10, "maxiter": 4000},
    )
    d, ls = (float(x) for x in mm.x)
    res = {}
    for key, (_, m, lcl) in TABLE3.items():
        mp = _table3_projectile(key, d, ls).mass_properties()
        res[key] = (mp.mass - m, mp.lc_over_l - lcl)
    return Table3Fit(d, ls, res)


# ---------------------------------------------------------------- named projectiles


def _validation_projectiles(
    path: Path = LIBRARY_DATA / "projectiles.yaml",
) -> dict[str, Projectile]:
    """The validation projectiles of the data file ``path`` (the projectile format; a
    ``derivation`` key says how a number the source does not print was obtained)."""
    data = _load_yaml(path, "projectile library")
    out: dict[str, Projectile] = {}
    for name, entry in data.items():
        entry = _mapping(entry, f"projectile library entry {brief(name)}")
        fields = {k: v for k, v in entry.items() if k != "derivation"}
        fields["source"] = " ".join(str(fields.get("source", "")).split())
        out[name] = projectile_from_dict({"name": name, **fields})
    return out


#: The fitted Table-3 geometry as shipped (derived data, provenance in the file).
TABLE3_GEOMETRY_FILE = Path(__file__).parent / "data" / "table3_geometry.yaml"


def shipped_table3_geometry(path: str | Path = TABLE3_GEOMETRY_FILE) -> tuple[float, float]:
    """Diameter and shank length (m) of projectiles #1-#4 from the shipped file.

    They are :func:`table3_fit`'s result written out by ``pencore fit-table3 --write``,
    so that the named projectiles do not depend on an optimiser run in every process.
    """
    data = _load_yaml(Path(path), "Table-3 geometry")
    check_keys(data, ["diameter_m", "shank_length_m"], str(path))
    return (
        _num(data, "diameter_m", str(path), "diameter", allow_str=False),
        _num(data, "shank_length_m", str(path), "length", allow_str=False),
    )


def write_table3_geometry(fit: Table3Fit, path: str | Path = TABLE3_GEOMETRY_FILE) -> None:
    """Write ``fit``'s diameter and shank length (m) to ``path`` atomically, with the
    provenance header that :data:`TABLE3_GEOMETRY_FILE` carries."""
    from pencore.io.atomic import atomic_write_text
    from pencore.io.outputs import YAML_SUFFIXES

    header = [ln for ln in TABLE3_GEOMETRY_FILE.read_text().splitlines() if ln.startswith("#")]
    text = "\n".join(
        [*header, f"diameter_m: {fit.diameter!r}", f"shank_length_m: {fit.shank_length!r}", ""]
    )
    atomic_write_text(path, text, suffixes=YAML_SUFFIXES)


@functools.cache
def _named_projectiles() -> dict[str, Projectile]:
    d, ls = shipped_table3_geometry()
    out = {
        key: _table3_projectile(
            key,
            d,
            ls,
            source=f"paper Table 3 (mass, shank density, Lc/L); geometry derived by "
            f"pencore.inputs.library.table3_fit: d={d:.5f} m, shank={ls:.5f} m",
        )
        for key in TABLE3
    }
    out.update(_validation_projectiles())
    return out


def projectile_names() -> list[str]:
    """The names of the library's projectiles (``pencore list`` shows their provenance).

    Returns
    -------
    list of str
        Sorted: the paper's ``p1``..``p4`` (Table 3) and the validation projectiles.

    Examples
    --------
    >>> import pencore
    >>> [name for name in pencore.projectile_names() if name.startswith("p")]
    ['p1', 'p2', 'p3', 'p4']
    """
    return sorted(_named_projectiles())


def target_names() -> list[str]:
    """The names of the library's targets (semi-infinite, one medium each).

    Returns
    -------
    list of str
        Sorted; the paper's Table 1 media and the validation targets.

    Examples
    --------
    >>> import pencore
    >>> pencore.target_names()
    ['aluminium', 'aluminium_3term', 'aluminium_cavity', 'concrete', 'soil']
    """
    return sorted(MEDIA)


# ---------------------------------------------------------------- YAML


def _num(
    d: dict[str, Any], key: str, what: str, limit: str | None = None, allow_str: bool = True
) -> float:
    """``d[key]`` as a number within ``LIMITS[limit or key]`` (YAML's ``1e6`` string
    form accepted unless ``allow_str`` is False)."""
    if key not in d:
        raise InputError(f"{what}: missing key {brief(key)}")
    # the object built from it (Projectile, Medium, Layer) judges its plausibility, once
    return number(d[key], limit or key, what, allow_str=allow_str, plausibility=False)


def _mapping(x: Any, what: str) -> dict[str, Any]:
    if not isinstance(x, dict):
        raise InputError(f"{what} must be a mapping, got {brief(x)}")
    return x


_NOSE_KEYS = {
    "ogive": ("kind", "crh", "density"),
    "cone": ("kind", "half_angle_deg", "density"),
    "flat": ("kind", "density"),
}


def projectile_from_dict(d: dict[str, Any]) -> Projectile:
    """Build a projectile from a mapping (the YAML format of the user guide's inputs page).

    Besides the outline (``diameter``, ``nose``, ``shank``), a mapping may give measured
    ``mass`` (kg), ``centre_of_mass`` (tip distance Lc, m) and
    ``inertia: {axial: ..., transverse: ...}`` (kg m^2, about the centre of mass); see
    :class:`~pencore.Projectile` for what is derived from the outline when they are not.

    Unknown keys, booleans or text where numbers belong, and values outside
    :data:`pencore.inputs.limits.LIMITS` raise :class:`~pencore.InputError` naming the key and
    value.
    """
    if not isinstance(d, dict):
        raise InputError(f"projectile definition must be a mapping, got {type(d).__name__}")
    name = str(d.get("name", "projectile"))
    what = f"projectile {brief(name)}"
    check_keys(
        d,
        (
            "name",
            "diameter",
            "nose",
            "shank",
            "source",
            "mass",
            "centre_of_mass",
            "inertia",
            "yield_strength",
        ),
        what,
    )
    diameter = _num(d, "diameter", what)
    nd = d.get("nose")
    if not isinstance(nd, dict):
        raise InputError(f"{what}: 'nose' must be a mapping with a 'kind', got {brief(nd)}")
    kind = nd.get("kind", "ogive")
    kind = kind.lower() if isinstance(kind, str) else kind
    if not isinstance(kind, str) or kind not in _NOSE_KEYS:
        raise InputError(f"{what}: nose kind must be ogive, cone or flat, got {brief(kind)}")
    check_keys(nd, _NOSE_KEYS[kind], f"{what} nose")
    rho = _num(nd, "density", what + " nose")
    if kind == "ogive":
        nose: OgiveNose | ConeNose | FlatNose = OgiveNose(_num(nd, "crh", what + " nose"), rho)
    elif kind == "cone":
        nose = ConeNose(math.radians(_num(nd, "half_angle_deg", what + " nose")), rho)
    else:
        nose = FlatNose(rho)
    shank = d.get("shank", [])
    if isinstance(shank, dict):
        shank = [shank]
    if not isinstance(shank, list) or not all(isinstance(c, dict) for c in shank):
        raise InputError(
            f"{what}: 'shank' must be a list of mappings with length and density, "
            f"got {brief(shank)}"
        )
    count(shank, "shank_segments", what)
    cyl = []
    for k, c in enumerate(shank):
        w = f"{what} shank segment {k}"
        check_keys(c, ("length", "density"), w)
        cyl.append(Cylinder(_num(c, "length", w), _num(c, "density", w)))
    given: dict[str, Any] = {}
    if "mass" in d:
        given["mass"] = _num(d, "mass", what)
    if "centre_of_mass" in d:
        given["centre_of_mass"] = _num(d, "centre_of_mass", what)
    if "yield_strength" in d:
        given["yield_strength"] = _num(d, "yield_strength", what)
    if "inertia" in d:
        inertia = d["inertia"]
        if not isinstance(inertia, dict):
            raise InputError(
                f"{what}: 'inertia' must be a mapping {{axial: ..., transverse: ...}} in "
                f"kg m^2, got {brief(inertia)}"
            )
        check_keys(inertia, ("axial", "transverse"), f"{what} inertia")
        given["inertia"] = tuple(
            _num(inertia, k, f"{what} inertia", "inertia") for k in ("axial", "transverse")
        )
    p = Projectile(
        name, diameter, nose, tuple(cyl), source=str(d.get("source", "user file")), **given
    )
    p.mass_properties()  # a body with no volume fails here, not later in a run
    return p


_MEDIUM_KEYS = (
    "name",
    "coefficients",
    "friction",
    "density",
    "source",
    "crater_depth",
    "free_surface_depth",
    "plastic_zone_ratio",
)
#: Depth-window keys (calibers) a layer may set on a named medium.
_WINDOW_KEYS = ("crater_depth", "free_surface_depth", "plastic_zone_ratio")


def _medium_from(x: Any, what: str) -> Medium:
    if isinstance(x, str):
        if x not in MEDIA:
            raise InputError(f"{what}: unknown medium {brief(x)}; known: {', '.join(MEDIA)}")
        return MEDIA[x]
    if not isinstance(x, dict):
        raise InputError(f"{what}: medium must be a name or a mapping, got {brief(x)}")
    name = str(x.get("name", "medium"))
    w = f"{what} medium {brief(name)}"
    if "law" in x:  # a law from material properties (pencore.inputs.laws)
        return medium_from_law(x, w)
    check_keys(x, _MEDIUM_KEYS, w)
    coef = x.get("coefficients")
    if not isinstance(coef, list | tuple) or not coef:
        raise InputError(f"{w}: needs a list 'coefficients' [a0, a1, a2, ...], got {brief(coef)}")
    coef_f = tuple(
        number(c, "coefficient", f"{w} a{i}", allow_str=True) for i, c in enumerate(coef)
    )
    fr = x.get("friction", 0.0)
    if isinstance(fr, list | tuple):
        if not fr or not all(isinstance(r, list | tuple) and len(r) == 2 for r in fr):
            raise InputError(f"{w}: friction table must be [[speed_m_s, mu], ...], got {brief(fr)}")
        count(fr, "friction_rows", w)
        sp = tuple(number(r[0], "friction_speed", w, allow_str=True) for r in fr)
        mu = tuple(number(r[1], "friction", w, allow_str=True) for r in fr)
    else:
        sp, mu = (0.0,), (number(fr, "friction", w, allow_str=True),)
    rho = _num(x, "density", w, "medium_density") if "density" in x else math.nan
    windows = {k: _num(x, k, w) for k in _WINDOW_KEYS if k in x}
    return Medium(name, coef_f, sp, mu, rho, str(x.get("source", "user file")), **windows)


def target_from_dict(d: dict[str, Any]) -> Target:
    """Build a target from a mapping: either a single medium or ``layers``.

    A layer is ``{medium: ..., thickness: ...}`` (no ``thickness``: semi-infinite, last
    layer only) or an air gap ``{gap: thickness}`` between two layers of a medium. A
    finite last layer makes a plate that can be perforated. Unknown keys and values
    outside :data:`pencore.inputs.limits.LIMITS` raise :class:`~pencore.InputError`.
    """
    if not isinstance(d, dict):
        raise InputError(f"target definition must be a mapping, got {type(d).__name__}")
    name = str(d.get("name", "target"))
    what = f"target {brief(name)}"
    if "layers" not in d:
        return Target(name, (Layer(_medium_from(d, what)),))
    check_keys(d, ("name", "layers", "source"), what)
    if not isinstance(d["layers"], list) or not d["layers"]:
        raise InputError(f"{what}: 'layers' must be a non-empty list, got {brief(d['layers'])}")
    count(d["layers"], "layers", what)
    layers = []
    for k, lay in enumerate(d["layers"]):
        w = f"{what} layer {k}"
        lay = _mapping(lay, w)
        if "gap" in lay:
            check_keys(lay, ("gap",), w)
            layers.append(Layer.gap(_num(lay, "gap", w, "thickness")))
            continue
        check_keys(lay, ("thickness", "medium", "gap", *_WINDOW_KEYS), w)
        if "medium" not in lay:
            raise InputError(f"{w}: needs a 'medium' (a name or a mapping)")
        th = _num(lay, "thickness", w) if "thickness" in lay else math.inf
        medium = _medium_from(lay["medium"], w)
        windows = {k: _num(lay, k, w) for k in _WINDOW_KEYS if k in lay}
        layers.append(Layer(replace(medium, **windows) if windows else medium, th))
    return Target(name, tuple(layers))


def _load_yaml(path: Path, what: str) -> dict[str, Any]:
    """The mapping in the YAML file ``path``, read through the input gate
    (:func:`pencore.inputs.gate.read_yaml`: regular files only, bounded size, depth and
    alias expansion, no repeated keys)."""
    data = read_yaml(path, what)
    if not isinstance(data, dict):
        raise InputError(f"{what} file {brief_path(path)} must contain a mapping")
    return data


def _load_media(path: Path = LIBRARY_DATA / "media.yaml") -> dict[str, Medium]:
    """The named media of the data file ``path``: coefficients, density and source of
    each (its ``law`` parameters are provenance, checked against the coefficients by the
    tests)."""
    data = _load_yaml(path, "media library")
    out: dict[str, Medium] = {}
    for name, entry in data.items():
        w = f"media library entry {brief(name)}"
        entry = _mapping(entry, w)
        check_keys(entry, ("coefficients", "density", "law", "source"), w)
        coef = entry.get("coefficients")
        if not isinstance(coef, list) or not coef:
            raise InputError(f"{w}: needs a list 'coefficients', got {brief(coef)}")
        out[name] = Medium(
            name,
            tuple(number(c, "coefficient", w, allow_str=True) for c in coef),
            density=_num(entry, "density", w, "medium_density"),
            source=" ".join(str(entry.get("source", "")).split()),
        )
    return out


#: The named media (paper Table 1 and its aluminium source's three-term law), read from
#: ``inputs/data/media.yaml``.
MEDIA: dict[str, Medium] = _load_media()


def _from_yaml_file(spec: str, what: str, build: Any) -> Any:
    """Load a YAML file and build from it; errors name the file."""
    data = _load_yaml(Path(spec), what)
    try:
        return build(data)
    except InputError as exc:
        raise InputError(f"{what} file {brief_path(spec)}: {exc}") from None


def _looks_like_path(s: str) -> bool:
    """Whether ``s`` names a YAML file: it ends in .yaml/.yml, holds a ``/``, or is an
    existing file (a name the system cannot even look up, e.g. longer than the file
    system allows, is not one)."""
    if s.endswith((".yaml", ".yml")) or "/" in s:
        return True
    try:
        return Path(s).is_file()
    except (OSError, ValueError):  # ENAMETOOLONG, ELOOP, an embedded NUL
        return False


def get_projectile(spec: str | Projectile | dict[str, Any]) -> Projectile:
    """A projectile by name, YAML file, mapping or object.

    Parameters
    ----------
    spec : str, path-like, dict or Projectile
        A library name (:func:`~pencore.projectile_names`: ``p1``..``p4`` of the paper's
        Table 3, the validation projectiles), the path of a YAML file, a mapping in that
        file's format (the user guide's Inputs page), or a :class:`~pencore.Projectile`
        (returned as it is).

    Returns
    -------
    Projectile

    Raises
    ------
    InputError
        An unknown name (the message lists the names), a file that cannot be read or
        parsed, an unknown key, or a value of the wrong type or out of its range (the
        one-line message names it).

    Examples
    --------
    >>> import pencore
    >>> p2 = pencore.get_projectile("p2")
    >>> print(f"{p2.diameter * 1e3:.2f} mm, {p2.mass_properties().mass:.2f} kg")
    94.97 mm, 23.16 kg
    >>> mine = pencore.get_projectile({
    ...     "name": "mine", "diameter": 0.03,
    ...     "nose": {"kind": "ogive", "crh": 3.0, "density": 7850.0},
    ...     "shank": [{"length": 0.2, "density": 7850.0}],
    ... })
    >>> mine.nose
    OgiveNose(crh=3.0, density=7850.0)
    >>> pencore.get_projectile("p9")
    Traceback (most recent call last):
    ...
    pencore.errors.InputError: unknown projectile 'p9'; use one of ... or a YAML file
    """
    if isinstance(spec, Projectile):
        return spec
    if isinstance(spec, dict):
        return projectile_from_dict(spec)
    if isinstance(spec, os.PathLike):  # a pathlib.Path: always a file
        return _from_yaml_file(os.fspath(spec), "projectile", projectile_from_dict)
    if not isinstance(spec, str):
        raise InputError(
            f"projectile must be a name, a YAML file, a mapping or a Projectile, got {brief(spec)}"
        )
    named = _named_projectiles()
    if spec in named:
        return named[spec]
    if _looks_like_path(spec):
        return _from_yaml_file(spec, "projectile", projectile_from_dict)
    raise InputError(
        f"unknown projectile {brief(spec)}; use one of {', '.join(sorted(named))} or a YAML file"
    )


def get_target(spec: str | Target | Medium | dict[str, Any]) -> Target:
    """A target by name, YAML file, mapping or object.

    Parameters
    ----------
    spec : str, path-like, dict, Target or Medium
        A library name (:func:`~pencore.target_names`: ``soil``, ``concrete``,
        ``aluminium``...), the path of a YAML file, a mapping in that file's format (the
        user guide's Inputs page), a :class:`~pencore.Target` (returned as it is) or a
        :class:`~pencore.Medium` (the half-space of it).

    Returns
    -------
    Target

    Raises
    ------
    InputError
        An unknown name (the message lists the names), a file that cannot be read or
        parsed, an unknown key, or a value of the wrong type or out of its range.

    Examples
    --------
    >>> import pencore
    >>> soil = pencore.get_target("soil")
    >>> print(soil.medium.coefficients, soil.finite)
    (17180000.0, 0.0, 4119.9) False
    >>> pencore.get_target("mud")
    Traceback (most recent call last):
    ...
    pencore.errors.InputError: unknown target 'mud'; use one of soil, concrete, ... or a YAML file
    """
    if isinstance(spec, Target):
        return spec
    if isinstance(spec, Medium):
        return Target.half_space(spec)
    if isinstance(spec, dict):
        return target_from_dict(spec)
    if isinstance(spec, os.PathLike):  # a pathlib.Path: always a file
        return _from_yaml_file(os.fspath(spec), "target", target_from_dict)
    if not isinstance(spec, str):
        raise InputError(
            f"target must be a name, a YAML file, a mapping or a Target, got {brief(spec)}"
        )
    if spec in MEDIA:
        return Target.half_space(MEDIA[spec])
    if _looks_like_path(spec):
        return _from_yaml_file(spec, "target", target_from_dict)
    raise InputError(f"unknown target {brief(spec)}; use one of {', '.join(MEDIA)} or a YAML file")


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
