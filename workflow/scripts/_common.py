"""Shared by the workflow scripts: logging to the rule's log file, and the job opened as
one call of the output gate (:func:`pencore.io.outputs.begin_call`: no output of the job
replaces one of its inputs, whatever writer writes it).

Snakemake puts this directory on ``sys.path`` for ``script:`` rules, so scripts do
``from _common import start_log``.
"""

from __future__ import annotations

import logging
import sys
import warnings
from pathlib import Path


def start_log(smk: object, name: str) -> logging.Logger:
    """Send logging, warnings and uncaught exceptions of the job ``smk`` (Snakemake's
    ``snakemake`` object) to its log file, and protect its inputs from its writers."""
    from pencore.io.outputs import begin_call

    begin_call([str(f) for f in smk.input])  # type: ignore[attr-defined]
    path = str(smk.log[0])  # type: ignore[attr-defined]
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
