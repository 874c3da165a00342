"""pencore.studies.validation.record: the concrete record scored by the solver, its held-out
statistics, and the shipped record and band calibration made from the archive."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pencore import closedform
from pencore.analysis.record import calibrate_level
from pencore.inputs.laws import size_term_constants
from pencore.inputs.record import BANDS_FILE, DEFAULT_RECORD_LAW, RECORD_LAWS, read_scores
from pencore.io.netcdf import read_netcdf
from pencore.measured.compilation import read_compilation, reason_counts
from pencore.studies.validation import record as R
from pencore.studies.validation.bodies import body_projectile
from pencore.studies.validation.size_term import fit_d0, fit_rows, implied_factors

ROOT = Path(__file__).resolve().parents[3]
ARCHIVE = ROOT / "results" / "archive" / "validation"


@pytest.fixture(scope="module")
def rows() -> pd.DataFrame:
    return R.record_rows_to_score()


def test_the_rows_scored_are_the_clean_and_the_eroding_only(rows):
    df = read_compilation()
    assert (rows["group"] == "clean").sum() == (df["status"] == "clean").sum()
    assert (rows["group"] == "eroding").sum() == reason_counts(df).loc["eroding", "only"]
    fit = {str(r) for r in size_term_constants()["rows"]}
    assert set(rows.loc[rows["in_fit"], "row"].astype(str)) <= fit
    assert len(R.record_rows_to_score(every=40)) == math.ceil(len(rows) / 40)
    with pytest.raises(Exception, match="every must be a whole number"):
        R.record_rows_to_score(every=0)


def test_a_law_meets_the_exact_1d_depth_and_its_held_out_refit(rows):
    # normal impact: pencore's depth is the model's exact 1-D depth within 2e-3 (the
    # verification study's tolerance); the size term refitted without the row's source
    fit_sources = sorted(set(rows.loc[rows["in_fit"], "reference_key"]))
    sub = pd.concat(
        [rows[rows["reference_key"] == fit_sources[0]].head(2), rows[~rows["in_fit"]].head(3)]
    ).reset_index(drop=True)
    ds = R.score_law("forrestal_size", sub)
    for i, (_, r) in enumerate(sub.iterrows()):
        proj = body_projectile(r, "rod")
        medium = R.law_medium(r, "forrestal_size")
        exact = closedform.depth(proj, medium, float(r["striking_velocity_m_s"]))
        assert float(ds["predicted"][i]) == pytest.approx(exact, rel=2e-3)
    shots = fit_rows()
    keep = shots["reference_key"] != fit_sources[0]
    f = implied_factors(shots[keep], "forrestal", "none")
    spec = size_term_constants()
    d0 = fit_d0(shots["diameter_m"][keep], f, shots["row"][keep], spec["d_ref_m"]).d0
    assert ds["held_out_d0"].values[:2].tolist() == [d0, d0]
    assert np.isnan(ds["held_out_d0"].values[2:]).all()
    assert (ds["held_out_predicted"].values[2:] == ds["predicted"].values[2:]).all()
    assert (ds["held_out_predicted"].values[:2] != ds["predicted"].values[:2]).all()


@pytest.fixture(scope="module")
def archived():
    ds = read_netcdf(ARCHIVE / "concrete_record.nc")
    stats = read_netcdf(ARCHIVE / "concrete_record_stats.nc")
    return ds, stats


def test_the_archive_scores_every_law_on_at_least_the_clean_rows(archived):
    ds, stats = archived
    assert set(RECORD_LAWS) <= set(ds["model"].values.astype(str))
    assert (ds["group"] == "clean").sum() == (read_compilation()["status"] == "clean").sum()
    for law in RECORD_LAWS:
        out = ds["outcome"].sel(model=law).values.astype(str)
        assert not any(o.startswith("solver_error") for o in out), law
        ok = np.isfinite(ds["predicted"].sel(model=law).values)
        assert all((o == "stopped") == k for o, k in zip(out, ok, strict=True)), law


def test_the_default_law_is_the_best_on_held_out_sources(archived):
    _, stats = archived
    assert stats.attrs["best_law"] == DEFAULT_RECORD_LAW
    laws = list(RECORD_LAWS)
    crit = stats[f"overall_{R.CRITERION}"].sel(rows="held_out", model=laws).values
    assert laws[int(np.argmin(crit))] == DEFAULT_RECORD_LAW


def test_the_statistics_recompute_from_the_archived_record(archived):
    ds, stats = archived
    again = R.record_statistics(ds)  # ds as read back: its flags are int8, not bool
    for v in stats.data_vars:
        np.testing.assert_array_equal(stats[v].values, again[v].values, err_msg=v)
    assert again.attrs["best_law"] == stats.attrs["best_law"]


def test_the_band_calibration_recomputes_from_the_archive(archived):
    ds, stats = archived
    for law in RECORD_LAWS:
        c = calibrate_level(R.scores(ds, law))
        assert stats["nominal_level"].sel(model=law) == c.nominal_level
        assert stats["held_out_coverage"].sel(model=law) == pytest.approx(c.held_out_coverage)
        # the stated coverage holds on held-out sources at the calibrated level
        assert c.held_out_coverage >= 0.8


def test_the_shipped_record_is_the_archives(archived, tmp_path):
    ds, stats = archived
    R.write_record(str(ARCHIVE), tmp_path / "r.csv", tmp_path / "b.yaml")
    shipped = read_scores()
    again = read_scores(tmp_path / "r.csv", tmp_path / "b.yaml")
    assert set(shipped) == set(again)
    for law, s in shipped.items():
        a = again[law]
        assert s.source.tolist() == a.source.tolist()
        for k in ("diameter", "fc", "velocity", "crh", "ratio"):
            np.testing.assert_array_equal(getattr(s, k), getattr(a, k), err_msg=k)
        assert (s.nominal_level, s.held_out_coverage) == (a.nominal_level, a.held_out_coverage)
    assert yaml.safe_load(BANDS_FILE.read_text()) == yaml.safe_load(
        (tmp_path / "b.yaml").read_text()
    )


def test_statistics_table_round_trips_the_statistics(archived):
    _, stats = archived
    t = R.statistics_table(stats)
    row = t[(t.model == DEFAULT_RECORD_LAW) & (t.grouping == "overall") & (t.group == "held_out")]
    assert float(row["median_abs_error"].iloc[0]) == float(
        stats["overall_median_abs_error"].sel(model=DEFAULT_RECORD_LAW, rows="held_out")
    )
    assert set(t["grouping"]) == {"overall", *R.BINS, "source", "regime"}
