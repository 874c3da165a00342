"""The sweep subcommands: ``depth-curve`` (depth, deceleration and forces against impact
speed), ``residual-velocity`` (residual speed against impact speed on a finite target)
and ``ballistic-table`` (ballistic limit over slab thickness and obliquity)
(:mod:`pencore.studies.sweeps`).

Each writes its table as netCDF or CSV (``--out``), prints a summary (``--format``) and
one progress line per point on stderr (``--quiet``: none).
"""

from __future__ import annotations

import argparse
import math
from typing import Any

import numpy as np

from pencore.cli.options import (
    each_of,
    exit_at_once_on_interrupt,
    number_type,
    obliquity,
    run_numerics,
    run_projectile,
    run_target,
    velocity,
    whole_type,
    window_values,
)
from pencore.cli.summary import (
    NOT_FOUND,
    Field,
    Progress,
    add_format_option,
    add_run_options,
    add_speed_bracket,
    add_start_option,
    check_bracket,
    check_outputs,
    start_of,
    write_outputs,
)

__all__ = ["add_parsers", "run_sweep"]


def _speeds(p: argparse.ArgumentParser) -> None:
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument(
        "--velocities", type=velocity, nargs="+", metavar="M_S", help="impact speeds in m/s"
    )
    g.add_argument("--range", action=each_of(velocity, velocity, whole_type("sweep_points")),
                   nargs=3, metavar=("LO", "HI", "N"),
                   help="N impact speeds evenly from LO to HI m/s")  # fmt: skip


def _impacts(p: argparse.ArgumentParser, target_metavar: str, target_help: str) -> None:
    """The projectile, target, impact speeds and obliquity of a sweep over impact speed."""
    p.add_argument("--projectile", required=True, metavar="NAME|FILE", help="projectile")
    p.add_argument("--target", required=True, metavar=target_metavar, help=target_help)
    _speeds(p)
    p.add_argument(
        "--obliquity",
        type=obliquity,
        default=0.0,
        metavar="DEG",
        help="obliquity in deg (default 0)",
    )


def _outputs(p: argparse.ArgumentParser, plot: bool) -> None:
    add_start_option(p)
    add_run_options(p, "numerical parameter override (repeatable)")
    p.add_argument(
        "--out",
        metavar="FILE.nc|FILE.csv",
        default=None,
        help="write the table as netCDF or CSV (SI units, units in the headers)",
    )
    if plot:
        p.add_argument(
            "--plot", metavar="FILE.png", default=None, help="draw the curve to this image file"
        )
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    add_format_option(p)  # fmt: skip


def add_parsers(sub: argparse._SubParsersAction) -> None:
    """Register ``depth-curve``, ``residual-velocity`` and ``ballistic-table``."""
    p = sub.add_parser(
        "depth-curve",
        help="penetration depth (m) and peak deceleration (g) against impact speed",
        description="Run one impact per speed and tabulate the penetration depth and path "
        "length (m), final deviation (deg), peak axial deceleration (m/s^2 and g) and "
        "peak axial and lateral forces (N) against impact speed (m/s).",
    )
    _impacts(p, "NAME|FILE", "target")
    p.add_argument(
        "--yaw",
        type=number_type("yaw"),
        default=0.0,
        metavar="DEG",
        help="velocity angle minus axis angle in deg, as for 'simulate' (default 0)",
    )
    _outputs(p, plot=False)  # fmt: skip

    p = sub.add_parser(
        "residual-velocity",
        help="residual speed (m/s) against impact speed on a finite target",
        description="Run one impact per speed on a finite target (a YAML file whose layers "
        "all have a thickness) and tabulate the residual speed (m/s; 0 when it does not "
        "perforate) and exit pitch (deg), with the Recht-Ipson curve fitted when three or "
        "more runs perforate.",
    )
    _impacts(p, "FILE", "finite target YAML file")
    _outputs(p, plot=True)  # fmt: skip

    p = sub.add_parser(
        "ballistic-table",
        help="ballistic limit (m/s) over slab thickness (m) and obliquity (deg)",
        description="Search the ballistic limit (m/s) of a slab of one medium for each "
        "thickness (m) and obliquity (deg). Exit status 3 if a cell's search found no "
        "threshold in [--lo, --hi] (its value is NaN in the table).",
    )
    p.add_argument("--projectile", required=True, metavar="NAME|FILE", help="projectile")
    p.add_argument(
        "--medium",
        required=True,
        metavar="NAME",
        help="medium of the slab (a target name: concrete, aluminium...)",
    )
    p.add_argument(
        "--thicknesses",
        type=number_type("thickness"),
        nargs="+",
        required=True,
        metavar="M",
        help="slab thicknesses in m",
    )
    p.add_argument(
        "--obliquities",
        type=obliquity,
        nargs="+",
        default=[0.0],
        metavar="DEG",
        help="obliquities in deg (default 0)",
    )
    add_speed_bracket(
        p,
        50.0,
        3000.0,
        (
            "lowest speed searched (default 50)",
            "highest speed searched (default 3000)",
            "width of the final bracket (default 5)",
        ),
    )
    _outputs(p, plot=True)  # fmt: skip


