"""depth-curve, residual-velocity and ballistic-table on the command line: the table
round trips through CSV and netCDF, a progress line per point, exit 3 for a cell with no
threshold."""

import json

import numpy as np
import pytest
import xarray as xr

import pencore
from pencore.cli.main import main
from pencore.cli.summary import read_csv


def test_depth_curve_csv_round_trip_and_progress(tmp_path, capsys):
    out = tmp_path / "depth.csv"
    argv = ["depth-curve", "--projectile", "p2", "--target", "soil", "--velocities", "200",
            "300", "--out", str(out), "--format", "json"]  # fmt: skip
    assert main(argv) == 0
    cap = capsys.readouterr()
    assert json.loads(cap.out)["depth_max"]["units"] == "m"
    assert cap.err.splitlines()[0].startswith("[1/2] 200 m/s: depth")
    frame = read_csv(out)
    assert frame.attrs["units"]["penetration_depth"] == "m"
    assert frame.attrs["units"]["peak_deceleration"] == "m s-2"
    for k, v in enumerate((200.0, 300.0)):
        ds = pencore.simulate("p2", "soil", v)
        assert frame.velocity[k] == v
        assert frame.penetration_depth[k] == float(ds.penetration_depth)
        assert frame.peak_deceleration_g[k] == ds.attrs["peak_deceleration_g"]


def test_residual_velocity_netcdf_and_plot(tmp_path, capsys):
    plate = tmp_path / "plate.yaml"
    plate.write_text("name: plate\nlayers:\n  - medium: aluminium\n    thickness: 0.02\n")
    out, png = tmp_path / "rv.nc", tmp_path / "rv.png"
    argv = ["residual-velocity", "--projectile", "p2", "--target", str(plate), "--range",
            "150", "450", "4", "--out", str(out), "--plot", str(png), "--quiet"]  # fmt: skip
    assert main(argv) == 0
    # a 2 cm plate is 0.21 calibres of #2 on the half-space law: one plausibility line
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("pencore: warning: target 'plate' layer 0: ")
    assert "plate thickness 0.210592 calibres" in err[0]
    with xr.open_dataset(out) as ds:
        np.testing.assert_array_equal(ds.velocity.values, [150.0, 250.0, 350.0, 450.0])
        assert ds.residual_velocity.attrs["units"] == "m s-1"
        assert (ds.residual_velocity.values > 0).all()
        assert ds.attrs["recht_ipson_p"] > 0
    assert png.stat().st_size > 0


def test_residual_velocity_needs_a_finite_target(capsys):
    argv = ["residual-velocity", "--projectile", "p2", "--target", "soil", "--velocities", "300"]
    assert main(argv) == 2
    assert "no rear face" in capsys.readouterr().err


def test_ballistic_table_exit_3_when_a_cell_is_not_found(tmp_path, capsys):
    out = tmp_path / "bt.csv"
    argv = ["ballistic-table", "--projectile", "p2", "--medium", "aluminium", "--thicknesses",
            "0.01", "--obliquities", "0", "--lo", "50", "--hi", "60", "--out", str(out),
            "--format", "json", "--quiet"]  # fmt: skip
    assert main(argv) == 3
    s = json.loads(capsys.readouterr().out)
    assert s["cells_not_found"]["value"] == 1
    frame = read_csv(out)
    assert frame.status[0] == "above_range" and np.isnan(frame.v_bl[0])


def test_ballistic_table_applies_the_window_options(tmp_path, capsys):
    # the near-surface options reach every slab and are recorded: a crater of 2 calibres
    # lowers the ballistic limit of a 25 mm aluminium plate (the library sphere-free law)
    def table(*extra):
        out = tmp_path / f"bt{len(extra)}.nc"
        argv = ["ballistic-table", "--projectile", "al_ogive_var4340", "--medium", "aluminium",
                "--thicknesses", "0.025", "--obliquities", "0", "--tol", "2", "--out",
                str(out), "--quiet", *extra]  # fmt: skip
        assert main(argv) == 0
        return xr.open_dataset(out)

    plain, crater = table(), table("--crater-depth", "2")
    assert "crater_depth_calibers" not in plain.attrs
    assert crater.attrs["crater_depth_calibers"] == 2.0
    v0, v2 = float(plain.v_bl[0, 0]), float(crater.v_bl[0, 0])
    assert v2 < v0 - 2.0  # more than the search tolerance apart


