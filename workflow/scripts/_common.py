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
        # the whole traceback goes to the rule's log; pencore's own errors (bad input,
        # a run that cannot finish) already name the value and cause, so the console
        # gets that one line, and a traceback only for what would be a bug
        log.critical("failed", exc_info=(exc_type, exc, tb))
        from pencore.errors import InputError, SolverError, WriteError

        if issubclass(exc_type, InputError | SolverError | WriteError):
            print(f"{name}: error: {exc} (details in {path})", file=sys.stderr)
            return
        sys.__excepthook__(exc_type, exc, tb)

    sys.excepthook = excepthook
    return log
