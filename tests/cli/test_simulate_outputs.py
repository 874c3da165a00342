"""simulate's summary as JSON with units, the yaw reading, the loads and --plot."""

import json

import pencore
from pencore.cli.main import main

BASE = ["simulate", "--projectile", "p2", "--target", "soil"]


def test_json_summary_has_units_and_the_peak_loads(capsys):
    assert main([*BASE, "--velocity", "1000", "--obliquity", "45", "--format", "json"]) == 0
    s = json.loads(capsys.readouterr().out)
    ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    assert s["penetration_depth"] == {"value": float(ds.penetration_depth), "units": "m"}
    assert s["peak_deceleration"]["units"] == "m s-2"
    assert s["peak_deceleration"]["value"] == ds.attrs["peak_deceleration_m_s2"]
    assert s["peak_deceleration_g"]["value"] == ds.attrs["peak_deceleration_g"]
    assert s["peak_lateral_force"] == {"value": ds.attrs["peak_lateral_force_N"], "units": "N"}


def test_yaw_alone_says_it_tilted_the_velocity_and_how_to_tilt_the_axis(capsys):
    assert main([*BASE, "--velocity", "600", "--yaw", "2"]) == 0
    out = capsys.readouterr().out
    line = next(ln for ln in out.splitlines() if ln.startswith("yaw reading:"))
    assert "axis at 0 deg, velocity at 2 deg" in line
    assert "--obliquity 2 --yaw -2" in line
    assert main([*BASE, "--velocity", "600", "--obliquity", "2", "--yaw", "-2"]) == 0
    out = capsys.readouterr().out
    assert "axis at 2 deg, velocity at 0 deg" in out


def test_help_says_which_angle_yaw_tilts(capsys):
    assert main(["simulate", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--yaw alone tilts the VELOCITY" in text and "--obliquity Y --yaw -Y" in text


def test_plot_is_written_and_a_bad_suffix_refused_before_the_run(tmp_path, capsys):
    png = tmp_path / "run.png"
    assert main([*BASE, "--velocity", "300", "--plot", str(png)]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    assert main([*BASE, "--velocity", "300", "--plot", str(tmp_path / "run.txt")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ".png" in err


def test_netcdf_keeps_the_loads(tmp_path):
    out = tmp_path / "run.nc"
    assert main([*BASE, "--velocity", "300", "--out", str(out)]) == 0
    ds = pencore.read_netcdf(out)
    assert ds.deceleration_g.attrs["units"] == "1"
    assert ds.axial_force.attrs["units"] == "N"
    assert ds.attrs["peak_deceleration_g"] > 0
