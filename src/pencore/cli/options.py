"""Shared pieces of the ``pencore`` subcommands: the one-line parser and failure, the
argument types that check a value against :data:`pencore.inputs.limits.LIMITS`, the
depth-window options, and the checks of names, files and the output path.

Every user error becomes one line on stderr and exit status 2 (1 for a failure to
write); the argument types name the value and what is allowed. SI units throughout
(m, m/s, rad/s), angles in degrees, window depths in calibers (projectile diameters).
This module imports no solver code, so the parser builds without loading numba or
xarray.
"""

from __future__ import annotations

import argparse
import errno
import os
import stat
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any, NoReturn

from pencore.errors import INTERRUPTED, InputError, WriteError
from pencore.inputs.gate import DECIMAL_WORDS, brief, brief_path, decimal, load_yaml_text
from pencore.inputs.limits import as_float, integer, number
from pencore.inputs.numerics import NUMERIC_FIELDS
from pencore.io.atomic import describe_os_error, file_kind

__all__ = [
    "PROG",
    "INTERRUPTED",
    "exit_at_once_on_interrupt",
    "CommandFailure",
    "Parser",
    "one_line",
    "number_type",
    "velocity",
    "obliquity",
    "whole_type",
    "each_of",
    "numerics_option",
    "add_window_options",
    "with_windows",
    "add_mass_options",
    "with_mass",
    "window_values",
    "check_output",
    "call_inputs",
    "refresh_interrupt_line",
    "resolve",
    "run_projectile",
    "run_target",
    "run_numerics",
    "cli_inputs",
]

PROG = "pencore"


def exit_at_once_on_interrupt() -> None:
    """Make Ctrl-C during an integration end the command at once: one line on stderr,
    exit status 130, whatever the numerics (the subcommands that integrate call this
    before their runs; they write their output files only after the runs). See
    :mod:`pencore.integrators.driver`."""
    from pencore.integrators.driver import exit_on_interrupt
    from pencore.io.outputs import interrupted_message

    exit_on_interrupt(f"{PROG}: error: {interrupted_message()}", 130)


class CommandFailure(Exception):
    """An error that ``pencore.cli.main.main()`` reports as one line and an exit status.

    Parameters
    ----------
    message : str
        The message, printed as ``pencore: error: <message>`` (whitespace runs made one
        space).
    status : int
        The exit status: 2 for bad input, 1 for a failure to write.
    """

    def __init__(self, message: str, status: int) -> None:
        super().__init__(message)
        self.status = status


class Parser(argparse.ArgumentParser):
    """An :class:`argparse.ArgumentParser` whose usage errors are one line.

    ``error`` prints ``pencore: error: <message> (see '<prog> --help')`` on stderr and
    exits with status 2, instead of argparse's usage block. Help and version text that
    cannot be written to standard output (a full device) raise the ``OSError`` that
    argparse would swallow, so that the command line reports it.
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """As argparse's, but an option that stores its value refuses to be given twice
        (``--velocity 300 --velocity 500`` would silently keep the last): the ``store``
        action is :class:`_StoreOnce` in the parser's registry, which its argument groups
        and mutually exclusive groups share."""
        super().__init__(*args, **kwargs)
        self.register("action", None, _StoreOnce)
        self.register("action", "store", _StoreOnce)

    def error(self, message: str) -> NoReturn:
        """Exit with status 2 and one line naming the error and ``--help``."""
        self.exit(2, f"{PROG}: error: {one_line(message)} (see '{self.prog} --help')\n")

    def _print_message(self, message: str, file: Any = None) -> None:
        if message and file is not None and file is sys.stdout:
            file.write(message)
            return
        super()._print_message(message, file)


class _StoreOnce(argparse.Action):
    """argparse's ``store``, refusing a second value for the same option."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._given: dict[int, str] = {}

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: Any,
        option_string: str | None = None,
    ) -> None:
        first = self._given.get(id(namespace))
        if first is not None:
            parser.error(
                f"{option_string or self.dest} given twice ({first} and "
                f"{option_string} {values}); give it once"
            )
        self._given[id(namespace)] = f"{option_string} {values}"
        setattr(namespace, self.dest, values)


def one_line(text: str) -> str:
    """Collapse ``text`` to one line.

    Parameters
    ----------
    text : str
        Any message (converted with :class:`str`).

    Returns
    -------
    str
        ``text`` with every run of whitespace (newlines included) made one space.
    """
    return " ".join(str(text).split())


