"""Reading the CSV tables: every shipped table opens with the call the docs show, its
``#`` provenance lines apart, and every ``read_csv(`` the docs show skips them."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pandas as pd
import pytest

import pencore
from pencore.errors import InputError

REPO = Path(__file__).resolve().parents[2]
SHIPPED = sorted(
    [*REPO.glob("config/*.csv"), *REPO.glob("results/archive/**/*.csv")]
    + [*REPO.glob("benchmarks/results/*.csv")]
)
DOCS = REPO / "docs"


def _rows_after_header(path: Path) -> tuple[list[str], pd.DataFrame]:
    """The leading ``#`` lines and the rows, split by hand (the reference)."""
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    n = next((i for i, ln in enumerate(lines) if not ln.startswith("#")), len(lines))
    return lines[:n], pd.read_csv(io.StringIO("".join(lines[n:])))


def test_there_are_shipped_tables_with_and_without_a_header():
    heads = [bool(_rows_after_header(p)[0]) for p in SHIPPED]
    assert any(heads) and not all(heads)
    assert any(p.parent.name == "config" for p in SHIPPED)
    assert any("archive" in p.parts for p in SHIPPED)


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.relative_to(REPO).as_posix())
def test_every_shipped_table_opens_with_the_documented_call(path):
    header, rows = _rows_after_header(path)
    frame = pencore.read_table(path)
    pd.testing.assert_frame_equal(frame, rows)
    assert len(frame) > 0 and not any(str(c).startswith("#") for c in frame.columns)
    assert frame.attrs["provenance"] == [ln[1:].strip() for ln in header]
    # the pandas call the docs show reads the same rows, except on the tables whose rows
    # hold a `#` (the docs name those and send them to read_table)
    plain = pd.read_csv(path, comment="#")
    rel = path.relative_to(REPO).as_posix()
    if rel in _named_as_cut_by_comment():
        assert not plain.equals(rows), f"{rel} is named as cut by comment='#' but is not"
    else:
        pd.testing.assert_frame_equal(plain, rows)


def _named_as_cut_by_comment() -> set[str]:
    """The tables the common-tasks page names as cut by ``comment="#"``."""
    text = (DOCS / "user-guide" / "common-tasks.md").read_text()
    section = text.split("## Reading a table", 1)[1].split("\n## ", 1)[0]
    cut = section.split("It also cuts a row", 1)[1]
    return set(re.findall(r"`((?:config|results)/[\w/]+\.csv)`", cut))


def test_the_tables_named_as_cut_are_all_that_are():
    named = _named_as_cut_by_comment()
    assert named
    cut = set()
    for path in SHIPPED:
        if not pd.read_csv(path, comment="#").equals(_rows_after_header(path)[1]):
            cut.add(path.relative_to(REPO).as_posix())
    assert cut == named


def _doc_files() -> list[Path]:
    files = [REPO / "README.md", *DOCS.rglob("*.md"), *DOCS.rglob("*.py")]
    skip = {"_build", "_generated", "_ext", "auto_examples"}
    return [f for f in files if not skip & set(f.relative_to(REPO).parts)]


def test_every_read_csv_the_docs_show_skips_the_header():
    calls = []
    for f in _doc_files():
        for m in re.finditer(r"read_csv\(([^()]*(?:\([^()]*\)[^()]*)*)\)", f.read_text()):
            calls.append((f.relative_to(REPO).as_posix(), m.group(0)))
    assert calls, "no page shows reading a CSV with pandas"
    bad = [c for c in calls if 'comment="#"' not in c[1]]
    assert not bad, f'read_csv( without comment="#" in the docs: {bad}'
    shown = [f for f in _doc_files() if "pencore.read_table(" in f.read_text()]
    assert len(shown) >= 3, shown


def test_a_written_table_round_trips_with_its_provenance(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("# pencore vcr --projectile p2\n#   units: m s-1\na [m s-1],note\n1.5,#2\n")
    frame = pencore.read_table(path)
    assert frame.attrs["provenance"] == ["pencore vcr --projectile p2", "units: m s-1"]
    assert frame["a [m s-1]"].tolist() == [1.5] and frame["note"].tolist() == ["#2"]
    assert frame.attrs["path"] == str(path)


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        (None, "does not exist"),
        (b"# only a header\n", "holds no table after its # lines"),
        (b"a,b\n\xff\xfe,1\n", "is not UTF-8 text"),
    ],
)
def test_a_bad_table_is_one_line_naming_the_file(tmp_path, text, needle):
    path = tmp_path / "bad.csv"
    if text is not None:
        path.write_bytes(text)
    with pytest.raises(InputError, match=needle) as err:
        pencore.read_table(path)
    assert str(path) in str(err.value) and "\n" not in str(err.value)
