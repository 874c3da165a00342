"""pencore.studies.common: the pieces the studies share: start points, axes, attributes,
the variables of a search, the numerics record, joining parts."""

import json

import numpy as np
import pytest
import xarray as xr
from helpers import search_results

from pencore.errors import InputError
from pencore.inputs.numerics import Numerics
from pencore.studies.common import (
    PROJECTILES,
    axis_values,
    combine,
    numerics_record,
    projectile_coords,
    search_variables,
    start_from_height,
    start_point,
    var_attrs,
)


def test_start_from_height_and_start_point():
    assert start_from_height(0.0) is None
    assert start_from_height(0.5) == (0.0, 0.5, 0.0)
    with pytest.raises(InputError, match="start height must be >= 0 m"):
        start_from_height(-1)
    assert start_point(None) is None
    assert start_point([-1, 1, 0]) == (-1.0, 1.0, 0.0)
    for bad in ([1, 2], [0, float("inf"), 0]):
        with pytest.raises(InputError, match="3 finite coordinates"):
            start_point(bad)


def test_axis_values_refuse_empty_nan_and_repeats():
    assert axis_values((15, 30.5), "obliquities").tolist() == [15.0, 30.5]
    for bad, needle in (([], "non-empty"), ([1, float("nan")], "non-empty"), ([1, 1], "repeated")):
        with pytest.raises(InputError, match=needle):
            axis_values(bad, "yaws")


def test_projectile_coords_rise_in_lc_over_l_and_carry_units():
    coords = projectile_coords(PROJECTILES)
    lc = coords["lc_over_l"][1]
    assert np.all(np.diff(lc) > 0)  # the paper orders #1-#4 by rising Lc/L
    assert coords["mass"][2]["units"] == "kg" and coords["lc_over_l"][2]["units"] == "1"
    assert var_attrs("m", "depth", note="n") == {"units": "m", "long_name": "depth", "note": "n"}


def test_search_variables_hold_each_bracket_and_status():
    res = search_results(np.array([[1000.0, np.nan]]), tol=4.0)
    data = search_variables(res, "vcr", "m s-1", "Vcr", ("projectile", "obliquity"))
    ds = xr.Dataset(data)
    assert ds["vcr"].attrs["units"] == ds["vcr_lo"].attrs["units"] == "m s-1"
    assert ds["vcr_lo"].values.tolist()[0][0] == 998.0
    assert ds["vcr_hi"].values.tolist()[0][0] == 1002.0
    assert ds["status"].values.tolist() == [["ok", "above_range"]]
    assert np.isnan(ds["vcr"].values[0, 1]) and ds["vcr_lo"].values[0, 1] == 4000.0
    assert all(json.loads(h) == [] for h in ds["history"].values.ravel())


def test_numerics_record_round_trips_through_json():
    num = Numerics()
    rec = json.loads(json.dumps(numerics_record(num)))
    assert Numerics(**rec) == num


def test_combine_joins_parts_and_refuses_none():
    parts = [
        xr.Dataset({"v": ("projectile", [float(i)])}, coords={"projectile": [p]}, attrs={"k": i})
        for i, p in enumerate(("p1", "p2"))
    ]
    ds = combine(parts)
    assert ds["v"].values.tolist() == [0.0, 1.0] and ds.attrs["k"] == 0
    with pytest.raises(InputError, match="nothing to combine"):
        combine([])
