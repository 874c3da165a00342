"""Speed and memory of one trajectory (reported, never asserted).

Case from the core issue: projectile p2 into soil at 45 deg obliquity and 1000 m/s with
the default (converged) numerics, on one core. Prints wall time per trajectory (median
of repeats, after the one-off numba compilation), without the loads on the body
(``loads=False``), and for the raw run without its Dataset (what a search's verdict
costs), right-hand-side evaluations, accepted and rejected steps, and the process's peak
resident memory.

Run: python benchmarks/bench_trajectory.py [--repeats N]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import time

import pencore
from pencore.run.impact import prepare, run_impact


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=20)
    ap.add_argument("--json", help="also write the figures to this JSON file")
    args = ap.parse_args()
    os.environ.setdefault("NUMBA_NUM_THREADS", "1")

    t0 = time.perf_counter()
    pr = prepare("p2", "soil")
    ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=pr)
    first = time.perf_counter() - t0

    walls = []
    for _ in range(args.repeats):
        t = time.perf_counter()
        ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=pr)
        walls.append(time.perf_counter() - t)
    # the Dataset without the loads on the body (``loads=False``): the loads evaluate the
    # right-hand side once more at every saved state (pencore.run.loads)
    no_loads = []
    for _ in range(args.repeats):
        t = time.perf_counter()
        pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=pr, loads=False)
        no_loads.append(time.perf_counter() - t)
    # the raw run without its Dataset: what each verdict of a search (Vcr, Vci, omega_c)
    # and each attribution run costs (pencore.run.impact.run_impact, the same run to the bit)
    raw = []
    for _ in range(args.repeats):
        t = time.perf_counter()
        run_impact("p2", "soil", 1000.0, obliquity=45.0, prepared=pr)
        raw.append(time.perf_counter() - t)
    peak_mib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0

    out = {
        "case": "p2, soil, obliquity 45 deg, 1000 m/s, default numerics",
        "wall_s_median": statistics.median(walls),
        "wall_s_min": min(walls),
        "no_loads_s_median": statistics.median(no_loads),
        "raw_run_s_median": statistics.median(raw),
        "raw_run_s_min": min(raw),
        "first_call_s_including_compile_or_cache_load": first,
        "rhs_evaluations": ds.attrs["n_rhs"],
        "accepted_steps": ds.attrs["n_steps"],
        "rejected_steps": ds.attrs["n_rejected"],
        "rhs_per_second": ds.attrs["n_rhs"] / statistics.median(walls),
        "peak_rss_mib": peak_mib,
        "trajectory_arrays_kib": ds.nbytes / 1024.0,
        "path_length_m": float(ds.path_length),
    }
    for k, v in out.items():
        print(f"{k:48s} {v:.4g}" if isinstance(v, float) else f"{k:48s} {v}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=2)


if __name__ == "__main__":
    main()