def number_type(key: str, label: str = "") -> Any:
    """Make an argparse ``type=`` for a number checked against the package's limits.

    Parameters
    ----------
    key : str
        Key into :data:`pencore.inputs.limits.LIMITS`, which gives the unit (m/s, deg,
        rad/s, m, calibers) and the allowed range, e.g. ``"velocity"``, ``"yaw"``: the
        command line accepts what the API accepts.
    label : str, optional
        How the error names the value when it is not the quantity ``key`` names
        (``"tolerance"`` for a width in m/s); default: the label of ``key``.

    Returns
    -------
    callable
        ``conv(text) -> float``: the value in the unit of ``key``; raises
        :class:`argparse.ArgumentTypeError` naming ``text`` and what is allowed.
    """

    def conv(text: str) -> float:
        try:
            # the API the value goes to judges its plausibility (one warning, not two)
            return number(text, key, allow_str=True, label=label, plausibility=False)
        except InputError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    return conv


def whole_type(key: str) -> Any:
    """Make an argparse ``type=`` for a whole number (a count) checked against
    ``LIMITS[key]``, from plain decimal text (``20``, ``2e1``); else
    :class:`argparse.ArgumentTypeError` naming the text and what is allowed."""

    def conv(text: str) -> int:
        v = as_float(text, allow_str=True)
        try:
            return integer(text if v is None else v, key)
        except InputError as exc:  # quote the text given, not the number read from it
            said = str(exc).rsplit(", got ", 1)[0]
            raise argparse.ArgumentTypeError(f"{said}, got {brief(text)}") from None

    return conv


def each_of(*types: Callable[[str], Any]) -> type[argparse.Action]:
    """An argparse ``action=`` for an option of several values of different kinds
    (``--range LO HI N``: two speeds and a count): value ``i`` is converted by
    ``types[i]``, and a refusal names the value by its metavar (``argument --range: N:
    number of speeds must be ...``), so that no value is called what it is not.

    Examples
    --------
    >>> p = argparse.ArgumentParser(prog="x", exit_on_error=False)
    >>> _ = p.add_argument("--range", nargs=3, metavar=("LO", "HI", "N"),
    ...                    action=each_of(velocity, velocity, whole_type("sweep_points")))
    >>> p.parse_args(["--range", "100", "500", "5"]).range
    [100.0, 500.0, 5]
    """

    class EachOf(_StoreOnce):  # given once, as every option that stores
        def __call__(
            self,
            parser: argparse.ArgumentParser,
            namespace: argparse.Namespace,
            values: Any,
            option_string: str | None = None,
        ) -> None:
            names = self.metavar if isinstance(self.metavar, tuple) else (self.dest,) * len(types)
            converted = []
            for conv, name, text in zip(types, names, values, strict=True):
                try:
                    converted.append(conv(text))
                except argparse.ArgumentTypeError as exc:
                    raise argparse.ArgumentError(self, f"{name}: {exc}") from None
            super().__call__(parser, namespace, converted, option_string)

    return EachOf


#: argparse type: a speed in m/s, > 0, up to the 10 km/s guard of ``LIMITS["velocity"]``.
velocity = number_type("velocity")
#: argparse type: an obliquity in deg, in ``LIMITS["obliquity"]`` (-90, 90); negative
#: tilts the axis towards -x.
obliquity = number_type("obliquity")


def path_type(text: str) -> str:
    """An argparse ``type=`` for a file path: refuses the empty or blank path, which
    names no file (``--write ''`` would otherwise write nothing without a word)."""
    if not text.strip():
        raise argparse.ArgumentTypeError(f"a file path is needed, got {text!r}")
    return text


def numerics_given(pairs: Sequence[tuple[str, Any]]) -> dict[str, Any]:
    """The ``--numerics KEY=VALUE`` options as a mapping; a key given twice is refused
    (the last would silently win)."""
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise InputError(
                f"--numerics {key} given twice ({key}={out[key]!r} and {key}={value!r}); "
                "give it once"
            )
        out[key] = value
    return out