def test_ballistic_table_refuses_a_thickness_that_is_not_positive(tmp_path, capsys):
    argv = ["ballistic-table", "--projectile", "p2", "--medium", "aluminium", "--thicknesses",
            "0.02", "0", "--obliquities", "0", "--out", str(tmp_path / "bt.csv")]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "thickness must be in (0, " in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_depth_curve_runs_from_the_start_given(tmp_path, capsys):
    """--start moves every run: the runs are simulate's with that start, bit for bit,
    and the table records it; the half-space is the same everywhere along x, so the
    depth from 1 m above and 1 m back is the default's to the integration's accuracy
    (rtol 1e-5 of the path; 1e-4 allowed)."""
    out = tmp_path / "depth.nc"
    argv = ["depth-curve", "--projectile", "p2", "--target", "soil", "--velocities", "300",
            "--start", "-1", "1", "0", "--out", str(out), "--quiet"]  # fmt: skip
    assert main(argv) == 0
    capsys.readouterr()
    with xr.open_dataset(out) as ds:
        assert list(ds.attrs["start_m"]) == [-1.0, 1.0, 0.0]
        depth = float(ds.penetration_depth[0])
    ref = pencore.simulate("p2", "soil", 300.0, start=(-1.0, 1.0, 0.0))
    assert depth == float(ref.penetration_depth)
    touching = float(pencore.simulate("p2", "soil", 300.0).penetration_depth)
    assert depth == pytest.approx(touching, rel=1e-4)


def test_a_sweep_whose_fit_cannot_be_made_finishes(tmp_path, capsys):
    # both speeds are run and written; the fit is NaN with its status, exit 0
    plate = tmp_path / "plate.yaml"
    plate.write_text("name: plate\nlayers:\n  - medium: aluminium\n    thickness: 0.02\n")
    out, png = tmp_path / "rv.csv", tmp_path / "rv.png"
    argv = ["residual-velocity", "--projectile", "p2", "--target", str(plate), "--velocities",
            "500", "900", "--out", str(out), "--plot", str(png), "--format", "json",
            "--quiet"]  # fmt: skip
    assert main(argv) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["recht_ipson_status"]["value"].startswith("not fitted: 2 of 2 runs perforate")
    assert s["v_bl_fit"]["value"] is None or np.isnan(s["v_bl_fit"]["value"])
    frame = read_csv(out)
    assert (frame.residual_velocity > 0).all() and frame.recht_ipson.isna().all()
    assert png.stat().st_size > 0


def test_a_stalled_cell_keeps_the_table_and_exits_3(tmp_path, capsys, monkeypatch):
    import pencore.search.perforation as perforation
    from pencore.errors import SolverError

    real = perforation.run_impact

    def run(projectile, target, v, obliquity, *args, **kwargs):
        if obliquity == 7.0 and v > 400.0:
            raise SolverError(f"step size fell below h_min at {v:g} m/s (stalled)")
        return real(projectile, target, v, obliquity, *args, **kwargs)

    monkeypatch.setattr(perforation, "run_impact", run)
    out = tmp_path / "bt.csv"
    argv = ["ballistic-table", "--projectile", "p2", "--medium", "aluminium", "--thicknesses",
            "0.01", "--obliquities", "6", "7", "--tol", "20", "--out", str(out),
            "--quiet"]  # fmt: skip
    assert main(argv) == 3
    frame = read_csv(out)
    assert list(frame.status) == ["ok", "solver_error"]
    assert np.isfinite(frame.v_bl[0]) and np.isnan(frame.v_bl[1])
    assert "stalled" in frame.message[1]
