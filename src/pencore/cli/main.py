"""Command-line interface: ``pencore simulate | ballistic-limit | fit-table3 | list``.

Every user error ends the program with exit status 2 and a single line on stderr,
``pencore: error: <message>``, naming the offending value and what is allowed; a solver
failure ends it with status 1 and a single line. ``simulate --out`` writes its NetCDF
file atomically (temporary file in the same directory, then :func:`os.replace`), so a
failed or interrupted run never leaves a partial or stale-looking output behind.
"""

from __future__ import annotations

import argparse
import errno
import math
import os
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, NoReturn

from pencore.errors import InputError, SolverError
from pencore.inputs.limits import number
from pencore.inputs.numerics import resolve_numerics
from pencore.io.atomic import describe_os_error
from pencore.version import __version__

__all__ = ["main", "build_parser"]

PROG = "pencore"


class _Failure(Exception):
    """An error to report as one line with a given exit status."""

    def __init__(self, message: str, status: int) -> None:
        super().__init__(message)
        self.status = status


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line: ``pencore: error: ...``."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{PROG}: error: {_one_line(message)} (see '{self.prog} --help')\n")


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


# ---------------------------------------------------------------- argument types


def _number(key: str, ok: Callable[[float], bool] = lambda v: True, allowed: str = "") -> Any:
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


_velocity = _number("velocity")
_obliquity = _number("obliquity", lambda v: 0.0 <= v < 90.0, "a number of degrees in [0, 90)")


def _numerics_option(text: str) -> tuple[str, Any]:
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


# ---------------------------------------------------------------- parser


_SIM_SUMMARY = """\
simulate options (all SI, angles in degrees):
  --projectile NAME|FILE  p1..p4, validation projectiles, or a projectile YAML file
  --target NAME|FILE      soil, concrete, aluminium, or a target YAML file
  --velocity M_S          impact speed (m/s), > 0
  --obliquity DEG         axis angle from the target normal (deg), in [0, 90)
  --yaw DEG               velocity angle minus axis angle (deg)
  --omega RAD_S           initial angular velocity about +z (rad/s)
  --start X Y Z           initial nose-tip position (m)
  --stop-at-reversal      end the run at the first trajectory reversal
  --crater-depth K        near-surface (crater) resistance ramp over K calibers
  --free-surface-depth K  resistance ramp within K calibers of a free face
  --numerics KEY=VALUE    numerical parameter override (repeatable), e.g. rtol=1e-6
  --out FILE.nc           write the full trajectory as NetCDF
Run 'pencore simulate --help' for details; 'pencore list' for the named projectiles
and targets.
"""


