"""Result files that cannot be read are named with what to run, and set aside so that a
plain rerun of the workflow makes them again."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from pencore.errors import ResultError
from pencore.io.netcdf import read_netcdf, write_netcdf
from pencore.io.results import readable_netcdf, set_aside_unreadable


def _write(path):
    ds = xr.Dataset(
        {"a": ("x", np.random.default_rng(0).random(50_000), {"units": "1", "long_name": "a"})}
    )
    write_netcdf(ds, path, config_slice={}, study="test")
    return path


@pytest.mark.parametrize("keep", [0.0, 0.1, 0.5, 0.9])
def test_truncated_netcdf_is_named_with_what_to_run(tmp_path, keep):
    path = _write(tmp_path / "results" / "part.nc")
    data = path.read_bytes()
    path.write_bytes(data[: int(len(data) * keep)])
    with pytest.raises(ResultError) as info:
        read_netcdf(path)
    text = str(info.value)
    assert "\n" not in text
    assert str(path) in text and "snakemake" in text and "corrupt or truncated" in text
    assert readable_netcdf(path) is not None


def test_unreadable_results_are_set_aside_and_good_ones_kept(tmp_path):
    good = _write(tmp_path / "results" / "a" / "good.nc")
    bad = _write(tmp_path / "results" / "b" / "bad.nc")
    bad.write_bytes(bad.read_bytes()[:1000])
    (tmp_path / "results" / "c.nc").write_text("not netCDF at all")
    found = set_aside_unreadable(tmp_path / "results")
    assert sorted(p.name for p, _ in found) == ["bad.nc", "c.nc"]
    assert good.is_file() and readable_netcdf(good) is None
    assert not bad.exists() and (bad.parent / "bad.nc.corrupt").is_file()
    assert set_aside_unreadable(tmp_path / "results") == []  # nothing left to set aside
    assert set_aside_unreadable(tmp_path / "missing") == []


def test_superblock_records_the_size_of_a_written_file(tmp_path):
    """The fast check reads the size HDF5 records on close: for a file pencore wrote it is
    the size on disk, and a file cut short by even one byte is named truncated."""
    from pencore.io.results import hdf5_stored_end

    path = _write(tmp_path / "results" / "whole.nc")
    data = path.read_bytes()
    assert hdf5_stored_end(path) == len(data)
    path.write_bytes(data[:-1])
    assert readable_netcdf(path) == f"truncated: {len(data) - 1} of {len(data)} bytes"
