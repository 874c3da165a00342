"""The ``pencore closed-form`` subcommand: the closed forms a user checks a depth with,
beside pencore's own run (:mod:`pencore.closedform`).

For a normal, zero-yaw, frictionless impact on a half-space of one medium whose law is
``sigma_n = a0 + a1 Vn + a2 Vn^2``, it prints (SI units; ``--format text|json|csv``):

* pencore's depth: the 3-D run (:func:`pencore.simulate`, normal impact, no yaw), unless
  ``--no-run``;
* the same model in one dimension (:func:`pencore.closedform.depth`): the nose loaded band
  by band as it enters, then the tunnel phase; with a crater region set on the medium,
  Forrestal's crater form, which is pencore's crater in this limit;
* the tunnel form from first contact (:func:`pencore.closedform.tunnel_depth` from the
  striking speed): the whole nose loaded from the first touch, the formula of
  Forrestal et al. and Piekutowski et al.; pencore is deeper, because it loads only the
  part of the nose already in the target;
* where the medium is a concrete, Forrestal's form with its crater region of two calibers
  (:func:`pencore.closedform.forrestal_crater_depth`).

Each form is given with pencore's depth relative to it (``pencore / form - 1``).
"""

from __future__ import annotations

import argparse
import math
from typing import Any

from pencore.cli.options import (
    exit_at_once_on_interrupt,
    run_numerics,
    run_projectile,
    run_target,
    velocity,
)
from pencore.cli.summary import Field, add_format_option, add_run_options, print_summary

__all__ = ["add_parser", "run", "CRATER_CALIBERS"]

#: Depth of Forrestal's crater region in calibers (Forrestal et al., IJIE 15 (1994)
#: 395-405: two projectile diameters).
CRATER_CALIBERS = 2.0


def add_parser(sub: argparse._SubParsersAction) -> None:
    """Register ``closed-form`` on the subparsers of ``pencore.cli.main.build_parser()``."""
    p = sub.add_parser(
        "closed-form",
        help="the closed-form depths (m) of a normal impact beside pencore's",
        description="Print the closed-form penetration depths (m) of a normal, zero-yaw "
        "impact on a half-space of one frictionless medium (sigma_n = a0 + a1 Vn + a2 Vn^2) "
        "beside pencore's 3-D run: the same model in 1-D (the nose loaded band by band as "
        "it enters, then the tunnel; pencore.closedform.depth), the tunnel form with the "
        "whole nose loaded from first contact (the formula of Forrestal et al.; "
        "pencore.closedform.tunnel_depth), and, for a concrete, Forrestal's form with its "
        "crater region of 2 calibers (pencore.closedform.forrestal_crater_depth); each with "
        "pencore's depth relative to it. pencore loads only the part of the nose already "
        "in the target, so it goes deeper than the form that loads the whole nose from "
        "first contact.",
    )
    p.add_argument(
        "--projectile",
        required=True,
        metavar="NAME|FILE",
        help="projectile name (see 'pencore list') or a projectile YAML file",
    )
    p.add_argument(
        "--target",
        required=True,
        metavar="NAME|FILE",
        help="a half-space of one frictionless medium: a target name or YAML file",
    )
    p.add_argument(
        "--velocity",
        required=True,
        type=velocity,
        metavar="M_S",
        help="impact speed in m/s (normal impact, no yaw)",
    )
    p.add_argument(
        "--no-run",
        action="store_true",
        help="print the closed forms only (no 3-D run, no comparison)",
    )
    add_run_options(p, "numerical parameter override of the 3-D run (repeatable)")
    add_format_option(p)


def is_concrete(medium: Any) -> bool:
    """Whether ``medium`` is a concrete by its name or its source (the library's
    ``concrete``, a ``law: concrete`` target, a medium named so): where Forrestal's crater
    form is printed."""
    return "concrete" in f"{medium.name} {medium.source}".lower()


def _half_space_medium(target: Any) -> Any:
    """The one medium of a half-space target, or ``InputError`` naming the target."""
    from pencore.errors import InputError

    layers = target.layers
    if len(layers) != 1 or math.isfinite(layers[0].thickness):
        raise InputError(
            f"closed forms are for a half-space of one medium; target {target.name!r} has "
            f"{len(layers)} layer(s) and is {target.thickness:g} m thick (give a target "
            "whose only layer has no thickness)"
        )
    return layers[0].medium


def _relative(depth: float, form: float) -> tuple[float, str]:
    """``depth / form - 1`` (dimensionless) and its text (``+10.7 %``; two decimals
    below 1 %)."""
    r = depth / form - 1.0
    return r, f"{100.0 * r:+.1f} %" if abs(r) >= 0.01 else f"{100.0 * r:+.2f} %"


