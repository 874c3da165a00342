"""Shared by the workflow scripts: logging to the rule's log file.

Snakemake puts this directory on ``sys.path`` for ``script:`` rules, so scripts do
``from _common import start_log``.
"""

from __future__ import annotations

import logging
import sys
import warnings
from pathlib import Path


def start_log(path: str, name: str) -> logging.Logger:
    """Send logging, warnings and uncaught exceptions of this job to ``path``."""
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    logging.basicConfig(
        filename=path,
        filemode="w",
        level=logging.INFO,
        format="%(asctime)s %(levelname)s %(name)s: %(message)s",
        force=True,
    )
    logging.captureWarnings(True)
    warnings.simplefilter("default")
    log = logging.getLogger(name)

    def excepthook(exc_type, exc, tb):
        log.critical("failed", exc_info=(exc_type, exc, tb))
        sys.__excepthook__(exc_type, exc, tb)

    sys.excepthook = excepthook
    return log
