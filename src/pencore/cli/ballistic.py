"""The ``pencore ballistic-limit`` subcommand: the lowest impact speed that perforates a
finite target."""

from __future__ import annotations

import argparse

from pencore.cli.options import (
    exit_at_once_on_interrupt,
    number_type,
    obliquity,
    run_numerics,
    run_projectile,
    run_target,
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

__all__ = ["add_parser", "run"]


def add_parser(sub: argparse._SubParsersAction) -> None:
    """Register ``ballistic-limit`` on the subparsers of ``pencore.cli.main.build_parser()``."""
    p = sub.add_parser(
        "ballistic-limit",
        help="search the ballistic limit (m/s) of a finite target",
        description="Search the ballistic limit v_bl (m/s): the lowest impact speed at "
        "which the projectile perforates a finite target (a target YAML file whose last "
        "layer has a thickness in m). Prints v_bl, its bracket (m/s), the number of runs "
        "and the status of the search (pencore.search.perforation.ballistic_limit). " + EXIT_NOTE,
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
    add_speed_bracket(
        p,
        50.0,
        3000.0,
        (
            "lowest speed (default: 50)",
            "highest speed (default: 3000)",
            "width of the final bracket in m/s (default: 5)",
        ),
    )
    add_start_option(p)
    add_search_outputs(p)


def run(args: argparse.Namespace) -> int:
    """Run the search and print the result; errors propagate to :func:`pencore.cli.main`."""
    from pencore.search.history import search_dataset
    from pencore.search.perforation import ballistic_limit

    exit_at_once_on_interrupt()
    check_bracket(args, " (m/s)")
    out, plot = check_outputs(args)
    projectile = run_projectile(args)
    target = run_target(args)
    start = start_of(args)
    at = {} if start is None else {"start": start}  # every run's start (m), where given
    r = ballistic_limit(
        projectile,
        target,
        args.obliquity,
        args.yaw,
        args.lo,
        args.hi,
        args.tol,
        scan=args.scan or None,
        numerics=run_numerics(args),
        **at,
    )
    ds = search_dataset(
        r,
        "v_bl",
        "m s-1",
        "ballistic limit (lowest speed that perforates)",
        projectile=args.projectile,
        target=args.target,
        obliquity_deg=args.obliquity,
        yaw_deg=args.yaw,
        **({} if start is None else {"start_m": list(start)}),
    )
    fields = search_fields(r, "v_bl", "m s-1", "m/s", label="ballistic limit")
    write_outputs(ds, fields, out, plot, args)
    return 0 if r.converged else NOT_FOUND
