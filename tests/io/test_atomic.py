"""Writes either complete or leave nothing: real disk-full, file-size-limit, SIGKILL and
SIGTERM failures of ``pencore.io.netcdf.write_netcdf`` and ``pencore simulate --out``."""

from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from helpers import assert_one_line_error

from pencore.errors import WriteError
from pencore.io.atomic import TEMP_MARK, atomic_path
from pencore.io.netcdf import read_netcdf, write_netcdf

# a dataset of ~1.6 MB that compresses poorly (random numbers)
BIG = """
import numpy as np, xarray as xr
ds = xr.Dataset({"a": ("x", np.random.default_rng(0).random(200_000),
                       {"units": "1", "long_name": "noise"})})
"""


def _python(code: str, **kw) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
        timeout=120, **kw,
    )  # fmt: skip


@pytest.fixture
def tiny_disk(tmp_path):
    """A real 256 KiB file system (tmpfs, needs root), unmounted afterwards."""
    mnt = tmp_path / "disk"
    mnt.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(mnt)],
                       capture_output=True, text=True)  # fmt: skip
    if r.returncode != 0:
        pytest.fail(f"cannot mount a tmpfs for the disk-full test (needs root): {r.stderr}")
    yield mnt
    subprocess.run(["umount", str(mnt)], check=False)


def test_disk_full_is_one_line_and_leaves_nothing(tiny_disk):
    r = _python(
        BIG
        + f"""
from pencore.io.netcdf import write_netcdf
from pencore.errors import WriteError
try:
    write_netcdf(ds, {str(tiny_disk / "out.nc")!r}, config_slice={{}}, study="t")
except WriteError as exc:
    print(exc)
"""
    )
    assert r.returncode == 0, r.stderr
    assert "disk full" in r.stdout and "out.nc" in r.stdout
    assert len(r.stdout.strip().splitlines()) == 1
    assert list(tiny_disk.iterdir()) == []


def test_cli_on_a_full_disk_exits_1_with_one_line(tiny_disk):
    # fill the disk first, so the trajectory file cannot fit
    (tiny_disk / "filler").write_bytes(b"x" * (250 * 1024))
    r = subprocess.run(
        [sys.executable, "-m", "pencore", "simulate", "--projectile", "p2", "--target",
         "soil", "--velocity", "280", "--out", str(tiny_disk / "run.nc")],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert r.returncode == 1
    assert_one_line_error(r.stderr, "run.nc", "disk full")
    assert sorted(p.name for p in tiny_disk.iterdir()) == ["filler"]


def test_file_size_limit_mid_write(tmp_path):
    """RLIMIT_FSIZE (ulimit -f) makes the write fail half-way with EFBIG."""
    out = tmp_path / "out.nc"
    r = _python(
        BIG
        + f"""
import resource, signal
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
resource.setrlimit(resource.RLIMIT_FSIZE, (65536, 65536))
from pencore.io.netcdf import write_netcdf
from pencore.errors import WriteError
try:
    write_netcdf(ds, {str(out)!r}, config_slice={{}}, study="t")
except WriteError as exc:
    print(exc)
"""
    )
    assert r.returncode == 0, r.stderr
    assert "file-size limit" in r.stdout
    assert list(tmp_path.iterdir()) == []


def _start_slow_write(out: Path) -> subprocess.Popen:
    """A process that writes ``out`` slowly (the netCDF call is held inside the temporary
    file's lifetime), so a signal can be sent while the temporary file exists."""
    code = (
        BIG
        + f"""
import time
from pencore.io.atomic import atomic_path
with atomic_path({str(out)!r}) as tmp:
    ds.to_netcdf(tmp)
    print("writing", flush=True)
    time.sleep(60)
"""
    )
    proc = subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)],
                            stdout=subprocess.PIPE, text=True)  # fmt: skip
    assert proc.stdout.readline().strip() == "writing"
    return proc


def _temps(directory: Path) -> list[Path]:
    return [p for p in directory.iterdir() if TEMP_MARK in p.name]


def test_sigkill_leaves_a_temp_that_the_next_write_removes(tmp_path):
    out = tmp_path / "out.nc"
    proc = _start_slow_write(out)
    assert len(_temps(tmp_path)) == 1
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    assert not out.exists() and len(_temps(tmp_path)) == 1  # what a killed run leaves
    ds = xr.Dataset({"a": ("x", np.arange(3.0), {"units": "1", "long_name": "a"})})
    write_netcdf(ds, out, config_slice={}, study="t")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.nc"]
    np.testing.assert_array_equal(read_netcdf(out)["a"].values, np.arange(3.0))


def test_sigterm_during_a_write_leaves_nothing(tmp_path):
    out = tmp_path / "out.nc"
    proc = _start_slow_write(out)
    t0 = time.monotonic()
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=30) == 128 + signal.SIGTERM
    assert time.monotonic() - t0 < 20  # hang guard
    assert list(tmp_path.iterdir()) == []


