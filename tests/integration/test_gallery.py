"""The gallery's examples (``docs/examples/plot_*.py``) run as a reader runs them and do
what a gallery page promises.

Each script is run in a fresh interpreter from its own folder (as sphinx-gallery runs
it) with the Agg backend; it must exit 0, print nothing to stderr but the one-off
compile notice, and leave at least one figure whose every axes has both labels, each
with a unit in parentheses (or a count: "number of ..."). The scripts use pencore's
public API only: no ``_private`` name of pencore is imported or reached as an
attribute. The docs build runs the same scripts under sphinx-gallery; this test fails
first, and names the script.
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from pencore.run.impact import COMPILE_NOTICE

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "docs" / "examples"
SCRIPTS = sorted(EXAMPLES.glob("plot_*.py"))
UNIT = re.compile(r"\([^()]*\)\s*$")  # "speed (m/s)", "Lc/L (dimensionless)"
COUNT = re.compile(r"^(number|evaluation number)\b")  # a count has no unit

#: Run after the script in the same interpreter: every axes of every figure, labelled.
CHECK = """
import matplotlib.pyplot as plt
for num in plt.get_fignums():
    for ax in plt.figure(num).axes:
        print("AXES", repr(ax.get_xlabel()), repr(ax.get_ylabel()))
"""


def test_there_are_at_least_six_examples_and_a_gallery_header():
    assert len(SCRIPTS) >= 6, [p.name for p in SCRIPTS]
    header = (EXAMPLES / "README.rst").read_text(encoding="utf-8").splitlines()
    assert header[:2] == ["Examples", "========"]


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_example_uses_only_public_names(script: Path):
    tree = ast.parse(script.read_text(encoding="utf-8"))
    private = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("pencore"):
            parts = node.module.split(".") + [a.name for a in node.names]
            private += [f"{node.module}: {p}" for p in parts if p.startswith("_")]
        elif isinstance(node, ast.Import):
            private += [a.name for a in node.names if "._" in a.name and "pencore" in a.name]
        elif isinstance(node, ast.Attribute) and node.attr.startswith("_"):
            if not node.attr.startswith("__"):
                private.append(f"line {node.lineno}: .{node.attr}")
    assert private == []


@pytest.mark.slow
@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_example_runs_and_ends_with_labelled_figures(script: Path):
    env = {**os.environ, "MPLBACKEND": "Agg"}
    env["PYTHONPATH"] = os.pathsep.join(
        [str(REPO / "src"), *filter(None, [os.environ.get("PYTHONPATH")])]
    )
    driver = f"import runpy; runpy.run_path({str(script)!r}, run_name='__main__')\n{CHECK}"
    out = subprocess.run(
        [sys.executable, "-c", driver],
        cwd=EXAMPLES,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stderr[-3000:]
    assert out.stderr.replace(COMPILE_NOTICE, "").strip() == ""
    axes = [line for line in out.stdout.splitlines() if line.startswith("AXES ")]
    assert axes, f"{script.name} made no figure"
    for line in axes:
        x, y = (ast.literal_eval(s) for s in re.findall(r"'[^']*'|\"[^\"]*\"", line))
        for label in (x, y):
            assert UNIT.search(label) or COUNT.search(label), f"{script.name}: axis {label!r}"
