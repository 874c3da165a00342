"""Assertions shared by the test modules (imported as ``from helpers import ...``)."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

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
