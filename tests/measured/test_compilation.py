"""The concrete compilation (pencore.measured.compilation): every row of the public
compilation with its source, its status recomputed from its inputs by the cleaning, each
reason at work on named rows and at its bound on synthetic rows, the text cells kept, the
107 Sandia/WES rows of config/concrete_ogive_shots.csv a subset with the same numbers, the
scaled series, and the reader's refusals."""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.measured import compilation as comp
from pencore.measured.shots import BODY_SHOT_COLUMNS, read_body_shot_table

REPO = Path(__file__).resolve().parents[2]
SANDIA = REPO / "config" / "concrete_ogive_shots.csv"

#: Rows per compiler's key, as the compilation holds them (column B of Data.xlsx).
ROWS_PER_KEY = {
    "Almusallam[1]": 3, "Chai C G[2]": 2, "Chen[3]": 5, "Chen X M[4]": 2, "Chen X M[5]": 8,
    "Chen X M[6]": 3, "Feng[7]": 15, "Forrestal[8]": 17, "Forrestal[9]": 15, "Frew[10]": 23,
    "Gao[11]": 12, "Gao F[12]": 12, "Geng[13]": 12, "Goel[14]": 35, "Gran[15]": 3,
    "Gu X H[16]": 6, "Guo L[17-18]": 29, "Haldar[15,19]": 33, "Hanchak & Forrestal[20]": 41,
    "Hou X F[21]": 2, "Huang[22]": 2, "Huang[23]": 5, "Huang M R[24]": 8, "Jason[25]": 4,
    "Jia K L[26]": 14, "Jiang[27]": 7, "Jiang R F[28]": 2, "Jiang Z G[29]": 7,
    "Jiang Z G[30]": 2, "Kamran[3]": 7, "Kataoka[31]": 11, "Kim[32]": 5, "Li[33]": 7,
    "Li[34]": 4, "Li[35]": 1, "Li L F[35]": 8, "Li X[36]": 4, "Li X[37]": 4, "Liang B[38]": 8,
    "Lin S L[39]": 2, "Liu[40]": 18, "Liu[33]": 5, "Liu Y S[41]": 9, "Liu Z L[42]": 12,
    "Liu[43]": 10, "Lu H[44]": 20, "Lu S B[45]": 4, "Luan X Y[46]": 3, "Lv Y Q[47]": 15,
    "Ma T B[48]": 4, "Mei Q Q[49]": 7, "Mina[50]": 19, "Nie[51]": 9, "Nie X D[52]": 8,
    "Ning[53]": 3, "Ning J G[54]": 4, "O\u2019Neil[55]": 8, "Qian B W[56-57]": 27,
    "Radoslav[50]": 3, "Sha H Y[58]": 7, "Shan Y[59]": 12, "Shen Z W[60]": 12,
    "Song M L[61-62]": 18, "Sun C J[63]": 11, "Wan F[64]": 28, "Wang[65]": 11,
    "Wang J[66]": 6, "Wang K H[67]": 3, "Wu[68]": 5, "Wu[69]": 1, "Wu B[70]": 7,
    "Wu C[71]": 39, "Wu H[72]": 29, "Wu H[73]": 20, "Wu H J[73]": 21, "Wu P[74]": 25,
    "Wu Y L[75]": 4, "Xu J B[1]": 29, "Xu S L[76]": 3, "Xue J F[77]": 15, "Yang Z Y[78]": 1,
    "Yao[79]": 6, "Zhai[80]": 4, "Zhang[81]": 12, "Zhang[82]": 29, "Zhang[83]": 10,
    "Zhang D M[84]": 6, "Zhang G L[85]": 8, "Zhang S[86]": 6, "Zhang W[87]": 5,
    "Zhang W H[86]": 8, "Zhang X Y[73]": 12, "Zhao[88]": 8, "Zhao X N[89]": 13,
}  # fmt: skip

#: One row of the compilation per reason, with what makes it so.
NAMED = {
    "text_cell": 282,  # striking speed compiled as '214..7'
    "empty_cell": 187,  # CRH empty (Guo L[17-18])
    "no_outline": 917,  # CRH 2.5 nose of a 12.6 mm rod is 18.9 mm: the compiled length
    "mass_above_solid": 598,  # Shen Z W[60]: 2.4 x the solid body
    "mass_below_hollow": 399,  # Liu[40]: 0.03296 kg among 0.329 kg siblings
    "not_concrete": 517,  # Nie[51]: granite
    "depth_near_thickness": 6,  # Chen[3]: 0.17 m into 0.2 m
    "shallow": 348,  # Kim[32]: 9.28 mm deep with a 20 mm rod
    "eroding": 71,  # Frew[10]: 1009 m/s (a Sandia/WES shot)
    "transcription": 165,  # Gran & Frew 1997: 2.3 kg
    "duplicate": 1000,  # Zhao X N[89]'s shot quoted before by Guo L[17-18] (row 177)
}


