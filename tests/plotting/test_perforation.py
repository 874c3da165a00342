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


def _table(thicknesses, obliquities, values):
    """A ballistic table as ballistic_table writes it, from synthetic searches."""
    import numpy as np
    import xarray as xr
    from helpers import search_results

    from pencore.studies.common import search_variables

    res = search_results(np.asarray(values, float))
    return xr.Dataset(
        search_variables(res, "v_bl", "m s-1", "ballistic limit", ("thickness", "obliquity")),
        coords={"thickness": ("thickness", thicknesses), "obliquity": ("obliquity", obliquities)},
        attrs={"projectile": "p2", "medium": "concrete", "search_tol_m_s": 5.0},
    )


def test_one_thickness_table_is_drawn_against_obliquity():
    """One thickness, three obliquities: one line of three points against obliquity (not
    three dots on a vertical line at the thickness), the thickness in the legend."""
    import numpy as np

    fig = plotting.plot_ballistic_limit(_table([0.5], [0.0, 30.0, 60.0], [[400, 450, 600]]))
    ax = fig.axes[0]
    (bars,) = ax.containers  # one errorbar set: the points and their brackets
    x, y = bars.lines[0].get_data()
    np.testing.assert_array_equal(x, [0.0, 30.0, 60.0])
    np.testing.assert_array_equal(y, [400.0, 450.0, 600.0])
    assert ax.get_xlabel() == "Obliquity (deg)"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["slab 0.5 m"]


def test_several_thicknesses_are_drawn_against_thickness():
    import numpy as np

    ds = _table([0.3, 0.5], [0.0, 30.0], [[300, 320], [400, 450]])
    ax = plotting.plot_ballistic_limit(ds).axes[0]
    assert ax.get_xlabel() == "Slab thickness (m)"
    assert len(ax.containers) == 2
    np.testing.assert_array_equal(ax.containers[1].lines[0].get_data()[1], [320.0, 450.0])
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["obliquity 0°", "obliquity 30°"]


def test_residual_velocity_title_gives_the_targets_thickness():
    """The command line's residual curve records the target's thickness, and the title
    shows it (it read 'slab nan m'); a dataset without one names the target alone. Two
    speeds that perforate are too few for a fit: the curve is NaN, the runs are drawn."""
    import warnings

    import pencore
    from pencore.studies.sweeps import residual_curve

    plate = pencore.Target("plate", (pencore.Layer(pencore.get_target("aluminium").medium, 0.02),))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pencore.PlausibilityWarning)  # a thin plate
        ds = residual_curve("p2", plate, [300.0, 400.0])
    assert ds.attrs["thickness_m"] == 0.02
    assert (ds["residual_velocity"].values > 0).all() and ds["recht_ipson"].isnull().all()
    title = plotting.plot_residual_velocity(ds).axes[0].get_title()
    assert "plate slab 0.02 m" in title and "nan" not in title
    del ds.attrs["thickness_m"]
    title = plotting.plot_residual_velocity(ds).axes[0].get_title()
    assert ", plate, obliquity 0°" in title and "nan" not in title


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
