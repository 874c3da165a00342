#!/usr/bin/env python
"""Write ``src/pencore/measured/data/concrete_compilation.csv`` from a snapshot of the public
compilation (``Data.xlsx`` and ``References.docx`` of
github.com/DavidZyh-0319/Concrete-Penetration-Failure-Response-Dataset), every row with its
status from :func:`pencore.measured.compilation.clean`.

    python tools/concrete_compilation.py SNAPSHOT [--out PATH] [--commit SHA]

``SNAPSHOT`` is a git directory of the repository (the files are read with ``git show
COMMIT:Data.xlsx``) or a folder holding ``Data.xlsx`` and ``References.docx``. Needs
``openpyxl`` and ``python-docx``, which pencore does not depend on: install them for this
script only. The spreadsheet and the reference list stay out of the project: the CSV
carries their values as facts, each row with its reference and the compilation's number.

The numbers are converted by an exact decimal shift (mm -> m, MPa -> Pa); a cell that is
text where a number belongs is left empty and kept verbatim in ``raw_cells``. The ``set``
of a row is ``<first author><year>_d<mm>_crh<CRH>_fc<MPa>`` (a letter after the year when
two references share author and year; ``_l<mm>`` when one reference has rods of one
diameter and CRH but several lengths); where one rod and one target (type and density) of
a reference come with more than three values of fc, the fc was measured per shot and the
set spans their range (``fc32-40``), as ``config/concrete_ogive_shots.csv`` groups them.
"""

from __future__ import annotations

import argparse
import io
import re
import subprocess
import sys
from collections import Counter
from decimal import Decimal
from pathlib import Path

import pandas as pd

from pencore.io.atomic import atomic_path
from pencore.measured.compilation import (
    COLUMNS,
    COMPILATION_CSV,
    REASONS,
    clean,
    read_errata,
    read_series,
)

COMMIT = "3463a15d33f619fd3677e362c449ff1576b4b937"
COMMIT_DATE = "2026-03-17"
SOURCE = "github.com/DavidZyh-0319/Concrete-Penetration-Failure-Response-Dataset"

#: spreadsheet header -> (column of the CSV, decimal shift to SI) ; None: text column
SHEET = {
    "Number": ("row", None),
    "Author": ("reference_key", None),
    "Projectile Material": ("projectile_material", None),
    "Projectile Tensile Strength (MPa)": ("ultimate_strength_pa", 6),
    "Projectile Yield Strength (MPa)": ("yield_strength_pa", 6),
    "Projectile Mass (kg)": ("mass_kg", 0),
    "Projectile Diameter (mm)": ("diameter_m", -3),
    "Projectile Length (mm)": ("length_m", -3),
    "Nose CRH Ratio (CRH)": ("crh", 0),
    "Projectile Density (kg/m^3)": ("projectile_density_kg_m3", 0),
    "Concrete Type": ("target_type", None),
    "Concrete Density (kg/m^3)": ("target_density_kg_m3", 0),
    "Concrete Compressive Strength (MPa)": ("fc_pa", 6),
    "Concrete Target Thickness (m)": ("target_thickness_m", 0),
    "Concrete Target Area (m^2)": ("target_area_m2", 0),
    "Impact Velocity (m/s)": ("striking_velocity_m_s", 0),
    "Penetration Depth (mm)": ("depth_m", -3),
    "Article": ("article", None),
}


def _read_bytes(snapshot: Path, name: str, commit: str) -> bytes:
    if (snapshot / name).is_file():
        return (snapshot / name).read_bytes()
    done = subprocess.run(
        ["git", "-C", str(snapshot), "show", f"{commit}:{name}"], capture_output=True
    )
    if done.returncode:
        sys.exit(f"concrete_compilation: cannot read {name} at {commit} in {snapshot}")
    return done.stdout


def exact(value: object, shift: int) -> str:
    """A numeric cell as the decimal text of its value times 10**shift (exact)."""
    text = repr(value) if isinstance(value, float) else str(value)
    d = Decimal(text).scaleb(shift).normalize()
    return format(d, "f")


def references(docx_bytes: bytes) -> dict[int, str]:
    import docx  # python-docx, for this script only

    out = {}
    for p in docx.Document(io.BytesIO(docx_bytes)).paragraphs:
        m = re.match(r"\[(\d+)\]\s*(.*\S)", p.text.strip())
        if m:
            out[int(m.group(1))] = m.group(2)
    return out


