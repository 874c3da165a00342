"""``benchmarks/bench_reproduction.py`` measures what it says: the CPU of every process a
run starts (not only the first), a failing run stops it with the exit code, and the
per-job table sums and floors the benchmark files' wall column."""

from __future__ import annotations

import sys

import pytest


@pytest.fixture(scope="module")
def bench(load_benchmark):
    return load_benchmark("bench_reproduction")


# a child that starts a grandchild which burns 0.3 s of its own CPU, as Snakemake starts
# its jobs; the child itself does next to nothing
BURN = "import time; t = time.process_time()\nwhile time.process_time() - t < 0.3: pass"
PARENT = f"import subprocess, sys; subprocess.run([sys.executable, '-c', {BURN!r}], check=True)"


def test_cpu_includes_the_grandchildren(bench, tmp_path):
    wall, cpu = bench.timed_run([sys.executable, "-c", PARENT], tmp_path)
    # the grandchild's process_time is part of its rusage, which reaches us through
    # the child's wait: at least 0.3 s by construction, whatever the machine's speed
    assert cpu >= 0.3
    assert wall > 0.0


def test_a_failing_run_stops_with_its_exit_code(bench, tmp_path):
    with pytest.raises(SystemExit, match="exited 3"):
        bench.timed_run([sys.executable, "-c", "import sys; sys.exit(3)"], tmp_path)


def test_job_table_sums_and_floors_the_wall_column(bench, tmp_path):
    header = "s\th:m:s\tmax_rss\tcpu_time\n"
    for job, wall in {"section4/fig8_part_p1": 6.5, "section4/fig8_figure": 2.0,
                      "validation/table2": 3.25}.items():  # fmt: skip
        f = tmp_path / f"{job}.tsv"
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(header + f"{wall}\t0:00:0{int(wall)}\t100\t0.1\n")
    s = bench.summary(bench.job_table(tmp_path))
    assert s["n_jobs"] == 3
    assert s["job_wall_sum_s"] == 11.75
    assert (s["job_wall_min_s"], s["cheapest_job"]) == (2.0, "section4/fig8_figure")
    assert s["job_floor_s"] == 6.0
    assert s["group_wall_sum_s"] == {"section4": 8.5, "validation": 3.25}
