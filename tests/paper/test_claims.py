"""The paper's claims as data (pencore/paper/data/paper_claims.csv, linked from
config/): the file is checked, every claim has a handler, and the comparison table's paper
values are the file's."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.io.netcdf import read_netcdf
from pencore.paper.claims import at, disputed_values, load_claims, paper_values
from pencore.studies.comparison import HANDLERS, paper_comparison

REPO = Path(__file__).resolve().parents[2]
ARCHIVE = REPO / "results" / "archive"


def test_every_claim_has_a_handler_and_a_place_in_the_paper():
    df = load_claims()
    assert len(df) >= 30
    assert set(df["computed_by"]) <= set(HANDLERS)
    assert (df["where"].str.len() > 0).all()
    assert set(df["provenance"]) <= {"paper", "derived"}
    # a derived claim says how in its note
    assert (df[df["provenance"] == "derived"]["note"].str.contains("derived")).all()


def test_attribution_and_studies_read_the_file():
    df = load_claims().set_index("id")
    pv = paper_values()
    disputed = disputed_values()
    assert pv["fig16_alpha_deg"] == {5.0: 0.14, 20.0: 2.86}
    assert pv["fig16_alpha_deg"][20.0] == float(df.loc["fig16_alpha_20", "value"])
    assert disputed["phi_p4"][1000.0] == float(df.loc["fig13_phi_1000", "value"])
    assert disputed["vcr_bracket"] == (
        float(df.loc["vcr_p2_45", "value"]),
        float(df.loc["vcr_p2_45", "value_hi"]),
    )


def test_at_parses_conditions():
    assert at("velocity=1641;velocity=1650") == [{"velocity": 1641.0}, {"velocity": 1650.0}]
    assert at("projectile=p2;obliquity=45") == [{"projectile": "p2", "obliquity": 45.0}]
    assert at("") == [{}]
    with pytest.raises(InputError, match="key=value"):
        at("velocity")


def _set(claim_id, column, value):
    return lambda d: d.assign(**{column: d[column].where(d["id"] != claim_id, value)})


@pytest.mark.parametrize(
    "edit, needle",
    [
        (lambda d: d.assign(kind=["guess"] + list(d["kind"][1:])), "kind must be one of"),
        (lambda d: pd.concat([d, d.iloc[[3]]]), "duplicate id"),
        (lambda d: d.drop(columns=["where"]), "lacks column"),
        (_set("fig16_alpha_5", "value", "x"), "not a number"),
        (_set("vcr_p2_45", "value_hi", "1000"), "value < value_hi"),
        (_set("fig8_vcr_lc", "value", "wiggles"), "rises or falls"),
        (_set("fig13_phi_280", "provenance", "memory"), "provenance"),
    ],
)
def test_bad_claims_files_one_line(tmp_path, edit, needle):
    bad = edit(load_claims().copy())
    path = tmp_path / "claims.csv"
    bad.to_csv(path, index=False)
    with pytest.raises(InputError, match=needle) as e:
        load_claims(path)
    assert "\n" not in str(e.value)


def test_unknown_handler_is_named(tmp_path):
    df = load_claims().copy()
    df.loc[df.index[0], "computed_by"] = "fig99"
    with pytest.raises(InputError, match="fig99"):
        paper_comparison(claims=df, table3=False)


def test_comparison_rows_come_from_the_claims():
    """On the archived datasets: every row names its claim, the paper values are the
    claims' (brackets at their midpoint), and editing a claim's value edits the table."""
    names = {
        "fig7": "fig7/trajectories", "fig8": "fig8/vcr", "fig13": "fig13/trajectories",
        "fig16": "fig16/trajectories", "fig18": "fig18/omega_c",
    }  # fmt: skip
    data = {k: read_netcdf(ARCHIVE / f"{v}.nc") for k, v in names.items()}
    claims = load_claims()
    df = paper_comparison(datasets=data, claims=claims, table3=False)
    assert set(df["claim"]) <= set(claims["id"])
    byid = claims.set_index("id")
    for _, r in df[df["kind"] == "value"].iterrows():
        c = byid.loc[r["claim"]]
        expect = float(c["value"])
        if c["kind"] == "bracket":
            expect = 0.5 * (expect + float(c["value_hi"]))
        assert float(r["paper_value"]) == pytest.approx(expect, rel=1e-6), r["quantity"]
    edited = claims.copy()
    edited.loc[edited["id"] == "fig16_alpha_20", "value"] = "9.99"
    df2 = paper_comparison(datasets=data, claims=edited, table3=False)
    row = df2[df2["claim"] == "fig16_alpha_20"].iloc[0]
    assert float(row["paper_value"]) == 9.99
