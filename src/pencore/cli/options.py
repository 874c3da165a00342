"""Shared pieces of the ``pencore`` subcommands: the one-line parser and failure, the
argument types that check a value against :data:`pencore.inputs.limits.LIMITS`, the
depth-window options, and the checks of names, files and the output path.

Every user error becomes one line on stderr and exit status 2 (1 for a failure to
write); the argument types name the value and what is allowed.
"""

from __future__ import annotations

import argparse
import errno
import math
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any, NoReturn

from pencore.errors import InputError
from pencore.inputs.limits import number
from pencore.io.atomic import describe_os_error

__all__ = [
    "PROG",
    "CommandFailure",
    "Parser",
    "one_line",
    "number_type",
    "velocity",
    "obliquity",
    "numerics_option",
    "add_window_options",
    "with_windows",
    "check_output",
    "resolve",
    "cli_inputs",
]

PROG = "pencore"


class CommandFailure(Exception):
    """An error to report as one line with a given exit status (``.status``)."""

    def __init__(self, message: str, status: int) -> None:
        super().__init__(message)
        self.status = status


class Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line: ``pencore: error: ...``."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{PROG}: error: {one_line(message)} (see '{self.prog} --help')\n")


def one_line(text: str) -> str:
    """``text`` with every run of whitespace (newlines included) made one space."""
    return " ".join(str(text).split())


def number_type(key: str, ok: Callable[[float], bool] = lambda v: True, allowed: str = "") -> Any:
    """An argparse type: a float within ``pencore.inputs.limits.LIMITS[key]`` for which ``ok``
    holds (a narrower range the CLI promises: ``allowed``), else an error naming the
    value and what is allowed."""

    def conv(text: str) -> float:
        try:
            v = float(text)
        except ValueError:
            v = math.nan
        if allowed and not (math.isfinite(v) and ok(v)):
            raise argparse.ArgumentTypeError(f"must be {allowed}, got {text!r}")
        try:
            return number(text, key, allow_str=True)
        except InputError as exc:
            raise argparse.ArgumentTypeError(str(exc).split(": ", 1)[-1]) from None

    return conv


velocity = number_type("velocity")
obliquity = number_type("obliquity", lambda v: 0.0 <= v < 90.0, "a number of degrees in [0, 90)")


def numerics_option(text: str) -> tuple[str, Any]:
    """``KEY=VALUE`` for ``--numerics``; the value is read as a YAML scalar."""
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"must be KEY=VALUE (e.g. rtol=1e-6), got {text!r}")
    import yaml

    try:
        parsed = yaml.safe_load(value)
    except yaml.YAMLError:
        parsed = value
    if isinstance(parsed, str):  # YAML reads 1e-6 (no decimal point) as text
        try:
            parsed = float(parsed)
        except ValueError:
            pass
    return key.strip(), parsed


def add_window_options(p: argparse.ArgumentParser) -> None:
    """``--crater-depth`` and ``--free-surface-depth`` (calibers), set on every medium."""
    p.add_argument(
        "--crater-depth",
        type=number_type("crater_depth"),
        default=None,
        metavar="K",
        help="near-surface (crater) region in calibers: the resistance rises linearly from "
        "0 at a layer's top face to full at K projectile diameters (Forrestal: K = 2; "
        "default: each medium's own, 0 = off)",
    )
    p.add_argument(
        "--free-surface-depth",
        type=number_type("free_surface_depth"),
        default=None,
        metavar="K",
        help="free-surface reduction in calibers: the resistance falls linearly to 0 at a "
        "free face (front face, rear face, faces next to a gap) over K projectile "
        "diameters (default: each medium's own, 0 = off)",
    )


def with_windows(target: Any, args: argparse.Namespace) -> Any:
    """``target`` with the ``--crater-depth`` / ``--free-surface-depth`` of ``args`` (in
    calibers) set on every medium, or ``target`` itself when neither was given."""
    if args.crater_depth is None and args.free_surface_depth is None:
        return target
    return target.with_windows(args.crater_depth, args.free_surface_depth)


def check_output(out: str) -> Path:
    """Check that ``out`` can be written, before any computation."""
    path = Path(out)
    if path.suffix != ".nc":
        raise CommandFailure(f"output file {out!r} must end in .nc", 2)
    if path.is_dir():
        raise CommandFailure(f"output file {out!r} is a directory; give a FILE.nc path", 2)
    parent = path.parent
    if not parent.is_dir():
        raise CommandFailure(
            f"output directory {str(parent)!r} of {out!r} does not exist; create it first", 2
        )
    # a real probe: os.access alone is fooled by root, read-only mounts, ACLs
    try:
        fd, probe = tempfile.mkstemp(dir=parent, prefix=f".{path.name}.", suffix=".probe")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        cause = describe_os_error(exc)
        raise CommandFailure(
            f"output directory {str(parent)!r} of {out!r} is not writable: {cause} "
            f"({exc.strerror})",
            1 if exc.errno in (errno.ENOSPC, errno.EDQUOT) else 2,
        ) from None
    return path


def cli_inputs(args: argparse.Namespace) -> dict[str, Any]:
    """The command-line arguments that made a run, for the file's provenance."""
    return {k: v for k, v in vars(args).items() if k not in ("func", "command")}


def resolve(kind: str, spec: str, getter: Callable[[str], Any]) -> Any:
    """Resolve a name or YAML file; every failure becomes an :class:`InputError`."""
    try:
        obj = getter(spec)
        if kind == "projectile":
            obj.mass_properties()  # catches bodies without volume before the run
        return obj
    except InputError:
        raise
    except UnicodeDecodeError:
        raise InputError(f"{kind} file {spec!r} is not a text (UTF-8) YAML file") from None
    except (ValueError, TypeError, KeyError, AttributeError, IndexError) as exc:
        raise InputError(f"invalid {kind} {spec!r}: {exc}") from None
