"""The paper's data ships with the package: one copy, inside ``pencore/paper/data/``, that
``config/`` of the repository links to; no module reads a file above the package, so an
installed wheel (no repository around it) reads the same claims and tables."""

from __future__ import annotations

import ast
import os
import re
import tomllib
from fnmatch import fnmatch
from pathlib import Path

import pytest

from pencore.errors import InputError
from pencore.paper import claims

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "src" / "pencore"


@pytest.mark.parametrize("name", ["paper_claims.csv", "table2.csv"])
def test_config_links_to_the_package_copy(name):
    linked = REPO / "config" / name
    shipped = claims.DATA_DIR / name
    assert shipped.is_file() and not shipped.is_symlink()
    # one copy in the repository: config/ holds a link to it (git stores it as a
    # symlink), never a second file that could drift
    assert linked.is_symlink(), f"config/{name} should link to the package's copy"
    assert linked.resolve() == shipped.resolve()


def test_package_data_is_declared_for_the_wheel():
    data = tomllib.loads((REPO / "pyproject.toml").read_text())
    patterns = data["tool"]["setuptools"]["package-data"]["pencore"]
    for f in claims.DATA_DIR.iterdir():
        rel = f.relative_to(PACKAGE).as_posix()
        assert any(fnmatch(rel, p) for p in patterns), f"{rel} is not package data"


def test_the_readers_default_to_the_shipped_files():
    assert claims.CLAIMS_FILE.parent == claims.DATA_DIR == PACKAGE / "paper" / "data"
    assert claims.TABLE2_FILE.parent == claims.DATA_DIR


def _parents_index(node: ast.AST) -> int | None:
    """``k`` of a ``Path(__file__)...parents[k]`` expression, else None."""
    if (
        isinstance(node, ast.Subscript)
        and isinstance(node.value, ast.Attribute)
        and node.value.attr == "parents"
        and "__file__" in ast.unparse(node.value)
        and isinstance(node.slice, ast.Constant)
    ):
        return int(node.slice.value)
    return None


def test_no_module_reads_a_path_above_the_package():
    """``Path(__file__).parents[k]`` of a module stays inside ``src/pencore`` (the
    repository around it is not there in a wheel)."""
    outside = []
    for py in PACKAGE.rglob("*.py"):
        depth = len(py.relative_to(PACKAGE).parts) - 1  # folders below src/pencore
        for node in ast.walk(ast.parse(py.read_text())):
            k = _parents_index(node)
            if k is not None and k > depth:
                outside.append(f"{py.relative_to(REPO)}:{node.lineno} parents[{k}]")
        text = py.read_text()
        for m in re.finditer(r"\.parent\.parent\.parent", text):
            outside.append(f"{py.relative_to(REPO)}: {m.group(0)}")
    assert not outside, f"modules reading outside the package: {outside}"


def test_override_names_the_missing_file(tmp_path, monkeypatch):
    missing = tmp_path / "nowhere.csv"
    monkeypatch.setenv("PENCORE_PAPER_CLAIMS", os.fspath(missing))
    with pytest.raises(InputError, match="nowhere.csv"):
        claims.load_claims()
