"""vcr / vci / omega-c / ballistic-limit on the command line: exit statuses, JSON with
units, the CSV round trip of the search's history."""

import json
import math

from pencore.cli.main import main
from pencore.cli.summary import NOT_FOUND, read_csv

P2 = ["--projectile", "p2", "--target", "soil"]


def _json(capsys):
    return json.loads(capsys.readouterr().out)


def test_vcr_found_exits_0_with_units_and_csv_round_trip(tmp_path, capsys):
    out = tmp_path / "vcr.csv"
    argv = ["vcr", *P2, "--obliquity", "45", "--tol", "100", "--scan", "0"]
    assert main([*argv, "--format", "json", "--out", str(out)]) == 0
    s = _json(capsys)
    assert s["vcr"]["units"] == "m s-1"
    assert s["vcr_lo"]["value"] < s["vcr"]["value"] < s["vcr_hi"]["value"]
    assert s["vcr_hi"]["value"] - s["vcr_lo"]["value"] <= 100.0
    assert s["status"]["value"] == "ok"
    frame = read_csv(out)
    assert frame.attrs["units"]["value"] == "m s-1"
    assert len(frame) == s["runs"]["value"]
    # the last False and the first True above it are the bracket
    assert frame.value[frame.verdict == 0].max() == s["vcr_lo"]["value"]
    assert frame.value[frame.verdict == 1].min() == s["vcr_hi"]["value"]


def test_no_threshold_in_range_exits_3_and_still_reports(tmp_path, capsys):
    out = tmp_path / "vcr.nc"
    argv = ["vcr", *P2, "--obliquity", "45", "--lo", "200", "--hi", "300", "--scan", "0"]
    assert main([*argv, "--format", "json", "--out", str(out)]) == NOT_FOUND == 3
    s = _json(capsys)
    assert s["vcr"]["value"] is None
    assert s["status"]["value"] == "above_range"
    import xarray as xr

    with xr.open_dataset(out) as ds:
        assert ds.attrs["status"] == "above_range" and math.isnan(float(ds.vcr))


def test_exit_3_is_in_the_help(capsys):
    for cmd in ("vcr", "vci", "omega-c", "ballistic-limit"):
        assert main([cmd, "--help"]) == 0
        text = " ".join(capsys.readouterr().out.split())
        assert "3 no threshold in the range" in text


def test_omega_c_csv_summary(capsys):
    argv = ["omega-c", *P2, "--velocity", "300", "--lo", "0", "--hi", "5", "--tol", "5"]
    status = main([*argv, "--scan", "0", "--format", "csv"])
    rows = capsys.readouterr().out.splitlines()
    assert rows[0] == "name,value,units"
    names = {r.split(",")[0]: r.split(",")[-1] for r in rows[1:]}
    assert names["omega_c"] == "rad s-1"
    assert status in (0, 3)


def test_vci_says_the_axis_is_tilted(capsys):
    assert main(["vci", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "tilts the AXIS by default" in text


def test_bad_range_is_one_line(capsys):
    assert main(["vcr", *P2, "--obliquity", "45", "--lo", "500", "--hi", "400"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--lo 500 must be below --hi 400" in err


def test_start_reaches_the_runs_of_omega_c(tmp_path, capsys):
    """A start 1 m above the surface lets the spinning body turn in flight before it
    touches (0.67 ms at 1500 m/s), so much less spin turns it back: the search's answer
    moves from 156-172 rad/s to 31-47 rad/s, and the file records the start."""
    argv = ["omega-c", *P2, "--velocity", "1500", "--lo", "0", "--hi", "500", "--tol", "25",
            "--scan", "0", "--format", "json"]  # fmt: skip
    assert main(argv) == 0
    touching = _json(capsys)
    out = tmp_path / "omega_c.nc"
    assert main([*argv, "--start", "0", "1", "0", "--out", str(out)]) == 0
    above = _json(capsys)
    assert touching["omega_c_lo"]["value"] > 150.0
    assert above["omega_c_hi"]["value"] < touching["omega_c_lo"]["value"] / 3
    import xarray as xr

    with xr.open_dataset(out) as ds:
        assert list(ds.attrs["start_m"]) == [0.0, 1.0, 0.0]


START_COMMANDS = {
    "vcr": ["vcr", *P2, "--obliquity", "45"],
    "vci": ["vci", *P2, "--yaw", "0.1", "--threshold", "1"],
    "omega-c": ["omega-c", *P2, "--velocity", "300", "--hi", "50"],
    "ballistic-limit": ["ballistic-limit", "--projectile", "p2", "--target", "SLAB"],
    "depth-curve": ["depth-curve", *P2, "--velocities", "300"],
    "residual-velocity": ["residual-velocity", "--projectile", "p2", "--target", "SLAB"]
    + ["--velocities", "300"],
    "ballistic-table": ["ballistic-table", "--projectile", "p2", "--medium", "concrete"]
    + ["--thicknesses", "0.5"],
}


def test_every_search_and_sweep_command_passes_its_start_to_the_runs(tmp_path, capsys):
    """Each command's runs refuse a start from which the body cannot reach the target
    within t_max (the check of pencore.simulate, made by each run before it integrates):
    the start reached them. The same option as 'simulate --start': three numbers in m."""
    slab = tmp_path / "slab.yaml"
    slab.write_text("name: slab\nlayers:\n  - {medium: concrete, thickness: 0.5}\n")
    for name, argv in START_COMMANDS.items():
        argv = [str(slab) if a == "SLAB" else a for a in argv]
        high = ["--start", "0", "100", "0", "--numerics", "t_max=0.01"]
        assert main([*argv, *high]) == 2, name
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "start height" in err and "t_max" in err, (name, err)
        assert main([*argv, "--start", "0", "-1", "0"]) == 2, name
        err = capsys.readouterr().err
        assert "start y must be >= 0 m" in err, (name, err)
        assert main([*argv, "--start", "0", "1"]) == 2, name  # three numbers
        assert "--start" in capsys.readouterr().err
        assert main([name, "--help"]) == 0
        assert "--start X Y Z" in capsys.readouterr().out, name
