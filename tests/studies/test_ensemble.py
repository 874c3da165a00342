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


def _wilson_by_hand(k, n, z=1.959963984540054):
    """The Wilson score interval as pencore wrote it before it called scipy."""
    p = k / n
    den = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / den
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / den
    return (0.0 if k == 0 else centre - half), (1.0 if k == n else centre + half)


def _quantile_by_hand(x, q, level=0.95):
    """The order-statistic interval as pencore wrote it before it called scipy."""
    from scipy import stats

    xs = np.sort(np.asarray(x, float))
    n = xs.size
    lo = int(stats.binom.ppf((1 - level) / 2, n, q))
    hi = int(stats.binom.ppf(1 - (1 - level) / 2, n, q)) + 1
    return (
        float(np.quantile(xs, q)),
        float(xs[max(lo - 1, 0)]) if lo >= 1 else -math.inf,
        float(xs[hi - 1]) if hi <= n else math.inf,
    )


def test_scipys_wilson_interval_is_the_hand_written_one():
    """scipy's Wilson interval against the formula it replaced: the same interval, to
    round-off. The two evaluate it in a different order; each end is a centre and a
    half-width below 1, so they differ by a few machine epsilons absolute (measured 1.5
    eps over n = 1..199 and every k; 4 eps allowed), and the ends 0 and 1 are exact."""
    eps = np.finfo(float).eps
    for n in (1, 2, 3, 5, 8, 16, 32, 50, 100, 1000, 1024, 4000):
        for k in range(0, n + 1, max(1, n // 37)):
            got, ref = wilson_interval(k, n), _wilson_by_hand(k, n)
            np.testing.assert_allclose(got, ref, rtol=0.0, atol=4 * eps)
        assert wilson_interval(0, n)[0] == 0.0 and wilson_interval(n, n)[1] == 1.0


def test_scipys_quantile_interval_is_the_hand_written_one():
    """scipy's quantile_test interval picks the same order statistics, so the same
    numbers bit for bit, and the same infinite ends where so few samples bound nothing."""
    rng = np.random.default_rng(1)
    for n in (1, 2, 3, 5, 8, 10, 16, 20, 31, 50, 101, 256, 1024):
        x = rng.normal(size=n)
        for q in (0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.95):
            assert quantile_interval(x, q) == _quantile_by_hand(x, q), (n, q)


def test_the_archived_ensembles_statistics_are_unchanged():
    """The gathered statistics of the archived ensemble, recomputed from its samples with
    scipy's intervals: quantile intervals bit for bit; Wilson intervals bit for bit but
    one end of the running interval at N = 32, one unit in the last place away (the
    order of the operations)."""
    from pathlib import Path

    import xarray as xr

    path = Path(__file__).resolve().parents[2] / "results/archive/ensemble/p2_soil_oblique.nc"
    with xr.open_dataset(path) as arch:
        ds = arch.load()
    n = ds.sizes["sample"]
    for k in ("reversed", "perforated"):
        assert wilson_interval(int(ds[k].sum()), n) == tuple(ds[f"p_{k}_ci95"].values)
    rev = ds["reversed"].values
    got = [wilson_interval(int(rev[:m].sum()), int(m)) for m in ds["n_used"].values]
    np.testing.assert_array_max_ulp(np.array(got), ds["running_p_reversed_ci95"].values, 1)
    for name in ("penetration_depth", "path_length", "downrange", "final_deviation"):
        qs = [quantile_interval(ds[name].values, q) for q in ds["quantile"].values]
        np.testing.assert_array_equal([q[0] for q in qs], ds[f"{name}_quantile"].values)
        np.testing.assert_array_equal([q[1:] for q in qs], ds[f"{name}_quantile_ci95"].values)


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


ANGLE_OF_ATTACK = {
    **CASE,
    "yaw_convention": "axis_tilted",
    "obliquity_deg": {"dist": "uniform", "min": 0, "max": 30},
    "yaw_deg": {"dist": "normal", "mean": 0, "sd": 2.0, "min": -5, "max": 5},
}


def test_an_angle_of_attack_draws_obliquity_and_yaw_tied():
    """axis_tilted: the draws are the same numbers as the default reading's (same seed),
    read as the velocity's angle and the axis's tilt from it, so every sample has
    simulate's obliquity = drawn obliquity + drawn yaw and simulate's yaw = -drawn yaw:
    the velocity stays at the drawn obliquity (obliquity + yaw), the axis moves."""
    from pencore.studies.ensemble import run_angles

    cond = sample_conditions(ANGLE_OF_ATTACK)
    same = sample_conditions({**ANGLE_OF_ATTACK, "yaw_convention": "velocity_tilted"})
    for k in cond:
        np.testing.assert_array_equal(cond[k], same[k])
    obl, yaw = run_angles(cond, "axis_tilted")
    np.testing.assert_array_equal(yaw, -cond["yaw_deg"])
    np.testing.assert_array_equal(obl, cond["obliquity_deg"] + cond["yaw_deg"])
    # the velocity's angle, obliquity + yaw, is the drawn one to round-off (one addition
    # and one subtraction: within 2 ulp of 30 deg)
    np.testing.assert_allclose(obl + yaw, cond["obliquity_deg"], rtol=0, atol=1e-14)
    assert np.std(yaw) > 1.0  # the axis does move
    o, y = run_angles(cond, "velocity_tilted")
    assert o is not None and np.array_equal(o, cond["obliquity_deg"])
    assert np.array_equal(y, cond["yaw_deg"])


def test_a_case_says_which_reading_it_draws_and_runs_it():
    """The output's attributes name the reading; an axis_tilted case records its draws
    beside simulate's angles, and each run has the velocity at the drawn obliquity and
    the axis tilted from it by the drawn angle of attack."""
    case = {**ANGLE_OF_ATTACK, "n_samples": 3, "n_chunks": 1, "velocity_m_s": 800.0}
    ds = gather([run_chunk(case, 0)])
    assert ds.attrs["yaw_convention"] == "axis_tilted"
    assert ds.attrs["yaw_reading"].startswith("angle of attack")
    np.testing.assert_array_equal(ds["yaw"].values, -ds["angle_of_attack"].values)
    np.testing.assert_array_equal(
        ds["obliquity"].values, ds["velocity_obliquity"].values + ds["angle_of_attack"].values
    )
    i = 1
    run = simulate("p2", "soil", 800.0, float(ds["obliquity"][i]), float(ds["yaw"][i]),
                   float(ds["omega"][i]), azimuth=float(ds["azimuth"][i]))  # fmt: skip
    assert float(ds["path_length"][i]) == float(run["path_length"])
    # at t = 0 the velocity is at the drawn obliquity, the axis at it plus the drawn angle
    vel = math.degrees(math.atan2(math.hypot(float(run.vel_x[0]), float(run.vel_z[0])),
                                  -float(run.vel_y[0])))  # fmt: skip
    axis = math.degrees(math.atan2(math.hypot(float(run.axis_x[0]), float(run.axis_z[0])),
                                   -float(run.axis_y[0])))  # fmt: skip
    drawn_v, drawn_a = float(ds["velocity_obliquity"][i]), float(ds["angle_of_attack"][i])
    assert vel == pytest.approx(drawn_v, abs=1e-9)
    assert axis == pytest.approx(abs(drawn_v + drawn_a), abs=1e-9)
    # the default reading says so too, and keeps its variables as they were
    plain = run_chunk({**CASE, "n_samples": 1, "n_chunks": 1}, 0)
    assert plain.attrs["yaw_convention"] == "velocity_tilted"
    assert plain.attrs["yaw_reading"].startswith("velocity yaw")
    assert "angle_of_attack" not in plain and "velocity_obliquity" not in plain
