"""The ``pencore simulate`` subcommand: one impact, a summary on stdout, and the
trajectory as netCDF (``--out``, written atomically)."""

from __future__ import annotations

import argparse
import math
import os
import time

from pencore.cli.options import (
    CommandFailure,
    add_mass_options,
    add_window_options,
    check_output,
    cli_inputs,
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

__all__ = ["SUMMARY", "add_parser", "run"]

#: The options of ``simulate`` in brief (the epilog of ``pencore --help``).
SUMMARY = """\
simulate options (all SI, angles in degrees):
  --projectile NAME|FILE  p1..p4, validation projectiles, or a projectile YAML file
  --target NAME|FILE      soil, concrete, aluminium, or a target YAML file
  --velocity M_S          impact speed (m/s), > 0
  --obliquity DEG         axis angle from the target normal (deg), in (-90, 90)
  --yaw DEG               velocity angle minus axis angle (deg)
  --omega RAD_S           initial angular velocity about +z (rad/s)
  --start X Y Z           initial nose-tip position (m)
  --mass KG               measured projectile mass (outline distribution scaled)
  --centre-of-mass M      measured tip-to-centre-of-mass distance Lc (m)
  --inertia IA IT         measured axial, transverse inertia about the c.m. (kg m^2)
  --stop-at-reversal      end the run at the first trajectory reversal
  --crater-depth K        Forrestal's crater region (F = c z) over K calibers
  --free-surface-depth K  resistance ramp within K calibers of a free face
  --plastic-zone-ratio C  finite-sphere free-surface reduction (Hill), c/a > 1
  --numerics KEY=VALUE    numerical parameter override (repeatable), e.g. rtol=1e-6
  --out FILE.nc           write the full trajectory as NetCDF
Run 'pencore simulate --help' for details; 'pencore list' for the named projectiles
and targets.
"""


def add_parser(sub: argparse._SubParsersAction) -> None:
    """Register ``simulate`` on the subparsers of ``pencore.cli.main.build_parser()``."""
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
        type=velocity,
        metavar="M_S",
        help="impact speed in m/s; must be > 0 and finite",
    )
    sim.add_argument(
        "--obliquity",
        type=obliquity,
        default=0.0,
        metavar="DEG",
        help="obliquity in deg: angle between the projectile axis and the "
        "target normal, positive towards +x; -90 < DEG < 90 (default: 0 deg)",
    )
    sim.add_argument(
        "--yaw",
        type=number_type("yaw"),
        default=0.0,
        metavar="DEG",
        help="yaw in deg: velocity angle minus axis angle; |obliquity + yaw| "
        "must stay below 90 deg (default: 0 deg)",
    )
    sim.add_argument(
        "--omega",
        type=number_type("omega"),
        default=0.0,
        metavar="RAD_S",
        help="initial angular velocity about the centre of mass, about +z, in "
        "rad/s; positive turns the nose towards +x (default: 0 rad/s)",
    )
    sim.add_argument(
        "--start",
        type=number_type("start"),
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
    add_mass_options(sim)
    add_window_options(sim)
    sim.add_argument(
        "--numerics",
        type=numerics_option,
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="override a numerical parameter, e.g. rtol=1e-6, eps=1e-3 (m/s), t_max=2 (s), "
        "method=Radau; repeat for several (see pencore.Numerics for the keys; the docs' "
        "user guide lists their valid ranges)",
    )
    sim.add_argument(
        "--out",
        metavar="FILE.nc",
        default=None,
        help="write the trajectory (time in s, positions in m, velocities in "
        "m/s, angles in deg, rates in rad/s) to this NetCDF file; its "
        "directory must exist and be writable; written atomically",
    )


def _fmt_slope(s: float) -> str:
    if not math.isfinite(s) or abs(s) > 1e6:
        return f"{s:.4g} (path essentially vertical)"
    return f"{s:.4g}"


def run(args: argparse.Namespace) -> int:
    """Run one impact and print its summary; errors propagate to ``pencore.cli.main.main()``."""
    from pencore.errors import WriteError
    from pencore.inputs.library import get_projectile, get_target
    from pencore.io.netcdf import write_netcdf
    from pencore.run.impact import simulate

    exit_at_once_on_interrupt()
    inputs = [args.projectile, args.target]
    out = check_output(args.out, inputs) if args.out is not None else None
    projectile = with_mass(resolve("projectile", args.projectile, get_projectile), args)
    target = with_windows(resolve("target", args.target, get_target), args)
    numerics = resolve_numerics(dict(args.numerics))
    if numerics.v_stop >= args.velocity:
        # the run would be over before its first step, with a depth of 0
        raise CommandFailure(
            f"numerics v_stop = {numerics.v_stop:g} m/s is not below the impact speed "
            f"{args.velocity:g} m/s: the run would stop before it starts (lower v_stop)",
            2,
        )
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
        numerics=numerics,
    )
    total = time.perf_counter() - t0
    if out is not None:
        try:
            write_netcdf(
                ds,
                out,
                config_slice={"cli": cli_inputs(args)},
                study="cli/simulate",
                protect=[p for p in inputs if os.path.isfile(p)],
            )
        except WriteError as exc:  # one line naming the path and the cause; nothing left
            raise CommandFailure(str(exc), 1) from None
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
