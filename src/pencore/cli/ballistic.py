"""The ``pencore ballistic-limit`` subcommand: the lowest impact speed that perforates a
finite target."""

from __future__ import annotations

import argparse
import math

from pencore.cli.options import (
    add_mass_options,
    add_window_options,
    exit_at_once_on_interrupt,
    number_type,
    numerics_option,
    obliquity,
    resolve,
    velocity,
    with_mass,
    with_windows,
)
from pencore.inputs.numerics import resolve_numerics

__all__ = ["add_parser", "run"]


def add_parser(sub: argparse._SubParsersAction) -> None:
    """Register ``ballistic-limit`` on the subparsers of ``pencore.cli.main.build_parser()``."""
    p = sub.add_parser(
        "ballistic-limit",
        help="search the ballistic limit (m/s) of a finite target",
        description="Search the ballistic limit v_bl (m/s): the lowest impact speed at "
        "which the projectile perforates a finite target (a target YAML file whose last "
        "layer has a thickness in m). Prints v_bl, its bracket (m/s), the number of runs "
        "and the status of the search (pencore.search.perforation.ballistic_limit).",
    )
    p.add_argument("--projectile", required=True, metavar="NAME|FILE", help="projectile")
    p.add_argument(
        "--target",
        required=True,
        metavar="FILE",
        help="finite target YAML file (layers with a thickness in m; gaps as {gap: m})",
    )
    p.add_argument(
        "--obliquity",
        type=obliquity,
        default=0.0,
        metavar="DEG",
        help="obliquity in deg, positive towards +x; -90 < DEG < 90 (default: 0)",
    )
    p.add_argument(
        "--yaw", type=number_type("yaw"), default=0.0, metavar="DEG", help="yaw in deg (default: 0)"
    )
    p.add_argument(
        "--lo", type=velocity, default=50.0, metavar="M_S", help="lowest speed (default: 50)"
    )
    p.add_argument(
        "--hi", type=velocity, default=3000.0, metavar="M_S", help="highest speed (default: 3000)"
    )
    p.add_argument(
        "--tol",
        type=number_type("velocity", "tolerance"),
        default=5.0,
        metavar="M_S",
        help="width of the final bracket in m/s (default: 5)",
    )
    add_mass_options(p)
    add_window_options(p)
    p.add_argument(
        "--numerics",
        type=numerics_option,
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="numerical parameter override (repeatable), as for 'simulate'",
    )


def run(args: argparse.Namespace) -> int:
    """Run the search and print the result; errors propagate to :func:`pencore.cli.main`."""
    from pencore.errors import InputError
    from pencore.inputs.library import get_projectile, get_target
    from pencore.search.perforation import ballistic_limit

    exit_at_once_on_interrupt()
    if not args.lo < args.hi:
        raise InputError(f"--lo {args.lo:g} must be below --hi {args.hi:g} (m/s)")
    projectile = with_mass(resolve("projectile", args.projectile, get_projectile), args)
    target = with_windows(resolve("target", args.target, get_target), args)
    r = ballistic_limit(
        projectile,
        target,
        args.obliquity,
        args.yaw,
        args.lo,
        args.hi,
        args.tol,
        numerics=resolve_numerics(dict(args.numerics)),
    )
    value = f"{r.value:.6g} m/s" if math.isfinite(r.value) else "not found"
    print(f"ballistic limit: {value}")
    print(f"bracket:         [{r.lo:.6g}, {r.hi:.6g}] m/s")
    print(f"runs:            {r.n_evals}")
    print(f"status:          {r.status} ({r.message})")
    return 0
