"""Tests of the ``pencore`` command line: validation, exit codes, atomic output, help."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from helpers import assert_one_line_error, heavy_modules_after

import pencore
from pencore.cli.main import main

BASE = ["simulate", "--projectile", "p2", "--target", "soil"]
DEPTH_RE = re.compile(r"^penetration depth:\s+(\S+) m$", re.MULTILINE)


def run_cli(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """Run ``python -m pencore`` (the ``pencore`` command) in a fresh interpreter."""
    return subprocess.run(
        [sys.executable, "-m", "pencore", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=300,
    )


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


# ---------------------------------------------------------------- bad input -> status 2


@pytest.mark.parametrize(
    ("option", "value", "needles"),
    [
        ("--velocity", "0", ["'0'", "m/s"]),
        ("--velocity", "-5", ["'-5'", "m/s"]),
        ("--velocity", "nan", ["'nan'", "m/s"]),
        ("--velocity", "inf", ["'inf'", "m/s"]),
        ("--velocity", "abc", ["'abc'", "m/s", "--velocity"]),
        ("--obliquity", "90", ["'90'", "(-90, 90) deg"]),
        ("--obliquity", "-90", ["'-90'", "(-90, 90) deg"]),
        ("--obliquity", "135.5", ["'135.5'", "(-90, 90) deg"]),
        ("--obliquity", "ten", ["'ten'", "--obliquity"]),
        ("--yaw", "x", ["'x'", "deg"]),
        ("--omega", "nan", ["'nan'", "rad/s"]),
    ],
)
def test_bad_numbers(tmp_path, capsys, option, value, needles):
    out = tmp_path / "out.nc"
    argv = [*BASE, "--velocity", "280", option, value, "--out", str(out)]
    if option == "--velocity":
        argv = [*BASE, f"--velocity={value}", "--out", str(out)]
    assert main(argv) == 2
    assert_one_line_error(capsys.readouterr().err, *needles)
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []


def test_yaw_beyond_horizon_comes_from_library(tmp_path, capsys):
    out = tmp_path / "out.nc"
    assert (
        main([*BASE, "--velocity", "280", "--obliquity", "60", "--yaw", "40", "--out", str(out)])
        == 2
    )
    assert_one_line_error(capsys.readouterr().err, "yaw", "40")
    assert not out.exists()


def _projectile_yaml(crh: str) -> str:
    return (
        "name: blunt\ndiameter: 0.1\n"
        f"nose: {{kind: ogive, crh: {crh}, density: 7850}}\n"
        "shank: [{length: 0.5, density: 7850}]\n"
    )


@pytest.mark.parametrize(
    ("kind", "make", "needles"),
    [
        (
            "projectile",
            lambda d: write(d / "crh.yaml", _projectile_yaml("0.3")),
            ["CRH", "0.3", "0.5"],
        ),
        ("projectile", lambda d: "p9", ["'p9'", "p1", "p4"]),
        ("target", lambda d: "mud", ["'mud'", "soil", "concrete", "aluminium"]),
        ("projectile", lambda d: str(d / "missing.yaml"), ["missing.yaml"]),
        ("target", lambda d: str(d / "missing.yaml"), ["missing.yaml"]),
        ("projectile", lambda d: write(d / "bad.yaml", "name: [unclosed\n"), ["bad.yaml", "YAML"]),
        ("target", lambda d: write(d / "list.yaml", "- 1\n- 2\n"), ["list.yaml", "mapping"]),
        (
            "projectile",
            lambda d: write(d / "nodiam.yaml", "name: q\nnose: {kind: flat}\n"),
            ["diameter"],
        ),
        (
            "projectile",
            lambda d: (d / "bin.yaml").write_bytes(b"\xff\xfe\x00") and d / "bin.yaml",
            ["bin.yaml"],
        ),
        (
            "projectile",
            lambda d: write(
                d / "shank.yaml",
                "name: q\ndiameter: 0.1\nnose: {kind: ogive, crh: 3, density: 7850}\nshank: 5\n",
            ),
            ["shank.yaml"],
        ),
        (
            "projectile",
            lambda d: write(
                d / "novol.yaml", "name: q\ndiameter: 0.1\nnose: {kind: flat, density: 7850}\n"
            ),
            ["novol.yaml", "volume"],
        ),
    ],
    ids=[
        "crh",
        "unknown-projectile",
        "unknown-target",
        "missing-projectile-file",
        "missing-target-file",
        "invalid-yaml",
        "non-mapping-yaml",
        "missing-key",
        "binary-file",
        "bad-shank",
        "no-volume",
    ],
)
def test_bad_projectile_or_target(tmp_path, capsys, kind, make, needles):
    spec = str(make(tmp_path))
    out = tmp_path / "out.nc"
    argv = [
        "simulate",
        "--projectile",
        "p2",
        "--target",
        "soil",
        "--velocity",
        "280",
        "--out",
        str(out),
    ]
    argv[argv.index(f"--{kind}") + 1] = spec
    assert main(argv) == 2
    assert_one_line_error(capsys.readouterr().err, *needles)
    assert not out.exists()
    assert not list(tmp_path.glob("*.nc*")) and not list(tmp_path.glob(".*"))


@pytest.mark.parametrize(
    ("make", "needles"),
    [
        (lambda d: d / "out.txt", ["out.txt", ".nc"]),
        (lambda d: d / "no" / "such" / "dir" / "out.nc", ["does not exist", "dir"]),
        (lambda d: (d / "adir.nc").mkdir() or d / "adir.nc", ["adir.nc", "directory"]),
        (
            lambda d: write(d / "afile", "") / "out.nc",
            ["afile", "is not a directory: it is a regular file"],
        ),
    ],
    ids=["suffix", "missing-dir", "is-directory", "parent-is-file"],
)
def test_bad_output_path(tmp_path, capsys, make, needles):
    out = make(tmp_path)
    assert main([*BASE, "--velocity", "280", "--out", str(out)]) == 2
    assert_one_line_error(capsys.readouterr().err, *needles)
    assert not out.is_file()


def test_unwritable_output_dir(tmp_path, capsys):
    """An output directory the process cannot write to. For a normal user chmod 0500 does
    it; root ignores permissions, so as root the directory becomes a read-only tmpfs
    mount, which root cannot write to either (EROFS). The test runs either way."""
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    mounted = False
    try:
        if os.access(ro, os.W_OK):
            r = subprocess.run(
                ["mount", "-t", "tmpfs", "-o", "ro,size=64k", "tmpfs", str(ro)],
                capture_output=True,
                text=True,
            )
            assert r.returncode == 0, f"cannot make a read-only directory as root: {r.stderr}"
            mounted = True
            assert not os.access(ro, os.W_OK)
        assert main([*BASE, "--velocity", "280", "--out", str(ro / "x.nc")]) == 2
        assert_one_line_error(capsys.readouterr().err, "not writable", str(ro))
        assert list(ro.iterdir()) == []
    finally:
        if mounted:
            subprocess.run(["umount", str(ro)], check=False)
        ro.chmod(0o700)


def test_unwritable_output_dir_checked_before_running(tmp_path, capsys, monkeypatch):
    """The writability probe runs before the simulation (even for root)."""
    import tempfile

    import pencore.run.impact

    def deny(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    def must_not_run(*args, **kwargs):
        raise AssertionError("simulate() ran before the output path was checked")

    monkeypatch.setattr(tempfile, "mkstemp", deny)
    monkeypatch.setattr(pencore.run.impact, "simulate", must_not_run)
    out = tmp_path / "x.nc"
    assert main([*BASE, "--velocity", "280", "--out", str(out)]) == 2
    assert_one_line_error(capsys.readouterr().err, "not writable", "Permission denied")
    assert not out.exists()


def test_existing_output_untouched_on_error(tmp_path, capsys):
    out = write(tmp_path / "old.nc", "previous result")
    assert main([*BASE, "--velocity", "-1", "--out", str(out)]) == 2
    assert out.read_text() == "previous result"


def test_argparse_errors_are_one_line(capsys):
    assert main(["simulate", "--projectile", "p2"]) == 2
    assert_one_line_error(capsys.readouterr().err, "--target", "--velocity")
    assert main(["frobnicate"]) == 2
    assert_one_line_error(capsys.readouterr().err, "frobnicate")
    assert main([]) == 2
    assert_one_line_error(capsys.readouterr().err)


# ---------------------------------------------------------------- runtime failures -> 1


def test_solver_error_exit_1(tmp_path, capsys, monkeypatch):
    import pencore.run.impact

    def fail(*args, **kwargs):
        raise pencore.SolverError("step limit of 10 steps reached at t = 0.001 s")

    monkeypatch.setattr(pencore.run.impact, "simulate", fail)
    out = tmp_path / "x.nc"
    assert main([*BASE, "--velocity", "280", "--out", str(out)]) == 1
    assert_one_line_error(capsys.readouterr().err, "step limit")
    assert list(tmp_path.iterdir()) == []


def test_failed_write_leaves_nothing(tmp_path, capsys, monkeypatch):
    """A write that dies half-way leaves neither the output nor its temporary file."""

    def half_write(self, path, *args, **kwargs):
        Path(path).write_bytes(b"CDF\x01 half a file")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", half_write)
    out = tmp_path / "x.nc"
    assert main([*BASE, "--velocity", "280", "--out", str(out)]) == 1
    assert_one_line_error(capsys.readouterr().err, "x.nc", "disk full")
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- success


@pytest.mark.slow
def test_simulate_writes_netcdf(tmp_path):
    res = run_cli(*BASE, "--velocity", "280", "--out", "x.nc", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    assert "Traceback" not in res.stderr
    match = DEPTH_RE.search(res.stdout)
    assert match, res.stdout
    printed = match.group(1)
    for label in (
        "tip path length below surface:",
        "outcome:",
        "reversed:",
        "final slope dy/dx:",
        "final deviation from normal:",
        "run time:",
        "steps:",
    ):
        assert label in res.stdout
    assert re.search(r"^final deviation from normal:\s+\S+ deg$", res.stdout, re.MULTILINE)
    assert re.search(r"^run time:\s+\S+ s", res.stdout, re.MULTILINE)
    assert re.search(r"^reversed:\s+(yes|no)$", res.stdout, re.MULTILINE)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.nc"]  # no temporary left
    with xr.open_dataset(tmp_path / "x.nc") as ds:
        depth = float(ds["penetration_depth"])
        assert ds["penetration_depth"].attrs["units"] == "m"
        assert ds.attrs["outcome"] in res.stdout
    assert depth > 0.0
    assert f"{depth:.6g}" == printed
    assert float(printed) == pytest.approx(depth, rel=1e-5)


@pytest.mark.slow
def test_simulate_all_options_in_process(tmp_path, capsys):
    out = tmp_path / "y.nc"
    rc = main(
        [
            *BASE,
            "--velocity",
            "280",
            "--obliquity",
            "30",
            "--yaw",
            "5",
            "--omega",
            "10",
            "--start",
            "0",
            "0.01",
            "0",
            "--stop-at-reversal",
            "--out",
            str(out),
        ]
    )
    assert rc == 0
    text = capsys.readouterr().out
    printed = DEPTH_RE.search(text).group(1)
    with xr.open_dataset(out) as ds:
        assert f"{float(ds['penetration_depth']):.6g}" == printed
        assert ds.attrs["obliquity_deg"] == 30.0
        assert ds.attrs["yaw_deg"] == 5.0
        assert ds.attrs["omega_rad_s"] == 10.0
    assert (out.stat().st_mode & 0o777) != 0o600  # not the private mode of a temp file


def test_a_vertical_path_prints_minus_infinity_whatever_the_round_off(tmp_path, capsys):
    """Radau through a 1e-12 m foil at normal incidence ends with a horizontal velocity of
    round-off whose vy / vx is positive; the summary shows the path going down."""
    foil = write(
        tmp_path / "foil.yaml",
        "name: foil\nlayers:\n  - medium: aluminium\n    thickness: 1.0e-12\n",
    )
    rc = main(
        [
            "simulate", "--projectile", "p2", "--target", str(foil), "--velocity", "300",
            "--numerics", "method=Radau",
        ]
    )  # fmt: skip
    assert rc == 0
    text = capsys.readouterr().out
    assert re.search(r"^outcome:\s+perforated$", text, re.MULTILINE), text
    assert re.search(
        r"^final slope dy/dx:\s+-inf \(path essentially vertical\)$", text, re.MULTILINE
    ), text


# ---------------------------------------------------------------- help, version, others


@pytest.mark.parametrize(
    ("argv", "needles"),
    [
        (["--help"], ["m/s", "deg", "rad/s", "(m)", "simulate", "fit-table3", "list"]),
        (
            ["simulate", "--help"],
            [
                "m/s",
                "deg",
                "rad/s",
                "in m",
                "--velocity",
                "--obliquity",
                "--yaw",
                "--omega",
                "--start",
                "--stop-at-reversal",
                "--out",
                "--projectile",
                "--target",
            ],
        ),
        (["fit-table3", "--help"], ["kg", "m"]),
        (["list", "--help"], ["kg", "mm", "Pa"]),
    ],
)
def test_help_mentions_units(capsys, argv, needles):
    assert main(argv) == 0
    text = capsys.readouterr().out
    for needle in needles:
        assert needle in text, needle


def test_version_subprocess():
    res = run_cli("--version")
    assert res.returncode == 0
    assert res.stdout.strip() == f"pencore {pencore.__version__}"


def test_bad_velocity_subprocess(tmp_path):
    res = run_cli(*BASE, "--velocity", "abc", "--out", "x.nc", cwd=tmp_path)
    assert res.returncode == 2
    assert res.stdout == ""
    assert_one_line_error(res.stderr, "'abc'", "m/s")
    assert list(tmp_path.iterdir()) == []


def test_list(capsys):
    assert main(["list"]) == 0
    text = capsys.readouterr().out
    for name in pencore.inputs.library.projectile_names() + pencore.inputs.library.target_names():
        assert name in text
    assert "mass_kg" in text and "diameter_mm" in text and "source" in text


def test_fit_table3(capsys):
    assert main(["fit-table3"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(pencore.inputs.library.table3_fit().report())
    assert "shipped geometry: diameter" in out


def test_fit_table3_write_round_trips_the_shipped_file(tmp_path, capsys):
    """``--write`` regenerates the shipped geometry file: the provenance header and the
    keys byte for byte, the values those of the fit, and a bad path is one line with
    exit 1 and nothing left behind.

    The values are compared to 1e-10 m, Nelder-Mead's ``xatol`` (as in
    ``test_geometry.test_shipped_table3_geometry_is_the_fit``), not to the bit: the
    fit's last digits follow the machine's BLAS and libm (on one AMD EPYC host the
    shank length came out 7.6e-13 m from the shipped value)."""
    out = tmp_path / "geometry.yaml"
    assert main(["fit-table3", "--write", str(out)]) == 0
    written = out.read_text().splitlines()
    shipped = pencore.inputs.library.TABLE3_GEOMETRY_FILE.read_text().splitlines()
    assert [ln if ln.startswith("#") else ln.split(":")[0] for ln in written] == [
        ln if ln.startswith("#") else ln.split(":")[0] for ln in shipped
    ]
    fit = pencore.inputs.library.table3_fit()
    new = pencore.inputs.library.shipped_table3_geometry(out)
    assert new == (fit.diameter, fit.shank_length)  # written to the last digit
    assert np.allclose(new, pencore.inputs.library.shipped_table3_geometry(), rtol=0, atol=1e-10)
    capsys.readouterr()
    # a folder that does not exist is bad input, refused before the fit
    assert main(["fit-table3", "--write", str(tmp_path / "no" / "g.yaml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "does not exist" in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["geometry.yaml"]


def test_output_into_a_closed_pipe_is_quiet():
    """`pencore list | head -1`: no BrokenPipeError traceback, status 141 (SIGPIPE). The
    reading end is closed before the command writes, so the failure is certain."""
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        proc = subprocess.run(
            [sys.executable, "-m", "pencore", "list"],
            stdout=write_end, stderr=subprocess.PIPE, timeout=120,
        )  # fmt: skip
    finally:
        os.close(write_end)
    assert proc.returncode == 141
    assert proc.stderr.decode() == ""


@pytest.mark.parametrize("argv", [["--help"], ["list"], ["simulate", "--help"]])
def test_commands_that_run_no_solver_do_not_load_it(argv):
    """``--help`` and ``list`` answer without importing the solver (numba, xarray: ~0.6 s
    of a start); the exit codes of solver failures are tested above."""
    code = (
        "import contextlib, io\n"
        "from pencore.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    assert main({argv!r}) == 0\n"
    )
    assert heavy_modules_after(code) == []
