"""pencore.studies.trends: a trend verdict within the searches' brackets: holds, partly,
does not hold, undetermined, with open brackets of out-of-range searches."""

import math

import pytest

from pencore.studies.trends import trend

NAN = math.nan


def test_trend_falls_holds_and_rises_does_not():
    par = [15.0, 30.0, 45.0]
    down = trend([("a", par, [300, 200, 100], [305, 205, 105])], "falls")
    assert (down.verdict, down.n_with, down.n_against) == ("holds", 2, 0)
    up = trend([("a", par, [100, 200, 300], [105, 205, 305])], "falls")
    assert (up.verdict, up.n_with, up.n_against) == ("does not hold", 0, 2)
    assert "a: 15->30" in up.note()
    assert trend([("a", par, [100, 200, 300], [105, 205, 305])], "rises").verdict == "holds"


def test_trend_mixed_flat_and_order():
    # one step down, one step up: partly
    mixed = trend([("a", [1, 2, 3], [300, 100, 200], [305, 105, 205])], "falls")
    assert mixed.verdict == "partly holds" and (mixed.n_with, mixed.n_against) == (1, 1)
    # overlapping brackets are equal within the tolerance: flat, which does not support
    # the claim on its own
    flat = trend([("a", [1, 2], [100, 102], [105, 107])], "falls")
    assert (flat.verdict, flat.n_flat) == ("does not hold", 1)
    # a flat step beside a falling one still holds
    assert trend([("a", [1, 2, 3], [200, 100, 102], [205, 105, 107])]).verdict == "holds"
    # parameters are sorted before comparing
    unsorted = trend([("a", [45, 15, 30], [100, 300, 200], [105, 305, 205])], "falls")
    assert unsorted.verdict == "holds" and unsorted.n_with == 2


def test_trend_open_brackets_from_out_of_range_searches():
    # above_range: lo = top of the range, hi = NaN (no event up to 500)
    line = ("p", [0.50, 0.52, 0.57], [500, 500, 19.5], [NAN, NAN, 20.0])
    t = trend([line], "falls")
    # >500 -> >500 cannot be compared; >500 -> 20 falls
    assert (t.verdict, t.n_with, t.n_undetermined) == ("holds", 1, 1)
    # a value rising out of the range is against "falls"
    t = trend([("p", [1, 2], [19.5, 500], [20.0, NAN])], "falls")
    assert t.verdict == "does not hold" and t.n_against == 1
    # unknown (both NaN, e.g. max_iter without bounds) is undetermined
    t = trend([("p", [1, 2], [NAN, 10], [NAN, 11])], "falls")
    assert (t.verdict, t.n_undetermined) == ("undetermined", 1)
    with pytest.raises(ValueError):
        trend([], "wobbles")
