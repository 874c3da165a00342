"""The reference of every public name: a numpydoc docstring whose Examples run.

Each name of ``pencore.__all__`` (and of :mod:`pencore.closedform`) has an Examples
section, and each example is executed here as doctest runs it: the printed output must
be what the docstring shows. Examples print rounded numbers, so the check holds on any
x86-64 CPU. Those that run the solver are marked slow (they still run in CI).
"""

from __future__ import annotations

import doctest
import inspect
import re

import pytest

import pencore
import pencore.closedform

#: Calls in an example that run the solver (a trajectory takes 0.1-1 s once compiled).
SOLVER_CALLS = ("simulate(", "vcr(", "vci(", "omega_c(", "ballistic_limit(", "prepare(")


def _public() -> list[tuple[str, object]]:
    names = [(f"pencore.{n}", getattr(pencore, n)) for n in pencore.__all__ if n != "__version__"]
    closed = pencore.closedform
    names += [(f"pencore.closedform.{n}", getattr(closed, n)) for n in closed.__all__]
    return names


PUBLIC = _public()


def _params(marks_solver: bool) -> list[object]:
    out = []
    for name, obj in PUBLIC:
        doc = inspect.getdoc(obj) or ""
        slow = marks_solver and any(call in doc for call in SOLVER_CALLS)
        out.append(pytest.param(name, obj, id=name, marks=[pytest.mark.slow] if slow else []))
    return out


def _section(doc: str, title: str) -> str:
    """The body of a numpydoc section ('' when absent)."""
    m = re.search(
        rf"^{title}\n-{{{len(title)}}}\n(.*?)(?=^\w[\w ]*\n-{{3,}}\n|\Z)", doc, re.M | re.S
    )
    return m.group(1) if m else ""


@pytest.mark.parametrize(("name", "obj"), _params(False))
def test_docstring_has_the_numpydoc_sections(name, obj):
    doc = inspect.getdoc(obj) or ""
    summary = doc.split("\n\n", 1)[0]
    assert summary and len(summary.splitlines()) <= 2, f"{name}: a short summary first"
    assert ">>> " in _section(doc, "Examples"), f"{name}: no Examples section"
    if inspect.isfunction(obj):
        takes = [p for p in inspect.signature(obj).parameters if p not in ("self",)]
        if takes:
            assert _section(doc, "Parameters"), f"{name}: no Parameters section"
            for p in takes:
                assert re.search(rf"\b{p}\b", _section(doc, "Parameters")), f"{name}: {p}"
        assert _section(doc, "Returns"), f"{name}: no Returns section"


def test_the_section_reader_finds_sections_and_only_them():
    doc = "Sum.\n\nParameters\n----------\nx : float\n\nReturns\n-------\nfloat\n"
    assert _section(doc, "Parameters").strip() == "x : float"
    assert _section(doc, "Returns").strip() == "float"
    assert _section(doc, "Examples") == ""


@pytest.mark.parametrize(("name", "obj"), _params(True))
def test_examples_run_and_show_their_output(name, obj):
    tests = doctest.DocTestFinder(recurse=False).find(obj, name, globs={})
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    report: list[str] = []
    for test in tests:
        runner.run(test, out=report.append)
    assert sum(len(t.examples) for t in tests) > 0, f"{name}: no examples"
    assert runner.failures == 0, "".join(report)


def test_a_wrong_example_fails():
    """The runner above does fail on an example whose output differs."""

    def f() -> None:
        """Example.

        >>> 1 + 1
        3
        """

    (test,) = doctest.DocTestFinder(recurse=False).find(f, "f", globs={})
    runner = doctest.DocTestRunner()
    runner.run(test, out=lambda _: None)
    assert runner.failures == 1
