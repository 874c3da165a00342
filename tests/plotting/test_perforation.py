"""pencore.plotting.perforation: its registered figures drawn from the archive, axes labelled
with units, none empty."""

from __future__ import annotations

import pytest

from pencore import plotting

KINDS = ("ballistic_limit", "residual_velocity", "measurements")


@pytest.mark.parametrize("kind", KINDS)
def test_figure_from_the_archive_has_labelled_axes_with_units(kind, archived_figure, figure_check):
    assert plotting.PLOTS[kind].__module__ == "pencore.plotting.perforation"
    figure_check(archived_figure(kind))


def test_ballistic_map_with_the_obliquity_ratio(figure_check):
    """The near-surface figure takes two datasets, as its rule passes them (the map and the
    obliquity ratio): both panels drawn and labelled."""
    from pathlib import Path

    from pencore.io.netcdf import read_netcdf

    archive = Path(__file__).resolve().parents[2] / "results" / "archive" / "near_surface"
    fig = plotting.plot_ballistic_map(
        read_netcdf(archive / "ballistic_map.nc"), read_netcdf(archive / "obliquity_ratio.nc")
    )
    assert len([ax for ax in fig.axes if ax.axison]) == 2
    figure_check(fig)
