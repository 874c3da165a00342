"""The machine, its load and the code, recorded next to every speed figure (lscpu model,
cores, uptime load averages, git commit)."""

from __future__ import annotations

import os
import platform
import subprocess
from datetime import UTC


def machine() -> dict[str, str | float | int]:
    """CPU model, logical cores, 1/5/15-min load averages, the UTC time of the reading and
    the commit measured."""
    model = platform.processor() or platform.machine()
    try:
        for line in subprocess.run(
            ["lscpu"], capture_output=True, text=True, check=True
        ).stdout.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
    except (OSError, subprocess.CalledProcessError):
        pass
    load1, load5, load15 = os.getloadavg()
    from datetime import datetime

    return {
        "cpu_model": model,
        "cores": os.cpu_count() or 0,
        "load_1min": round(load1, 2),
        "load_5min": round(load5, 2),
        "load_15min": round(load15, 2),
        "measured_utc": datetime.now(UTC).strftime("%Y-%m-%dT%H:%MZ"),
        "commit": commit(),
    }


def commit() -> str:
    """Short hash of the checked-out commit, ``-dirty`` if the tree has changes outside
    ``benchmarks/results``; ``unknown`` outside a git checkout."""
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # repository root
    try:
        head = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], cwd=here, capture_output=True, text=True,
            check=True,
        ).stdout.strip()  # fmt: skip
        dirty = subprocess.run(
            # the benchmarks' own result files do not make the measured code dirty
            ["git", "status", "--porcelain", "--untracked-files=no", "--", ".",
             ":(exclude)benchmarks/results"], cwd=here,
            capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return head + ("-dirty" if dirty else "")