def test_a_live_writers_temp_is_left_alone(tmp_path):
    out = tmp_path / "out.nc"
    proc = _start_slow_write(out)
    try:
        with atomic_path(out) as tmp:
            tmp.write_bytes(b"second writer")
        assert len(_temps(tmp_path)) == 1  # the other process's file is still there
    finally:
        proc.kill()
        proc.wait()


@pytest.mark.parametrize(
    ("code", "words"),
    [
        (errno.EACCES, "permission denied"),
        (errno.EROFS, "read-only file system"),
        (errno.EDQUOT, "disk quota exceeded"),
        (errno.EIO, "EIO"),
    ],
)
def test_every_os_error_becomes_one_write_error(tmp_path, code, words):
    """Causes that cannot be produced for real here (root ignores permissions)."""
    with pytest.raises(WriteError) as info, atomic_path(tmp_path / "x.nc") as tmp:
        tmp.write_bytes(b"partial")
        raise OSError(code, os.strerror(code))
    assert words in str(info.value) and "x.nc" in str(info.value)
    assert "\n" not in str(info.value)
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_during_a_write_passes_through_and_cleans_up(tmp_path):
    with pytest.raises(KeyboardInterrupt), atomic_path(tmp_path / "x.nc") as tmp:
        tmp.write_bytes(b"partial")
        raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("points_to", ["other.txt", "nowhere.nc"])
def test_a_symbolic_link_is_not_replaced(tmp_path, points_to):
    # renaming onto a link replaces the link itself: refused, link and file kept
    from pencore.io.atomic import check_replaceable

    (tmp_path / "other.txt").write_text("kept\n")
    link = tmp_path / "out.nc"
    os.symlink(points_to, link)
    with pytest.raises(WriteError, match=f"symbolic link \\(to '{points_to}'\\)"):
        check_replaceable(link)
    assert link.is_symlink() and os.readlink(link) == points_to
    assert (tmp_path / "other.txt").read_text() == "kept\n"
    check_replaceable(tmp_path / "other.txt")  # a regular file may be replaced


def test_every_writer_goes_through_the_output_gate():
    """No module of the package or the workflow writes a file but through
    ``atomic_path`` (the output gate's writer): a new writer that calls a library's own
    writer on a destination is caught here. The allowed calls write the temporary file
    ``atomic_path`` handed out; the kernel build writes its own folders atomically."""
    import re

    repo = Path(__file__).resolve().parents[2]
    raw = re.compile(
        r"\.(savefig|to_netcdf|write_text|write_bytes)\(|\.to_csv\((?!index=|\))|"
        r"open\([^)]*['\"][wax]b?['\"]"
    )
    allowed = {
        "src/pencore/io/atomic.py",  # the writer itself
        "src/pencore/io/netcdf.py",  # to_netcdf(tmp) inside atomic_path
        "src/pencore/plotting/style.py",  # savefig(tmp) inside atomic_path
        "src/pencore/kernels/cache.py",  # the kernel cache's stamp (its own folder)
        "src/pencore/kernels/buildcache.py",  # the build step's folders, renamed whole
    }
    found = []
    for path in [*(repo / "src").rglob("*.py"), *(repo / "workflow").rglob("*.py")]:
        rel = path.relative_to(repo).as_posix()
        if rel in allowed:
            continue
        for n, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("#", 1)[0]
            if ">>>" in line or "..." in line[:12]:
                continue  # doctests write their own temporary files
            if raw.search(code):
                found.append(f"{rel}:{n}: {line.strip()}")
    assert found == [], "writes around the output gate:\n" + "\n".join(found)


def test_a_call_protects_what_it_read_but_what_it_is_meant_to_rewrite(tmp_path):
    from pencore.io import outputs

    data = tmp_path / "geometry.yaml"
    data.write_text("diameter_m: 1.0\n")
    other = tmp_path / "other.yaml"
    other.write_text("x: 1\n")
    with outputs.output_call():
        outputs.note_input(data)
        outputs.note_input(other)
        with pytest.raises(WriteError, match="input of this run"):
            outputs.check_destination(data, outputs.YAML_SUFFIXES)
        outputs.allow_rewrite(data)  # fit-table3 --write onto the shipped geometry
        outputs.check_destination(data, outputs.YAML_SUFFIXES)
        with pytest.raises(WriteError, match="input of this run"):
            outputs.check_destination(other, outputs.YAML_SUFFIXES)
        with pytest.raises(WriteError, match="input of this run"):  # an explicit protect wins
            outputs.check_destination(data, outputs.YAML_SUFFIXES, protect=[data])
    outputs.check_destination(other, outputs.YAML_SUFFIXES)  # outside a call: nothing kept
