"""pencore.analysis.record: binned statistics and the band's held-out calibration."""

from __future__ import annotations

import numpy as np
import pytest

from pencore.analysis.record import binned, calibrate_level, held_out_bands
from pencore.errors import InputError
from pencore.inputs.record import Scores


def test_binned_statistics_by_hand():
    e = np.array([0.1, -0.3, 0.5, 0.2, np.nan])
    x = np.array([1.0, 2.0, 3.0, 10.0, 1.0])
    b = binned(e, x, [0.0, 5.0, 20.0, 30.0])
    assert b["n"].tolist() == [3, 1, 0]
    assert b["median_error"][:2].tolist() == [0.1, 0.2]
    assert b["median_abs_error"][0] == pytest.approx(0.3)
    assert b["mean_abs_error"][0] == pytest.approx(0.3)
    assert b["within"][:2].tolist() == [pytest.approx(1 / 3), 1.0]
    assert np.isnan(b["median_error"][2])
    with pytest.raises(InputError, match="edges must increase"):
        binned(e, x, [1.0, 1.0])


def _scores(ratio: np.ndarray, source: np.ndarray) -> Scores:
    n = ratio.size
    return Scores("demo", source, np.full(n, 0.02), np.full(n, 40e6), np.full(n, 500.0),
                  np.full(n, 3.0), ratio, np.nan, np.nan)  # fmt: skip


def test_held_out_bands_never_use_the_shots_own_source():
    # two sources, each its own cluster: a shot's band comes from the other one only
    ratio = np.r_[np.full(12, 1.0), np.full(12, 2.0)]
    source = np.repeat(["a", "b"], 12)
    lo, hi, n = held_out_bands(_scores(ratio, source), 0.8)
    assert n.tolist() == [12] * 24
    assert lo[:12].tolist() == [2.0] * 12 and lo[12:].tolist() == [1.0] * 12


def test_calibration_widens_the_band_when_sources_differ():
    rng = np.random.default_rng(7)
    # 20 sources, each with its own offset: bands from other sources hold fewer of a
    # source's shots than the nominal level says, so the level must widen
    src = np.repeat(np.arange(20).astype(str), 15)
    offset = np.repeat(rng.normal(0.0, 0.25, 20), 15)
    ratio = np.exp(offset + rng.normal(0.0, 0.1, src.size))
    c = calibrate_level(_scores(ratio, src))
    assert c.coverage_at_stated < 0.8
    assert c.nominal_level > 0.8 and c.held_out_coverage >= 0.8
    assert c.n_with_band == c.n_shots == 300
    # one source: no shot has comparable shots of another source, so no band at all
    one = calibrate_level(_scores(ratio, np.full(ratio.size, "a")))
    assert one.n_with_band == 0 and np.isnan(one.held_out_coverage)
