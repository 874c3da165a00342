"""pencore.inputs.record: comparable shots, the band from their ratios, the shipped record."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.errors import InputError
from pencore.inputs import record
from pencore.inputs.record import Scores, band_factors, comparable, depth_band


def scores(n: int = 20, **over) -> Scores:
    base = dict(
        law="demo",
        source=np.array([f"s{i % 4}" for i in range(n)]),
        diameter=np.full(n, 0.02),
        fc=np.full(n, 40e6),
        velocity=np.full(n, 500.0),
        crh=np.full(n, 3.0),
        ratio=np.linspace(0.5, 1.5, n),
        nominal_level=0.9,
        held_out_coverage=0.81,
    )
    base.update(over)
    return Scores(**base)


def test_comparable_windows_are_factors_and_a_crh_margin():
    d = np.array([0.01, 0.0099, 0.04, 0.0405, 0.02, 0.02, 0.02, 0.02])
    fc = np.array([40e6] * 4 + [25e6, 64e6, 24.9e6, 40e6])
    crh = np.array([3.0] * 7 + [4.6])
    s = scores(8, diameter=d, fc=fc, crh=crh)
    m = comparable(s, 0.02, 40e6, 500.0, 3.0)
    # a factor 2 in diameter both ways, 1.6 in fc, CRH within 1.5
    assert m.tolist() == [True, False, True, False, True, True, False, False]
    v = scores(3, velocity=np.array([358.0, 700.0, 701.0]))
    assert comparable(v, 0.02, 40e6, 500.0, 3.0).tolist() == [True, True, False]
    # a nose that is no ogive matches nothing
    assert not comparable(s, 0.02, 40e6, 500.0, math.nan).any()


def test_band_factors_are_central_quantiles():
    r = np.arange(1.0, 102.0)  # 1 .. 101
    assert band_factors(r, 0.8) == pytest.approx((11.0, 91.0), rel=1e-15)
    assert band_factors(r, 1.0) == (1.0, 101.0)


def test_depth_band_scales_the_prediction_and_says_where_it_comes_from():
    s = scores()
    b = depth_band(s, 2.0, diameter=0.02, fc=40e6, velocity=500.0, crh=3.0)
    lo, hi = np.quantile(s.ratio, [0.05, 0.95])
    assert (b.lo, b.hi) == pytest.approx((2 * lo, 2 * hi), rel=1e-15)
    assert b.n_shots == 20 and b.n_sources == 4 and b.level == record.STATED_LEVEL
    assert b.nominal_level == 0.9 and b.held_out_coverage == 0.81
    assert b.ranges["diameter"] == (0.02, 0.02)
    assert "20 comparable shots from 4 sources" in b.describe()
    # too few comparable shots: no band
    assert depth_band(s, 2.0, diameter=0.2, fc=40e6, velocity=500.0, crh=3.0) is None
    few = scores(record.MIN_SHOTS - 1)
    assert depth_band(few, 2.0, diameter=0.02, fc=40e6, velocity=500.0, crh=3.0) is None


def test_read_scores_refuses_a_record_that_does_not_match_its_calibration(tmp_path):
    rec, cal = tmp_path / "r.csv", tmp_path / "b.yaml"
    rec.write_text("# x\n" + ",".join(record.RECORD_COLUMNS) + "\nf,1,a,0.02,4e7,500,3,1.1\n")
    cal.write_text("laws: {g: {nominal_level: 0.9, held_out_coverage: 0.8}}\n")
    with pytest.raises(InputError, match="no calibration of law 'f'"):
        record.read_scores(rec, cal)
    cal.write_text("laws: {f: {nominal_level: 0.9, held_out_coverage: 0.8}}\n")
    assert record.read_scores(rec, cal)["f"].ratio.tolist() == [1.1]
    rec.write_text("law,row\nf,1\n")
    with pytest.raises(InputError, match="columns must be"):
        record.read_scores(rec, cal)
    assert record.read_scores(tmp_path / "none.csv", cal) == {}


def test_the_shipped_record_scores_every_law_with_a_calibrated_level():
    from pencore.analysis.record import LEVELS

    shipped = record.read_scores()
    assert set(shipped) == set(record.RECORD_LAWS)
    assert record.DEFAULT_RECORD_LAW in shipped
    for law, s in shipped.items():
        assert s.nominal_level in LEVELS, law
        # a held-out coverage below the stated level is only possible at the widest level
        assert s.held_out_coverage >= record.STATED_LEVEL or s.nominal_level == max(LEVELS)
        assert np.all(s.ratio > 0) and np.all(np.isfinite(s.ratio)), law
