"""The "How to cite" page is generated from CITATION.cff (docs/_ext/pencore_docs.py)."""

from __future__ import annotations

from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[2]


def test_cite_page_follows_the_citation_file(gen, tmp_path):
    cff = yaml.safe_load((REPO / "CITATION.cff").read_text())
    page = gen.cite_page()
    assert f"version {cff['version']}" in page
    paper = cff["references"][0]
    assert f"{paper['volume']} ({paper['year']}) {paper['start']}-{paper['end']}" in page
    assert "@software{pencore," in page and "@article{li2011," in page
    # a changed file changes the page: a version and a repository URL
    cff["version"] = "9.9.9"
    cff["repository-code"] = "https://example.org/pencore"
    other = tmp_path / "CITATION.cff"
    other.write_text(yaml.safe_dump(cff))
    page = gen.cite_page(other)
    assert "version 9.9.9, https://example.org/pencore" in page
    assert "url = {https://example.org/pencore}" in page


def test_cite_page_is_in_the_site(gen):
    index = (REPO / "docs" / "index.md").read_text()
    assert "[How to cite](cite.md)" in index
    assert "_generated/cite.md" in (REPO / "docs" / "cite.md").read_text()
    assert "cite.md" in gen.PAGES