def numerics_option(text: str) -> tuple[str, Any]:
    """Parse one ``--numerics KEY=VALUE`` (an argparse ``type=``).

    Parameters
    ----------
    text : str
        ``KEY=VALUE``, e.g. ``rtol=1e-6``, ``t_max=2`` (s), ``method=Radau``. The value is
        read as a YAML scalar; text in plain decimal notation
        (:data:`pencore.inputs.gate.DECIMAL`; YAML leaves ``1e-6`` a string) becomes a
        float; other text given to a numeric key is refused here. Keys and ranges are
        checked later, by :func:`pencore.inputs.numerics.resolve_numerics`.

    Returns
    -------
    tuple of (str, Any)
        The key (stripped) and the value, in the unit of the key.

    Raises
    ------
    argparse.ArgumentTypeError
        When ``text`` has no ``=``, an empty key, or an empty value (nothing, ``~`` or
        ``null``: YAML's null, which would mean the default), or gives a numeric key text
        that is not plain decimal.
    """
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"must be KEY=VALUE (e.g. rtol=1e-6), got {brief(text)}")
    try:
        parsed = load_yaml_text(value, f"--numerics value of {brief(key)}")
    except InputError:
        parsed = value
    if parsed is None:  # YAML's null: an empty value, ~ or null
        raise argparse.ArgumentTypeError(
            f"{brief(key)} has no value, got {brief(text)}; give KEY=VALUE, or leave the "
            "option out for the default"
        )
    if isinstance(parsed, str):  # YAML reads 1e-6 (no decimal point) as text
        value_f = decimal(parsed)
        if value_f is not None:
            parsed = value_f
        elif key in NUMERIC_FIELDS:
            raise argparse.ArgumentTypeError(
                f"{key} must be a number {DECIMAL_WORDS}, got {brief(parsed)}"
            )
    return key, parsed


