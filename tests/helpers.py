"""Assertions shared by the test modules (imported as ``from helpers import ...``)."""

from __future__ import annotations

import ast
import fcntl
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

#: the repository's root (its Snakefile, workflow/, config/ and .test/)
REPO = Path(__file__).resolve().parents[1]

#: Modules that cost a start ~1 s together (the solver's kernels, scipy, xarray with
#: pandas, matplotlib) and that light entry points must not load.
HEAVY_MODULES = ("numba", "scipy", "xarray", "pandas", "matplotlib", "pencore.run.impact")


def assert_one_line_error(err: str, *needles: str) -> None:
    """stderr is exactly one ``pencore: error: ...`` line, with no traceback, containing
    every needle."""
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("pencore: error: "), err
    for needle in needles:
        assert needle in lines[0], (needle, err)


def heavy_modules_after(code: str, cwd: Path | None = None) -> list[str]:
    """Run ``code`` in a fresh interpreter and return the :data:`HEAVY_MODULES` it left
    imported (sorted); the code failing fails the calling test with its stderr."""
    probe = f"\nimport sys\nprint(sorted(m for m in {HEAVY_MODULES!r} if m in sys.modules))\n"
    out = subprocess.run(
        [sys.executable, "-c", code + probe], capture_output=True, text=True, cwd=cwd
    )
    assert out.returncode == 0, out.stderr
    return ast.literal_eval(out.stdout.strip().splitlines()[-1])


def search_results(values, tol: float = 5.0) -> np.ndarray:
    """An object array of :class:`pencore.search.threshold.CriticalResult` with thresholds
    at ``values``, brackets of width ``tol``; NaN is ``above_range`` at 4000."""
    from pencore.search.threshold import CriticalResult

    out = []
    for v in np.ravel(values):
        if np.isnan(v):
            out.append(
                CriticalResult(math.nan, 4000.0, math.nan, 2, True, "above_range", "", (), tol)
            )
        else:
            out.append(CriticalResult(v, v - tol / 2, v + tol / 2, 9, True, "ok", "", (), tol))
    return np.array(out, dtype=object).reshape(np.shape(values))


def copy_workflow(dest: Path) -> Path:
    """The Snakefile, ``workflow/``, ``config/`` and ``.test/`` copied into ``dest``, so a
    test's Snakemake run never touches the repository's own ``results/``."""
    shutil.copy2(REPO / "Snakefile", dest / "Snakefile")
    for d in ("workflow", "config", ".test"):
        shutil.copytree(REPO / d, dest / d)
    return dest


def machine_load() -> tuple[float, int]:
    """The 1-minute load average and the logical cores of this machine."""
    return os.getloadavg()[0], os.cpu_count() or 1


def guard_scale(load: float, cores: int) -> float:
    """How many times longer than on an idle machine a job may take at ``load`` on
    ``cores``: ``load / cores`` (each runnable process gets about ``cores / load`` of a
    core), at least 1; ``PENCORE_TEST_GUARD_SCALE`` multiplies it (a slower machine)."""
    return max(1.0, load / max(cores, 1)) * float(os.environ.get("PENCORE_TEST_GUARD_SCALE", "1"))


class TooSlow(RuntimeError):
    """A guarded command outlived its guard: the machine is too slow or too busy for it
    (or it hangs), which the message says with the load it saw."""


