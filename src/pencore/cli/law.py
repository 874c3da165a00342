"""The ``pencore law`` subcommand: the resistance law of a concrete, a metal or a soil
computed from its material properties (:mod:`pencore.inputs.laws`), printed as the
coefficients a target file takes, with their units and provenance."""

from __future__ import annotations

import argparse

__all__ = ["add_parser", "run"]

#: Law -> [(option, keyword, metavar, help)].
_OPTIONS: dict[str, list[tuple[str, str, str, str]]] = {
    "concrete": [
        ("--fc", "fc", "PA", "unconfined compressive strength in Pa (40 MPa: 40e6)"),
        ("--density", "density", "KG_M3", "density in kg/m^3"),
        ("--s", "s", "S", "Forrestal's S if measured (default: 82.6 fc^-0.544, fc in MPa)"),
        ("--crater-depth", "crater_depth", "K", "Forrestal's crater region in calibers (0: off)"),
    ],
    "metal": [
        ("--youngs-modulus", "youngs_modulus", "PA", "Young's modulus E in Pa (69 GPa: 69e9)"),
        ("--poisson-ratio", "poisson_ratio", "NU", "Poisson's ratio, 0 to 0.5"),
        ("--yield-strength", "yield_strength", "PA", "yield strength Y in Pa (276 MPa: 276e6)"),
        ("--hardening-exponent", "hardening_exponent", "N", "power-law hardening exponent, 0-1"),
        ("--density", "density", "KG_M3", "density in kg/m^3"),
    ],
    "soil": [
        ("--a", "a", "A", "Forrestal-Luk A (dimensionless)"),
        ("--tau0", "tau0", "PA", "shear strength tau0 in Pa"),
        ("--b", "b", "B", "Forrestal-Luk B (dimensionless)"),
        ("--density", "density", "KG_M3", "density in kg/m^3"),
    ],
}
_OPTIONAL = {"s", "crater_depth"}


def add_parser(sub: argparse._SubParsersAction) -> None:
    """Register ``law`` (with ``concrete``, ``metal``, ``soil``) on the subparsers of
    ``pencore.cli.main.build_parser()``."""
    p = sub.add_parser(
        "law",
        help="compute a target's resistance law from its material properties (Pa, kg/m^3)",
        description="Compute the resistance law sigma_n = a0 + a1 Vn + a2 Vn^2 of a concrete "
        "(Forrestal's S fc + rho Vn^2), a metal (spherical cavity expansion, elastic-plastic "
        "with power-law hardening) or a soil (Forrestal-Luk) from its material properties, "
        "and print the coefficients (a0 Pa, a1 Pa s/m, a2 Pa s^2/m^2) with their provenance "
        "and the target-file lines that give the same medium.",
    )
    laws = p.add_subparsers(dest="law", metavar="LAW", required=True)
    for law, options in _OPTIONS.items():
        q = laws.add_parser(law, help=f"the {law} law")
        for flag, dest, metavar, text in options:
            q.add_argument(
                flag, dest=dest, metavar=metavar, required=dest not in _OPTIONAL, help=text
            )
        if law == "concrete":
            q.add_argument(
                "--s-model",
                dest="s_model",
                choices=("forrestal", "li_chen"),
                help="S from fc when --s is not given: forrestal, 82.6 fc^-0.544 (default); "
                "li_chen, 72 fc^-0.5 (Li & Chen 2003, Eq. 21)",
            )
            q.add_argument(
                "--crater",
                choices=("none", "forrestal", "li_chen"),
                help="the crater region by name: none (default), forrestal (2 calibers), "
                "li_chen (0.707 + H/d calibers, H the nose length: set with the projectile)",
            )
            q.add_argument(
                "--size-term",
                dest="size_term",
                choices=("none", "fit"),
                help="none (default), or fit: S falls with the projectile diameter, "
                "S(fc) ((1 + d_ref/d0) / (1 + d/d0))^0.5, a declared fit (set with the "
                "projectile)",
            )
        if law == "metal":
            q.add_argument(
                "--inertia",
                choices=("compressible", "incompressible"),
                default="compressible",
                help="B from the compressible elastic-perfectly plastic solution fitted up "
                "to --max-speed (default), or the incompressible 3/2",
            )
            q.add_argument(
                "--max-speed",
                default=None,
                metavar="M_S",
                help="upper end of the compressible fit in m/s: your impact speeds (default: 1000)",
            )
            q.add_argument(
                "--finite-sphere",
                action="store_true",
                help="also set Hill's finite-sphere free-surface reduction "
                "(plastic_zone_ratio = (E / (3 (1 - nu) Y))^(1/3))",
            )


def run(args: argparse.Namespace) -> int:
    """Compute and print the law; a bad value raises :class:`pencore.errors.InputError`
    (exit status 2 with one line naming it); a plausibility warning is one line on
    stderr."""
    from pencore.inputs import laws

    kwargs = {
        dest: getattr(args, dest)
        for _, dest, _, _ in _OPTIONS[args.law]
        if getattr(args, dest) is not None
    }
    if args.law == "concrete":
        for key in ("s_model", "crater", "size_term"):
            if getattr(args, key) is not None:
                kwargs[key] = getattr(args, key)
    if args.law == "metal":
        kwargs["inertia"] = args.inertia
        if args.max_speed is not None:  # checked whatever the inertia (default: 1000 m/s)
            kwargs["max_speed"] = args.max_speed
        kwargs["finite_sphere"] = args.finite_sphere
    # a plausibility warning: one line on stderr (pencore.cli.main), the usual filters apply
    medium = laws.LAWS[args.law][0](**kwargs)
    a = medium.coefficients
    units = ("Pa", "Pa s/m", "Pa s^2/m^2")
    print(f"law:     {args.law}")
    for i, c in enumerate(a):
        print(f"a{i}:      {c:.6g} {units[i] if i < len(units) else 'SI'}")
    print(f"density: {medium.density:g} kg/m^3")
    if medium.crater_depth:
        print(f"crater:  {medium.crater_depth:g} calibers")
    if medium.crater_rule == "li_chen":
        print("crater:  0.707 + H/d calibers (H the nose length; set with the projectile)")
    if medium.size_term is not None:
        t = medium.size_term
        print(
            f"size:    a0 above is at d_ref = {t.d_ref:g} m; times "
            f"((1 + d_ref/d0) / (1 + d/d0))^{t.exponent:g}, d0 = {t.d0:.4g} m, with the "
            "projectile's diameter d"
        )
    if medium.plastic_zone_ratio:
        print(f"plastic zone ratio (finite sphere): {medium.plastic_zone_ratio:.6g}")
    print(f"source:  {medium.source}")
    given = ", ".join(
        f"{k}: {str(v).lower() if isinstance(v, bool) else v}" for k, v in kwargs.items()
    )
    print(f"as a target file, or a layer's medium: {{law: {args.law}, {given}}}")
    return 0
