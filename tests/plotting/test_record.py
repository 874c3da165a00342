"""pencore.plotting.record: the concrete record's figure from the archive."""

from __future__ import annotations

import numpy as np
import pytest

from pencore import plotting
from pencore.errors import InputError
from pencore.inputs.record import DEFAULT_RECORD_LAW

KINDS = ("concrete_record",)


def test_figure_from_the_archive_has_labelled_axes_with_units(archived_figure, figure_check):
    fig = archived_figure("concrete_record")
    figure_check(fig)
    scatter, by_d, by_v = fig.axes[:3]
    assert DEFAULT_RECORD_LAW in scatter.get_title()
    # every scored model has its line of medians in both error panels
    from pathlib import Path

    from pencore.io.netcdf import read_netcdf

    archive = Path(__file__).resolve().parents[2] / "results" / "archive" / "validation"
    ds = read_netcdf(archive / "concrete_record.nc")
    models = {str(m) for m in ds["model"].values}
    for ax in (by_d, by_v):
        assert {line.get_label() for line in ax.get_lines()} >= models
    # the scatter holds every row with a prediction, held out, fitted and eroding
    points = sum(len(line.get_xdata()) for line in scatter.get_lines()[1:])
    assert points == int(np.isfinite(ds["held_out_predicted"].sel(model=DEFAULT_RECORD_LAW)).sum())


def test_a_dataset_of_another_kind_is_refused():
    import xarray as xr

    with pytest.raises(InputError, match="needs the concrete record's dataset"):
        plotting.plot_concrete_record(xr.Dataset({"x": ("t", [1.0])}))