def run_guarded(
    argv: list[str],
    cwd: Path,
    *,
    idle_s: float,
    label: str,
    log: Path | None = None,
    env: dict[str, str] | None = None,
    progress: Callable[[str], None] | None = None,
    load: Callable[[], tuple[float, int]] = machine_load,
    poll_s: float = 2.0,
    every_s: float = 60.0,
    gap_s: float = 15.0,
) -> subprocess.CompletedProcess:
    """Run ``argv`` in ``cwd`` under a hang guard that scales with the machine's load.

    The guard allows ``idle_s`` seconds of wall (what the command needs on an idle
    machine, with a wide margin) times :func:`guard_scale` of the mean load seen while it
    runs, so a busy machine gets proportionally longer and only a hang (or a machine far
    slower than this one) is stopped. Stopped, the command's whole process group is killed
    and :class:`TooSlow` names the elapsed time, the load and the last Snakemake progress
    line. ``progress`` receives a line when a new ``N of M steps`` line of the output is at
    least ``gap_s`` seconds after the last line it received, and every ``every_s`` seconds
    in any case. Output goes to ``log`` (stdout and stderr
    together) when given, else to temporary files; the result holds both as text.
    """
    tmp = Path(tempfile.mkdtemp(prefix="guarded-"))
    out_path, err_path = tmp / "stdout", log or tmp / "stderr"
    loads: list[float] = []
    t0 = time.monotonic()
    last_step, last_report = "", t0
    try:
        with open(out_path, "w") as out, open(err_path, "w") as err:
            proc = subprocess.Popen(
                argv, cwd=cwd, env=env, stdout=err if log else out, stderr=err,
                stdin=subprocess.DEVNULL, text=True, start_new_session=True,
            )  # fmt: skip
            while True:
                try:
                    proc.wait(timeout=poll_s)
                    break
                except subprocess.TimeoutExpired:
                    pass
                now = time.monotonic()
                level, cores = load()
                loads.append(level)
                mean = sum(loads) / len(loads)
                allowed = idle_s * guard_scale(mean, cores)
                steps = _STEPS.findall(err_path.read_text(errors="replace"))
                step = steps[-1] if steps else ""
                where = f"{step} done" if step else "no step done yet"
                if now - t0 > allowed:
                    os.killpg(proc.pid, signal.SIGKILL)
                    proc.wait()
                    why = (
                        "a busy machine, not a failure of the code: rerun when it is quieter"
                        if mean > cores
                        else "on a machine this idle it should have finished: a hang, or a "
                        "machine much slower than the one the guard was set on"
                    )
                    raise TooSlow(
                        f"{label}: too slow, stopped after {now - t0:.0f} s with {where}: the "
                        f"machine's load averaged {mean:.1f} on {cores} cores (now {level:.1f}); "
                        f"the guard allows {idle_s:.0f} s on an idle machine times load/cores "
                        f"({allowed:.0f} s here). Likely {why} (PENCORE_TEST_GUARD_SCALE=2 or "
                        "more lengthens the guards)."
                    )
                since = now - last_report
                if progress and ((step != last_step and since >= gap_s) or since >= every_s):
                    progress(
                        f"{label}: {where} after {now - t0:.0f} s (load {level:.1f} on "
                        f"{cores} cores; guard {allowed:.0f} s)"
                    )
                    last_step, last_report = step, now
    finally:
        stdout = out_path.read_text(errors="replace") if not log else ""
        stderr = err_path.read_text(errors="replace") if err_path.exists() else ""
        shutil.rmtree(tmp, ignore_errors=True)
    return subprocess.CompletedProcess(argv, proc.returncode, stdout, stderr)


_STEPS = re.compile(r"^(\d+ of \d+ steps) \(", re.M)


def run_snakemake(
    cwd: Path, *args: str, timeout: float = 600, **kw: Any
) -> subprocess.CompletedProcess:
    """``python -m snakemake *args`` in ``cwd`` with this interpreter, output captured,
    under :func:`run_guarded`'s load-scaled guard (``timeout``: seconds on an idle
    machine)."""
    kw.setdefault("label", f"snakemake {' '.join(args)[:60]}")
    return run_guarded([sys.executable, "-m", "snakemake", *args], cwd, idle_s=timeout, **kw)


def shared_once(
    root: Path,
    make: Callable[[Path], None],
    *,
    attempts: int = 2,
) -> Path:
    """``root/wd`` made once by ``make(wd)`` for every test process that asks.

    The first process to take ``root/.lock`` runs ``make`` and records the outcome in
    ``root/done.json`` (written whole: a temporary file renamed); the others wait on the
    lock and reuse the record. A folder left without a record (a process killed or
    interrupted in the middle) is removed and made again. A failed attempt is removed and
    retried once (``attempts``), except a :class:`TooSlow` one: on the same busy machine a
    second attempt would only double the wait. A recorded failure fails every caller with
    its message, once per process, without a second run.
    """
    root.mkdir(parents=True, exist_ok=True)
    done = root / "done.json"
    wd = root / "wd"
    with open(root / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.exists():
            result: dict[str, Any] = {"ok": False, "message": ""}
            for attempt in range(1, attempts + 1):
                if wd.exists():  # half made by an attempt that failed or was killed
                    shutil.rmtree(wd)
                wd.mkdir()
                try:
                    make(wd)
                except TooSlow as exc:
                    result = {"ok": False, "message": str(exc)}
                    break
                except Exception as exc:  # noqa: BLE001 (recorded for every caller)
                    result = {
                        "ok": False,
                        "message": f"attempt {attempt} of {attempts} failed: {exc}",
                    }
                    continue
                result = {"ok": True, "message": "", "attempts": attempt}
                break
            tmp = done.with_suffix(".tmp")
            tmp.write_text(json.dumps(result))
            os.replace(tmp, done)
    result = json.loads(done.read_text())
    if not result["ok"]:
        raise SharedRunFailed(result["message"])
    return wd


class SharedRunFailed(RuntimeError):
    """The run :func:`shared_once` records failed (its message is the run's)."""


#: An ensemble case with every kind of distribution (the config check's and the ensemble
#: study's tests share it; copy before changing it).
ENSEMBLE_CASE = {
    "name": "t",
    "projectile": "p2",
    "target": "soil",
    "n_samples": 2000,
    "n_chunks": 7,
    "seed": 5,
    "velocity_m_s": {"dist": "normal", "mean": 1400, "sd": 150, "min": 1200, "max": 1500},
    "obliquity_deg": {"dist": "uniform", "min": 30, "max": 60},
    "yaw_deg": 0.5,
    "omega_rad_s": {"dist": "normal", "mean": 0, "sd": 2.0},
    "azimuth_deg": {"dist": "uniform", "min": 0, "max": 360},
}
