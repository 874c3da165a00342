"""Choice of the default ``Numerics.jacobian_age`` (how long a Jacobian is held).

For each age, the benchmark case (p2, soil, 45 deg, 1000 m/s) is run and timed in thread
CPU time (so the load of a shared machine matters little), with its right-hand-side
calls, accepted and rejected steps, path length and turning angle, and the critical
reverse velocity of p2 at 45 deg (the ``vcr_p2_45`` search of ``convergence.py``) with its
CPU time. Changes are against age 1 (a fresh Jacobian every step, the old scheme).

Writes benchmarks/results/jacobian_age.csv. Run: python benchmarks/bench_jacobian.py
"""

from __future__ import annotations

import dataclasses
import os
import statistics
import time
from pathlib import Path

import pandas as pd

import pencore
from pencore import analysis
from pencore.run.impact import prepare
from pencore.search import critical

AGES = [1, 2, 4, 6, 8, 12, 16]


def measure(age: int, repeats: int = 5) -> dict[str, float]:
    num = dataclasses.replace(pencore.Numerics(), jacobian_age=age)
    pr = prepare("p2", "soil", num)
    pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=pr)  # compile / load
    cpu = []
    for _ in range(repeats):
        t = time.thread_time()
        ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=pr)
        cpu.append(time.thread_time() - t)
    t = time.thread_time()
    v = critical.vcr(
        "p2", "soil", 45.0, lo=1300.0, hi=1900.0, tol=1.0, numerics=num, start=(-1.0, 1.0, 0.0)
    )
    vcr_cpu = time.thread_time() - t
    return {
        "jacobian_age": age,
        "traj_cpu_ms": 1e3 * statistics.median(cpu),
        "rhs_evaluations": ds.attrs["n_rhs"],
        "accepted_steps": ds.attrs["n_steps"],
        "rejected_steps": ds.attrs["n_rejected"],
        "path_45_1000": float(ds.path_length),
        "turn_45_1000": float(analysis.turning_angle(ds).delta_theta),
        "vcr_p2_45": float(v.value),
        "vcr_cpu_s": vcr_cpu,
    }


def main() -> None:
    os.environ.setdefault("NUMBA_NUM_THREADS", "1")
    rows = []
    for age in AGES:
        rows.append(measure(age))
        print(rows[-1], flush=True)
    df = pd.DataFrame(rows)
    base = df.iloc[0]
    for col in ("path_45_1000", "turn_45_1000", "vcr_p2_45"):
        df[f"{col}_rel_change"] = df[col] / base[col] - 1.0
    df["traj_speedup"] = base["traj_cpu_ms"] / df["traj_cpu_ms"]
    df["vcr_speedup"] = base["vcr_cpu_s"] / df["vcr_cpu_s"]
    out = Path(__file__).parent / "results"
    out.mkdir(exist_ok=True)
    df.to_csv(out / "jacobian_age.csv", index=False, float_format="%.6g")
    print(df.to_string(index=False, float_format=lambda x: f"{x:.6g}"))


if __name__ == "__main__":
    main()
