"""Assertions shared by the test modules (imported as ``from helpers import ...``)."""

from __future__ import annotations

import ast
import math
import shutil
import subprocess
import sys
from pathlib import Path

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


def run_snakemake(cwd: Path, *args: str, timeout: float = 600) -> subprocess.CompletedProcess:
    """``python -m snakemake *args`` in ``cwd`` with this interpreter, output captured."""
    return subprocess.run(
        [sys.executable, "-m", "snakemake", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


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
