"""Error statistics of predictions against measurements (pencore.analysis.errors): closed
forms of the statistics on samples small enough to work by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.analysis.errors import (
    error_statistics,
    relative_errors,
    sample_statistics,
    summary_statistics,
    t_half_width,
)
from pencore.errors import InputError


def test_error_statistics_closed_form():
    # e = predicted / measured - 1 = +0.1 and -0.1: mean 0, RMS 0.1, largest 0.1, and the
    # t interval of two values is mean +- t(0.975, 1) * sd / sqrt(2) with sd = 0.1 sqrt(2)
    s = error_statistics([1.0, 2.0], [1.1, 1.8])
    assert s["n"] == 2
    assert s["mean_rel_error"] == pytest.approx(0.0, abs=1e-15)
    assert s["rms_rel_error"] == pytest.approx(0.1, rel=1e-12)
    assert s["max_abs_rel_error"] == pytest.approx(0.1, rel=1e-12)
    assert s["ci95_hi"] == pytest.approx(12.706204736 * 0.1, rel=1e-8)
    assert s["ci95_lo"] == pytest.approx(-s["ci95_hi"], rel=1e-12)
    one = error_statistics([2.0], [3.0])
    assert one["mean_rel_error"] == pytest.approx(0.5) and math.isnan(one["ci95_lo"])


def test_relative_errors_skip_unmeasured_and_zero():
    e = relative_errors([2.0, 0.0, np.nan, 4.0], [3.0, 1.0, 1.0, 2.0])
    assert e[0] == pytest.approx(0.5) and e[3] == pytest.approx(-0.5)
    assert np.isnan(e[1]) and np.isnan(e[2])


def test_summary_statistics_keep_the_sign_of_the_worst():
    st = summary_statistics([0.1, -0.3, np.nan, 0.2])
    assert st["n"] == 3
    assert st["mean_abs_rel_error"] == pytest.approx(0.2, rel=1e-12)
    assert st["bias"] == pytest.approx(0.0, abs=1e-15)
    assert st["worst"] == -0.3
    none = summary_statistics([np.nan])
    assert none["n"] == 0 and math.isnan(none["bias"])


def test_sample_statistics_of_no_shot_is_nan():
    st = sample_statistics(np.array([]), np.array([]))
    assert st["n"] == 0 and math.isnan(st["mean_rel_error"])


def test_t_half_width_two_values():
    # t(0.975, 1) = 12.706...; sd of (0, 2) is sqrt(2); / sqrt(2) -> 12.706
    assert t_half_width([0.0, 2.0]) == pytest.approx(12.706204736, rel=1e-9)
    assert math.isnan(t_half_width([1.0]))


def test_error_statistics_refuse_bad_input():
    with pytest.raises(InputError, match="equal-length"):
        error_statistics([1.0], [1.0, 2.0])
    with pytest.raises(InputError, match="non-negative"):
        error_statistics([-1.0], [1.0])