def slugs(refs: dict[int, str]) -> dict[int, str]:
    """``<first author's surname><year>`` per reference, a letter added where two share it."""
    base = {}
    for n, text in refs.items():
        surname = re.sub(r"[^a-z]", "", text.split(",")[0].lower())
        year = re.search(r"\b(19|20)\d\d\b", text)
        base[n] = surname + (year.group(0) if year else "nd")
    count = Counter(base.values())
    seen: Counter[str] = Counter()
    out = {}
    for n in sorted(base):
        b = base[n]
        if count[b] > 1:
            out[n] = b + "abcdefghij"[seen[b]]
            seen[b] += 1
        else:
            out[n] = b
    return out


def _g(x: str) -> str:
    """A number's text as in a set id: ``26.9``, ``2``, ``4.25``."""
    return format(Decimal(x).normalize(), "f") if x else "NA"


def set_ids(df: pd.DataFrame, slug: dict[int, str]) -> list[str]:
    """The ``set`` of every row (see the module notes)."""
    mm = df["diameter_m"].map(lambda x: exact(x, 3) if x else "")
    fc_mpa = df["fc_pa"].map(lambda x: exact(x, -6) if x else "")
    rod = [df["reference_number"], mm, df["crh"], df["length_m"]]
    target = [df["target_type"], df["target_density_kg_m3"]]
    fc_label = fc_mpa.map(_g)
    for _, g in df.groupby([*rod, *target], sort=False).groups.items():
        values = sorted({float(fc_mpa[i]) for i in g if fc_mpa[i]})
        if len(values) > 3:
            label = f"{values[0]:.0f}-{values[-1]:.0f}"
            for i in g:
                fc_label[i] = label
    ids = [
        f"{slug[int(n)]}_d{_g(d)}_crh{_g(c)}_fc{f}"
        for n, d, c, f in zip(df["reference_number"], mm, df["crh"], fc_label, strict=True)
    ]
    ids = pd.Series(ids, index=df.index)
    lengths = df.groupby(ids)["length_m"].transform("nunique")
    for i in df.index[lengths > 1]:
        ids[i] += f"_l{_g(exact(df.at[i, 'length_m'], 3))}" if df.at[i, "length_m"] else "_lNA"
    return list(ids)


def rows(xlsx_bytes: bytes, refs: dict[int, str]) -> pd.DataFrame:
    import openpyxl  # for this script only

    ws = openpyxl.load_workbook(io.BytesIO(xlsx_bytes), read_only=True).worksheets[0]
    table = list(ws.iter_rows(values_only=True))
    header = [str(h).strip() for h in table[0]]
    if header != list(SHEET):
        sys.exit(f"concrete_compilation: unexpected columns {header}")
    out = []
    for xlsx_row, cells in enumerate(table[1:], start=2):
        r: dict[str, object] = {"xlsx_row": xlsx_row}
        raw = []
        for (column, shift), v in zip(SHEET.values(), cells, strict=True):
            if shift is None:
                r[column] = "" if v is None else str(v).strip()
            elif v is None:
                r[column] = ""
            elif isinstance(v, (int, float)) and not isinstance(v, bool):
                r[column] = exact(v, shift)
            else:
                if ";" in str(v) or "=" in str(v):
                    sys.exit(f"concrete_compilation: row {xlsx_row}: cell {v!r} needs quoting")
                r[column] = ""
                raw.append(f"{column}={v}")
        r["raw_cells"] = "; ".join(raw)
        numbers = [int(x) for x in re.findall(r"\d+", str(r["reference_key"]).split("[")[-1])]
        cited = [n for n in numbers if refs.get(n, "").strip() == r["article"]]
        if len(cited) != 1:
            sys.exit(f"concrete_compilation: row {xlsx_row}: its article is not one of {numbers}")
        r["reference_number"] = cited[0]
        r["reference"] = refs[cited[0]]
        out.append(r)
    df = pd.DataFrame(out)
    if list(df["row"].astype(int)) != list(range(1, len(df) + 1)):
        sys.exit("concrete_compilation: the Numbers are not 1..N in order")
    return df


