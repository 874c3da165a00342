"""``benchmarks/bench_tests.py`` reads pytest's summary line as it is printed, and counts
the CPU of the processes a run starts."""

from __future__ import annotations

import sys

import pytest


@pytest.fixture(scope="module")
def bench(load_benchmark):
    return load_benchmark("bench_tests")


def test_summary_counts_of_a_failing_and_a_passing_run(bench):
    text = "....\nFAILED a\n= 2258 passed, 3 skipped, 10 errors in 451.20s (0:07:31) =\n"
    assert bench.summary_counts(text) == {"passed": 2258, "failed": 0, "errors": 10,
                                          "skipped": 3}  # fmt: skip
    text = "2300 passed, 1 failed, 1 error in 300.0s\n"
    assert bench.summary_counts(text) == {"passed": 2300, "failed": 1, "errors": 1, "skipped": 0}
    assert bench.summary_counts("no summary") == {"passed": 0, "failed": 0, "errors": 0,
                                                  "skipped": 0}  # fmt: skip


def test_timed_counts_the_child_s_cpu(bench, tmp_path):
    burn = "import time; t = time.process_time()\nwhile time.process_time() - t < 0.3: pass"
    wall, cpu, load, out = bench.timed([sys.executable, "-c", burn + "\nprint('x')"], tmp_path)
    assert cpu >= 0.3 and wall > 0 and load >= 0 and out.strip() == "x"
