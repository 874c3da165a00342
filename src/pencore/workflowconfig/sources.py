"""Hashes of pencore's source, split so that a rule reruns only for the code it runs.

The workflow gives each rule a hash as ``params.code`` (Snakemake's own ``code`` trigger
sees only the rule's script, not the package it imports):

* solver and study rules get :func:`physics_source_hash`: every ``.py`` of
  ``src/pencore`` except the ``plotting`` package;
* figure rules get :func:`plotting_source_hash`: the ``plotting`` package only. A figure
  rule reads a dataset that a study rule wrote, so a physics change reaches it through its
  input (the study reruns, the dataset is new); hashing the physics here as well would
  only duplicate that trigger.

So a comment in a plotting module replots every figure and reruns no solver, and a change
in the physics reruns the studies and, through their outputs, the figures.
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable
from pathlib import Path

__all__ = [
    "PACKAGE_ROOT",
    "PLOTTING_PACKAGE",
    "physics_sources",
    "plotting_sources",
    "source_hash",
    "physics_source_hash",
    "plotting_source_hash",
]

#: ``src/pencore``.
PACKAGE_ROOT = Path(__file__).resolve().parents[1]
#: The sub-package whose changes rerun only figure rules.
PLOTTING_PACKAGE = "plotting"


def _is_plotting(path: Path, root: Path) -> bool:
    return path.relative_to(root).parts[0] == PLOTTING_PACKAGE


def physics_sources(root: Path = PACKAGE_ROOT) -> list[Path]:
    """Every ``.py`` under ``root`` outside the plotting package, sorted."""
    return sorted(p for p in root.rglob("*.py") if not _is_plotting(p, root))


def plotting_sources(root: Path = PACKAGE_ROOT) -> list[Path]:
    """Every ``.py`` of the plotting package under ``root``, sorted."""
    return sorted(p for p in root.rglob("*.py") if _is_plotting(p, root))


def source_hash(paths: Iterable[Path], root: Path = PACKAGE_ROOT) -> str:
    """SHA-256 (hex) of ``paths``: each file's name relative to ``root``, then its bytes.

    Parameters
    ----------
    paths
        Files under ``root``; hashed in sorted order, so the order given does not matter.
    root
        Directory the names are taken relative to (a rename changes the hash).

    Returns
    -------
    str
        64 hex digits.
    """
    digest = hashlib.sha256()
    for path in sorted(paths):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()


def physics_source_hash(root: Path = PACKAGE_ROOT) -> str:
    """:func:`source_hash` of :func:`physics_sources` (for solver and study rules)."""
    return source_hash(physics_sources(root), root)


def plotting_source_hash(root: Path = PACKAGE_ROOT) -> str:
    """:func:`source_hash` of :func:`plotting_sources` (for figure rules)."""
    return source_hash(plotting_sources(root), root)
