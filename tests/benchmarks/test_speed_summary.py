"""benchmarks/speed_summary.py: the docs' performance table is the one generated from
benchmarks/results/, and the generator reads what the benchmarks write."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import pandas as pd

REPO = Path(__file__).resolve().parents[2]


def test_docs_table_is_generated_from_the_results(load_benchmark):
    summary = load_benchmark("speed_summary")
    page = (REPO / "docs" / "performance.md").read_text()
    assert "```{include} _generated/speed.md" in page
    spec = importlib.util.spec_from_file_location("gen", REPO / "docs/_ext/pencore_docs.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    assert gen.PAGES["speed.md"]() == summary.markdown_table().strip()


def test_table_shows_each_figure_with_its_commit(load_benchmark, tmp_path):
    summary = load_benchmark("speed_summary")
    speed = pd.DataFrame(
        {
            "figure": [key for src, key, *_ in summary.TABLE_ROWS if src == "speed"],
            "value": 1.5,
            "unit": "ms",
            "commit": "abc1234",
            "measured_utc": "2026-01-02T03:04Z",
        }
    )
    speed.to_csv(tmp_path / "speed.csv", index=False)
    pd.DataFrame(
        {
            "case": ["first_result", "warmup"],
            "cpu_s": [44.8, 46.0],
            "commit": "def5678",
            "measured_utc": "2026-01-03T00:00Z",
        }
    ).to_csv(tmp_path / "compile.csv", index=False)
    pd.DataFrame(
        {
            "case": ["first_result_fresh_install", "build_wheel"],
            "wall_s": [2.25, 150.0],
            "commit": "0123abc",
            "measured_utc": "2026-01-04T00:00Z",
        }
    ).to_csv(tmp_path / "fresh_install.csv", index=False)
    table = summary.markdown_table(tmp_path)
    rows = table.strip().splitlines()[2:]
    assert len(rows) == len(summary.TABLE_ROWS)
    assert "| 44.8 s | def5678, 2026-01-03 |" in table
    assert "| 2.25 s | 0123abc, 2026-01-04 |" in table
    assert all(re.search(r"\| 1\.5 ms \| abc1234, 2026-01-02 \|", r) for r in rows if "ms" in r)
