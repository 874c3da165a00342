"""``benchmarks/search_cost.py`` reads the searches' own log lines: every evaluation of a
real search is found and classed by the bracket it bisects, and the seconds are the gaps
between the lines' timestamps."""

from __future__ import annotations

import logging

import pytest

from pencore.search.threshold import find_threshold


@pytest.fixture(scope="module")
def cost(load_benchmark):
    return load_benchmark("search_cost")


def _log_search(path, lo, hi, tol, scan):
    """A real search's log, written as the workflow's jobs write theirs."""
    handler = logging.FileHandler(path)
    handler.setFormatter(logging.Formatter("%(asctime)s %(levelname)s %(name)s: %(message)s"))
    log = logging.getLogger("pencore.search")
    old = log.level
    log.addHandler(handler)
    log.setLevel(logging.INFO)
    try:
        return find_threshold(lambda v: v >= 1234.5, lo, hi, tol, scan=scan, name="v_bl")
    finally:
        log.removeHandler(handler)
        log.setLevel(old)
        handler.close()


def test_every_evaluation_of_a_real_search_is_read(cost, tmp_path):
    path = tmp_path / "job.log"
    r1 = _log_search(path, 50.0, 3000.0, 2.0, 5)
    r2 = _log_search(path, 600.0, 2600.0, 5.0, None)
    found = cost.searches(path)
    assert [s["n_evals"] for s in found] == [r1.n_evals, r2.n_evals]
    assert [s["status"] for s in found] == [r1.status, r2.status] == ["ok", "ok"]
    assert [s["value"] for s in found] == pytest.approx([r1.value, r2.value], rel=1e-5)
    assert [s["tol"] for s in found] == [2.0, 5.0]


LINES = """\
2026-11-28 05:00:00,000 INFO pencore.search: v_bl: search in [0, 1000], tol 2
2026-11-28 05:00:01,000 INFO pencore.search: v_bl: evaluation 1 at 0 -> False (bracket [0, 1000])
2026-11-28 05:00:03,000 INFO pencore.search: v_bl: evaluation 2 at 1000 -> True (bracket [0, 1000])
2026-11-28 05:00:03,500 INFO pencore.search: v_bl: evaluation 3 at 500 -> True (bracket [0, 1000])
2026-11-28 05:00:07,500 INFO pencore.search: v_bl: evaluation 4 at 31.25 -> True (bracket [0, 62.5])
2026-11-28 05:00:07,750 INFO pencore.search: v_bl: evaluation 5 at 250 -> True (bracket [0, 500])
2026-11-28 05:00:08,000 INFO pencore.search: v_bl: ok after 5 evaluations, value 1 in [0, 2]
2026-11-28 05:00:09,000 INFO pencore.search: v_bl: search in [0, 10], tol 2
2026-11-28 05:00:10,000 INFO pencore.search: v_bl: evaluation 1 at 0 -> False (bracket [0, 10])
"""


def test_seconds_are_the_gaps_and_the_class_is_the_bracket(cost, tmp_path):
    path = tmp_path / "job.log"
    path.write_text(LINES)
    first, second = cost.searches(path)
    # ends and scan: the range itself (1 + 2 + 0.5 s); narrow: a bracket of at most
    # 32 tolerances (62.5 <= 64: 4 s); wide: 500 > 64 (0.25 s)
    assert (first["ends_scan_s"], first["narrow_s"], first["wide_s"]) == (3.5, 4.0, 0.25)
    assert (first["ends_scan_n"], first["narrow_n"], first["wide_n"]) == (3, 1, 1)
    assert (first["n_evals"], first["status"], first["value"]) == (5, "ok", 1.0)
    # a search its log does not finish (its job stopped, or a run of it raised)
    assert (second["status"], second["n_evals"], second["ends_scan_s"]) == ("unfinished", 1, 1.0)
