"""The full reproduction, ``snakemake --cores 2 --forceall``, timed in a fresh clone.

The repository's HEAD is cloned into a temporary directory (the working tree's
``results/`` are left alone), the install step ``python -m pencore.warmup`` is run there
(untimed: README command 1 runs it once before Snakemake), and then
``python -m snakemake --cores N --forceall`` is timed:

* ``wall_s``: from start to exit;
* ``cpu_s``: user + system CPU of Snakemake and every job it ran, exactly, from
  ``getrusage(RUSAGE_CHILDREN)`` (each process waits for its children, so a job's
  CPU is added to Snakemake's and Snakemake's to ours). Snakemake's own ``cpu_time``
  column of the benchmark files is *not* used: it samples a job's processes every 0.5 s
  and, after 30 samples, every 30 s, so it misses the CPU after the last sample (up to
  0.5 s of every job, and e.g. 15 s read for a job that took 33 s);
* per job, the ``s`` column of the benchmark files (start to end, exact): their sum,
  the cheapest job (process start, imports and kernel loading: what every job pays)
  and the sum per study group. A job is one thread and ``--cores 2`` runs at most two,
  so on an otherwise idle 2-core machine a job's wall is its CPU.

Writes benchmarks/results/reproduction.json (with the machine and its load), which
``speed_summary.py`` reads. Run (from the repository root, after the install step):
python benchmarks/bench_reproduction.py [--cores 2]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402


def children_cpu() -> float:
    """User + system CPU seconds of this process's terminated, waited-for descendants."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed_run(args: list[str], cwd: Path, env: dict[str, str] | None = None) -> tuple[float, float]:
    """Run ``args`` in ``cwd`` (with ``env``, default this process's environment); return
    (wall s, CPU s of it and all its descendants)."""
    c0, t0 = children_cpu(), time.perf_counter()
    done = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)
    wall, cpu = time.perf_counter() - t0, children_cpu() - c0
    if done.returncode != 0:
        tail = "\n".join(done.stderr.splitlines()[-20:])
        script = Path(sys.argv[0]).stem
        raise SystemExit(f"{script}: {' '.join(args)} exited {done.returncode}\n{tail}")
    return wall, cpu


def job_table(benchmarks: Path) -> pd.DataFrame:
    """One row per Snakemake benchmark file under ``benchmarks``: job, group, wall s."""
    rows = []
    for f in sorted(benchmarks.rglob("*.tsv")):
        job = f.relative_to(benchmarks).with_suffix("").as_posix()
        wall = float(pd.read_csv(f, sep="\t")["s"].iloc[0])
        rows.append({"job": job, "group": job.split("/")[0], "wall_s": wall})
    return pd.DataFrame(rows, columns=["job", "group", "wall_s"])


def summary(jobs: pd.DataFrame) -> dict:
    """Sum, cheapest job and per-group sums of the jobs' wall seconds."""
    cheapest = jobs.loc[jobs["wall_s"].idxmin()]
    return {
        "n_jobs": len(jobs),
        "job_wall_sum_s": float(jobs["wall_s"].sum()),
        "job_wall_min_s": float(cheapest["wall_s"]),
        "cheapest_job": str(cheapest["job"]),
        "job_floor_s": float(len(jobs) * cheapest["wall_s"]),
        "group_wall_sum_s": {g: float(s) for g, s in jobs.groupby("group")["wall_s"].sum().items()},
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cores", type=int, default=2)
    ap.add_argument("--json", default=str(HERE / "results" / "reproduction.json"))
    ap.add_argument(
        "--jobs-csv",
        default=str(HERE / "results" / "reproduction_jobs.csv"),
        help="per-job wall seconds (job, group, wall_s), slowest first",
    )
    ap.add_argument(
        "--keep",
        metavar="DIR",
        help="clone into DIR (new) and keep it, to compare its results with the archive "
        "(python .ci/compare_results.py)",
    )
    args = ap.parse_args()
    repo = HERE.parent
    with tempfile.TemporaryDirectory(prefix="pencore-repro-") as tmp:
        clone = Path(args.keep) if args.keep else Path(tmp) / "clone"
        subprocess.run(["git", "clone", "-q", str(repo), str(clone)], check=True)
        # the clone's own sources, kernel cache and install step (as README command 1)
        env_src = str(clone / "src")
        os.environ["PYTHONPATH"] = env_src + os.pathsep + os.environ.get("PYTHONPATH", "")
        print("bench_reproduction: install step (python -m pencore.warmup) ...", flush=True)
        timed_run([sys.executable, "-m", "pencore.warmup"], clone)
        before = machine()
        # the clone is of HEAD: what it measures is HEAD, whatever the working tree holds
        head = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], cwd=clone, capture_output=True,
            text=True, check=True,
        ).stdout.strip()  # fmt: skip
        if before["commit"].endswith("-dirty"):
            print("bench_reproduction: uncommitted changes are not measured (the clone is "
                  f"of HEAD, {head})", flush=True)  # fmt: skip
        before["commit"] = head
        print(f"bench_reproduction: snakemake --cores {args.cores} --forceall ...", flush=True)
        wall, cpu = timed_run(
            [sys.executable, "-m", "snakemake", "--cores", str(args.cores), "--forceall",
             "--quiet", "all"],
            clone,
        )  # fmt: skip
        jobs = job_table(clone / "results" / "benchmarks")
        out = {
            "wall_s": wall,
            "cpu_s": cpu,
            "cores": args.cores,
            **summary(jobs),
            "machine_before": before,
            "machine_after": {**machine(), "commit": before["commit"]},
        }
    Path(args.json).parent.mkdir(parents=True, exist_ok=True)
    Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
    jobs.sort_values("wall_s", ascending=False).to_csv(args.jobs_csv, index=False)
    print(
        f"wall {wall:.1f} s, CPU {cpu:.1f} s, {out['n_jobs']} jobs "
        f"(wall sum {out['job_wall_sum_s']:.1f} s, cheapest {out['job_wall_min_s']:.2f} s: "
        f"{out['cheapest_job']})"
    )


if __name__ == "__main__":
    main()
