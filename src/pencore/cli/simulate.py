"""The ``pencore simulate`` subcommand: one impact, a summary on stdout, and the
trajectory as netCDF (``--out``, written atomically)."""

from __future__ import annotations

import argparse
import math
import os
from typing import Any

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
    refresh_interrupt_line,
    run_numerics,
    run_projectile,
    run_target,
    velocity,
)
from pencore.cli.summary import (
    Field,
    add_format_option,
    add_start_option,
    check_plot_output,
    print_summary,
    start_of,
    write_plot,
)

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
  --yield-strength PA     projectile yield strength, for the rigid-regime check (Pa)
  --stop-at-reversal      end the run at the first trajectory reversal
  --crater-depth K        Forrestal's crater region (F = c z) over K calibers
  --free-surface-depth K  resistance ramp within K calibers of a free face
  --plastic-zone-ratio C  finite-sphere free-surface reduction (Hill), c/a > 1
  --numerics KEY=VALUE    numerical parameter override (repeatable), e.g. rtol=1e-6
  --out FILE.nc           write the full trajectory (and its loads) as NetCDF
  --plot FILE.png         draw the run: path, deviation, speed, deceleration
  --format text|json|csv  the summary's form (numbers in SI units)
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
        "from the target normal (deg), which angle the yaw tilted, the peak axial "
        "deceleration (m/s^2 and g) and peak axial and lateral forces (N), run time (s) and "
        "number of steps. The target is y <= 0 and the projectile moves towards +x and -y.",
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
        help="yaw in deg: velocity angle minus axis angle, so --yaw alone tilts the "
        "VELOCITY and leaves the axis along the normal; the paper's normal impact with yaw "
        "(Figs 13-15, and 'pencore vci') tilts the AXIS with the velocity normal: "
        "--obliquity Y --yaw -Y. |obliquity + yaw| must stay below 90 deg (default: 0 deg)",
    )
    sim.add_argument(
        "--omega",
        type=number_type("omega"),
        default=0.0,
        metavar="RAD_S",
        help="initial angular velocity about the centre of mass, about +z, in "
        "rad/s; positive turns the nose towards +x (default: 0 rad/s)",
    )
    add_start_option(
        sim,
        "initial nose-tip position in m (default: tip at x = z = 0, "
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
        "m/s, angles in deg, rates in rad/s, forces in N, decelerations in m/s^2 and g) "
        "to this NetCDF file; its directory must exist and be writable; written atomically",
    )
    sim.add_argument(
        "--plot",
        metavar="FILE.png",
        default=None,
        help="draw the run (path y(x), deviation, speed and deceleration against time) to "
        "this image file (.png, .pdf or .svg); its directory must exist",
    )
    add_format_option(sim)


def _fmt_slope(s: float) -> str:
    if not math.isfinite(s) or abs(s) > 1e6:
        return f"{s:.4g} (path essentially vertical)"
    return f"{s:.4g}"


def yaw_reading(obliquity: float, yaw: float) -> str:
    """Which angle ``--yaw`` tilted, in words, and how to get the other reading.

    ``simulate``'s yaw is the velocity angle minus the axis angle (paper Fig. 10): with
    ``--obliquity 0``, ``--yaw Y`` tilts the velocity and leaves the axis along the
    normal. The paper's "normal impact with yaw" (Figs 13-15) and ``pencore vci`` tilt
    the axis: ``--obliquity Y --yaw -Y`` (velocity along the normal)."""
    if yaw == 0.0:
        return "none (axis and velocity along the same line)"
    text = (
        f"axis at {obliquity:g} deg, velocity at {obliquity + yaw:g} deg from the normal "
        "(--yaw tilts the velocity from the axis)"
    )
    if obliquity == 0.0:
        text += (
            f"; for the paper's normal impact with yaw (axis tilted, velocity normal) "
            f"use --obliquity {yaw:g} --yaw {-yaw:g}"
        )
    return text