def build_parser() -> argparse.ArgumentParser:
    """Build the ``pencore`` argument parser.

    Returns
    -------
    argparse.ArgumentParser
        Parser with the ``simulate``, ``fit-table3`` and ``list`` subcommands.
    """
    parser = _Parser(
        prog=PROG,
        description="3-D rigid-projectile penetration with the differential area force "
        "law (Li & Flores-Johnson, IJIE 2011). SI units throughout (m, kg, s, m/s, "
        "rad/s); angles in degrees.",
        epilog=_SIM_SUMMARY,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--version",
        action="version",
        version=f"{PROG} {__version__}",
        help="print the pencore version and exit",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    sim = sub.add_parser(
        "simulate",
        help="simulate one impact and print a summary (m, m/s, deg, rad/s)",
        description="Simulate one impact of a rigid projectile on a target and print a "
        "summary: penetration depth (m), nose-tip path length below the surface (m), "
        "outcome, reversal, final trajectory slope dy/dx, final deviation of the velocity "
        "from the target normal (deg), run time (s) and number of steps. The target is "
        "y <= 0 and the projectile moves towards +x and -y.",
    )
    sim.add_argument(
        "--projectile",
        required=True,
        metavar="NAME|FILE",
        help="projectile name (see 'pencore list'; lengths in m, masses in "
        "kg) or a projectile YAML file (diameter and lengths in m, densities "
        "in kg/m^3)",
    )
    sim.add_argument(
        "--target",
        required=True,
        metavar="NAME|FILE",
        help="target name (soil, concrete, aluminium) or a target YAML file "
        "(resistance coefficients in Pa, Pa s/m, Pa s^2/m^2, ...)",
    )
    sim.add_argument(
        "--velocity",
        required=True,
        type=_velocity,
        metavar="M_S",
        help="impact speed in m/s; must be > 0 and finite",
    )
    sim.add_argument(
        "--obliquity",
        type=_obliquity,
        default=0.0,
        metavar="DEG",
        help="obliquity in deg: angle between the projectile axis and the "
        "target normal, towards +x; 0 <= DEG < 90 (default: 0 deg)",
    )
    sim.add_argument(
        "--yaw",
        type=_number("yaw"),
        default=0.0,
        metavar="DEG",
        help="yaw in deg: velocity angle minus axis angle; |obliquity + yaw| "
        "must stay below 90 deg (default: 0 deg)",
    )
    sim.add_argument(
        "--omega",
        type=_number("omega"),
        default=0.0,
        metavar="RAD_S",
        help="initial angular velocity about the centre of mass, about +z, in "
        "rad/s; positive turns the nose towards +x (default: 0 rad/s)",
    )
    sim.add_argument(
        "--start",
        type=_number("start"),
        nargs=3,
        default=None,
        metavar=("X", "Y", "Z"),
        help="initial nose-tip position in m (default: tip at x = z = 0, "
        "body just touching the surface y = 0 m)",
    )
    sim.add_argument(
        "--stop-at-reversal",
        action="store_true",
        help="end the run at the first reversal of the trajectory (dy/dx "
        "changes sign; outcome 'reversed')",
    )
    _window_options(sim)
    sim.add_argument(
        "--numerics",
        type=_numerics_option,
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="override a numerical parameter, e.g. rtol=1e-6, eps=1e-3 (m/s), t_max=2 (s), "
        "method=Radau; repeat for several (see pencore.Numerics for the keys and the "
        "README for their valid ranges)",
    )
    sim.add_argument(
        "--out",
        metavar="FILE.nc",
        default=None,
        help="write the trajectory (time in s, positions in m, velocities in "
        "m/s, angles in deg, rates in rad/s) to this NetCDF file; its "
        "directory must exist and be writable; written atomically",
    )

    from pencore.cli.ballistic import add_parser as _add_ballistic

    _add_ballistic(sub)
    fit3 = sub.add_parser(
        "fit-table3",
        help="fit the p1..p4 geometry (diameter and shank length in m) to the paper's "
        "Table 3 (masses in kg, Lc/L)",
        description="Fit a solid CRH-3 ogive + cylinder (diameter and shank length in "
        "m) to the masses (kg) and Lc/L of paper Table 3, print the residuals (kg and "
        "dimensionless), and compare the fit with the geometry pencore ships "
        "(pencore/data/table3_geometry.yaml).",
    )
    fit3.add_argument(
        "--write",
        metavar="PATH",
        help="also write the fitted geometry to PATH (YAML, written atomically); "
        "src/pencore/inputs/data/table3_geometry.yaml regenerates the shipped file",
    )
    sub.add_parser(
        "list",
        help="list the named projectiles (mass in kg, diameter in mm) and targets "
        "(coefficients in Pa, Pa s/m, Pa s^2/m^2)",
        description="List the named projectiles (mass in kg, Lc/L = tip-to-centre-of-"
        "mass distance over length, diameter in mm, source) and targets (resistance "
        "coefficients a0 in Pa, a1 in Pa s/m, a2 in Pa s^2/m^2, source). Takes no options.",
    )
    return parser


# ---------------------------------------------------------------- helpers


def _window_options(p: argparse.ArgumentParser) -> None:
    """``--crater-depth`` and ``--free-surface-depth`` (calibers), set on every medium."""
    p.add_argument(
        "--crater-depth",
        type=_number("crater_depth"),
        default=None,
        metavar="K",
        help="near-surface (crater) region in calibers: the resistance rises linearly from "
        "0 at a layer's top face to full at K projectile diameters (Forrestal: K = 2; "
        "default: each medium's own, 0 = off)",
    )
    p.add_argument(
        "--free-surface-depth",
        type=_number("free_surface_depth"),
        default=None,
        metavar="K",
        help="free-surface reduction in calibers: the resistance falls linearly to 0 at a "
        "free face (front face, rear face, faces next to a gap) over K projectile "
        "diameters (default: each medium's own, 0 = off)",
    )


def _with_windows(target: Any, args: argparse.Namespace) -> Any:
    if args.crater_depth is None and args.free_surface_depth is None:
        return target
    return target.with_windows(args.crater_depth, args.free_surface_depth)


def _check_output(out: str) -> Path:
    """Check that ``out`` can be written, before any computation."""
    path = Path(out)
    if path.suffix != ".nc":
        raise _Failure(f"output file {out!r} must end in .nc", 2)
    if path.is_dir():
        raise _Failure(f"output file {out!r} is a directory; give a FILE.nc path", 2)
    parent = path.parent
    if not parent.is_dir():
        raise _Failure(
            f"output directory {str(parent)!r} of {out!r} does not exist; create it first", 2
        )
    # a real probe: os.access alone is fooled by root, read-only mounts, ACLs
    try:
        fd, probe = tempfile.mkstemp(dir=parent, prefix=f".{path.name}.", suffix=".probe")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        cause = describe_os_error(exc)
        raise _Failure(
            f"output directory {str(parent)!r} of {out!r} is not writable: {cause} "
            f"({exc.strerror})",
            1 if exc.errno in (errno.ENOSPC, errno.EDQUOT) else 2,
        ) from None
    return path


def _cli_inputs(args: argparse.Namespace) -> dict[str, Any]:
    """The command-line arguments that made a run, for the file's provenance."""
    return {k: v for k, v in vars(args).items() if k not in ("func", "command")}


def _resolve(kind: str, spec: str, getter: Callable[[str], Any]) -> Any:
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


def _fmt_slope(s: float) -> str:
    if not math.isfinite(s) or abs(s) > 1e6:
        return f"{s:.4g} (path essentially vertical)"
    return f"{s:.4g}"


# ---------------------------------------------------------------- commands


def _cmd_simulate(args: argparse.Namespace) -> int:
    from pencore.errors import WriteError
    from pencore.inputs.library import get_projectile, get_target
    from pencore.io.netcdf import write_netcdf
    from pencore.run.impact import simulate

    out = _check_output(args.out) if args.out is not None else None
    projectile = _resolve("projectile", args.projectile, get_projectile)
    target = _with_windows(_resolve("target", args.target, get_target), args)
    t0 = time.perf_counter()
    ds = simulate(
        projectile,
        target,
        args.velocity,
        args.obliquity,
        args.yaw,
        args.omega,
        start=None if args.start is None else tuple(args.start),
        stop_at_reversal=args.stop_at_reversal,
        numerics=resolve_numerics(dict(args.numerics)),
    )
    total = time.perf_counter() - t0
    if out is not None:
        try:
            write_netcdf(ds, out, config_slice={"cli": _cli_inputs(args)}, study="cli/simulate")
        except WriteError as exc:  # one line naming the path and the cause; nothing left
            raise _Failure(str(exc), 1) from None
    a = ds.attrs
    rows = [
        (
            "projectile",
            f"{a['projectile']} ({a['mass_kg']:.4g} kg, "
            f"{a['length_m']:.4g} m long, Lc/L = {a['lc_over_l']:.3f})",
        ),
        ("target", str(a["target"])),
        (
            "impact",
            f"{args.velocity:g} m/s, obliquity {args.obliquity:g} deg, "
            f"yaw {args.yaw:g} deg, omega {args.omega:g} rad/s",
        ),
        ("penetration depth", f"{float(ds['penetration_depth']):.6g} m"),
        ("tip path length below surface", f"{float(ds['path_length']):.6g} m"),
        ("outcome", str(a["outcome"])),
        ("reversed", "yes" if a["reversed"] else "no"),
        ("final slope dy/dx", _fmt_slope(float(ds["final_slope"]))),
        ("final deviation from normal", f"{float(ds['final_deviation']):.4g} deg"),
        *(
            [
                ("residual velocity", f"{a['residual_velocity']:.6g} m/s"),
                (
                    "exit pitch / angle of attack",
                    f"{a['exit_pitch_deg']:.4g} / {a['exit_angle_of_attack_deg']:.4g} deg",
                ),
            ]
            if a["outcome"] == "perforated"
            else []
        ),
        ("run time", f"{a['wall_time_s']:.3g} s integration, {total:.3g} s total"),
        ("steps", str(a["n_steps"])),
    ]
    if out is not None:
        rows.append(("output", str(out)))
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        print(f"{k + ':':<{width + 1}} {v}")
    return 0


def _cmd_fit_table3(args: argparse.Namespace) -> int:
    from pencore.cli.library import fit_table3

    return fit_table3(args)


def _cmd_list(args: argparse.Namespace) -> int:
    from pencore.cli.library import list_library

    return list_library(args)


def _cmd_ballistic_limit(args: argparse.Namespace) -> int:
    from pencore.cli.ballistic import run

    return run(args)


_COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {
    "simulate": _cmd_simulate,
    "ballistic-limit": _cmd_ballistic_limit,
    "fit-table3": _cmd_fit_table3,
    "list": _cmd_list,
}


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
        status = _COMMANDS[args.command](args)
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        # the reader went away (`pencore list | head`): stop quietly, as Unix tools do;
        # point stdout at devnull so the interpreter's final flush does not fail again
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141  # 128 + SIGPIPE, what a shell reports for a tool killed by SIGPIPE
    except _Failure as exc:
        msg, status = str(exc), exc.status
    except InputError as exc:
        msg, status = str(exc), 2
    except KeyboardInterrupt:
        msg, status = "interrupted (Ctrl-C); nothing was written", 130
    except SolverError as exc:
        msg, status = f"solver failed: {exc}", 1
    print(f"{PROG}: error: {_one_line(msg)}", file=sys.stderr)
    return status


if __name__ == "__main__":
    raise SystemExit(main())
