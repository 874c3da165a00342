"""The public compilation of concrete shots as data, and its cleaning in one place.

``concrete_compilation.csv`` (shipped in ``pencore/measured/data/``; ``config/`` links to
it) holds every row of a public compilation of normal-impact, ogive-nose shots into
concrete (its header names the source, its commit and the row mapping): the compilation's
``row`` (its "Number") and ``xlsx_row``, a ``set`` (one reference, rod and target), the
compiler's ``reference_key``, the ``reference_number`` and full ``reference`` of its
reference list, every input in SI units, the ``raw_cells`` that are text where a number
belongs, a ``series`` (a geometrically scaled series the row belongs to), and the
``status`` (``clean`` or ``set_aside``) with its ``reason`` codes (:data:`REASONS`) and,
for a duplicate, the row it repeats (``same_shot_as``). The clean rows are a body shot
table (:data:`pencore.measured.shots.BODY_SHOT_COLUMNS`): the body shot reader gives
only them.

The cleaning (:func:`clean`) recomputes every row's status from its inputs and the errata
file (``concrete_compilation_errata.csv``: transcription errors found in the compilation,
each with its evidence); the bounds are named constants here and nowhere else:

- ``text_cell`` / ``empty_cell``: a number the cleaning or a run needs
  (:data:`REQUIRED`) is text (kept verbatim in ``raw_cells``) or empty;
- ``no_outline``: no tangent-ogive rod has the compiled outline (a CRH below 0.5, or a
  nose ``a sqrt(4 CRH - 1)`` not shorter than the compiled length);
- ``mass_above_solid`` / ``mass_below_hollow``: the mass is above
  :data:`MASS_RATIO_MAX` or below :data:`MASS_RATIO_MIN` times a solid body of the outline
  at the compiled projectile density (:func:`solid_mass`); hollow, instrumented or
  explosive-filled bodies lighter than solid are normal;
- ``not_concrete``: the target is rock (:data:`NOT_CONCRETE`);
- ``depth_near_thickness``: the depth is above :data:`DEPTH_THICKNESS_MAX` of the target's
  thickness, where the rear face takes part;
- ``shallow``: depth below :data:`SHALLOW_CALIBRES` diameters or striking speed below
  :data:`SHALLOW_SPEED_M_S`: cratering, scabbing and the slab's response decide, not the
  tunnel's resistance;
- ``eroding``: striking speed above :data:`ERODING_SPEED_M_S` (provisional: the rigid-regime
  criterion is stated elsewhere);
- ``transcription``: a row of the errata file;
- ``duplicate``: the same shot (diameter, fc, striking speed and depth) as another row,
  quoted by the same or another source: one row of the group is kept, the first with no
  other reason (else the first), the others name it in ``same_shot_as``.

Comparisons against a bound are exact on the decimal numbers of the file (a depth of
exactly 0.7 of the thickness is kept).

Examples
--------
>>> round(solid_mass(0.0129, 0.0889, 3.0, 7800.0), 4)  # the 12.9 mm Sandia rod, kg
0.0807
>>> reasons_of({"crh": 3.0, "diameter_m": 0.0129, "length_m": 0.0889, "mass_kg": 0.064,
...             "projectile_density_kg_m3": 7800.0, "target_density_kg_m3": 2000.0,
...             "fc_pa": 13.5e6, "target_thickness_m": 1.0, "striking_velocity_m_s": 1200.0,
...             "depth_m": 0.9, "target_type": "Grout", "raw_cells": ""})
['depth_near_thickness', 'eroding']
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from fractions import Fraction
from pathlib import Path
from typing import Any

import pandas as pd

from pencore.errors import InputError, hint_keywords
from pencore.measured.shots import read_data_csv

__all__ = [
    "DATA",
    "COMPILATION_CSV",
    "ERRATA_CSV",
    "SERIES_CSV",
    "COLUMNS",
    "NUMBER_COLUMNS",
    "REQUIRED",
    "REASONS",
    "MASS_RATIO_MAX",
    "MASS_RATIO_MIN",
    "DEPTH_THICKNESS_MAX",
    "SHALLOW_CALIBRES",
    "SHALLOW_SPEED_M_S",
    "ERODING_SPEED_M_S",
    "NOT_CONCRETE",
    "DUPLICATE_KEY",
    "nose_length",
    "solid_mass",
    "parse_raw_cells",
    "reasons_of",
    "clean",
    "read_compilation",
    "read_errata",
    "read_series",
    "clean_rows",
    "rows_allowing",
    "status_mismatches",
    "reason_codes",
    "reason_counts",
    "source_counts",
]

#: Folder of the shipped data.
DATA = Path(__file__).resolve().parent / "data"
#: The compilation, every row with its status.
COMPILATION_CSV = DATA / "concrete_compilation.csv"
#: Transcription errors found in the compilation, each with its evidence.
ERRATA_CSV = DATA / "concrete_compilation_errata.csv"
#: The geometrically scaled series among the compilation's rows.
SERIES_CSV = DATA / "concrete_compilation_series.csv"

#: The numeric columns, with their units (empty where the compilation has no number).
NUMBER_COLUMNS = {
    "ultimate_strength_pa": "Pa",
    "yield_strength_pa": "Pa",
    "mass_kg": "kg",
    "diameter_m": "m",
    "length_m": "m",
    "crh": "calibers",
    "projectile_density_kg_m3": "kg/m3",
    "target_density_kg_m3": "kg/m3",
    "fc_pa": "Pa",
    "target_thickness_m": "m",
    "target_area_m2": "m2",
    "striking_velocity_m_s": "m/s",
    "depth_m": "m",
}
#: The file's columns, in order.
COLUMNS = (
    "row",
    "xlsx_row",
    "set",
    "series",
    "reference_key",
    "reference_number",
    "reference",
    "projectile_material",
    "ultimate_strength_pa",
    "yield_strength_pa",
    "mass_kg",
    "diameter_m",
    "length_m",
    "crh",
    "projectile_density_kg_m3",
    "target_type",
    "target_density_kg_m3",
    "fc_pa",
    "target_thickness_m",
    "target_area_m2",
    "striking_velocity_m_s",
    "depth_m",
    "raw_cells",
    "status",
    "reason",
    "same_shot_as",
)
#: The numbers the cleaning or a run needs: a row lacking one is set aside.
REQUIRED = (
    "mass_kg",
    "diameter_m",
    "length_m",
    "crh",
    "projectile_density_kg_m3",
    "target_density_kg_m3",
    "fc_pa",
    "target_thickness_m",
    "striking_velocity_m_s",
    "depth_m",
)

#: Mass above this multiple of a solid body of the outline: no body of the outline has it.
#: The compiled diameters and lengths are rounded (0.1 mm of 10 mm is 2 % of the mass) and
#: the densities nominal; the consistent sets of the compilation reach 1.10 (dense cores,
#: heavy alloys), the next rows 1.20.
MASS_RATIO_MAX = 1.15
#: Mass below this multiple of the solid body: no steel case is that thin. The hollow and
#: instrumented bodies of the compilation weigh 0.39 and more; below 0.3 are decimal slips.
MASS_RATIO_MIN = 0.3
#: Depth above this fraction of the target's thickness: the rear face (scabbing, bulging,
#: a release from the free surface) takes part, and the target is not a half-space.
DEPTH_THICKNESS_MAX = 0.7
#: Depth below this many diameters: the shot ends inside the entry crater, the region every
#: rigid law models apart from the tunnel (Forrestal's crater is 2 diameters deep, Li &
#: Chen's 0.707 + H/d with H the nose length), so cratering, not the tunnel's resistance,
#: decides it.
SHALLOW_CALIBRES = 1.0
#: Striking speed below this (m/s): missile impacts of tens of m/s on slabs, where the slab
#: and the crater respond (the data of the empirical missile formulas), not a tunnel.
SHALLOW_SPEED_M_S = 100.0
#: Striking speed above this (m/s): the nose erodes (provisional; the rigid-regime criterion
#: is the model's, not the data's).
ERODING_SPEED_M_S = 1000.0
#: Words of a target type that is not a concrete, grout or mortar (case-insensitive).
NOT_CONCRETE = ("granite",)
#: Columns that identify a shot: two rows with all of them equal are the same shot.
DUPLICATE_KEY = ("diameter_m", "fc_pa", "striking_velocity_m_s", "depth_m")

#: Reason codes, in the order a row's reasons are listed: code -> what it means.
REASONS = {
    "text_cell": "a number the cleaning or a run needs is text in the compilation "
    "(kept verbatim in raw_cells)",
    "empty_cell": "a number the cleaning or a run needs is empty in the compilation",
    "no_outline": "no tangent-ogive rod has the compiled outline (CRH below 0.5, or a nose "
    "not shorter than the compiled length)",
    "mass_above_solid": f"mass above {MASS_RATIO_MAX:g} x a solid body of the outline at "
    "the compiled density",
    "mass_below_hollow": f"mass below {MASS_RATIO_MIN:g} x a solid body of the outline: no "
    "steel case is that thin",
    "not_concrete": "the target is rock, not a concrete, grout or mortar",
    "depth_near_thickness": f"depth above {DEPTH_THICKNESS_MAX:g} of the target's thickness",
    "shallow": f"depth below {SHALLOW_CALIBRES:g} diameter or striking speed below "
    f"{SHALLOW_SPEED_M_S:g} m/s: cratering and the slab decide",
    "eroding": f"striking speed above {ERODING_SPEED_M_S:g} m/s: the nose erodes "
    "(provisional bound)",
    "transcription": "a transcription error in the compilation (the errata file shows "
    "the evidence)",
    "duplicate": "the same shot as the row in same_shot_as (same diameter, fc, speed and "
    "depth), quoted again",
}

STATUSES = ("clean", "set_aside")


def nose_length(diameter: float, crh: float) -> float:
    """Length (m) of a tangent ogive of caliber-radius-head ``crh`` on a rod of
    ``diameter`` (m): ``a sqrt(4 crh - 1)``, ``a`` the radius; NaN below CRH 0.25."""
    return diameter / 2.0 * math.sqrt(4.0 * crh - 1.0) if crh >= 0.25 else math.nan


def solid_mass(diameter: float, length: float, crh: float, density: float) -> float:
    """Mass (kg) of a solid body of a tangent-ogive nose of ``crh`` and a cylinder making up
    the total ``length`` (m), of ``diameter`` (m) and ``density`` (kg/m3).

    The ogive's volume in closed form: with ``R = 2 crh a`` the ogive radius, ``H`` the nose
    length and ``c = R - a``, the nose is ``r(x) = sqrt(R^2 - x^2) - c`` for ``0 <= x <= H``
    and ``V = pi (R^2 H - H^3/3 - c R^2 asin(H/R))``.

    Returns
    -------
    float
        The mass, or NaN where no body has the outline (CRH below 0.5, or a nose not
        shorter than ``length``).
    """
    if not crh >= 0.5:
        return math.nan
    a = diameter / 2.0
    big_r = 2.0 * crh * a
    h = nose_length(diameter, crh)
    if not h < length:
        return math.nan
    c = big_r - a
    nose = math.pi * (big_r**2 * h - h**3 / 3.0 - c * big_r**2 * math.asin(h / big_r))
    return density * (nose + math.pi * a * a * (length - h))


def parse_raw_cells(text: Any) -> dict[str, str]:
    """The ``raw_cells`` column (``column=text; column=text``) as a mapping."""
    if not isinstance(text, str) or not text.strip():
        return {}
    out = {}
    for part in text.split("; "):
        column, sep, value = part.partition("=")
        if not sep:
            raise InputError(f"raw_cells entry {part!r} is not column=text")
        out[column.strip()] = value
    return out


def _num(row: Mapping[str, Any], column: str) -> float:
    try:
        x = float(row[column])
    except (KeyError, TypeError, ValueError):
        return math.nan
    return x


def _exact(x: float) -> Fraction:
    """A number of the file as its exact decimal (the shortest repr is the file's text)."""
    return Fraction(repr(float(x)))


def _above(x: float, bound: float, of: float = 1.0) -> bool:
    """``x > bound * of`` on the exact decimals."""
    return _exact(x) > _exact(bound) * _exact(of)


def _below(x: float, bound: float, of: float = 1.0) -> bool:
    """``x < bound * of`` on the exact decimals."""
    return _exact(x) < _exact(bound) * _exact(of)


def reasons_of(row: Mapping[str, Any], errata_rows: frozenset[int] = frozenset()) -> list[str]:
    """The reason codes (:data:`REASONS`, in its order) of one row, all but ``duplicate``
    (which needs the other rows: :func:`clean`); ``errata_rows`` are the rows of the
    errata file. A rule whose numbers are missing does not apply."""
    raw = parse_raw_cells(row.get("raw_cells"))
    v = {c: _num(row, c) for c in REQUIRED}
    missing = [c for c in REQUIRED if not math.isfinite(v[c])]
    found = set()
    if any(c in raw for c in missing):
        found.add("text_cell")
    if any(c not in raw for c in missing):
        found.add("empty_cell")
    d, length, crh = v["diameter_m"], v["length_m"], v["crh"]
    if all(math.isfinite(x) for x in (d, length, crh)):
        solid = solid_mass(d, length, crh, 1.0)
        if not math.isfinite(solid):
            found.add("no_outline")
        elif math.isfinite(v["mass_kg"]) and math.isfinite(v["projectile_density_kg_m3"]):
            ratio = v["mass_kg"] / (solid * v["projectile_density_kg_m3"])
            if ratio > MASS_RATIO_MAX:
                found.add("mass_above_solid")
            elif ratio < MASS_RATIO_MIN:
                found.add("mass_below_hollow")
    kind = str(row.get("target_type", "")).lower()
    if any(word in kind for word in NOT_CONCRETE):
        found.add("not_concrete")
    depth, thickness, speed = v["depth_m"], v["target_thickness_m"], v["striking_velocity_m_s"]
    if math.isfinite(depth) and math.isfinite(thickness):
        if _above(depth, DEPTH_THICKNESS_MAX, thickness):
            found.add("depth_near_thickness")
    if math.isfinite(depth) and math.isfinite(d) and _below(depth, SHALLOW_CALIBRES, d):
        found.add("shallow")
    if math.isfinite(speed):
        if _below(speed, SHALLOW_SPEED_M_S):
            found.add("shallow")
        if _above(speed, ERODING_SPEED_M_S):
            found.add("eroding")
    if errata_rows and int(row["row"]) in errata_rows:
        found.add("transcription")
    return [code for code in REASONS if code in found]


def clean(df: pd.DataFrame, errata_rows: frozenset[int] = frozenset()) -> pd.DataFrame:
    """Every row's ``status``, ``reason`` and ``same_shot_as``, recomputed from its inputs.

    Parameters
    ----------
    df : pandas.DataFrame
        The compilation's rows (at least ``row``, ``target_type``, ``raw_cells`` and the
        :data:`REQUIRED` numbers, NaN where there is none).
    errata_rows : frozenset of int
        The rows of the errata file (:func:`read_errata`).

    Returns
    -------
    pandas.DataFrame
        Indexed like ``df``: ``status`` (``clean`` or ``set_aside``), ``reason`` (codes of
        :data:`REASONS` joined by ``"; "``, empty when clean) and ``same_shot_as`` (the
        kept row of a duplicate, else NA).
    """
    reasons = {i: reasons_of(r, errata_rows) for i, r in df.iterrows()}
    same: dict[Any, int] = {}
    key = df[list(DUPLICATE_KEY)].astype(float)
    complete = key.notna().all(axis=1)
    order = df.assign(_row=df["row"].astype(int)).sort_values("_row")
    groups = order[complete[order.index]].groupby(list(DUPLICATE_KEY), sort=False)
    for _, g in groups:
        if len(g) < 2:
            continue
        free = [i for i in g.index if not reasons[i]]
        kept = free[0] if free else g.index[0]
        for i in g.index:
            if i != kept:
                same[i] = int(df.at[kept, "row"])
                reasons[i] = [c for c in REASONS if c in {*reasons[i], "duplicate"}]
    out = pd.DataFrame(index=df.index)
    out["status"] = ["set_aside" if reasons[i] else "clean" for i in df.index]
    out["reason"] = ["; ".join(reasons[i]) for i in df.index]
    out["same_shot_as"] = pd.array([same.get(i) for i in df.index], dtype="Int64")
    return out


def read_errata(path: str | Path = ERRATA_CSV) -> pd.DataFrame:
    """The errata file: ``row``, ``column``, ``compiled`` (the cell as compiled) and
    ``evidence``, one line per cell found wrong."""
    df = read_data_csv(path, ("row", "column", "compiled", "evidence"), "compilation errata")
    df["row"] = df["row"].astype(int)
    bad = df[df["evidence"].isna() | (df["evidence"].astype(str).str.strip() == "")]
    if not bad.empty:
        raise InputError(f"compilation errata {path}: rows {list(bad['row'])} have no evidence")
    return df


def read_series(path: str | Path = SERIES_CSV) -> pd.DataFrame:
    """The scaled series: ``series`` and ``row``, one line per row of a series."""
    df = read_data_csv(path, ("series", "row"), "compilation series")
    df["row"] = df["row"].astype(int)
    if df["row"].duplicated().any():
        dup = sorted(set(df["row"][df["row"].duplicated()]))
        raise InputError(f"compilation series {path}: rows {dup} are in two series")
    return df


def read_compilation(path: str | Path = COMPILATION_CSV) -> pd.DataFrame:
    """The compilation, every row: the columns of :data:`COLUMNS`, the numbers of
    :data:`NUMBER_COLUMNS` as floats (NaN where the compilation has none), ``row`` and
    ``xlsx_row`` as int, ``same_shot_as`` as a nullable int, texts empty where none.

    Raises
    ------
    InputError
        One line naming the file: no such file, a missing column, a duplicate row, a
        number that is text, a status or reason code not of the vocabulary.
    """
    label = f"concrete compilation {str(path)!r}"
    df = read_data_csv(path, COLUMNS, label)
    for c in NUMBER_COLUMNS:
        try:
            df[c] = pd.to_numeric(df[c]).astype(float)
        except (TypeError, ValueError):
            raise InputError(
                f"{label}: column {c} holds text (text cells go to raw_cells)"
            ) from None
    for c in ("row", "xlsx_row"):
        df[c] = df[c].astype(int)
    df["same_shot_as"] = pd.array(df["same_shot_as"], dtype="Int64")
    for c in ("set", "series", "reference_key", "reference", "projectile_material"):
        df[c] = df[c].fillna("").astype(str)
    for c in ("target_type", "raw_cells", "reason", "status"):
        df[c] = df[c].fillna("").astype(str)
    if df["row"].duplicated().any():
        raise InputError(
            f"{label}: duplicate rows {sorted(set(df['row'][df['row'].duplicated()]))}"
        )
    bad = sorted(set(df["status"]) - set(STATUSES))
    if bad:
        raise InputError(f"{label}: status {bad} not one of {list(STATUSES)}")
    codes = {c for text in df["reason"] for c in reason_codes(text)}
    unknown = sorted(codes - set(REASONS))
    if unknown:
        raise InputError(f"{label}: reason codes {unknown} not one of {list(REASONS)}")
    return df


def status_mismatches(df: pd.DataFrame, errata_rows: frozenset[int] | None = None) -> pd.DataFrame:
    """Rows whose written ``status``, ``reason`` or ``same_shot_as`` differ from
    :func:`clean`'s (empty when the file is what its cleaning says)."""
    if errata_rows is None:
        errata_rows = frozenset(read_errata()["row"])
    now = clean(df, errata_rows)
    differ = (
        (now["status"] != df["status"])
        | (now["reason"] != df["reason"])
        | (now["same_shot_as"].fillna(-1) != df["same_shot_as"].fillna(-1))
    )
    return df.loc[differ, ["row", "status", "reason", "same_shot_as"]].join(
        now[differ].add_suffix("_recomputed")
    )


def clean_rows(path: str | Path = COMPILATION_CSV) -> pd.DataFrame:
    """The rows of status ``clean`` (:func:`read_compilation`), every required number
    finite and > 0: a body shot table's rows."""
    df = read_compilation(path)
    return df[df["status"] == "clean"].reset_index(drop=True)


def reason_codes(text: str) -> list[str]:
    """The codes of a ``reason`` cell (``"a; b"`` -> ``["a", "b"]``; empty when clean)."""
    return [c for c in str(text).split("; ") if c]


def rows_allowing(df: pd.DataFrame, allowed: Collection[str]) -> pd.DataFrame:
    """The rows whose reasons are all in ``allowed`` (the clean rows among them): for
    example the clean rows and those set aside only as ``eroding``, to judge a criterion
    of the rigid regime on them."""
    unknown = sorted(set(allowed) - set(REASONS))
    if unknown:
        raise InputError(f"unknown reason codes {unknown}; use {list(REASONS)}")
    keep = [set(reason_codes(text)) <= set(allowed) for text in df["reason"]]
    return df[keep]


def reason_counts(df: pd.DataFrame) -> pd.DataFrame:
    """Per reason code (:data:`REASONS`, in its order): ``rows`` that carry it and ``only``,
    the rows set aside for it alone; its ``text``."""
    codes = [reason_codes(text) for text in df["reason"]]
    return pd.DataFrame(
        {
            "rows": [sum(c in r for r in codes) for c in REASONS],
            "only": [sum(r == [c] for r in codes) for c in REASONS],
            "text": list(REASONS.values()),
        },
        index=pd.Index(list(REASONS), name="reason"),
    )


def source_counts(df: pd.DataFrame) -> pd.DataFrame:
    """Per compiler's key (in the compilation's order): the ``references`` its rows cite
    (their numbers, ``"15, 19"``), the ``rows``, the ``clean`` rows and the first and last
    ``row``."""
    g = df.groupby("reference_key", sort=False)
    return pd.DataFrame(
        {
            "references": g["reference_number"].apply(
                lambda s: ", ".join(str(n) for n in sorted(set(s)))
            ),
            "rows": g.size(),
            "clean": g["status"].apply(lambda s: int((s == "clean").sum())),
            "first_row": g["row"].min(),
            "last_row": g["row"].max(),
        }
    )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
