"""Command-line interface: ``pencore simulate | ballistic-limit | fit-table3 | list``.

Every user error ends the program with exit status 2 and a single line on stderr,
``pencore: error: <message>``, naming the offending value and what is allowed; a solver
failure ends it with status 1 and a single line. ``simulate --out`` writes its NetCDF
file atomically (temporary file in the same directory, then :func:`os.replace`), so a
failed or interrupted run never leaves a partial or stale-looking output behind. Each
subcommand is a module of this package (:mod:`~pencore.cli.simulate`,
:mod:`~pencore.cli.ballistic`, :mod:`~pencore.cli.library`); they import the solver only
when they run, so ``--help`` and ``list`` start light.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence

from pencore.cli import ballistic, library, simulate
from pencore.cli.options import INTERRUPTED, PROG, CommandFailure, Parser, one_line
from pencore.errors import InputError, SolverError
from pencore.version import __version__

__all__ = ["main", "build_parser"]

#: Subcommand -> the function that runs it (exit status).
COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {
    "simulate": simulate.run,
    "ballistic-limit": ballistic.run,
    "fit-table3": library.fit_table3,
    "list": library.list_library,
}


def build_parser() -> argparse.ArgumentParser:
    """Build the ``pencore`` argument parser.

    Returns
    -------
    argparse.ArgumentParser
        Parser with the ``simulate``, ``fit-table3`` and ``list`` subcommands.
    """
    parser = Parser(
        prog=PROG,
        description="3-D rigid-projectile penetration with the differential area force "
        "law (Li & Flores-Johnson, IJIE 2011). SI units throughout (m, kg, s, m/s, "
        "rad/s); angles in degrees.",
        epilog=simulate.SUMMARY,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--version",
        action="version",
        version=f"{PROG} {__version__}",
        help="print the pencore version and exit",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    simulate.add_parser(sub)
    ballistic.add_parser(sub)
    library.add_parsers(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the ``pencore`` command line.

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name; default ``sys.argv[1:]``.

    Returns
    -------
    int
        Exit status: 0 success, 1 solver or write failure, 2 bad input, 130 interrupted,
        141 output pipe closed early.
    """
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, usage errors
        return exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
    try:
        status = COMMANDS[args.command](args)
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        # the reader went away (`pencore list | head`): stop quietly, as Unix tools do;
        # point stdout at devnull so the interpreter's final flush does not fail again
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141  # 128 + SIGPIPE, what a shell reports for a tool killed by SIGPIPE
    except CommandFailure as exc:
        msg, status = str(exc), exc.status
    except InputError as exc:
        msg, status = str(exc), 2
    except KeyboardInterrupt:
        msg, status = INTERRUPTED, 130
    except SolverError as exc:
        msg, status = f"solver failed: {exc}", 1
    print(f"{PROG}: error: {one_line(msg)}", file=sys.stderr)
    return status


if __name__ == "__main__":
    raise SystemExit(main())
