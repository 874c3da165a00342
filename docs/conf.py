"""Sphinx configuration of the pencore documentation.

Built with ``python -m sphinx -W --keep-going -n -b html docs docs/_build/html``
(``.ci/docs.sh`` does it in CI): every warning fails the build, and so does every
cross-reference that does not resolve (``-n``). The build needs no network: the
intersphinx inventories are files of ``docs/_inventories/`` and MathJax is served from the
site itself (copied from the docs extra's ``django-static-mathjax``). Every table of
numbers in the pages is generated at build time by ``docs/_ext/pencore_docs.py`` from the
files that hold the numbers (the archive, ``config/paper_claims.csv``,
``benchmarks/results/``, :data:`pencore.inputs.limits.LIMITS`, the workflow's schema), and
the examples gallery runs every ``docs/examples/plot_*.py``.
"""

from __future__ import annotations

import shutil
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
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
    "pencore_docs",
]

source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["_build", "_generated", "_inventories", "_templates", "examples/README.rst"]
templates_path = ["_templates"]
myst_enable_extensions = ["colon_fence", "dollarmath", "substitution", "deflist"]
myst_heading_anchors = 3

# API reference: numpydoc renders the numpy-style docstrings; autosummary writes one page
# per public name listed in api/index.md and one per module under api/modules.md (a
# recursive listing: a new module gets its page without being listed).
autosummary_generate = True
# each object is documented in the module that defines it, not again where a package
# re-exports it
autodoc_default_options = {"members": True, "ignore-module-all": True}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()

# Intersphinx from inventories in the repository (CI has no network, and a strict build
# must not depend on one): docs/_inventories/make_inventories.py writes them from the
# installed packages with each project's URL pattern; the links point to the projects' sites.
INVENTORIES = DOCS / "_inventories"
intersphinx_mapping = {
    name: (url, str(INVENTORIES / f"{name}.inv"))
    for name, url in {
        "python": "https://docs.python.org/3/",
        "numpy": "https://numpy.org/doc/stable/",
        "scipy": "https://docs.scipy.org/doc/scipy/",
        "xarray": "https://docs.xarray.dev/en/stable/",
        "matplotlib": "https://matplotlib.org/stable/",
    }.items()
}

# MathJax served from the site: the docs extra installs MathJax 3 (django-static-mathjax,
# which vendors MathJax's own build, Apache-2.0); the build copies its browser build into
# _static/mathjax/, so a page loads nothing from another host.
MATHJAX_FILES = ("tex-mml-chtml.js", "input", "output/chtml", "ui", "a11y", "sre", "adaptors")
mathjax_path = "mathjax/tex-mml-chtml.js"


def _mathjax_source() -> Path:
    try:
        import mathjax  # the package django-static-mathjax installs
    except ImportError as exc:
        raise RuntimeError(
            "MathJax is missing: install the docs extra (python -m pip install -e '.[docs]')"
        ) from exc
    return Path(mathjax.__path__[0]) / "static" / "mathjax" / "es5"


def _copy_mathjax(app, exception) -> None:  # noqa: ANN001  (Sphinx's event signature)
    if exception is not None or app.builder.format != "html":
        return
    source, dest = _mathjax_source(), Path(app.outdir) / "_static" / "mathjax"
    for name in MATHJAX_FILES:
        if (source / name).is_dir():
            shutil.copytree(source / name, dest / name, dirs_exist_ok=True)
        else:
            dest.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source / name, dest / name)
    shutil.copy2(source.parent / "LICENSE", dest / "LICENSE")


def setup(app) -> None:  # noqa: ANN001
    _mathjax_source()  # fail at the start of a build, not after it
    app.connect("build-finished", _copy_mathjax)


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
    # every top-level page in the navbar (the API reference too), none under "More"
    "header_links_before_dropdown": 12,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "secondary_sidebar_items": ["page-toc"],
}
html_static_path = ["_static"]
html_favicon = "_static/favicon.svg"
# the theme reads the reader's saved choice; a first visit gets light mode
html_context = {"default_mode": "light"}
html_show_sourcelink = False