@pytest.fixture(scope="module")
def df() -> pd.DataFrame:
    return comp.read_compilation()


def _row(df: pd.DataFrame, n: int) -> pd.Series:
    return df[df["row"] == n].iloc[0]


def test_every_row_of_the_compilation(df):
    assert list(df.columns) == list(comp.COLUMNS)
    assert list(df["row"]) == list(range(1, 1013))
    assert (df["xlsx_row"] == df["row"] + 1).all()
    assert df["reference_number"].nunique() == 89
    assert (df["reference"].str.len() > 20).all() and (df["set"] != "").all()


def test_rows_per_source(df):
    assert df.groupby("reference_key", sort=False).size().to_dict() == ROWS_PER_KEY
    counts = comp.source_counts(df)
    assert counts["rows"].sum() == 1012
    assert counts.loc["Wu B[70]", "first_row"] == 693 and counts.loc["Wu B[70]", "last_row"] == 699


def test_the_key_names_the_cited_reference(df):
    """Every key's bracket holds the reference the row cites (column R), e.g. both
    Almusallam[1] and Xu J B[1] cite reference [1]."""
    for key, n in zip(df["reference_key"], df["reference_number"], strict=True):
        spec = key.rsplit("[", 1)[1].rstrip("]")
        numbers = set()
        for part in spec.split(","):
            lo, _, hi = part.partition("-")
            numbers |= set(range(int(lo), int(hi or lo) + 1))
        assert n in numbers, (key, n)
    assert _row(df, 693)["reference"].startswith("Wu, B., Ren, H.Q., Chen, L., et al., 2020.")


def test_status_is_what_the_cleaning_says(df):
    """Every row's status, reasons and kept duplicate, recomputed from its inputs."""
    mismatches = comp.status_mismatches(df)
    assert mismatches.empty, mismatches.head().to_string()
    assert set(df["status"]) == {"clean", "set_aside"}
    assert ((df["reason"] == "") == (df["status"] == "clean")).all()


def test_the_header_counts_are_the_files(df):
    text = comp.COMPILATION_CSV.read_text(encoding="utf-8")
    counts = comp.reason_counts(df)
    clean = int((df["status"] == "clean").sum())
    assert f"Rows: 1012; clean {clean}; set aside {1012 - clean}." in text
    listed = dict(re.findall(r"(\w+) (\d+)[,.]", text.split("several): ")[1].split("\n")[0]))
    assert {k: int(v) for k, v in listed.items()} == counts["rows"].to_dict()


@pytest.mark.parametrize(("reason", "row"), sorted(NAMED.items()))
def test_every_reason_on_a_named_row(df, reason, row):
    r = _row(df, row)
    assert reason in comp.reason_codes(r["reason"]) and r["status"] == "set_aside"


def test_every_reason_is_used(df):
    counts = comp.reason_counts(df)
    assert (counts["rows"] > 0).all(), counts[counts["rows"] == 0]


def test_clean_rows_count(df):
    """Clean rows and the simple filter (mass at most 1.15 x the solid body, speed at most
    1000 m/s, depth at most 0.7 of the thickness): every row the filter keeps is clean
    unless shallow, a duplicate, a light-mass transcription or not concrete."""
    clean = df[df["status"] == "clean"]
    ratio = df["mass_kg"] / [
        comp.solid_mass(d, ln, c, rho)
        for d, ln, c, rho in zip(
            df["diameter_m"],
            df["length_m"],
            df["crh"],
            df["projectile_density_kg_m3"],
            strict=True,
        )
    ]
    simple = df[
        (ratio <= comp.MASS_RATIO_MAX)
        & (df["striking_velocity_m_s"] <= comp.ERODING_SPEED_M_S)
        & (df["depth_m"] <= comp.DEPTH_THICKNESS_MAX * df["target_thickness_m"])
    ]
    assert set(clean["row"]) <= set(simple["row"])
    others = {c for text in simple["reason"] for c in comp.reason_codes(text)}
    assert others == {"shallow", "duplicate", "mass_below_hollow", "transcription", "not_concrete"}
    assert len(clean) == 518 and len(simple) == 608


