"""Shot tables: measured shots as their sources print them, read and checked.

Two forms, each a CSV with ``#`` comment lines (the file's provenance) and one row per shot:

*A shot table* (:data:`SHOT_COLUMNS`): the shots of a penetration paper at normal
incidence (the target face normal to the line of flight), with ``striking_velocity_m_s``,
``depth_m``, the angles of attack ``pitch_deg`` and ``yaw_deg`` read from the X-rays, the
authors' remark, a ``rigid`` flag set by the authors' stated limits, the table and page,
and a library ``projectile``. The two angles of attack combine into the total angle between
axis and velocity, ``delta = atan(sqrt(tan^2 pitch + tan^2 yaw))``; an axisymmetric body at
normal incidence is rotated about the target normal so that this angle lies in pencore's
x-y plane, which is exact, and run with the axis tilted by ``delta`` and the velocity along
the normal (:func:`pencore.inputs.conventions.normal_impact_angles`, ``axis_tilted``:
``obliquity = delta``, ``yaw = -delta``). :func:`read_shot_table` gives the rows in the
common form of the measurement files.

*A body shot table* (:data:`BODY_SHOT_COLUMNS`): shots each with its own body and target
described by measured properties instead of library names (the measured mass, diameter,
total length and CRH of a tangent-ogive rod; the target's density and unconfined
compressive strength ``fc``), grouped in sets (``set``: one reference, projectile and target),
with the source's ``row``. No angles of attack: normal impact, no yaw.
:func:`read_body_shot_table` checks every number (finite, > 0) and names the offending row.
A body shot table with a ``status`` column (the concrete compilation,
:mod:`pencore.measured.compilation`) gives only its rows of status ``clean``: the rows set
aside keep their reason in the file and are not run.

Examples
--------
>>> round(total_angle_of_attack(3.0, 4.0), 3)
4.994
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pencore.errors import InputError, hint_keywords
from pencore.inputs.conventions import normal_impact_angles
from pencore.inputs.gate import decimal
from pencore.inputs.limits import plausible
from pencore.paper.tables import read_csv

__all__ = [
    "SHOT_COLUMNS",
    "BODY_SHOT_COLUMNS",
    "read_data_csv",
    "total_angle_of_attack",
    "read_shot_table",
    "shot_table",
    "read_body_shot_table",
]

#: Columns of a shot table (a penetration paper's shots as printed; see the module notes).
SHOT_COLUMNS = (
    "shot",
    "projectile",
    "striking_velocity_m_s",
    "depth_m",
    "pitch_deg",
    "yaw_deg",
    "rigid",
    "table",
    "page",
    "source",
)

#: Columns of a body shot table, with their units: the numbers must be finite and > 0.
BODY_SHOT_NUMBERS = {
    "mass_kg": "kg",
    "diameter_m": "m",
    "length_m": "m",
    "crh": "calibers",
    "target_density_kg_m3": "kg/m3",
    "fc_pa": "Pa",
    "striking_velocity_m_s": "m/s",
    "depth_m": "m",
}
#: Columns of a body shot table (see the module notes).
BODY_SHOT_COLUMNS = ("row", "set", "reference", *BODY_SHOT_NUMBERS)


def read_data_csv(path: str | Path, columns: Sequence[str], label: str) -> pd.DataFrame:
    """A data file (CSV, ``#`` comments) that exists, has ``columns`` and has rows.

    Raises
    ------
    InputError
        One line starting with ``label``: no such file, an empty file (or comments only),
        the columns it lacks, or no rows.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{label}: no such file {str(path)!r}")
    # through the input gate: an empty, comments-only, Latin-1 or binary file is one line
    df = read_csv(path, "data", label=label, comment="#")
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise InputError(f"{label}: {path} lacks column(s) {missing}")
    if df.empty:
        raise InputError(f"{label}: {path} has no rows")
    return df


def total_angle_of_attack(pitch_deg: float, yaw_deg: float) -> float:
    """Angle (deg) between axis and velocity from the pitch and yaw angles of attack (deg)
    measured in two perpendicular planes: ``atan(sqrt(tan^2 pitch + tan^2 yaw))``."""
    tp, ty = math.tan(math.radians(pitch_deg)), math.tan(math.radians(yaw_deg))
    return math.degrees(math.atan(math.hypot(tp, ty)))


def _cell(v: Any) -> Any:
    """A numeric cell as a number: one text cell turns a whole column into text, so each
    row's text is read back as a plain decimal number (the gate's notation) when it is
    one, and kept as text (refused by the row's check, naming it) when it is not."""
    if isinstance(v, str):
        f = decimal(v.strip())
        return v if f is None else f
    return v


def _shot_row(r: pd.Series, where: str) -> dict[str, Any]:
    """One row of a shot table in the common form (impact angles mapped, see the notes)."""
    r = r.copy()
    for c in ("striking_velocity_m_s", "depth_m", "pitch_deg", "yaw_deg"):
        r[c] = _cell(r[c])
    for c in ("table", "page", "source", "projectile"):
        if pd.isna(r[c]) or not str(r[c]).strip():
            raise InputError(f"{where}: no {c}")
    for c in ("striking_velocity_m_s", "depth_m"):
        v = r[c]
        if c == "depth_m" and pd.isna(v):
            continue  # no depth printed (e.g. a channel length only): kept, compared with nothing
        if not isinstance(v, (int, float, np.number)) or not math.isfinite(float(v)) or v <= 0:
            raise InputError(f"{where}: {c} must be a finite number > 0, got {v!r}")
        plausible(float(v), "velocity" if c == "striking_velocity_m_s" else "depth", where)
    angles = []
    for c in ("pitch_deg", "yaw_deg"):
        v = r[c]
        if pd.isna(v):
            angles.append(0.0)  # not measured: taken as none, recorded as NaN below
            continue
        if not isinstance(v, (int, float, np.number)) or not abs(float(v)) < 45.0:
            raise InputError(f"{where}: {c} must be a number in (-45, 45) deg, got {v!r}")
        angles.append(float(v))
    rigid = r["rigid"]
    if isinstance(rigid, str) and rigid.strip().lower() in ("true", "false"):
        rigid = rigid.strip().lower() == "true"
    if not isinstance(rigid, (bool, np.bool_)):
        raise InputError(f"{where}: rigid must be true or false, got {rigid!r}")
    obliquity, yaw = normal_impact_angles(total_angle_of_attack(*angles), "axis_tilted")
    remark = r.get("remark", "")
    return {
        "test": r["shot"],
        "projectile": str(r["projectile"]),
        "velocity_m_s": float(r["striking_velocity_m_s"]),
        "obliquity_deg": obliquity,
        "yaw_deg": yaw,
        "measured_depth_m": float(r["depth_m"]),
        "unmeasured": bool(pd.isna(r["depth_m"])),
        "pitch_measured_deg": float(r["pitch_deg"]),
        "yaw_measured_deg": float(r["yaw_deg"]),
        "rigid": bool(rigid),
        "remark": "" if pd.isna(remark) else str(remark),
        "source": f"{r['source']}, Table {r['table']}, p. {r['page']}",
    }


def read_shot_table(path: str | Path, label: str | None = None) -> pd.DataFrame:
    """A shot table (:data:`SHOT_COLUMNS`) in the common form of the measurement files
    (:func:`pencore.studies.validation.measurements.load_measurements`): ``test``,
    ``projectile``, ``velocity_m_s``, ``obliquity_deg`` and ``yaw_deg``
    (mapped from the angles of attack, see the module notes), ``measured_depth_m`` (NaN
    where the source prints none; ``unmeasured`` is then true), the measured angles, the
    ``rigid`` flag, the ``remark`` and the ``source`` with its table and page.

    Raises
    ------
    InputError
        One line naming the file and row: a missing column, a duplicate shot, a value out
        of range, a row with no table, page or source.
    """
    label = label or f"shot table {str(path)!r}"
    return shot_table(read_data_csv(path, SHOT_COLUMNS, label), label)


def shot_table(df: pd.DataFrame, label: str) -> pd.DataFrame:
    """The rows of a shot table already read (:func:`read_data_csv`), each checked and mapped
    as :func:`read_shot_table` does; ``label`` starts every error message."""
    # a shot id is compared as written without its blanks: " 12" repeats "12"
    ids = df["shot"].astype(str).str.strip()
    dup = ids.duplicated()
    if dup.any():
        raise InputError(f"{label}: duplicate shots {sorted(set(ids[dup]))}")
    return pd.DataFrame(
        [_shot_row(r, f"{label} row {i + 1} (shot {r['shot']!r})") for i, r in df.iterrows()]
    )


def read_body_shot_table(path: str | Path, label: str | None = None) -> pd.DataFrame:
    """A body shot table (:data:`BODY_SHOT_COLUMNS`), checked: one row per shot.

    Parameters
    ----------
    path : str or Path
        The CSV (``#`` comments).
    label : str, optional
        Starts every error message (default: the file's name).

    Returns
    -------
    pandas.DataFrame
        The file's columns, the numbers of :data:`BODY_SHOT_COLUMNS` as floats, ``row`` and
        ``set`` as text; where the file has a ``status`` column, only its ``clean`` rows.

    Raises
    ------
    InputError
        One line naming the file and the row: no such file, no rows, a missing column, a
        duplicate ``row``, an empty ``set`` or ``reference``, or a number that is text,
        missing, not finite or not > 0.
    """
    label = label or f"shot table {str(path)!r}"
    df = read_data_csv(path, BODY_SHOT_COLUMNS, label)
    if "status" in df.columns:
        df = df[df["status"].astype(str).str.strip() == "clean"].reset_index(drop=True)
        if df.empty:
            raise InputError(f"{label}: {path} has no row of status clean")
    out = df.copy()
    for i, r in df.iterrows():
        where = f"{label} row {i + 1} (row {r['row']!r})"
        for c in ("row", "set", "reference"):
            if pd.isna(r[c]) or not str(r[c]).strip():
                raise InputError(f"{where}: no {c}")
        for c, units in BODY_SHOT_NUMBERS.items():
            v = r[c]
            try:
                x = float(v)
            except (TypeError, ValueError):
                x = math.nan
            if isinstance(v, (bool, np.bool_)) or not math.isfinite(x) or x <= 0:
                raise InputError(f"{where}: {c} must be a finite number > 0 ({units}), got {v!r}")
    for c in BODY_SHOT_NUMBERS:
        out[c] = out[c].astype(float)
    out["row"] = out["row"].astype(str)
    out["set"] = out["set"].astype(str)
    dup = out["row"].duplicated()
    if dup.any():
        raise InputError(f"{label}: duplicate rows {sorted(set(out['row'][dup]))}")
    return out


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
