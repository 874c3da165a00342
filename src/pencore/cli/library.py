"""The ``pencore list`` and ``pencore fit-table3`` subcommands (kept apart from
:mod:`pencore.cli`, which registers them): the projectile and target library, and the
Table-3 geometry fit."""

from __future__ import annotations

import argparse

__all__ = ["list_library", "fit_table3"]


def fit_table3(args: argparse.Namespace) -> int:
    """``pencore fit-table3 [--write PATH]``: the minimax fit of the paper's Table 3, beside
    the shipped geometry; exit status 0, or 1 when the file cannot be written."""
    from pencore.cli.main import _Failure
    from pencore.inputs.library import shipped_table3_geometry, table3_fit, write_table3_geometry

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
            raise _Failure(str(exc), 1) from None
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
