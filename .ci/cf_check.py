"""CF compliance of the project's netCDF files, with the official CF checker (cfchecker).

Checks (a) a file pencore writes now (``pencore simulate --out``), (b) every file under
``results/archive/``, and (c) any files given on the command line, against the CF version
the files declare (``pencore.io.netcdf.CF_CONVENTIONS``). Prints the error count per file and
exits 1 if any file has an error. Run ``bash .ci/install-cf-checker.sh`` first.

Usage: python .ci/cf_check.py [FILE.nc ...]
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TABLES = [
    "-s", str(HERE / "cf" / "cache" / "cf-standard-name-table.xml"),
    "-a", str(HERE / "cf" / "area-type-table.xml"),
    "-r", str(HERE / "cf" / "standardized-region-list.xml"),
]  # fmt: skip


def errors(path: Path, version: str) -> tuple[int, list[str]]:
    r = subprocess.run(
        ["cfchecks", "-v", version, *TABLES, str(path)], capture_output=True, text=True
    )
    out = r.stdout + r.stderr
    found = re.search(r"ERRORS detected: (\d+)", out)
    if found is None:
        return -1, out.strip().splitlines()[-5:]
    return int(found.group(1)), [ln for ln in out.splitlines() if ln.startswith("ERROR")]


def main() -> int:
    from pencore.io.netcdf import CF_CONVENTIONS

    version = CF_CONVENTIONS.removeprefix("CF-")
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / "fresh.nc"
        subprocess.run(
            [sys.executable, "-m", "pencore.cli", "simulate", "--projectile", "p2",
             "--target", "soil", "--velocity", "300", "--out", str(fresh)],
            check=True, capture_output=True,
        )  # fmt: skip
        files = [fresh, *sorted((ROOT / "results" / "archive").rglob("*.nc"))]
        files += [Path(a) for a in sys.argv[1:]]
        bad = 0
        for f in files:
            n, lines = errors(f, version)
            name = "fresh pencore simulate file" if f == fresh else str(f)
            print(f"{n:3d} CF-{version} errors  {name}")
            for ln in lines[:5]:
                print(f"      {ln}")
            bad += n != 0
    print(f"cf_check: {len(files) - bad} of {len(files)} files pass CF-{version}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
