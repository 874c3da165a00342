"""The ``pencore vcr``, ``pencore vci`` and ``pencore omega-c`` subcommands: the paper's
critical values (:mod:`pencore.search.critical`) from the command line.

Each prints the value, its final bracket, the number of runs and the status of the
search (``--format text|json|csv``), writes the search's evaluations (``--out`` .nc or
.csv, :func:`pencore.search.history.search_dataset`) and draws them (``--plot``). A
search that finds no threshold in its range (status ``below_range``, ``above_range`` or
``max_iter``) still prints and writes, and exits with status 3
(:data:`pencore.cli.summary.NOT_FOUND`).
"""

from __future__ import annotations

import argparse
from typing import Any

from pencore.cli.options import (
    exit_at_once_on_interrupt,
    number_type,
    obliquity,
    run_numerics,
    run_projectile,
    run_target,
    velocity,
)
from pencore.cli.summary import (
    EXIT_NOTE,
    NOT_FOUND,
    add_search_outputs,
    add_speed_bracket,
    add_start_option,
    check_bracket,
    check_outputs,
    search_fields,
    start_of,
    write_outputs,
)

__all__ = ["add_parsers", "run_search"]

#: What each command searches: (quantity, units, text units, long name).
QUANTITIES = {
    "vcr": ("vcr", "m s-1", "m/s", "critical reverse velocity (lowest speed that turns back)"),
    "vci": ("vci", "m s-1", "m/s", "critical velocity for instability"),
    "omega-c": (
        "omega_c",
        "rad s-1",
        "rad/s",
        "critical angular velocity (lowest that turns back)",
    ),
}


def _common(p: argparse.ArgumentParser, target_help: str = "target name or YAML file") -> None:
    p.add_argument(
        "--projectile", required=True, metavar="NAME|FILE", help="projectile name or YAML file"
    )
    p.add_argument("--target", required=True, metavar="NAME|FILE", help=target_help)


def _speed_bracket(p: argparse.ArgumentParser, lo: float) -> None:
    """``--lo``, ``--hi`` and ``--tol`` of ``vcr`` and ``vci`` (m/s)."""
    add_speed_bracket(
        p,
        lo,
        4000.0,
        (
            f"lowest speed searched (default: {lo:g} m/s)",
            "highest speed searched (default: 4000 m/s)",
            "width of the final bracket (default: 5 m/s)",
        ),
    )


