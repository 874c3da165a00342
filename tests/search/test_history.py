"""A search's evaluations as a Dataset: the same values and verdicts, in order."""

import math

import numpy as np

from pencore import find_threshold
from pencore.search.history import search_dataset


def test_history_round_trip():
    r = find_threshold(lambda x: x >= 0.3, 0.0, 1.0, 0.01, scan=5)
    ds = search_dataset(r, "x", "1", "a threshold", projectile="p2")
    pairs = zip(ds.value.values, ds.verdict.values, strict=True)
    assert [(float(v), bool(b)) for v, b in pairs] == list(r.history)
    assert float(ds.x) == r.value and float(ds.x_lo) == r.lo and float(ds.x_hi) == r.hi
    assert ds.attrs["status"] == "ok" and ds.attrs["converged"] == 1
    for name in ds.variables:
        assert "units" in ds[name].attrs and "long_name" in ds[name].attrs


def test_not_found_is_nan_and_not_converged():
    r = find_threshold(lambda x: True, 0.0, 1.0, 0.01, scan=None)
    ds = search_dataset(r, "x", "1", "a threshold")
    assert ds.attrs["status"] == "below_range" and ds.attrs["converged"] == 0
    assert math.isnan(float(ds.x))
    assert np.all(ds.verdict.values == 1)
