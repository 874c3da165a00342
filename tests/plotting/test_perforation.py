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


def test_ballistic_map_names_the_model_and_says_why_a_point_is_missing(figure_check):
    """The map's title names the paper's model (not the option key "none"); a cell without
    a number (a failed search) and a cell the ring-mesh check did not pass are listed under
    the figure with their reasons."""
    from pathlib import Path

    from pencore.io.netcdf import read_netcdf
    from pencore.studies.perforation.mesh_check import mesh_check

    archive = Path(__file__).resolve().parents[2] / "results" / "archive" / "near_surface"
    bl_map = read_netcdf(archive / "ballistic_map.nc").load()
    cmp = read_netcdf(archive / "obliquity_ratio.nc")
    fine = bl_map.copy(deep=True)
    tod = bl_map.t_over_d.values  # the ratio panel's thickness, as the figure picks it
    t_pick = float(tod[abs(tod - float(cmp["t_over_d"].median())).argmin()])
    cell = {"option": "crater_2", "t_over_d": t_pick, "obliquity": 45.0}
    fine["v_bl"].loc[cell] = bl_map["v_bl"].loc[cell] + 10.0
    gone = {**cell, "obliquity": 60.0}
    for ds in (bl_map, fine):
        ds["v_bl"].loc[gone] = float("nan")
        ds["ratio"].loc[gone] = float("nan")
        ds["status"].loc[gone] = "solver_error"
    fig = plotting.plot_ballistic_map(bl_map, cmp, mesh_check(bl_map, fine, 2.0))
    figure_check(fig)
    assert "the paper's model, no near-surface option" in fig.axes[0].get_title()
    text = "\n".join(t.get_text() for t in fig.texts)
    if float(cmp["t_over_d"].median()) == pytest.approx(t_pick, abs=0.3):
        assert (
            f"crater_2, t/d {t_pick:g}, 60°: no point drawn, the search ended solver_error" in text
        )
    assert f"crater_2, t/d {t_pick:g}, 45°: V_bl moves +10.0 m/s on 2x the rings" in text