def _velocities(args: argparse.Namespace) -> np.ndarray:
    from pencore.errors import InputError

    if args.velocities is not None:
        return np.array(args.velocities, dtype=float)
    lo, hi, n = args.range
    if not lo < hi:  # each is a speed and N a count of at least 2: their types check
        raise InputError(f"--range LO HI N needs LO < HI (m/s), got {lo:g} {hi:g} {n}")
    return np.linspace(lo, hi, n)


def run_sweep(args: argparse.Namespace) -> int:
    """Run a sweep: table, plot, summary; exit 3 when a ballistic-table cell was not found."""
    from pencore.inputs.library import get_target
    from pencore.studies import sweeps

    exit_at_once_on_interrupt()
    out, plot = check_outputs(args)
    projectile = run_projectile(args)
    num = run_numerics(args)
    status = 0
    fields: list[Field]
    if args.command == "ballistic-table":
        check_bracket(args, " (m/s)")  # --thicknesses > 0: their type (number_type) refuses
        get_target(args.medium)  # a bad name is one line before any run
        n = len(args.thicknesses) * len(args.obliquities)
        ds = sweeps.ballistic_table(
            projectile, args.medium, args.thicknesses, args.obliquities, lo=args.lo,
            hi=args.hi, tol=args.tol, numerics=num, progress=Progress(n, args.quiet),
            windows=window_values(args), start=start_of(args),
        )  # fmt: skip
        found = np.isfinite(ds["v_bl"].values)
        status = 0 if found.all() else NOT_FOUND
        fields = [
            Field("cells", "cells", int(found.size), "1", text=str(found.size)),
            Field("cells_not_found", "cells without a threshold in the range",
                  int((~found).sum()), "1", text=str(int((~found).sum()))),
            Field("v_bl_min", "lowest ballistic limit", _min(ds["v_bl"].values), "m s-1"),
            Field("v_bl_max", "highest ballistic limit", _max(ds["v_bl"].values), "m s-1"),
        ]  # fmt: skip
    else:
        target = run_target(args)
        v = _velocities(args)
        progress = Progress(v.size, args.quiet)
        if args.command == "depth-curve":
            ds = sweeps.depth_curve(projectile, target, v, args.obliquity, args.yaw,
                                    numerics=num, progress=progress,
                                    start=start_of(args))  # fmt: skip
            d = ds["penetration_depth"].values
            g = ds["peak_deceleration_g"].values
            fields = [
                Field("points", "points", int(v.size), "1", text=str(v.size)),
                _failed_runs(ds),
                Field("depth_max", "deepest", _max(d), "m"),
                Field("peak_deceleration_g_max", "highest peak deceleration", _max(g), "1",
                      text=f"{_max(g):.4g} g"),
            ]  # fmt: skip
        else:
            ds = sweeps.residual_curve(projectile, target, v, args.obliquity, numerics=num,
                                       progress=progress, start=start_of(args))  # fmt: skip
            a = ds.attrs
            fields = [
                Field("points", "points", int(v.size), "1", text=str(v.size)),
                _failed_runs(ds),
                Field("perforated", "runs that perforate",
                      int((ds["residual_velocity"].values > 0).sum()), "1"),
                Field("recht_ipson_status", "Recht-Ipson fit", a["recht_ipson_status"]),
                Field("v_bl_fit", "Recht-Ipson v_bl (fitted)", a["v_bl_m_s"], "m s-1"),
                Field("recht_ipson_a", "Recht-Ipson a", a["recht_ipson_a"], "1"),
                Field("recht_ipson_p", "Recht-Ipson p", a["recht_ipson_p"], "1"),
            ]  # fmt: skip
        if (ds["outcome"].values == "solver_error").any():
            status = NOT_FOUND  # the table is written; those rows say why they are empty
    write_outputs(ds, fields, out, plot, args, draw=_draw(args.command))
    return status


def _failed_runs(ds: Any) -> Field:
    """How many runs of a sweep could not finish (their rows: outcome solver_error, the
    reason in ``message``)."""
    failed = ds["outcome"].values == "solver_error"
    n = int(failed.sum())
    text = f"{n} (first: {ds['message'].values[failed][0]})" if n else "0"
    return Field("runs_failed", "runs that could not finish", n, "1", text=text)


def _draw(command: str) -> Any:
    """What draws the table of ``command`` (imported only when a plot is drawn)."""

    def draw(ds: Any) -> Any:
        from pencore.plotting.perforation import plot_ballistic_limit, plot_residual_velocity

        if command == "ballistic-table":
            return plot_ballistic_limit(ds)
        return plot_residual_velocity(ds)

    return draw


def _min(a: Any) -> float:
    a = np.asarray(a, dtype=float)
    return float(np.nanmin(a)) if np.isfinite(a).any() else math.nan


def _max(a: Any) -> float:
    a = np.asarray(a, dtype=float)
    return float(np.nanmax(a)) if np.isfinite(a).any() else math.nan