def summary_fields(ds: Any, args: argparse.Namespace) -> list[Field]:
    """The summary of one run (SI units): what ``simulate`` prints."""
    a = ds.attrs
    slope = float(ds["final_slope"])
    dev = float(ds["final_deviation"])
    data = {"in_text": False}
    fields = [
        Field(
            "projectile",
            "projectile",
            str(a["projectile"]),
            text=f"{a['projectile']} ({a['mass_kg']:.4g} kg, "
            f"{a['length_m']:.4g} m long, Lc/L = {a['lc_over_l']:.3f})",
        ),
        Field("mass", "mass", float(a["mass_kg"]), "kg", **data),
        Field("target", "target", str(a["target"])),
        *(
            [Field("law_resolved", "law", str(a["law_resolved"]))]
            if "law_resolved" in a
            else []
        ),
        Field(
            "impact",
            "impact",
            None,
            text=f"{args.velocity:g} m/s, obliquity {args.obliquity:g} deg, "
            f"yaw {args.yaw:g} deg, omega {args.omega:g} rad/s",
            in_data=False,
        ),
        Field("impact_velocity", "impact velocity", float(args.velocity), "m s-1", **data),
        Field("obliquity", "obliquity", float(args.obliquity), "degree", **data),
        Field("yaw", "yaw", float(args.yaw), "degree", **data),
        Field("omega", "omega", float(args.omega), "rad s-1", **data),
        Field("yaw_reading", "yaw reading", yaw_reading(args.obliquity, args.yaw)),
        Field("penetration_depth", "penetration depth", float(ds["penetration_depth"]), "m"),
        Field("path_length", "tip path length below surface", float(ds["path_length"]), "m"),
        Field("outcome", "outcome", str(a["outcome"])),
        Field("reversed", "reversed", bool(a["reversed"]), text="yes" if a["reversed"] else "no"),
        Field("final_slope", "final slope dy/dx", slope, "1", text=_fmt_slope(slope)),
        Field("final_deviation", "final deviation from normal", dev, "degree",
              text=f"{dev:.4g} deg"),
    ]  # fmt: skip
    if "depth_band" in a:
        band = ds["depth_band"].values if "depth_band" in ds else [math.nan, math.nan]
        fields += [
            Field("depth_band", "depth band (measured shots)", None, text=str(a["depth_band"]),
                  in_data=False),
            Field("depth_band_lo", "depth band, low end", float(band[0]), "m", **data),
            Field("depth_band_hi", "depth band, high end", float(band[1]), "m", **data),
            Field("depth_band_note", "depth band", str(a["depth_band"]), in_text=False),
        ]  # fmt: skip
    if "peak_deceleration_m_s2" in a:
        fields += [
            Field(
                "peak_deceleration",
                "peak deceleration (axial)",
                float(a["peak_deceleration_m_s2"]),
                "m s-2",
                text=f"{a['peak_deceleration_m_s2']:.4g} m/s^2 = "
                f"{a['peak_deceleration_g']:.4g} g at t = "
                f"{a['time_of_peak_deceleration_s']:.4g} s",
            ),
            Field("peak_deceleration_g", "peak deceleration in g",
                  float(a["peak_deceleration_g"]), "1", **data),
            Field("time_of_peak_deceleration", "time of peak deceleration",
                  float(a["time_of_peak_deceleration_s"]), "s", **data),
            Field("peak_axial_force", "peak axial force", float(a["peak_axial_force_N"]), "N",
                  text=f"{a['peak_axial_force_N']:.4g} N"),
            Field("peak_lateral_force", "peak lateral force",
                  float(a["peak_lateral_force_N"]), "N",
                  text=f"{a['peak_lateral_force_N']:.4g} N"),
        ]  # fmt: skip
    if a["outcome"] == "perforated":
        fields += [
            Field("residual_velocity", "residual velocity", float(a["residual_velocity"]),
                  "m s-1"),
            Field(
                "exit_pitch_angle_of_attack",
                "exit pitch / angle of attack",
                None,
                text=f"{a['exit_pitch_deg']:.4g} / {a['exit_angle_of_attack_deg']:.4g} deg",
                in_data=False,
            ),
            Field("exit_pitch", "exit pitch", float(a["exit_pitch_deg"]), "degree", **data),
            Field("exit_angle_of_attack", "exit angle of attack",
                  float(a["exit_angle_of_attack_deg"]), "degree", **data),
        ]  # fmt: skip
    fields += [
        Field("wall_time", "run time", float(a["wall_time_s"]), "s",
              text=f"{a['wall_time_s']:.3g} s integration"),
        Field("steps", "steps", int(a["n_steps"]), "1", text=str(a["n_steps"])),
    ]  # fmt: skip
    return fields


def run(args: argparse.Namespace) -> int:
    """Run one impact and print its summary; errors propagate to ``pencore.cli.main.main()``."""
    from pencore.errors import WriteError
    from pencore.io.netcdf import write_netcdf
    from pencore.run.impact import simulate

    exit_at_once_on_interrupt()
    inputs = [args.projectile, args.target]
    out = check_output(args.out, inputs) if args.out is not None else None
    projectile = run_projectile(args)
    target = run_target(args)
    numerics = run_numerics(args)
    if numerics.v_stop >= args.velocity:
        # the run would be over before its first step, with a depth of 0
        raise CommandFailure(
            f"numerics v_stop = {numerics.v_stop:g} m/s is not below the impact speed "
            f"{args.velocity:g} m/s: the run would stop before it starts (lower v_stop)",
            2,
        )
    plot = check_plot_output(args.plot) if args.plot is not None else None
    ds = simulate(
        projectile,
        target,
        args.velocity,
        args.obliquity,
        args.yaw,
        args.omega,
        start=start_of(args),
        stop_at_reversal=args.stop_at_reversal,
        numerics=numerics,
    )
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
        refresh_interrupt_line()
    if plot is not None:
        from pencore.plotting.run import plot_run

        write_plot(plot_run(ds), plot)
    fields = summary_fields(ds, args)
    if out is not None:
        fields.append(Field("output", "output", str(out)))
    if args.plot is not None:
        fields.append(Field("plot", "plot", str(args.plot)))
    print_summary(fields, args.format)
    return 0
