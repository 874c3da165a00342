"""Ensemble (Monte Carlo) studies (pencore.studies.ensemble): seeded sampling independent
of chunking, distributions respected, statistics with their closed
forms, and samples that are the solver's own runs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers import ENSEMBLE_CASE

from pencore import simulate
from pencore.errors import InputError
from pencore.studies.ensemble import (
    chunk_indices,
    gather,
    quantile_interval,
    run_chunk,
    sample_conditions,
    wilson_interval,
)

CASE = ENSEMBLE_CASE


def test_sampling_is_seeded_and_respects_the_distributions():
    a, b = sample_conditions(CASE), sample_conditions({**CASE, "n_chunks": 1})
    for k in a:
        np.testing.assert_array_equal(a[k], b[k])  # the chunking does not enter
    c = sample_conditions({**CASE, "seed": 6})
    assert not np.array_equal(a["velocity_m_s"], c["velocity_m_s"])
    v = a["velocity_m_s"]
    assert v.min() >= 1200 and v.max() <= 1500  # truncation
    assert np.all(a["yaw_deg"] == 0.5)
    o = a["obliquity_deg"]
    assert o.min() >= 30 and o.max() <= 60
    # uniform mean within 4 standard errors (sd of U(30, 60) is 30 / sqrt(12))
    assert abs(o.mean() - 45.0) < 4 * (30 / math.sqrt(12)) / math.sqrt(o.size)
    # a larger N starts with the same samples (one stream per variable)
    d = sample_conditions({**CASE, "n_samples": 4000})
    np.testing.assert_array_equal(d["obliquity_deg"][:2000], o)


def test_chunks_partition_the_samples():
    n, k = 103, 7
    got = np.concatenate([chunk_indices(n, k, i) for i in range(k)])
    np.testing.assert_array_equal(got, np.arange(n))
    with pytest.raises(InputError, match="chunk 7 outside"):
        chunk_indices(n, k, 7)


def test_wilson_interval_properties():
    lo, hi = wilson_interval(0, 50)
    assert lo == 0.0 and hi == pytest.approx(1.959963984540054**2 / (50 + 3.841458820694124))
    lo, hi = wilson_interval(30, 100)
    assert lo < 0.3 < hi
    # width shrinks like 1/sqrt(n) at fixed p
    w1 = np.subtract(*wilson_interval(300, 1000)[::-1])
    w2 = np.subtract(*wilson_interval(1200, 4000)[::-1])
    assert w1 / w2 == pytest.approx(2.0, rel=0.02)
    with pytest.raises(InputError):
        wilson_interval(5, 3)


def test_quantile_interval_covers_the_true_median():
    rng = np.random.default_rng(0)
    hits = 0
    for _ in range(400):
        est, lo, hi = quantile_interval(rng.normal(size=101), 0.5)
        hits += lo <= 0.0 <= hi
    # the order-statistic interval has coverage >= 95 %; 400 trials: sd of the rate 1.1 %
    assert hits / 400 >= 0.92


def test_samples_are_the_solver_runs_and_gather_joins_chunks():
    case = {**CASE, "n_samples": 6, "n_chunks": 2}
    parts = [run_chunk(case, 1), run_chunk(case, 0)]
    ds = gather(parts)
    np.testing.assert_array_equal(ds["sample"].values, np.arange(6))
    one = gather([run_chunk({**case, "n_chunks": 1}, 0)])
    np.testing.assert_array_equal(ds["penetration_depth"].values, one["penetration_depth"].values)
    cond = sample_conditions(case)
    i = 4
    run = simulate(
        "p2",
        "soil",
        cond["velocity_m_s"][i],
        cond["obliquity_deg"][i],
        cond["yaw_deg"][i],
        cond["omega_rad_s"][i],
        azimuth=cond["azimuth_deg"][i],
    )
    assert float(ds["path_length"][i]) == float(run["path_length"])
    assert str(ds["outcome"].values[i]) == run.attrs["outcome"]
    k = int(ds["reversed"].sum())
    assert float(ds["p_reversed"]) == k / 6
    with pytest.raises(InputError, match="cover samples"):
        gather([parts[0]])
    # every variable and coordinate says what it is (CF: long_name; checked in CI by the
    # compliance-checker on the archived ensemble)
    unnamed = [v for v in ds.variables if not ds[v].attrs.get("long_name")]
    assert unnamed == []


def test_azimuth_only_turns_the_trajectory():
    """The target is invariant about its normal, so with everything else fixed the
    azimuth changes neither depth nor downrange, and the motion stays in the impact plane
    (cross_range is integration noise: the adaptive steps differ from run to run at
    round-off, about rtol times the path)."""
    case = {**CASE, "n_samples": 4, "n_chunks": 1, "velocity_m_s": 1000.0,
            "obliquity_deg": 40.0, "omega_rad_s": 0.0}  # fmt: skip
    ds = run_chunk(case, 0)
    path = float(ds["path_length"].max())
    tol = 1e-4 * path  # 10 x the default rtol (1e-5) of the path: integration error only
    assert np.ptp(ds["downrange"].values) < tol
    assert np.ptp(ds["penetration_depth"].values) < tol
    assert np.abs(ds["cross_range"].values).max() < tol