def test_the_mass_bounds_sit_in_gaps_of_the_data(df):
    """No compiled rod weighs 1.11 to 1.19 or 0.1 to 0.39 times the solid body of its
    outline: the bounds (1.15 and 0.3) do not cut through a group of rows."""
    ratio = np.array(
        [
            r.mass_kg / comp.solid_mass(r.diameter_m, r.length_m, r.crh, r.projectile_density_kg_m3)
            for r in df.itertuples()
        ]
    )
    assert not ((ratio > 1.11) & (ratio < 1.19)).any()
    assert not ((ratio > 0.1) & (ratio < 0.39)).any()
    assert comp.MASS_RATIO_MIN < 0.39 and 1.11 < comp.MASS_RATIO_MAX < 1.19


def test_non_number_cells_are_kept_visible(df):
    raw = [comp.parse_raw_cells(t) for t in df["raw_cells"]]
    cells = [(n, c, v) for n, r in zip(df["row"], raw, strict=True) for c, v in r.items()]
    assert len(cells) == 43
    assert (282, "striking_velocity_m_s", "214..7") in cells
    assert (842, "depth_m", "~1550") in cells
    assert (856, "depth_m", "~15") in cells and (469, "crh", "\u2014\u2014") in cells
    for n, column, _ in cells:
        assert math.isnan(_row(df, n)[column]), (n, column)
    # a text cell outside REQUIRED (the face area of rows 684-686) is no reason
    assert "target_area_m2" in raw[684] and _row(df, 685)["reason"] == "eroding"


def test_duplicates_name_the_kept_shot(df):
    dup = df[df["same_shot_as"].notna()]
    assert (dup["reason"].str.contains("duplicate")).all()
    for _, r in dup.iterrows():
        kept = _row(df, int(r["same_shot_as"]))
        for c in comp.DUPLICATE_KEY:
            assert kept[c] == r[c]
        assert "duplicate" not in kept["reason"]
    pairs = dict(zip(dup["row"], dup["same_shot_as"].astype(int), strict=True))
    # the same shots quoted by two sources: Zhao X N[89] and Guo L[17-18], Wan F[64] and
    # Jiang Z G[29], Liu Z L[42] and Feng[7], Gao F[12] and Gao[11]
    assert pairs[1000] == 177 and pairs[639] == 326 and pairs[417] == 28 and pairs[106] == 96


# -- each rule at its bound, on synthetic rows ----------------------------------------------

BASE = {
    "row": 1,
    "mass_kg": 0.5,
    "diameter_m": 0.02,
    "length_m": 0.2,
    "crh": 3.0,
    "projectile_density_kg_m3": 7850.0,
    "target_type": "C40",
    "target_density_kg_m3": 2400.0,
    "fc_pa": 40e6,
    "target_thickness_m": 1.0,
    "striking_velocity_m_s": 500.0,
    "depth_m": 0.3,
    "raw_cells": "",
}


def _reasons(**change):
    return comp.reasons_of({**BASE, **change})


def test_a_plain_row_is_clean():
    assert _reasons() == []


def test_mass_bounds():
    solid = comp.solid_mass(0.02, 0.2, 3.0, 7850.0)
    for ratio, expected in (
        (comp.MASS_RATIO_MAX * (1 - 1e-9), []),
        (comp.MASS_RATIO_MAX * (1 + 1e-9), ["mass_above_solid"]),
        (comp.MASS_RATIO_MIN * (1 + 1e-9), []),
        (comp.MASS_RATIO_MIN * (1 - 1e-9), ["mass_below_hollow"]),
    ):
        assert _reasons(mass_kg=ratio * solid) == expected, ratio


def test_depth_against_thickness_bound_is_exact():
    # 0.7 x 0.6 is 0.41999999999999993 in binary: the bound compares the decimals
    assert _reasons(target_thickness_m=0.6, depth_m=0.42) == []
    assert _reasons(target_thickness_m=0.6, depth_m=0.4200001) == ["depth_near_thickness"]


def test_shallow_bounds():
    assert _reasons(depth_m=0.02) == []  # one diameter deep
    assert _reasons(depth_m=0.0199999) == ["shallow"]
    assert _reasons(striking_velocity_m_s=100.0, depth_m=0.05) == []
    assert _reasons(striking_velocity_m_s=99.99, depth_m=0.05) == ["shallow"]


def test_eroding_bound():
    assert _reasons(striking_velocity_m_s=comp.ERODING_SPEED_M_S) == []
    assert _reasons(striking_velocity_m_s=1000.01) == ["eroding"]


