"""Fresh process to first result, with a cold and a warm numba cache (reported, never asserted).

Each measurement starts a new Python process that imports pencore and computes the
benchmark trajectory (p2, soil, 45 deg, 1000 m/s), timed from before the process starts
to the result being back. The kernel cache is pointed (``NUMBA_CACHE_DIR``) at a fresh
empty directory and the kernels the package ships are left unused
(``PENCORE_NO_SHIPPED_KERNELS=1``; ``bench_fresh_install.py`` measures them), so the
runs are:

* ``cold``: empty cache, every kernel compiled (what a fresh clone paid before the
  install step ``python -m pencore.warmup``);
* ``warmup``: the install step itself on that empty cache;
* ``warm``: a fresh process after the warm-up (what a clone that ran the set-up
  commands, a CI run after ``.ci/run``'s install, and every workflow job pay);
* ``import``: a fresh process that only imports the solver (``pencore.run.impact``; the
  package itself imports its names on first use);
* ``snakemake_dry_run``: ``python -m snakemake -n`` of the whole workflow in this
  repository (parse, configuration check, DAG): what every Snakemake start costs before
  its first job, and each job of a cluster run, which starts Snakemake again on its
  node (left out, with a note, where Snakemake is not installed).

Writes benchmarks/results/startup.csv (with the machine and its load).
Run: python benchmarks/bench_startup.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).parent))
from machine import machine  # noqa: E402

FIRST = (
    "import pencore; ds = pencore.simulate('p2', 'soil', 1000.0, obliquity=45.0); "
    "print(float(ds.path_length))"
)


def timed(args: list[str], env: dict[str, str]) -> float:
    """Wall seconds of one fresh process running ``python args``."""
    t = time.perf_counter()
    subprocess.run([sys.executable, *args], env=env, check=True, capture_output=True)
    return time.perf_counter() - t


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as cache:
        # the kernels the package ships are left unused: cold is a first compile
        env = {**os.environ, "NUMBA_CACHE_DIR": cache, "PENCORE_NO_SHIPPED_KERNELS": "1"}
        rows.append(("cold", timed(["-c", FIRST], env)))
        # the cold run filled the cache with the default kernels; start the warm-up
        # from an empty cache again so that it is measured as a fresh install pays it
        with tempfile.TemporaryDirectory() as cache2:
            env2 = {**env, "NUMBA_CACHE_DIR": cache2}
            rows.append(("warmup", timed(["-m", "pencore.warmup"], env2)))
            warm = [timed(["-c", FIRST], env2) for _ in range(args.repeats)]
        rows.append(("warm", statistics.median(warm)))
        imp = [timed(["-c", "import pencore.run.impact"], env) for _ in range(args.repeats)]
        rows.append(("import", statistics.median(imp)))
    if importlib.util.find_spec("snakemake") is None:
        print("bench_startup: Snakemake is not installed; no snakemake_dry_run figure")
    else:
        repo = Path(__file__).resolve().parents[1]
        dry = ["-m", "snakemake", "-n", "--quiet", "--directory", str(repo), "--snakefile"]
        dry.append(str(repo / "Snakefile"))
        dry_runs = [timed(dry, dict(os.environ)) for _ in range(args.repeats)]
        rows.append(("snakemake_dry_run", statistics.median(dry_runs)))
    m = machine()
    df = pd.DataFrame([{"case": c, "wall_s": s, **m} for c, s in rows])
    out = Path(__file__).parent / "results"
    out.mkdir(exist_ok=True)
    df.to_csv(out / "startup.csv", index=False, float_format="%.3g")
    print(df.to_string(index=False))


if __name__ == "__main__":
    main()
