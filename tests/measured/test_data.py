"""The measured shots' data ships with the package: one copy, inside
``pencore/measured/data/``, that ``config/`` of the repository links to, declared as package
data so that an installed wheel reads the same compilation."""

from __future__ import annotations

import tomllib
from fnmatch import fnmatch
from pathlib import Path

import pytest

from pencore.measured import compilation as comp

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "src" / "pencore"
NAMES = ["concrete_compilation.csv", "concrete_compilation_errata.csv",
         "concrete_compilation_series.csv"]  # fmt: skip


@pytest.mark.parametrize("name", NAMES)
def test_config_links_to_the_package_copy(name):
    linked = REPO / "config" / name
    shipped = comp.DATA / name
    assert shipped.is_file() and not shipped.is_symlink()
    assert linked.is_symlink(), f"config/{name} should link to the package's copy"
    assert linked.resolve() == shipped.resolve()


def test_package_data_is_declared_for_the_wheel():
    data = tomllib.loads((REPO / "pyproject.toml").read_text())
    patterns = data["tool"]["setuptools"]["package-data"]["pencore"]
    files = sorted(comp.DATA.iterdir())
    assert [f.name for f in files] == sorted(NAMES)
    for f in files:
        rel = f.relative_to(PACKAGE).as_posix()
        assert any(fnmatch(rel, p) for p in patterns), f"{rel} is not package data"


def test_the_readers_default_to_the_shipped_files():
    assert comp.DATA == PACKAGE / "measured" / "data"
    for path in (comp.COMPILATION_CSV, comp.ERRATA_CSV, comp.SERIES_CSV):
        assert path.parent == comp.DATA and path.name in NAMES