def header(df: pd.DataFrame, commit: str) -> str:
    n = len(df)
    clean_n = int((df["status"] == "clean").sum())
    per_reason = Counter(c for text in df["reason"] for c in text.split("; ") if c)
    lines = [
        "Every row of a public compilation of measured normal-impact shots of ogive-nose rods",
        f"into concrete, grout and mortar ({n} shots, {df['reference_number'].nunique()} "
        "references), one row per shot, each with its status and the reason a row is set aside.",
        "SECONDARY SOURCE. Every number is taken from a public compilation, not from the primary",
        "papers (which were not available to the project):",
        f"  Data.xlsx of {SOURCE}",
        f"  (commit {commit}, {COMMIT_DATE}), compiled by DavidZyh-0319, sheet 1: {n}",
        "  normal-impact, ogive-nose, non-perforating shots into semi-infinite targets (the",
        f'  compiler\'s README), "Number" 1-{n} in column A, spreadsheet row = Number + 1, each',
        "  row's source named in column R and in References.docx of the same commit. The",
        "  repository has no licence: the values are carried as measured facts, each with its",
        "  primary reference and the compilation's number; the spreadsheet is not copied.",
        "Written by tools/concrete_compilation.py from that snapshot (re-runnable); the status",
        "by pencore.measured.compilation.clean, with concrete_compilation_errata.csv (the",
        "transcription errors found, each with its evidence) and concrete_compilation_series.csv",
        "(the geometrically scaled series), beside this file.",
        "Conversions: mm -> m (diameter, length, depth) and MPa -> Pa (strengths, fc) by an exact",
        "decimal shift; mass (kg), densities (kg/m3), thickness (m), area (m2) and speed (m/s) as",
        "compiled. A cell that is text where a number belongs ('-', '——', '214..7', '~1550') is",
        "left empty and kept verbatim in raw_cells; an empty cell stays empty. Nothing else is",
        "computed or corrected.",
        "Cautions: the compiler's author keys are kept as compiled. Several keys name the",
        "same reference (Almusallam[1] and Xu J B[1] name Xu 2001; Chen[3] and Kamran[3] name",
        "Iqbal 2022): the key is the compiler's label, reference_number the reference cited in",
        "column R. The keys Forrestal[8] and Forrestal[9] look swapped (see",
        "config/concrete_ogive_shots.csv, the 107 Sandia/WES rows of this file).",
        f"Rows: {n}; clean {clean_n}; set aside {n - clean_n}. Rows per reason (a row may have",
        "several): " + ", ".join(f"{c} {per_reason[c]}" for c in REASONS) + ".",
        "Columns:",
        "  row, xlsx_row            the compilation's Number (column A) and its spreadsheet row",
        "  set                      <first author><year>_d<diameter mm>_crh<CRH>_fc<MPa, or the",
        "                           range of per-shot values>: one reference, rod and target",
        "  series                   the scaled series the row belongs to (or empty)",
        "  reference_key            the compiler's author key (column B)",
        "  reference_number, reference  the reference cited (column R) and its entry in",
        "                           References.docx",
        "  projectile_material      as compiled (column C)",
        "  ultimate_strength_pa, yield_strength_pa  the projectile's steel (columns D, E)",
        "  mass_kg                  measured projectile mass (column F)",
        "  diameter_m, length_m     shank diameter and total length, nose included (G, H)",
        "  crh                      ogive caliber-radius-head (column I)",
        "  projectile_density_kg_m3 as compiled (column J)",
        "  target_type              as compiled (column K)",
        "  target_density_kg_m3, fc_pa  the target's density and unconfined compressive",
        "                           strength (columns L, M)",
        "  target_thickness_m, target_area_m2  target depth along the shot line and face area",
        "                           (columns N, O; area empty where not compiled)",
        "  striking_velocity_m_s    (column P); depth_m penetration depth (column Q)",
        "  raw_cells                column=text for each cell that is text, not a number",
        "  status, reason           clean or set_aside; the reason codes (pencore.measured.",
        "                           compilation.REASONS), joined by '; '",
        "  same_shot_as             for a duplicate, the row of the same shot that is kept",
    ]
    return "".join(f"# {line}\n" if line else "#\n" for line in lines)


def build(snapshot: Path, commit: str = COMMIT) -> str:
    refs = references(_read_bytes(snapshot, "References.docx", commit))
    df = rows(_read_bytes(snapshot, "Data.xlsx", commit), refs)
    df["set"] = set_ids(df, slugs(refs))
    series = read_series()
    of_row = dict(zip(series["row"], series["series"], strict=True))
    df["series"] = df["row"].astype(int).map(of_row).fillna("")
    typed = df.copy()
    typed["row"] = typed["row"].astype(int)
    numeric = [c for c in COLUMNS if c.endswith(("_pa", "_kg", "_m", "_m2", "_kg_m3", "_m_s"))]
    for c in [*numeric, "crh"]:
        typed[c] = pd.to_numeric(typed[c].replace("", None)).astype(float)
    status = clean(typed, frozenset(read_errata()["row"]))
    df["status"] = status["status"]
    df["reason"] = status["reason"]
    df["same_shot_as"] = status["same_shot_as"].astype(str).replace("<NA>", "")
    body = df[list(COLUMNS)].to_csv(index=False, lineterminator="\n")
    return header(df, commit) + body


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("snapshot", type=Path, help="git directory or folder of the compilation")
    parser.add_argument("--out", type=Path, default=COMPILATION_CSV)
    parser.add_argument("--commit", default=COMMIT)
    args = parser.parse_args(argv)
    text = build(args.snapshot, args.commit)
    with atomic_path(args.out) as tmp:
        tmp.write_text(text, encoding="utf-8")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