def add_window_options(p: argparse.ArgumentParser) -> None:
    """Add ``--crater-depth K``, ``--free-surface-depth K`` and ``--plastic-zone-ratio C_A``
    to a subcommand.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser. The first two options are depths in calibers
        (projectile diameters), the third a ratio of radii; each defaults to ``None``
        (each medium keeps its own); see :func:`with_windows`.
    """
    p.add_argument(
        "--crater-depth",
        type=number_type("crater_depth"),
        default=None,
        metavar="K",
        help="near-surface (crater) region in calibers: Forrestal's axial force F = c z "
        "from a layer's top face to K projectile diameters (K = 2 there; at least the "
        "nose length; default: each medium's own, 0 = off)",
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
    p.add_argument(
        "--plastic-zone-ratio",
        type=number_type("plastic_zone_ratio"),
        default=None,
        metavar="C_A",
        help="free-surface reduction of a spherical cavity in a finite sphere (Hill 1950): "
        "plastic-zone over cavity radius of the half-space law, > 1 (default: each "
        "medium's own, 0 = off)",
    )


def with_windows(target: Any, args: argparse.Namespace) -> Any:
    """Apply the depth-window options to a target.

    Parameters
    ----------
    target : pencore.inputs.target.Target
        The resolved target.
    args : argparse.Namespace
        Parsed arguments with ``crater_depth`` and ``free_surface_depth`` (calibers, or
        ``None``), as added by :func:`add_window_options`.

    Returns
    -------
    pencore.inputs.target.Target
        ``target`` with both windows set on every medium, or ``target`` itself when
        neither option was given.
    """
    windows = window_values(args)
    return target if windows is None else target.with_windows(*windows)


def window_values(args: argparse.Namespace) -> tuple[Any, Any, Any] | None:
    """The depth-window options as given: ``(crater_depth, free_surface_depth,
    plastic_zone_ratio)`` (calibers, calibers, ratio; ``None`` each one not given, and the
    ratio where the subcommand has no such option), or ``None`` when none was given."""
    windows = (
        args.crater_depth,
        args.free_surface_depth,
        getattr(args, "plastic_zone_ratio", None),
    )
    return None if windows == (None, None, None) else windows


def add_mass_options(p: argparse.ArgumentParser) -> None:
    """Add ``--mass KG``, ``--centre-of-mass M`` and ``--inertia AXIAL TRANSVERSE`` to a
    subcommand: measured mass properties that override the projectile's (see
    :class:`pencore.Projectile` for what is derived from the outline when not given).

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser; each option defaults to ``None`` (the projectile's own).
    """
    p.add_argument(
        "--mass",
        type=number_type("mass"),
        default=None,
        metavar="KG",
        help="measured projectile mass in kg (default: the projectile's own; the outline's "
        "distribution is scaled to it: same Lc, inertias scaled)",
    )
    p.add_argument(
        "--centre-of-mass",
        type=number_type("centre_of_mass"),
        default=None,
        metavar="M",
        help="measured tip-to-centre-of-mass distance Lc in m, inside the body (default: "
        "the projectile's own)",
    )
    p.add_argument(
        "--inertia",
        action=each_of(number_type("inertia"), number_type("inertia")),
        nargs=2,
        default=None,
        metavar=("AXIAL", "TRANSVERSE"),
        help="measured moments of inertia about the centre of mass in kg m^2 (default: "
        "from the outline)",
    )
    p.add_argument(
        "--yield-strength",
        type=number_type("yield_strength"),
        default=None,
        metavar="PA",
        help="the projectile material's yield strength in Pa (1.3 GPa: 1.3e9), for the "
        "rigid-regime check only (default: the projectile's own, else 1720 MPa assumed)",
    )


def with_mass(projectile: Any, args: argparse.Namespace) -> Any:
    """Apply the mass options of :func:`add_mass_options` (and the yield strength) to a
    projectile.

    Parameters
    ----------
    projectile : pencore.Projectile
        The resolved projectile.
    args : argparse.Namespace
        Parsed arguments with ``mass``, ``centre_of_mass`` and ``inertia`` (or ``None``).

    Returns
    -------
    pencore.Projectile
        ``projectile`` with the given values, or ``projectile`` itself when none is given.

    Raises
    ------
    pencore.errors.GeometryError
        A value no body of this outline can have (one line naming it).
    """
    strength = getattr(args, "yield_strength", None)
    if strength is not None:
        projectile = replace(projectile, yield_strength=strength)
    mass = getattr(args, "mass", None)
    lc = getattr(args, "centre_of_mass", None)
    inertia = getattr(args, "inertia", None)
    if mass is None and lc is None and inertia is None:
        return projectile
    return projectile.with_mass(mass, lc, None if inertia is None else tuple(inertia))


def check_output(
    out: str,
    inputs: Sequence[str] = (),
    suffixes: Sequence[str] = (".nc",),
    what: str = "output file",
) -> Path:
    """Check that ``out`` can be written, before any computation: the output gate's rules
    (:func:`pencore.io.outputs.check_destination`) and a writable, existing folder.

    A temporary file is created and removed in the output directory (``os.access`` is
    fooled by root, read-only mounts and ACLs).

    Parameters
    ----------
    out : str
        The ``--out``, ``--plot`` or ``--write`` path; must end in one of ``suffixes``,
        name a file (not a directory, nor end in ``/``), be writable if it exists, not be
        an input of the call (``inputs``, and the files of the open call,
        :func:`call_inputs`), and lie in an existing, writable directory.
    inputs : sequence of str
        The run's input files (names that are not files are skipped): the output must
        not replace them.
    suffixes : sequence of str
        The suffixes the option writes (``.nc``; ``.png``, ``.pdf``, ``.svg``; ...).
    what : str
        How the messages name the path (``"output file"``, ``"plot file"``).

    Returns
    -------
    pathlib.Path
        ``out`` as a path.

    Raises
    ------
    CommandFailure
        Status 2 naming the path and the problem; status 1 when the disk or quota is
        full.
    """
    from pencore.io.outputs import check_destination

    try:
        path = check_destination(out, suffixes, [p for p in inputs if os.path.isfile(p)])
    except WriteError as exc:
        raise CommandFailure(f"{what} {str(exc).removeprefix('cannot write ')}", 2) from None
    parent = path.parent
    _check_directory(parent, out)
    # a real probe: os.access alone is fooled by root, read-only mounts, ACLs
    try:
        fd, probe = tempfile.mkstemp(dir=parent, prefix=".pencore-probe-", suffix=".probe")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        cause = describe_os_error(exc)
        raise CommandFailure(
            f"output directory {brief_path(parent)} of {brief_path(out)} is not writable: {cause} "
            f"({exc.strerror})",
            1 if exc.errno in (errno.ENOSPC, errno.EDQUOT) else 2,
        ) from None
    return path


#: The options that name files a command writes (never protected as its inputs).
OUTPUT_OPTIONS = ("out", "plot", "write")


def call_inputs(args: argparse.Namespace) -> list[str]:
    """Every argument of a command that names an existing file, but its outputs
    (:data:`OUTPUT_OPTIONS`): the inputs no output of the call may replace, whatever
    option names them (``--projectile``, ``--target``, a table, a config)."""
    found: list[str] = []
    for key, value in vars(args).items():
        if key in OUTPUT_OPTIONS or key in ("func", "command"):
            continue
        for v in value if isinstance(value, list | tuple) else [value]:
            if isinstance(v, str | os.PathLike):
                try:
                    if os.path.isfile(v):
                        found.append(os.fspath(v))
                except (OSError, ValueError):
                    continue
    return found


def refresh_interrupt_line() -> None:
    """After a file is written, make the Ctrl-C line of the runs that may follow say so
    (:func:`exit_at_once_on_interrupt`); nothing when no run was started."""
    if "pencore.integrators.driver" in sys.modules:
        exit_at_once_on_interrupt()


def _check_directory(parent: Path, out: str) -> None:
    """Refuse an output directory ``parent`` (of ``out``) that is not a directory: one
    that does not exist, or one that is, or lies under, a file of another kind."""
    where = f"output directory {brief_path(parent)} of {brief_path(out)}"
    try:
        st = os.stat(parent)
    except FileNotFoundError:
        raise CommandFailure(f"{where} does not exist; create it first", 2) from None
    except NotADirectoryError:  # a file where a directory of the path should be
        blocker = next(
            (a for a in reversed(parent.parents) if a.exists() and not a.is_dir()), parent
        )
        raise CommandFailure(
            f"{where} is not a directory: {brief_path(blocker)} is {_kind(blocker)}", 2
        ) from None
    except OSError as exc:
        raise CommandFailure(f"{where} cannot be reached: {exc.strerror or exc}", 2) from None
    if not stat.S_ISDIR(st.st_mode):
        raise CommandFailure(f"{where} is not a directory: it is {_kind(parent)}", 2)


def _kind(path: Path) -> str:
    """What the existing non-directory ``path`` is, in words."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return "not a directory"
    return "a regular file" if stat.S_ISREG(mode) else file_kind(mode)


def run_projectile(args: argparse.Namespace) -> Any:
    """The subcommand's ``--projectile`` (:func:`resolve`) with its mass options applied
    (:func:`with_mass`)."""
    from pencore.inputs.library import get_projectile

    return with_mass(resolve("projectile", args.projectile, get_projectile), args)


def run_target(args: argparse.Namespace) -> Any:
    """The subcommand's ``--target`` (:func:`resolve`) with its window options applied
    (:func:`with_windows`)."""
    from pencore.inputs.library import get_target

    return with_windows(resolve("target", args.target, get_target), args)


def run_numerics(args: argparse.Namespace) -> Any:
    """The subcommand's numerics: the defaults with its ``--numerics KEY=VALUE`` options
    (:func:`numerics_given`, :func:`pencore.inputs.numerics.resolve_numerics`)."""
    from pencore.inputs.numerics import resolve_numerics

    return resolve_numerics(numerics_given(args.numerics))


def cli_inputs(args: argparse.Namespace) -> dict[str, Any]:
    """The command-line arguments that made a run, for the output file's provenance.

    Parameters
    ----------
    args : argparse.Namespace
        Parsed arguments (values in the units of their options).

    Returns
    -------
    dict of str to Any
        Every argument except the dispatch keys ``func`` and ``command``.
    """
    return {k: v for k, v in vars(args).items() if k not in ("func", "command")}


def resolve(kind: str, spec: str, getter: Callable[[str], Any]) -> Any:
    """Resolve a library name or a YAML file into a projectile or target.

    Parameters
    ----------
    kind : str
        ``"projectile"`` or ``"target"``, for the messages; a projectile's mass
        properties are computed at once, so a body without volume fails here, before
        the run.
    spec : str
        A library name (see ``pencore list``) or the path of a YAML file (SI units).
    getter : callable
        :func:`pencore.inputs.library.get_projectile` or ``get_target``.

    Returns
    -------
    Any
        What ``getter`` returns.

    Raises
    ------
    pencore.errors.InputError
        For every failure (unknown name, missing or non-UTF-8 file, invalid YAML or
        values), one line naming ``spec``.
    """
    try:
        obj = getter(spec)
        if kind == "projectile":
            obj.mass_properties()  # catches bodies without volume before the run
        return obj
    except InputError:
        raise
    except UnicodeDecodeError:
        raise InputError(
            f"{kind} file {brief_path(spec)} is not a text (UTF-8) YAML file"
        ) from None
    except (ValueError, TypeError, KeyError, AttributeError, IndexError) as exc:
        raise InputError(f"invalid {kind} {brief_path(spec)}: {exc}") from None
