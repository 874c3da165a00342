"""The ``pencore list`` and ``pencore fit-table3`` subcommands: the projectile and target
library, and the Table-3 geometry fit."""

from __future__ import annotations

import argparse

from pencore.cli.options import CommandFailure, check_output, path_type

__all__ = ["add_parsers", "list_library", "fit_table3"]


def add_parsers(sub: argparse._SubParsersAction) -> None:
    """Register ``fit-table3`` and ``list`` on the subparsers of
    ``pencore.cli.main.build_parser()``."""
    fit3 = sub.add_parser(
        "fit-table3",
        help="fit the p1..p4 geometry (diameter and shank length in m) to the paper's "
        "Table 3 (masses in kg, Lc/L)",
        description="Fit a solid CRH-3 ogive + cylinder (diameter and shank length in "
        "m) to the masses (kg) and Lc/L of paper Table 3, print the residuals (kg and "
        "dimensionless), and compare the fit with the geometry pencore ships "
        "(pencore/inputs/data/table3_geometry.yaml).",
    )
    fit3.add_argument(
        "--write",
        metavar="PATH",
        type=path_type,
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


def fit_table3(args: argparse.Namespace) -> int:
    """``pencore fit-table3 [--write PATH]``: the minimax fit of the paper's Table 3, beside
    the shipped geometry; exit status 0, or 1 when the file cannot be written."""
    from pencore.inputs.library import shipped_table3_geometry, table3_fit, write_table3_geometry

    if args.write:  # the output gate's rules, before the fit
        from pencore.inputs.library import TABLE3_GEOMETRY_FILE
        from pencore.io.outputs import YAML_SUFFIXES, allow_rewrite

        check_output(args.write, suffixes=YAML_SUFFIXES)
        # the shipped geometry, which every run reads, is the file this command regenerates
        allow_rewrite(TABLE3_GEOMETRY_FILE)
    fit = table3_fit()
    print(fit.report())
    d, ls = shipped_table3_geometry()
    print(
        f"shipped geometry: diameter {d!r} m, shank length {ls!r} m; fit minus shipped: "
        f"{fit.diameter - d:.3g} m, {fit.shank_length - ls:.3g} m"
    )
    if args.write:
        from pencore.errors import WriteError

        try:
            write_table3_geometry(fit, args.write)
        except WriteError as exc:
            raise CommandFailure(str(exc), 1) from None
        print(f"wrote {args.write}")
    return 0


def list_library(args: argparse.Namespace) -> int:
    """``pencore list``: the named projectiles and targets with their data and sources."""
    from pencore.inputs.library import MEDIA, get_projectile, projectile_names

    print("projectiles:")
    print(f"  {'name':<18} {'mass_kg':>9} {'Lc/L':>6} {'diameter_mm':>11}  source")
    for name in projectile_names():
        p = get_projectile(name)
        mp = p.mass_properties()
        print(
            f"  {name:<18} {mp.mass:9.3f} {mp.lc_over_l:6.3f} {p.diameter * 1e3:11.2f}  {p.source}"
        )
    print()
    print("targets (normal stress = a0 + a1 Vn + a2 Vn^2; a0 Pa, a1 Pa s/m, a2 Pa s^2/m^2):")
    for name in sorted(MEDIA):
        m = MEDIA[name]
        coef = ", ".join(f"a{i}={c:.4g}" for i, c in enumerate(m.coefficients))
        fric = "frictionless" if m.frictionless else f"friction mu={m.friction_mu}"
        print(f"  {name:<10} {coef}; density {m.density:g} kg/m^3; {fric}")
        print(f"  {'':<10} source: {m.source}")
    return 0
