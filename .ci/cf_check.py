"""CF compliance of the project's netCDF files, with two independent checkers.

Checks (a) a file pencore writes now (``pencore simulate --out``), (b) every file under
``results/archive/``, and (c) any files given on the command line, with

* ``cfchecker``, the CF community's reference checker, against the CF version the files
  declare (``pencore.io.netcdf.CF_CONVENTIONS``), and
* the IOOS ``compliance-checker``, suite ``cf:1.10`` (:data:`IOOS_SUITE`), whose checks
  partly differ from cfchecker's (for example, that a dimension named like a CF axis,
  ``time`` or ``depth``, carries that axis's standard name).

An error is a cfchecker ERROR, or a message of a failed high-priority ("Errors") check
of the compliance-checker; its warnings (for example that the files declare CF-1.8, not
CF-1.10) are not errors. Prints the error counts per file and exits 1 if any file has an
error under either checker. Run ``bash .ci/install-cf-checker.sh`` first.

Usage: python .ci/cf_check.py [FILE.nc ...]
"""

from __future__ import annotations

import json
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

#: The compliance-checker suite: the newest CF version its 6.1 release checks.
IOOS_SUITE = "cf:1.10"


def cfchecker_errors(path: Path, version: str) -> tuple[int, list[str]]:
    """(number of ERRORs, their lines) of cfchecker on ``path``; -1 if it did not finish."""
    r = subprocess.run(
        ["cfchecks", "-v", version, *TABLES, str(path)], capture_output=True, text=True
    )
    out = r.stdout + r.stderr
    found = re.search(r"ERRORS detected: (\d+)", out)
    if found is None:
        return -1, out.strip().splitlines()[-5:]
    return int(found.group(1)), [
        ln for ln in out.splitlines() if ln.startswith("ERROR") and "detected" not in ln
    ]


def ioos_errors(path: Path, suite: str = IOOS_SUITE) -> tuple[int, list[str]]:
    """(number of error messages, the messages) of the IOOS compliance-checker on ``path``.

    The messages of every failed high-priority check (the report's "Errors"); -1 if the
    checker gave no report.
    """
    r = subprocess.run(
        ["compliance-checker", "--test", suite, "--format", "json", "--output", "-", str(path)],
        capture_output=True,
        text=True,
    )
    try:
        report = json.loads(r.stdout)[suite]
    except (json.JSONDecodeError, KeyError):
        return -1, (r.stdout + r.stderr).strip().splitlines()[-5:]
    msgs = []
    for check in report["high_priorities"]:
        scored, possible = check["value"]
        if scored < possible:
            msgs += [f"{check['name']}: {m}" for m in check["msgs"]] or [check["name"]]
    return len(msgs), msgs


def main() -> int:
    from pencore.io.netcdf import CF_CONVENTIONS

    version = CF_CONVENTIONS.removeprefix("CF-")
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / "fresh.nc"
        subprocess.run(
            [sys.executable, "-m", "pencore", "simulate", "--projectile", "p2",
             "--target", "soil", "--velocity", "300", "--out", str(fresh)],
            check=True, capture_output=True,
        )  # fmt: skip
        files = [fresh, *sorted((ROOT / "results" / "archive").rglob("*.nc"))]
        files += [Path(a) for a in sys.argv[1:]]
        bad = {"cfchecker": 0, "compliance-checker": 0}
        for f in files:
            n_cf, lines_cf = cfchecker_errors(f, version)
            n_io, lines_io = ioos_errors(f)
            name = "fresh pencore simulate file" if f == fresh else str(f)
            print(f"{n_cf:3d} CF-{version} errors (cfchecker)  {n_io:3d} {IOOS_SUITE} errors "
                  f"(compliance-checker)  {name}")  # fmt: skip
            for ln in [*lines_cf[:5], *lines_io[:5]]:
                print(f"      {ln}")
            bad["cfchecker"] += n_cf != 0
            bad["compliance-checker"] += n_io != 0
    print(
        f"cf_check: {len(files) - bad['cfchecker']} of {len(files)} files pass cfchecker "
        f"CF-{version}, {len(files) - bad['compliance-checker']} of {len(files)} pass "
        f"compliance-checker {IOOS_SUITE}"
    )
    return 1 if any(bad.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