def test_outline_bounds():
    assert _reasons(crh=0.5, mass_kg=0.3) == []  # a hemispherical nose
    assert _reasons(crh=0.49) == ["no_outline"]
    nose = comp.nose_length(0.02, 3.0)
    assert _reasons(length_m=nose) == ["no_outline"]
    assert "no_outline" not in _reasons(length_m=nose * (1 + 1e-9))


def test_cells_that_are_not_numbers():
    assert _reasons(depth_m=math.nan, raw_cells="depth_m=~15") == ["text_cell"]
    assert _reasons(crh=math.nan) == ["empty_cell"]
    # an optional column's text is kept and sets nothing aside
    assert _reasons(raw_cells="target_area_m2=-") == []


def test_not_concrete_and_transcription():
    assert _reasons(target_type="Granite") == ["not_concrete"]
    assert comp.reasons_of(BASE, frozenset({1})) == ["transcription"]
    assert comp.reasons_of(BASE, frozenset({2})) == []


def test_duplicates_keep_the_first_row_free_of_other_reasons():
    rows = pd.DataFrame([{**BASE, "row": n} for n in (5, 3, 9)])
    out = comp.clean(rows)
    assert list(out["reason"]) == ["duplicate", "", "duplicate"]
    assert list(out["same_shot_as"]) == [3, pd.NA, 3]
    # the first row set aside for another reason: the next one is kept
    rows.loc[1, "striking_velocity_m_s"] = 500.0
    rows.loc[1, "target_type"] = "granite"
    out = comp.clean(rows)
    assert list(out["reason"]) == ["", "not_concrete; duplicate", "duplicate"]
    assert list(out["same_shot_as"]) == [pd.NA, 5, 5]
    # another speed is another shot
    rows.loc[2, "striking_velocity_m_s"] = 501.0
    assert list(comp.clean(rows)["reason"]) == ["", "not_concrete; duplicate", ""]


def test_solid_mass_is_the_geometry_s():
    """The closed form against the outline's Gauss-Legendre quadrature of pencore's
    geometry (exact for the cylinder, converged to round-off on the ogive)."""
    from pencore.inputs.geometry import Cylinder, OgiveNose, Projectile

    for d, ln, crh in ((0.0129, 0.0889, 3.0), (0.0762, 0.53073, 6.0), (0.04, 0.086, 0.5)):
        nose = comp.nose_length(d, crh)
        p = Projectile("p", d, OgiveNose(crh, 7850.0), (Cylinder(ln - nose, 7850.0),))
        assert comp.solid_mass(d, ln, crh, 7850.0) == pytest.approx(
            p.mass_properties().mass, rel=1e-10
        )


# -- the Sandia/WES subset ------------------------------------------------------------------


STRENGTHS = {
    "projectile_ultimate_pa": "ultimate_strength_pa",
    "projectile_yield_pa": "yield_strength_pa",
}


@pytest.mark.parametrize(
    ("path", "rows"), [(SANDIA, 107), (REPO / "config" / "concrete_scaled_series.csv", 7)]
)
def test_the_shot_files_are_subsets_with_the_same_numbers(df, path, rows):
    """The Sandia/WES rows and Wu et al.'s scaled series (the size term's fit rows) are
    rows of the compilation, number for number."""
    old = pd.read_csv(path, comment="#").rename(columns=STRENGTHS)
    assert len(old) == rows
    new = df.set_index("row").loc[old["row"]]
    for column in old.columns:
        if column in ("row", "reference"):  # the reference: a short form there, in full here
            continue
        a, b = old[column].to_numpy(), new[column].to_numpy()
        if column == "target_area_m2":
            # that file gives areas to 8 decimals (0.073061835 -> 0.07306184, its header)
            a, b = np.round(a.astype(float), 8), np.round(b.astype(float), 8)
        if a.dtype.kind == "f" or column in comp.NUMBER_COLUMNS:
            np.testing.assert_array_equal(a.astype(float), b.astype(float), err_msg=column)
        else:
            assert list(a.astype(str)) == list(b.astype(str)), column


# -- the clean rows are a body shot table ----------------------------------------------------


def test_the_body_shot_reader_gives_the_clean_rows(df):
    from pencore.studies.validation.bodies import body_projectile

    body = read_body_shot_table(comp.COMPILATION_CSV)
    clean = comp.clean_rows()
    assert list(body["row"].astype(int)) == list(clean["row"])
    assert set(BODY_SHOT_COLUMNS) <= set(df.columns)
    for _, r in body.iterrows():  # every clean rod has a body of its outline
        assert body_projectile(r, r["set"]).mass_properties().mass == pytest.approx(r["mass_kg"])


