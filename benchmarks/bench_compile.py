"""The cold numba compile: what a process pays with no cached kernels (reported, never asserted).

Each case starts a new Python process with ``NUMBA_CACHE_DIR`` pointed at a fresh empty
temporary directory and the kernels the package ships left unused
(``PENCORE_NO_SHIPPED_KERNELS=1``), so no existing cache is used, every kernel the case
needs is compiled, and nothing in the repository is written (the kernels' ``__pycache__`` is
left alone). The cases:

* ``first_result``: import pencore and compute the benchmark trajectory (p2, soil,
  45 deg, 1000 m/s) with the default path (the DAFL on rings, the Rosenbrock pair, the
  closed-form Jacobian): what a fresh clone pays for its first result without the
  install step;
* ``warmup``: the install step ``python -m pencore.warmup`` (every kernel variant).

For each: wall seconds from before the process starts to its exit; CPU seconds (user +
system) of the process from ``getrusage(RUSAGE_CHILDREN)``, the steadier figure on a
shared machine; the index files (``.nbi``: one per compiled function) and compiled
files (``.nbc``: one per specialisation, a function compiled for one tuple of argument
types) it left in the cache; the functions compiled more than once; the numba and
Python versions, the machine and its load, and the commit measured.

Writes benchmarks/results/compile.csv. Run: python benchmarks/bench_compile.py
[--case first_result|warmup] (default: both, one after the other, never in parallel).
"""

from __future__ import annotations

import argparse
import os
import platform
import re
import resource
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import pandas as pd

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

FIRST = (
    "import pencore; ds = pencore.simulate('p2', 'soil', 1000.0, obliquity=45.0); "
    "print(float(ds.path_length))"
)

#: case -> arguments of ``python``.
CASES: dict[str, list[str]] = {
    "first_result": ["-c", FIRST],
    "warmup": ["-m", "pencore.warmup"],
}

# <module>.<qualname>-<line>.py311.nbi and <module>.<qualname>-<line>.py311.<n>.nbc
_CACHE_FILE = re.compile(r"^(?P<function>.+)\.py\d+(?:\.\d+\.nbc|\.nbi)$")


def children_cpu() -> float:
    """User + system CPU seconds of this process's terminated, waited-for children."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed_run(args: list[str], env: dict[str, str]) -> tuple[float, float]:
    """Run ``python args``; return (wall s, CPU s of it and its descendants)."""
    c0, t0 = children_cpu(), time.perf_counter()
    done = subprocess.run([sys.executable, *args], env=env, capture_output=True, text=True)
    wall, cpu = time.perf_counter() - t0, children_cpu() - c0
    if done.returncode != 0:
        tail = "\n".join(done.stderr.splitlines()[-20:])
        raise SystemExit(f"bench_compile: python {' '.join(args)} exited {done.returncode}\n{tail}")
    return wall, cpu


def specialisations(cache: Path) -> Counter[str]:
    """Compiled files (``.nbc``) per function (``module.qualname-line``) under ``cache``."""
    return Counter(m["function"] for f in cache.rglob("*.nbc") if (m := _CACHE_FILE.match(f.name)))


def cache_counts(cache: Path) -> dict[str, int | str]:
    """Index files (compiled functions), compiled files (specialisations) under ``cache``,
    and the functions with more than one specialisation (``name:count``, most first)."""
    per_function = specialisations(cache)
    several = [f"{k}:{n}" for k, n in per_function.most_common() if n > 1]
    return {
        "index_files": sum(1 for _ in cache.rglob("*.nbi")),
        "compiled_files": sum(per_function.values()),
        "specialised_functions": " ".join(several),
    }


def cold(args: list[str]) -> dict[str, float | int | str]:
    """Run ``python args`` on an empty temporary numba cache: wall, CPU and cache counts."""
    with tempfile.TemporaryDirectory(prefix="pencore-numba-cold-") as cache:
        # the kernels the package ships are left unused: this measures a first compile
        env = {**os.environ, "NUMBA_CACHE_DIR": cache, "PENCORE_NO_SHIPPED_KERNELS": "1"}
        env.pop("NUMBA_DISABLE_JIT", None)
        wall, cpu = timed_run(args, env)
        return {"wall_s": wall, "cpu_s": cpu, **cache_counts(Path(cache))}


def numba_version() -> str:
    """The numba version the child processes import (read without importing numba here)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("numba")
    except PackageNotFoundError:
        return "not installed"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", choices=sorted(CASES), action="append", help="default: all")
    ap.add_argument("--csv", default=str(HERE / "results" / "compile.csv"))
    args = ap.parse_args()
    rows = []
    for case in args.case or list(CASES):
        print(f"bench_compile: {case} on an empty cache ...", flush=True)
        before = machine()  # the load before the run (a compile raises it)
        rows.append(
            {
                "case": case,
                **cold(CASES[case]),
                "numba": numba_version(),
                "python": platform.python_version(),
                **before,
            }
        )
    df = pd.DataFrame(rows)
    out = Path(args.csv)
    out.parent.mkdir(parents=True, exist_ok=True)
    if args.case and out.exists():  # one case re-measured: keep the other rows
        old = pd.read_csv(out, keep_default_na=False)
        df = pd.concat([old[~old["case"].isin(df["case"])], df], ignore_index=True)
    df.to_csv(out, index=False, float_format="%.3g")
    print(df.drop(columns=["specialised_functions"]).to_string(index=False))
    for _, r in df.iterrows():
        print(f"{r['case']}: compiled more than once: {r['specialised_functions'] or 'none'}")


if __name__ == "__main__":
    main()
