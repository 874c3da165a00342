"""Command-line interface: ``pencore simulate | ballistic-limit | vcr | ... | closed-form``.

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
import signal
import sys
from collections.abc import Callable, Sequence

from pencore.cli import ballistic, closed_form, critical, law, library, simulate, sweeps
from pencore.cli.options import PROG, CommandFailure, Parser, call_inputs, one_line
from pencore.errors import InputError, SolverError, interrupted_import
from pencore.inputs.limits import one_line_warnings
from pencore.io.atomic import describe_os_error
from pencore.io.outputs import interrupted_message, output_call
from pencore.version import __version__

__all__ = ["main", "build_parser"]

#: Subcommand -> the function that runs it (exit status).
COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {
    "simulate": simulate.run,
    "ballistic-limit": ballistic.run,
    "vcr": critical.run_search,
    "vci": critical.run_search,
    "omega-c": critical.run_search,
    "depth-curve": sweeps.run_sweep,
    "residual-velocity": sweeps.run_sweep,
    "ballistic-table": sweeps.run_sweep,
    "fit-table3": library.fit_table3,
    "list": library.list_library,
    "law": law.run,
    "closed-form": closed_form.run,
}


def build_parser() -> argparse.ArgumentParser:
    """Build the ``pencore`` argument parser.

    Returns
    -------
    argparse.ArgumentParser
        Parser with the ``simulate``, ``ballistic-limit``, ``vcr``, ``vci``, ``omega-c``,
        the sweeps, ``fit-table3``, ``list``, ``law`` and ``closed-form`` subcommands.
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
    critical.add_parsers(sub)
    sweeps.add_parsers(sub)
    library.add_parsers(sub)
    law.add_parser(sub)
    closed_form.add_parser(sub)
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
        Exit status: 0 success, 1 solver or write failure, 2 bad input, 3 a search found
        no threshold in its range (``vcr``, ``vci``, ``omega-c``, ``ballistic-limit``),
        130 interrupted (Ctrl-C), 141 output pipe closed early, 143 terminated (SIGTERM)
        while a file was written.
    """
    with one_line_warnings(PROG):  # a PlausibilityWarning is one line; the run goes on
        return _main(argv)


def _main(argv: Sequence[str] | None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, usage errors
        status = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
        return _flushed(status)
    except OSError as exc:  # help or version text that standard output did not take
        return _flushed(0, exc)
    if sys.stdout is None:  # started with standard output closed (`pencore ... >&-`)
        print(f"{PROG}: error: standard output is closed; nothing was run", file=sys.stderr)
        return 1
    real_stdout = sys.stdout
    sys.stdout = _GuardedStdout(real_stdout)  # type: ignore[assignment]
    call = output_call(call_inputs(args))  # no output of the command replaces an input
    call.__enter__()
    try:
        status = COMMANDS[args.command](args)
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        # the reader went away (`pencore list | head`): stop quietly, as Unix tools do;
        # point stdout at devnull so the interpreter's final flush does not fail again
        _silence_stdout(real_stdout)
        return 141  # 128 + SIGPIPE, what a shell reports for a tool killed by SIGPIPE
    except _StdoutFailed as exc:
        # a full device (`> /dev/full`) or an unusable descriptor; output files are
        # written completely before the summary is printed, and are kept
        _silence_stdout(real_stdout)
        msg = (
            f"cannot write to standard output: {describe_os_error(exc.cause)}; "
            "files written before are kept"
        )
        status = 1
    except CommandFailure as exc:
        msg, status = str(exc), exc.status
    except InputError as exc:
        msg, status = str(exc), 2
    except KeyboardInterrupt:
        msg, status = interrupted_message(), 130
    except ImportError as exc:
        if not interrupted_import(exc):
            raise
        msg, status = interrupted_message(), 130
    except SystemExit as exc:
        if exc.code != 128 + signal.SIGTERM:  # SIGTERM during a write (pencore.io.atomic)
            raise
        msg, status = interrupted_message("terminated (SIGTERM)"), exc.code
    except SolverError as exc:
        msg, status = f"solver failed: {exc}", 1
    finally:
        call.__exit__(None, None, None)
        sys.stdout = real_stdout
        driver = sys.modules.get("pencore.integrators.driver")
        if driver is not None:  # main() called in-process: Ctrl-C behaves as before
            driver.exit_on_interrupt(None)
    print(f"{PROG}: error: {one_line(msg)}", file=sys.stderr)
    return status


class _StdoutFailed(Exception):
    """Writing to standard output failed (other than a broken pipe)."""

    def __init__(self, cause: OSError) -> None:
        super().__init__(str(cause))
        self.cause = cause


class _GuardedStdout:
    """Standard output whose write failures are told apart from other ``OSError``."""

    def __init__(self, stream: object) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        try:
            try:
                return self._stream.write(text)  # type: ignore[attr-defined]
            except UnicodeEncodeError:
                # a name the locale's encoding cannot show (a non-ASCII --out under an
                # ASCII locale): shown with backslash escapes; the file itself is written
                enc = getattr(self._stream, "encoding", None) or "ascii"
                safe = text.encode(enc, "backslashreplace").decode(enc)
                return self._stream.write(safe)  # type: ignore[attr-defined]
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise _StdoutFailed(exc) from None

    def flush(self) -> None:
        try:
            self._stream.flush()  # type: ignore[attr-defined]
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise _StdoutFailed(exc) from None

    def __getattr__(self, name: str) -> object:
        return getattr(self._stream, name)


def _flushed(status: int, failed: OSError | None = None) -> int:
    """``status`` once what argparse printed (help, version) has reached standard output;
    141 when the reader went away, 1 with one line on stderr when the write failed
    (``failed``: the write already failed so)."""
    if sys.stdout is None:
        return status
    try:
        if failed is not None:
            raise failed
        sys.stdout.flush()
    except BrokenPipeError:
        _silence_stdout(sys.stdout)
        return 141
    except OSError as exc:
        _silence_stdout(sys.stdout)
        print(
            f"{PROG}: error: cannot write to standard output: {describe_os_error(exc)}",
            file=sys.stderr,
        )
        return 1
    return status


def _silence_stdout(stream: object) -> None:
    """Point standard output at the null device, so that the interpreter's final flush
    of what is still buffered does not fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, stream.fileno())  # type: ignore[attr-defined]
    except (OSError, ValueError, AttributeError):
        pass


if __name__ == "__main__":
    raise SystemExit(main())