def test_rows_allowing(df):
    rows = comp.rows_allowing(df, {"eroding"})
    assert set(rows["row"]) >= set(comp.clean_rows()["row"])
    assert len(rows) == 518 + comp.reason_counts(df).loc["eroding", "only"]
    with pytest.raises(InputError, match="unknown reason codes"):
        comp.rows_allowing(df, {"erosion"})


# -- the scaled series ----------------------------------------------------------------------


def test_the_series_column_is_the_series_file(df):
    series = comp.read_series()
    of_row = dict(zip(series["row"], series["series"], strict=True))
    assert dict(zip(df["row"], df["series"], strict=True)) == {
        n: of_row.get(n, "") for n in df["row"]
    }
    assert sorted(series[series["series"] == "wu2020_scale"]["row"]) == list(range(693, 700))


@pytest.mark.parametrize("name", ["wu2020_scale", "wu2019_scale", "frew2006_scale",
                                  "forrestal1996_scale", "xu2001_scale"])  # fmt: skip
def test_a_series_is_geometrically_scaled(df, name):
    """One reference and CRH, two or more diameters, L/d within 1 % and M/d^3 within 3 %
    (the per-diameter medians)."""
    rows = df[df["series"] == name]
    assert rows["reference_number"].nunique() == 1 and rows["crh"].nunique() == 1
    per_d = rows.groupby("diameter_m").agg(ld=("length_m", "median"), m=("mass_kg", "median"))
    assert len(per_d) >= 2
    ld = per_d["ld"] / per_d.index
    md3 = per_d["m"] / per_d.index**3
    assert ld.max() / ld.min() - 1 < 0.01 and md3.max() / md3.min() - 1 < 0.03


# -- the errata -----------------------------------------------------------------------------


def test_every_erratum_is_a_compiled_cell_with_evidence(df):
    errata = comp.read_errata()
    for _, e in errata.iterrows():
        r = _row(df, e["row"])
        assert float(r[e["column"]]) == float(e["compiled"]), e["row"]
        assert "transcription" in r["reason"]
    assert set(errata["row"]) == set(df["row"][df["reason"].str.contains("transcription")])


# -- the reader's refusals ------------------------------------------------------------------


def _write(tmp_path, df: pd.DataFrame) -> Path:
    path = tmp_path / "c.csv"
    path.write_text(df.to_csv(index=False))
    return path


@pytest.mark.parametrize(
    ("column", "value", "words"),
    [
        ("status", "maybe", "status \\['maybe'\\]"),
        ("reason", "eroded", "reason codes \\['eroded'\\]"),
        ("depth_m", "~15", "column depth_m holds text"),
        ("row", 2, "duplicate rows \\[2\\]"),
    ],
)
def test_the_reader_refuses(tmp_path, df, column, value, words):
    bad = df.head(3).copy()
    bad[column] = bad[column].astype(object)
    bad.loc[0, column] = value
    with pytest.raises(InputError, match=words):
        comp.read_compilation(_write(tmp_path, bad))


def test_the_body_reader_leaves_out_rows_set_aside(tmp_path, df):
    rows = df[df["row"].isin([281, 282])].copy()  # a clean row and '214..7'
    assert list(rows["status"]) == ["clean", "set_aside"]
    body = read_body_shot_table(_write(tmp_path, rows))
    assert list(body["row"]) == ["281"]
    rows["status"] = "set_aside"
    with pytest.raises(InputError, match="no row of status clean"):
        read_body_shot_table(_write(tmp_path, rows))


# -- the table is what the snapshot gives ----------------------------------------------------


@pytest.mark.skipif(
    not os.environ.get("PENCORE_COMPILATION_SNAPSHOT"),
    reason="PENCORE_COMPILATION_SNAPSHOT (a snapshot of the compilation) not set",
)
def test_the_table_is_rebuilt_from_the_snapshot(tmp_path):
    pytest.importorskip("openpyxl")
    pytest.importorskip("docx")
    out = tmp_path / "c.csv"
    done = subprocess.run(
        [
            sys.executable,
            str(REPO / "tools" / "concrete_compilation.py"),
            os.environ["PENCORE_COMPILATION_SNAPSHOT"],
            "--out",
            str(out),
        ],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert out.read_text(encoding="utf-8") == comp.COMPILATION_CSV.read_text(encoding="utf-8")
