"""The docs build and the built site need no network: intersphinx reads inventories kept
in the repository, MathJax is served by the site, and the browser check refuses a request
from a docs page to any other host."""

from __future__ import annotations

import importlib.util
import zlib
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / "docs"


def _module(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def conf():
    return _module(DOCS / "conf.py", "pencore_docs_conf")


def _inventory(path: Path) -> dict[str, str]:
    """name -> role of a Sphinx inventory (version 2)."""
    raw = path.read_bytes()
    header, _, body = raw.partition(b"# The remainder of this file is compressed using zlib.\n")
    assert header.startswith(b"# Sphinx inventory version 2\n")
    rows = zlib.decompress(body).decode().splitlines()
    return {row.split(" ")[0]: row.split(" ")[1] for row in rows}


def test_intersphinx_reads_files_of_the_repository(conf):
    assert set(conf.intersphinx_mapping) == {"python", "numpy", "scipy", "xarray", "matplotlib"}
    for url, inventory in conf.intersphinx_mapping.values():
        assert url.startswith("https://")
        assert Path(inventory).is_file(), inventory
        assert Path(inventory).parent == DOCS / "_inventories"


@pytest.mark.parametrize(
    ("project", "name", "role"),
    [
        ("xarray", "xarray.Dataset", "py:class"),
        ("numpy", "numpy.ndarray", "py:class"),
        ("scipy", "scipy.integrate.solve_ivp", "py:function"),
        ("matplotlib", "matplotlib.figure.Figure", "py:class"),
        ("python", "pathlib.Path", "py:class"),
    ],
)
def test_inventories_hold_the_objects_the_docs_refer_to(project, name, role):
    assert _inventory(DOCS / "_inventories" / f"{project}.inv").get(name) == role


def test_mathjax_is_served_by_the_site(conf):
    pytest.importorskip("mathjax", reason="the docs extra (django-static-mathjax)")
    assert "://" not in conf.mathjax_path and not conf.mathjax_path.startswith("//")
    source = conf._mathjax_source()
    for name in conf.MATHJAX_FILES:
        assert (source / name).exists(), name
    assert (source / conf.mathjax_path.removeprefix("mathjax/")).is_file()


def test_browser_check_refuses_other_hosts():
    pytest.importorskip("selenium")
    check = _module(REPO / ".ci" / "browser_check.py", "browser_check")
    base = "http://127.0.0.1:8000"
    urls = [
        f"{base}/_static/mathjax/tex-mml-chtml.js",
        "data:image/png;base64,AAAA",
        "https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-mml-chtml.js",
        "http://127.0.0.1:9999/other-port.js",
    ]
    assert check.other_hosts(urls, base) == urls[2:]