def run(args: argparse.Namespace) -> int:
    """Compute the closed forms (and pencore's run) and print them; errors propagate
    to ``pencore.cli.main.main()`` (a medium no closed form takes: one line, status 2)."""
    from pencore import closedform
    from pencore.errors import InputError

    projectile = run_projectile(args)
    target = run_target(args)
    medium = _half_space_medium(target)
    v0 = args.velocity
    if medium.plastic_zone_ratio > 0.0:  # closedform.depth would leave it out silently
        raise InputError(
            f"target {target.name!r}: closed forms have no free-surface reduction "
            f"(plastic_zone_ratio {medium.plastic_zone_ratio:g}); give 0 or leave it out"
        )
    try:  # a law or a window no closed form takes (friction, free surface, a3...)
        model = closedform.depth(projectile, medium, v0)
        full_nose = closedform.tunnel_depth(projectile, medium, v0)
    except InputError as exc:
        raise InputError(f"target {target.name!r}: {exc}") from None
    crater_on = medium.crater_depth > 0.0
    two_term = medium.coefficients[1] == 0.0  # Forrestal's form: a0 + a2 Vn^2
    fits = CRATER_CALIBERS * projectile.diameter >= projectile.nose_length
    forrestal = (
        closedform.forrestal_crater_depth(projectile, medium, v0, CRATER_CALIBERS)
        if is_concrete(medium) and two_term and fits and not crater_on
        else None
    )
    mp = projectile.mass_properties()
    model_how = (
        f"with the medium's crater region of {medium.crater_depth:g} calibers: "
        "Forrestal's crater form"
        if crater_on
        else "the nose loaded band by band as it enters, then the tunnel"
    )
    fields = [
        Field(
            "projectile",
            "projectile",
            projectile.name,
            text=f"{projectile.name} ({mp.mass:.4g} kg, {projectile.diameter * 1e3:.4g} mm "
            f"diameter, nose {projectile.nose_length * 1e3:.4g} mm, N* = "
            f"{projectile.nose_factor():.4g})",
        ),
        Field("mass", "mass", float(mp.mass), "kg", in_text=False),
        Field(
            "target",
            "target",
            target.name,
            text=target.name if medium.name == target.name else f"{target.name} ({medium.name})",
        ),
        Field(
            "impact_velocity",
            "impact velocity",
            float(v0),
            "m s-1",
            text=f"{v0:g} m/s, normal, no yaw",
        ),
    ]
    depth = None
    if not args.no_run:
        from pencore.run.impact import simulate

        exit_at_once_on_interrupt()
        numerics = run_numerics(args)
        if numerics.v_stop >= v0:  # the run would end before its first step, at depth 0
            raise InputError(
                f"numerics v_stop = {numerics.v_stop:g} m/s is not below the impact speed "
                f"{v0:g} m/s: the run would stop before it starts (lower v_stop, or "
                "--no-run for the closed forms alone)"
            )
        ds = simulate(projectile, target, v0, numerics=numerics, loads=False)
        depth = float(ds["penetration_depth"])
        fields.append(
            Field(
                "pencore_depth",
                "pencore (3-D run)",
                depth,
                "m",
                text=f"{depth:.6g} m ({ds.attrs['outcome']})",
            )
        )
    forms = [
        ("model_depth", "same model in 1-D", model_how, model),
        (
            "full_nose_depth",
            "whole nose from contact",
            "the tunnel formula of Forrestal et al. from the striking speed",
            full_nose,
        ),
    ]
    if forrestal is not None:
        forms.append(
            (
                "forrestal_crater_depth",
                "Forrestal with crater",
                f"his form with its crater region of {CRATER_CALIBERS:g} calibers",
                forrestal,
            )
        )
    for key, label, how, value in forms:
        text = f"{value:.6g} m ({how}"
        if depth is not None:
            rel, shown = _relative(depth, value)
            text += f"; pencore {shown}"
        fields.append(Field(key, label, float(value), "m", text=text + ")"))
        if depth is not None:
            fields.append(
                Field(
                    f"pencore_vs_{key}",
                    f"pencore / {key} - 1",
                    rel,
                    "1",
                    in_text=False,
                )
            )
    if not crater_on:
        v1, zn = closedform.nose_entry_speed(projectile, medium, v0)
        fields += [
            Field(
                "nose_entry_speed",
                "nose-entry speed (1-D)",
                float(v1),
                "m s-1",
                text=f"{v1:.6g} m/s at tip depth {zn:.4g} m (the nose length)",
            ),
            Field("nose_length", "nose length", float(projectile.nose_length), "m", in_text=False),
        ]
    if depth is not None and not crater_on:
        fields.append(
            Field(
                "why",
                "why they differ",
                "pencore loads only the part of the nose already in the target; the "
                "tunnel formula loads the whole nose from first contact",
                in_data=False,
            )
        )
    print_summary(fields, args.format)
    return 0
