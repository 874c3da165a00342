"""Interrupted workflow runs: after Ctrl-C (SIGINT) or a hard kill (SIGKILL) in the middle
of a job, the commands the README gives finish the run, and every netCDF file is
readable and equal to the one an uninterrupted run writes.

Each case copies the workflow to a temporary directory, starts ``snakemake`` on the Fig. 8
target of the small configuration (two search jobs and a gather), interrupts it once a
job has started, then runs the README's recovery commands.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from helpers import run_snakemake

REPO = Path(__file__).resolve().parents[2]
TARGET = "results/fig8/vcr.nc"
SNAKEMAKE = [sys.executable, "-m", "snakemake"]
# last on the command line: --configfile takes every word after it
OPTIONS = ["--cores", "2", "--configfile", ".test/config.yaml"]
# attributes that record when and where a file was made, not what it holds
VOLATILE = {"created_utc", "history", "git_dirty"}


def _copy(dest: Path) -> Path:
    shutil.copy2(REPO / "Snakefile", dest / "Snakefile")
    for d in ("workflow", "config", ".test"):
        shutil.copytree(REPO / d, dest / d)
    return dest


def _run(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return run_snakemake(cwd, *args, *OPTIONS)


def _netcdf_files(root: Path) -> dict[str, Path]:
    return {str(p.relative_to(root)): p for p in sorted((root / "results").rglob("*.nc"))}


@pytest.fixture(scope="module")
def baseline(tmp_path_factory) -> Path:
    wd = _copy(tmp_path_factory.mktemp("uninterrupted"))
    r = _run(wd, TARGET)
    assert r.returncode == 0, r.stderr[-3000:]
    return wd


def _interrupt(wd: Path, sig: int) -> None:
    """Start the run, wait until a job is under way, then send ``sig`` to the whole
    process group (snakemake and its jobs, as a terminal's Ctrl-C or an OOM kill would)."""
    proc = subprocess.Popen(
        [*SNAKEMAKE, TARGET, *OPTIONS], cwd=wd, start_new_session=True,
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        # the default SIGINT a terminal gives, even if the test run itself was started
        # in the background (`cmd &`), which makes children inherit an ignored SIGINT
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )  # fmt: skip
    incomplete = wd / ".snakemake" / "incomplete"
    deadline = time.monotonic() + 300
    while not (incomplete.is_dir() and any(incomplete.iterdir())):
        assert proc.poll() is None, "the run ended before a job started"
        assert time.monotonic() < deadline, "no job started within 300 s"
        time.sleep(0.05)
    # into the job: its search has logged its first run (a search job makes 20+ runs;
    # a fixed delay raced the job, which now takes ~2 s in all)
    logs = wd / "results" / "logs"
    while not any("evaluation 1 " in f.read_text() for f in logs.rglob("*.log")):
        assert proc.poll() is None, "the run ended before a search started"
        assert time.monotonic() < deadline, "no search started within 300 s"
        time.sleep(0.01)
    os.killpg(proc.pid, sig)
    proc.wait(timeout=120)
    assert not (wd / TARGET).exists(), "the interrupt came too late to test anything"


def _stable(attrs: dict) -> dict:
    return {k: np.asarray(v).tolist() for k, v in attrs.items() if k not in VOLATILE}


def _assert_equal_results(wd: Path, baseline: Path) -> None:
    got, want = _netcdf_files(wd), _netcdf_files(baseline)
    assert sorted(got) == sorted(want)
    for name, path in want.items():
        with xr.open_dataset(path) as a, xr.open_dataset(got[name]) as b:  # readable
            assert sorted(a.variables) == sorted(b.variables), name
            for v in a.variables:
                np.testing.assert_array_equal(a[v].values, b[v].values, err_msg=f"{name}:{v}")
            assert _stable(a.attrs) == _stable(b.attrs), name
    leftovers = [p for p in (wd / "results").rglob("*") if p.name.startswith(".")]
    assert leftovers == [], leftovers


@pytest.mark.slow
def test_after_ctrl_c_the_readme_command_finishes_the_run(tmp_path, baseline):
    wd = _copy(tmp_path)
    _interrupt(wd, signal.SIGINT)
    r = _run(wd, "--rerun-incomplete", TARGET)  # README: "After an interruption"
    assert r.returncode == 0, r.stderr[-3000:]
    _assert_equal_results(wd, baseline)


@pytest.mark.slow
def test_after_a_hard_kill_unlock_then_the_readme_command_finishes_the_run(tmp_path, baseline):
    wd = _copy(tmp_path)
    _interrupt(wd, signal.SIGKILL)
    locked = _run(wd, "--rerun-incomplete", TARGET)
    assert locked.returncode != 0 and "unlock" in (locked.stdout + locked.stderr)
    assert _run(wd, "--unlock").returncode == 0  # README: after a hard kill
    r = _run(wd, "--rerun-incomplete", TARGET)
    assert r.returncode == 0, r.stderr[-3000:]
    _assert_equal_results(wd, baseline)
