"""pencore.io: provenance, compression, atomic writes, downsampling."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

import pencore
from pencore.io.netcdf import (
    ELAPSED_TIME,
    config_hash,
    downsample,
    read_netcdf,
    write_netcdf,
)


def _trajectory(n: int = 1000) -> xr.Dataset:
    t = np.linspace(0.0, 1.0, n)
    y = -np.sin(np.pi * t) * (1 + 0.1 * t)  # deepest point not on the regular grid
    return xr.Dataset(
        {
            "tip_y": ("time", y, {"units": "m", "long_name": "nose tip y"}),
            "count": ("time", np.arange(n), {"units": "1", "long_name": "index"}),
            "penetration_depth": ((), float(-y.min()), {"units": "m", "long_name": "depth"}),
        },
        coords={"time": ("time", t, {"units": "s", "long_name": "time"})},
        attrs={"flag": True, "items": ["a", 1], "none": None},
    )


def test_round_trip_with_provenance(tmp_path):
    ds = _trajectory()
    cfg = {"b": [1, 2], "a": {"x": 1.5}}
    path = write_netcdf(ds, tmp_path / "sub" / "t.nc", config_slice=cfg, study="test/study")
    back = read_netcdf(path)
    xr.testing.assert_allclose(
        back[["tip_y", "penetration_depth"]], ds[["tip_y", "penetration_depth"]]
    )
    assert back["time"].dtype.kind == "f" and back["time"].attrs["units"] == "s"
    a = back.attrs
    assert a["study"] == "test/study"
    assert a["pencore_version"] == pencore.__version__
    assert a["git_commit"] == "unknown" or len(a["git_commit"]) == 40
    assert json.loads(a["config_json"]) == cfg
    assert a["config_sha256"] == config_hash({"a": {"x": 1.5}, "b": [1, 2]})  # key order
    assert a["created_utc"].endswith("Z")
    assert a["flag"] == 1 and json.loads(a["items"]) == ["a", 1] and a["none"] == ""
    assert ds.attrs == {"flag": True, "items": ["a", 1], "none": None}  # input untouched


def test_float_variables_are_compressed(tmp_path):
    path = write_netcdf(_trajectory(), tmp_path / "t.nc", config_slice={}, study="s")
    back = xr.open_dataset(path)
    try:
        for name in ("tip_y", ELAPSED_TIME):
            assert back[name].encoding["zlib"] and back[name].encoding["complevel"] == 4
        assert not back["count"].encoding.get("zlib", False)
    finally:
        back.close()


def test_elapsed_time_is_not_a_cf_time_axis_on_disk(tmp_path):
    """The run's elapsed time has no reference date/time, so it is not a CF time
    coordinate (CF 1.10 section 4.4): on disk it is a generic coordinate in seconds under
    a name checkers do not take for a time axis; read_netcdf gives back ``time``."""
    ds = _trajectory(50)
    path = write_netcdf(ds, tmp_path / "t.nc", config_slice={}, study="s")
    with xr.open_dataset(path, decode_times=False) as raw:
        assert "time" not in raw.dims and "time" not in raw.variables
        assert raw["tip_y"].dims == (ELAPSED_TIME,)
        attrs = raw[ELAPSED_TIME].attrs
        assert attrs["units"] == "s" and "since" not in attrs["units"]
        assert "standard_name" not in attrs and "axis" not in attrs
        assert "not a CF time coordinate" in attrs["comment"]
        np.testing.assert_array_equal(raw[ELAPSED_TIME].values, ds["time"].values)
    back = read_netcdf(path)
    assert back["tip_y"].dims == ("time",)
    assert back["time"].attrs == ds["time"].attrs
    np.testing.assert_array_equal(back["time"].values, ds["time"].values)
    np.testing.assert_array_equal(back["tip_y"].values, ds["tip_y"].values)


def test_files_written_with_a_time_dimension_still_read(tmp_path):
    ds = _trajectory(20)
    path = tmp_path / "old.nc"
    ds.drop_attrs().to_netcdf(path, engine="netcdf4")
    back = read_netcdf(path)
    assert back["tip_y"].dims == ("time",)
    np.testing.assert_array_equal(back["time"].values, ds["time"].values)


def test_write_is_atomic(tmp_path, monkeypatch):
    path = tmp_path / "t.nc"
    write_netcdf(_trajectory(), path, config_slice={"v": 1}, study="s")
    before = path.read_bytes()

    def broken(self, *args, **kwargs):
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", broken)
    with pytest.raises(OSError, match="disk full"):
        write_netcdf(_trajectory(10), path, config_slice={"v": 2}, study="s")
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["t.nc"]  # no temporary left


def test_written_file_is_world_readable(tmp_path):
    path = write_netcdf(_trajectory(), tmp_path / "t.nc", config_slice={}, study="s")
    assert path.stat().st_mode & 0o044  # not the 0600 of a raw temporary file


def test_read_missing_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="no netCDF file"):
        read_netcdf(tmp_path / "missing.nc")


def test_downsample_keeps_ends_and_deepest_point():
    ds = _trajectory(1001)
    thin = downsample(ds, 50)
    assert 50 <= thin.sizes["time"] <= 52
    assert thin["time"][0] == ds["time"][0] and thin["time"][-1] == ds["time"][-1]
    assert float(-thin["tip_y"].min()) == float(ds["penetration_depth"])
    assert np.all(np.diff(thin["time"].values) > 0)
    assert thin.attrs["downsampled_from"] == 1001
    assert float(thin["penetration_depth"]) == float(ds["penetration_depth"])


def test_downsample_leaves_short_or_timeless_datasets():
    ds = _trajectory(30)
    assert downsample(ds, 50) is ds
    grid = xr.Dataset({"d": (("case", "velocity"), np.ones((2, 3)))})
    assert downsample(grid, 2) is grid
    with pytest.raises(ValueError, match="n >= 2"):
        downsample(ds, 1)


def test_downsample_real_trajectory():
    ds = pencore.simulate("p2", "soil", 278.0, 30.0)
    thin = downsample(ds, 40)
    assert thin.sizes["time"] <= 42
    assert float(-thin["tip_y"].min()) == pytest.approx(float(ds["penetration_depth"]))


def test_reading_and_plotting_results_does_not_load_the_solver():
    """pencore's public names are imported on first use (pencore/__init__.py), so a
    process that only reads and plots results (the workflow's figure jobs) does not
    import numba or scipy; every public name and submodule attribute still resolves."""
    import subprocess
    import sys

    code = (
        "import sys, pencore.io, pencore.plotting; "
        "print(sorted(m for m in ('numba', 'scipy', 'pencore.run.impact') if m in sys.modules)); "
        "import pencore; "
        "[getattr(pencore, n) for n in pencore.__all__]; "
        "print(pencore.inputs.library.__name__, 'numba' in sys.modules)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.split("\n")
    assert out[0] == "[]"
    assert out[1] == "pencore.inputs.library True"
