"""Assertions shared by the test modules (imported as ``from helpers import ...``)."""

from __future__ import annotations


def assert_one_line_error(err: str, *needles: str) -> None:
    """stderr is exactly one ``pencore: error: ...`` line, with no traceback, containing
    every needle."""
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("pencore: error: "), err
    for needle in needles:
        assert needle in lines[0], (needle, err)
