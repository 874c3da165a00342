"""The ``pencore`` command and ``python -m pencore``: ``pencore.cli.main.main()``, with
Ctrl-C answered the same at every moment the process is ours.

The command line ends a run interrupted by Ctrl-C with one line and exit status 130
(``pencore.cli.main.main()``). This entry point extends that to the moments around it:
while the command line's modules load (the first tenth of a second) it says the same and
exits 130, and once the command has returned, a late Ctrl-C no longer turns the finished
command into a traceback during the interpreter's shutdown: the exit status is the
command's. Only the interpreter's own start, before this module runs, is outside it.
"""

from __future__ import annotations

import signal
import sys

from pencore.errors import INTERRUPTED, interrupted_import

__all__ = ["run"]


def run() -> int:
    """Run the command line on ``sys.argv[1:]``; returns its exit status."""
    try:
        from pencore.cli.main import main

        status = main()
    except (KeyboardInterrupt, ImportError) as exc:  # before the command line's own
        # handling, or after it; an ImportError only when Ctrl-C caused it
        if not isinstance(exc, KeyboardInterrupt) and not interrupted_import(exc):
            raise
        print(f"pencore: error: {INTERRUPTED}", file=sys.stderr)
        status = 130
    # the command has finished (its files are complete or removed): a Ctrl-C from here
    # on would only interrupt the interpreter's shutdown
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    return status


if __name__ == "__main__":
    sys.exit(run())
