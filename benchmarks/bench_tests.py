"""The README's test command, ``python -m pytest -q -n 2``, timed.

Runs the command in the repository (in the environment this script runs in: the README's
``.venv-test``) and appends one row to ``benchmarks/results/tests.csv``: the wall time,
the CPU of pytest and every process it started (``getrusage(RUSAGE_CHILDREN)``), the
counts of the summary line (passed, failed, errors, skipped), the machine with its load
at the start (:func:`machine.machine`) and the mean 1-minute load seen during the run
(sampled every 10 s), so that a figure from a busy host says so. The README's timing line
reads the newest row (``docs/_ext/pencore_docs.py --readme``).

Run (from the repository root, on an otherwise idle host for the README's figure):
python benchmarks/bench_tests.py [pytest arguments instead of -q -n 2]
"""

from __future__ import annotations

import csv
import os
import re
import resource
import subprocess
import sys
import threading
import time
from pathlib import Path

HERE = Path(__file__).parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

OUT = HERE / "results" / "tests.csv"
COLUMNS = [
    "command", "wall_s", "cpu_s", "passed", "failed", "errors", "skipped", "load_mean",
    "cpu_model", "cores", "load_1min", "load_5min", "load_15min", "measured_utc", "commit",
]  # fmt: skip


def summary_line(text: str) -> str:
    """pytest's last summary line (``2258 passed, 10 errors in ...``), '' when none."""
    lines = [ln for ln in text.splitlines() if re.search(r"\d+ (passed|failed|error)", ln)]
    return lines[-1].strip("= ") if lines else ""


def summary_counts(text: str) -> dict[str, int]:
    """The counts of pytest's last summary line (``2258 passed, 10 errors in ...``)."""
    counts = {"passed": 0, "failed": 0, "errors": 0, "skipped": 0}
    for n, word in re.findall(r"(\d+) (passed|failed|errors?|skipped)", summary_line(text)):
        counts["errors" if word.startswith("error") else word] = int(n)
    return counts


def timed(argv: list[str], cwd: Path) -> tuple[float, float, float, str]:
    """Run ``argv``; (wall s, CPU s of it and its descendants, mean load, output)."""
    loads: list[float] = []
    stop = threading.Event()

    def sample() -> None:
        while not stop.wait(10.0):
            loads.append(os.getloadavg()[0])

    sampler = threading.Thread(target=sample, daemon=True)
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    sampler.start()
    done = subprocess.run(argv, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    stop.set()
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    mean = sum(loads) / len(loads) if loads else os.getloadavg()[0]
    return wall, cpu, mean, done.stdout + done.stderr


def main(argv: list[str] | None = None) -> int:
    args = (argv if argv is not None else sys.argv[1:]) or ["-q", "-n", "2"]
    command = [sys.executable, "-m", "pytest", *args]
    at_start = machine()
    wall, cpu, mean, output = timed(command, REPO)
    row = {
        "command": "python -m pytest " + " ".join(args),
        "wall_s": round(wall, 1),
        "cpu_s": round(cpu, 1),
        **summary_counts(output),
        "load_mean": round(mean, 2),
        **at_start,
    }
    new = not OUT.exists()
    with open(OUT, "a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        if new:
            writer.writeheader()
        writer.writerow(row)
    print(summary_line(output) or output.strip()[-2000:] or "(no output)")
    print(f"bench_tests: {row['wall_s']} s wall, {row['cpu_s']} s CPU, mean load {mean:.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
