"""Shots of bodies and targets given by measured properties, made ready to run.

A body shot table (:func:`pencore.measured.shots.read_body_shot_table`) gives each shot's rod
by its measured mass, diameter, total length and CRH, and its target by density and
unconfined compressive strength ``fc``. This module turns each row into a
:class:`~pencore.Projectile` and, per law, a half-space :class:`~pencore.Target`, in the
common form of :func:`pencore.studies.validation.measurements.load_measurements`.

The rod: a tangent ogive of the CRH ``psi`` (nose length ``a sqrt(4 psi - 1)``) and one
cylinder making up the total length, given its measured mass (:func:`body_projectile`,
:class:`~pencore.Projectile`'s ``mass``): the outline's mass distribution scaled, so ``Lc``
is the outline's and the inertias scale with the mass (at normal incidence and no yaw only
the mass acts). The compilation's rods weigh 0.77 to 1.0 of a solid steel body of their outline
(``config/concrete_ogive_shots.csv`` header), so the measured mass is the input.

The concrete laws (Forrestal's form ``sigma_n = S fc + rho Vn^2``, no friction, no crater:
the paper's model), :data:`LAWS`:

``paper_s21``
    the paper's Table 1 law (library target ``concrete``: S = 21, fc = 13.5 MPa,
    rho = 1960 kg/m3), applied only to shots into targets of fc = 13.5 MPa, where it is
    the paper's own choice;
``s_of_fc``
    :func:`pencore.inputs.laws.concrete_law`: ``S = 82.6 fc^-0.544`` (fc in MPa; Frew,
    Hanchak, Green & Forrestal, IJIE 21 (1998) 489-497) with the shot's fc and density:
    every shot. At 13.5 MPa it gives S = 20.05, not the paper's 21. Beyond the 13.5-108 MPa
    the form was built on (the O'Neil et al. 1999 shots) the law warns; the shot's remark
    says so. No constant is fitted to the shots compared here.

Examples
--------
>>> row = {"mass_kg": 0.064, "diameter_m": 0.0129, "length_m": 0.0889, "crh": 3.0}
>>> p = body_projectile(row, "rod")
>>> print(f"{p.mass_properties().mass:.4f} kg, length {p.length:.4f} m")
0.0640 kg, length 0.0889 m
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from typing import Any

import pandas as pd

from pencore.errors import InputError, PlausibilityWarning
from pencore.inputs.geometry import Cylinder, OgiveNose, Projectile
from pencore.inputs.laws import concrete_law
from pencore.inputs.library import get_target
from pencore.inputs.target import Target
from pencore.measured.shots import read_body_shot_table

__all__ = ["LAWS", "STEEL_DENSITY", "body_projectile", "concrete_target", "body_rows"]

#: Nominal steel density (kg/m3) of the outline, whose distribution the measured mass scales.
STEEL_DENSITY = 7850.0

#: Concrete laws a body shot table is run with (see the module notes): name -> description.
LAWS = {
    "paper_s21": "paper Table 1: S = 21, fc = 13.5 MPa, rho = 1960 kg/m3 (13.5 MPa shots only)",
    "s_of_fc": "S = 82.6 fc^-0.544 (Frew et al. 1998) with the shot's fc and density",
}

#: fc (Pa) of the targets the paper's Table 1 law is for.
PAPER_FC = 13.5e6


def body_projectile(row: Mapping[str, Any], name: str) -> Projectile:
    """The tangent-ogive rod of a body shot row (``mass_kg``, ``diameter_m``, ``length_m``,
    ``crh``): the outline in steel of :data:`STEEL_DENSITY` with the measured mass given.

    Raises
    ------
    InputError
        A nose longer than the rod (``a sqrt(4 psi - 1) >= length``), or a value the
        geometry refuses (its message).
    """
    d, length, crh = float(row["diameter_m"]), float(row["length_m"]), float(row["crh"])
    nose_length = d / 2 * math.sqrt(4 * crh - 1)
    if not nose_length < length:
        raise InputError(
            f"{name}: a CRH {crh:g} ogive of diameter {d:g} m is {nose_length:.4g} m long, "
            f"not shorter than the rod's length {length:g} m"
        )
    return Projectile(
        name,
        d,
        OgiveNose(crh, STEEL_DENSITY),
        (Cylinder(length - nose_length, STEEL_DENSITY),),
        source=f"measured: {row['mass_kg']:g} kg, d {d:g} m, length {length:g} m, CRH {crh:g}; "
        "outline distribution scaled to the measured mass",
        mass=float(row["mass_kg"]),
    )


def concrete_target(row: Mapping[str, Any], law: str) -> Target | None:
    """The half-space of a body shot row under ``law`` (:data:`LAWS`); None where the law
    does not apply (``paper_s21`` for fc other than 13.5 MPa)."""
    fc, rho = float(row["fc_pa"]), float(row["target_density_kg_m3"])
    if law == "paper_s21":
        return get_target("concrete") if fc == PAPER_FC else None
    if law == "s_of_fc":
        return Target.half_space(concrete_law(fc, rho, name="s_of_fc", size_term="none"))
    raise InputError(f"unknown concrete law {law!r}; use one of {', '.join(LAWS)}")


def body_rows(entry: Mapping[str, Any]) -> pd.DataFrame:
    """The shots of a body shot table, once per law, in the common form of
    :func:`pencore.studies.validation.measurements.load_measurements`, with the built
    ``projectile_body`` and ``target_body`` and a ``target_key`` (law, fc, density) for
    caching; ``dataset`` is the table's ``set``, ``target`` the law.

    ``entry``: ``name``, ``csv``, ``laws`` (default: every law of :data:`LAWS`),
    ``depth_measure``, ``label``.
    """
    laws = entry.get("laws") or list(LAWS)
    bad = [law for law in laws if law not in LAWS]
    if bad:
        raise InputError(f"measurements {entry['name']}: unknown law(s) {bad}; use {list(LAWS)}")
    df = read_body_shot_table(entry["csv"], f"measurements {entry['name']}")
    rows = []
    for _, r in df.iterrows():
        proj_name = f"{r['set']} ({r['mass_kg']:g} kg)"
        proj = body_projectile(r, proj_name)
        for law in laws:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", PlausibilityWarning)
                target = concrete_target(r, law)
            if target is None:
                continue
            notes = "; ".join(str(w.message) for w in caught)
            rows.append(
                {
                    "shot": f"{entry['name']}:{law}:{r['row']}",
                    "dataset": r["set"],
                    "label": entry["label"],
                    "projectile": proj_name,
                    "target": law,
                    "thickness_m": math.inf,
                    "velocity_m_s": float(r["striking_velocity_m_s"]),
                    "obliquity_deg": 0.0,
                    "yaw_deg": 0.0,
                    "pitch_measured_deg": math.nan,
                    "yaw_measured_deg": math.nan,
                    "rigid": True,
                    "remark": "normal impact, no yaw measured; rigid assumed (the "
                    "compilation records no deformation)" + (f"; {notes}" if notes else ""),
                    "quantity": "penetration_depth",
                    "measured": float(r["depth_m"]),
                    "depth_measure": entry["depth_measure"],
                    "source": f"{r['reference']}; compilation row {r['row']}",
                    "projectile_body": proj,
                    "target_body": target,
                    "target_key": (law, float(r["fc_pa"]), float(r["target_density_kg_m3"])),
                }
            )
    return pd.DataFrame(rows)