def add_parsers(sub: argparse._SubParsersAction) -> None:
    """Register ``vcr``, ``vci`` and ``omega-c`` on the subparsers of ``pencore``."""
    p = sub.add_parser(
        "vcr",
        help="critical reverse velocity Vcr (m/s): lowest impact speed that turns back",
        description="Search the critical reverse velocity Vcr (m/s): the lowest impact "
        "speed at which the projectile turns back towards the surface, at the given "
        "obliquity and yaw (paper Section 4.2, Figs 8 and 12; pencore.vcr). " + EXIT_NOTE,
    )
    _common(p)
    p.add_argument(
        "--obliquity",
        type=obliquity,
        required=True,
        metavar="DEG",
        help="obliquity of the axis from the target normal in deg, in (-90, 90)",
    )
    p.add_argument(
        "--yaw",
        type=number_type("yaw"),
        default=0.0,
        metavar="DEG",
        help="velocity angle minus axis angle in deg (as for 'simulate'; default 0)",
    )
    _speed_bracket(p, 100.0)
    add_start_option(p)
    add_search_outputs(p)

    p = sub.add_parser(
        "vci",
        help="critical velocity for instability Vci (m/s): normal impact with a small yaw",
        description="Search the critical velocity for instability Vci (m/s): the lowest "
        "normal-impact speed at which, with the given yaw, the final deviation exceeds "
        "--threshold deg or the projectile turns back (paper Figs 13-15; pencore.vci). "
        "The yaw tilts the AXIS by default (the velocity along the normal, the paper's "
        "reading; --convention velocity_tilted tilts the velocity instead, which is what "
        "'simulate --yaw' alone does). " + EXIT_NOTE,
    )
    _common(p)
    p.add_argument(
        "--yaw",
        type=number_type("yaw"),
        required=True,
        metavar="DEG",
        help="initial yaw in deg, e.g. 0.1",
    )
    p.add_argument(
        "--threshold",
        type=number_type("yaw", "threshold"),
        required=True,
        metavar="DEG",
        help="deviation (deg) above which the run is unstable",
    )
    p.add_argument(
        "--convention",
        choices=("axis_tilted", "velocity_tilted"),
        default="axis_tilted",
        help="which of the axis or the velocity the yaw tilts (default: axis_tilted)",
    )
    _speed_bracket(p, 200.0)
    add_start_option(p)
    add_search_outputs(p)

    p = sub.add_parser(
        "omega-c",
        help="critical angular velocity omega_c (rad/s): lowest initial spin that turns back",
        description="Search the critical angular velocity omega_c (rad/s): the lowest "
        "initial angular velocity about +z at which a normal impact turns back (paper Figs "
        "16-18; pencore.omega_c). " + EXIT_NOTE,
    )
    _common(p)
    p.add_argument(
        "--velocity", type=velocity, required=True, metavar="M_S", help="impact speed in m/s"
    )
    p.add_argument(
        "--lo",
        type=number_type("omega"),
        default=0.0,
        metavar="RAD_S",
        help="lowest angular velocity searched (default: 0 rad/s)",
    )
    p.add_argument(
        "--hi",
        type=number_type("omega"),
        required=True,
        metavar="RAD_S",
        help="highest angular velocity searched (rad/s)",
    )
    p.add_argument(
        "--tol",
        type=number_type("omega", "tolerance"),
        default=0.5,
        metavar="RAD_S",
        help="width of the final bracket (default: 0.5 rad/s)",
    )
    add_start_option(p)
    add_search_outputs(p)


def run_search(args: argparse.Namespace) -> int:
    """Run ``vcr``, ``vci`` or ``omega-c``: summary, files, exit status."""
    from pencore.errors import InputError
    from pencore.search import critical
    from pencore.search.history import search_dataset

    exit_at_once_on_interrupt()
    check_bracket(args)
    if args.scan < 0 or args.scan == 1:
        raise InputError(f"--scan must be 0 (none) or at least 2 points, got {args.scan}")
    out, plot = check_outputs(args)
    projectile = run_projectile(args)
    target = run_target(args)
    num = run_numerics(args)
    scan = args.scan or None
    quantity, units, text_units, long_name = QUANTITIES[args.command]
    inputs: dict[str, Any] = {"projectile": args.projectile, "target": args.target}
    start = start_of(args)
    # the runs' start, where given (m): passed to every run and recorded in the result
    at: dict[str, Any] = {} if start is None else {"start": start}
    if start is not None:
        inputs["start_m"] = list(start)
    if args.command == "vcr":
        r = critical.vcr(projectile, target, args.obliquity, args.yaw, args.lo, args.hi,
                         args.tol, scan=scan, numerics=num, **at)  # fmt: skip
        inputs.update(obliquity_deg=args.obliquity, yaw_deg=args.yaw)
    elif args.command == "vci":
        r = critical.vci(projectile, target, args.yaw, args.lo, args.hi, args.threshold,
                         args.tol, convention=args.convention, scan=scan, numerics=num,
                         **at)  # fmt: skip
        inputs.update(yaw_deg=args.yaw, threshold_deg=args.threshold,
                      yaw_convention=args.convention)  # fmt: skip
    else:
        r = critical.omega_c(projectile, target, args.velocity, args.lo, args.hi, args.tol,
                             scan=scan, numerics=num, **at)  # fmt: skip
        inputs.update(impact_velocity_m_s=args.velocity)
    ds = search_dataset(r, quantity, units, long_name, **inputs)
    write_outputs(ds, search_fields(r, quantity, units, text_units), out, plot, args)
    return 0 if r.converged else NOT_FOUND
