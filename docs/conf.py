"""Sphinx configuration of the pencore documentation.

Built with ``python -m sphinx -W --keep-going -n -b html docs docs/_build/html``
(``.ci/docs.sh`` does it in CI). Every table of numbers in the pages is generated at build
time by ``docs/_ext/pencore_docs.py`` from the files that hold the numbers (the archive,
``config/paper_claims.csv``, ``benchmarks/results/``, :data:`pencore.inputs.limits.LIMITS`,
the workflow's schema), and the examples gallery runs every ``docs/examples/plot_*.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS / "_ext"))

import pencore  # noqa: E402

project = "pencore"
author = "the pencore developers"
copyright = "2026, the pencore developers"
release = pencore.__version__
version = release

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
    "pencore_docs",
]

source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["_build", "_generated", "examples/README.rst"]
myst_enable_extensions = ["colon_fence", "dollarmath", "substitution", "deflist"]
myst_heading_anchors = 3

# API reference: numpydoc renders the numpy-style docstrings; autosummary writes one page
# per public module listed in api/index.md.
autosummary_generate = True
# each object is documented in the module that defines it, not again where a package
# re-exports it
autodoc_default_options = {"members": True, "ignore-module-all": True}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()

# No intersphinx: CI has no network, and a strict build must not depend on it.

sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    # an example that raises fails the build
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "within_subsection_order": "FileNameSortKey",
    # the timing pages load jQuery from a CDN, which a build without network cannot reach
    "write_computation_times": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"pencore {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "navbar_align": "left",
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "secondary_sidebar_items": ["page-toc"],
}
html_static_path = ["_static"]
html_favicon = "_static/favicon.svg"
# the theme reads the reader's saved choice; a first visit gets light mode
html_context = {"default_mode": "light"}
html_show_sourcelink = False
