"""Mass distributions the paper leaves open: bodies of Table 3's outline that could be built.

Table 3 gives each projectile's mass, shank density and ``Lc/L``; Fig. 6 (the dimensions)
is not in the text, and an FE rigid body's inertia is an input apart from its outline.
pencore's default bodies are the fitted solid ones (:func:`pencore.inputs.library.table3_fit`):
a solid steel CRH-3 ogive plus a solid cylinder of the table's shank density.
:func:`build_body` gives, for one of the paper's projectiles, a body with another mass
distribution inside the same outline, with a sentence saying how it would be built and
whether it can be (the densest material allowed: :data:`BALLAST_DENSITY`).

Kinds (``spec["kind"]``):

``solid``
    the default fitted body, unchanged;
``lc``
    the centre of mass moved along the axis: the shank made of a front and a rear half of
    two densities with the same total (mass unchanged), solved for ``Lc/L`` = ``lc_over_l``
    of #2; the other projectiles move by the same amount from their Table 3 ``Lc/L``.
    Within Table 3's rounding (0.525 +/- 0.0005 for #2) and beyond it;
``hollow_shank``
    the shank a tube of steel (of the ballast alloy when the table's shank density exceeds
    steel's) whose bore gives the table's mean density: mass, ``Lc`` unchanged, the mass
    moved outwards;
``dense_core``
    the shank an aluminium sleeve around a ballast-alloy core of the table's mean density:
    the mass moved inwards;
``skin`` / ``axis``
    the radial limits (not buildable): every station's mass on the skin (``I_axial`` twice
    the solid's, ``I_transverse`` + ``I_axial / 2``), or on the axis (``I_axial`` ->
    :data:`AXIS_FRACTION` of the solid's, ``I_transverse`` - ``I_axial / 2``);
``ballast``
    the axial limit of least transverse inertia: the nose solid steel, the shank a thin
    steel tube (wall :data:`TUBE_WALL`) carrying one ballast slug placed to keep ``Lc``;
``end_masses``
    the axial limit of largest transverse inertia: the same tube with two slugs, one behind
    the nose and one at the tail, sized to keep ``Lc``;
``outline``
    the outline fitted to this projectile's two numbers alone (diameter and shank length
    solving its mass and ``Lc/L`` exactly), instead of the joint fit to all four;
``given``
    ``lc_over_l`` of #2 (the others moved by the same amount) and the transverse inertia
    ``i_transverse_factor`` times the solid body's (``lc_over_l`` omitted: the solid
    body's ``Lc``): the mass properties of the inverse step
    (:mod:`pencore.studies.attribution.inverse`), judged buildable when ``Lc`` is within
    the ``ballast`` body's reach and the inertia between the ``ballast`` and
    ``end_masses`` bodies at that ``Lc``.

Sources: steel 7850 kg/m^3 (paper, Table 3's nose); ballast: tungsten heavy alloy, ASTM
B777 class 4 (97 % W), 18.25-18.85 g/cm^3, the lower end; aluminium 2700 kg/m^3.

Examples
--------
>>> from pencore.paper.bodies import build_body
>>> b = build_body("p2", {"kind": "lc", "lc_over_l": 0.5255})
>>> mp = b.projectile.mass_properties()
>>> print(f"{mp.mass:.2f} kg, Lc/L {mp.lc_over_l:.4f}, buildable {b.buildable}")
23.16 kg, Lc/L 0.5255, buildable True
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from pencore.errors import InputError
from pencore.inputs.geometry import Cylinder, OgiveNose, Projectile
from pencore.inputs.library import TABLE3, TABLE3_CRH, TABLE3_NOSE_DENSITY, get_projectile
from pencore.inputs.limits import check_keys

__all__ = [
    "BODY_KINDS",
    "BALLAST_DENSITY",
    "Body",
    "build_body",
    "check_body",
    "inertia_range",
]

#: Steel (kg/m^3): Table 3's nose density.
STEEL = 7850.0
#: Aluminium (kg/m^3).
ALUMINIUM = 2700.0
#: The densest material a body may be built of (kg/m^3): tungsten heavy alloy, ASTM B777
#: class 4, lower end of 18.25-18.85 g/cm^3.
BALLAST_DENSITY = 18250.0
#: Wall (m) of the steel tube that carries the ballast slugs.
TUBE_WALL = 0.002
#: The ``axis`` limit's axial inertia as a fraction of the solid body's (0 is not a body).
AXIS_FRACTION = 1e-3
#: The kinds of body :func:`build_body` builds.
BODY_KINDS = (
    "solid",
    "lc",
    "hollow_shank",
    "dense_core",
    "skin",
    "axis",
    "ballast",
    "end_masses",
    "outline",
    "given",
)
_KEYS = {
    "solid": (),
    "lc": ("lc_over_l",),
    "hollow_shank": (),
    "dense_core": (),
    "skin": (),
    "axis": (),
    "ballast": (),
    "end_masses": (),
    "outline": (),
    "given": ("lc_over_l", "i_transverse_factor"),
}
#: Keys a kind may omit.
_OPTIONAL = {"given": ("lc_over_l",)}


@dataclass(frozen=True)
class Body:
    """A projectile with a mass distribution, how it would be built, whether it can be."""

    projectile: Projectile
    description: str
    buildable: bool


@dataclass(frozen=True)
class _Part:
    """One piece of a body: mass (kg), centre (m from the tip), own inertias (kg m^2)."""

    m: float
    s: float
    i_ax: float
    i_tr: float


def _combine(parts: list[_Part]) -> tuple[float, float, float, float]:
    """Mass, centre, axial and transverse inertia (about the centre) of the parts."""
    m = sum(p.m for p in parts)
    s = sum(p.m * p.s for p in parts) / m
    i_ax = sum(p.i_ax for p in parts)
    i_tr = sum(p.i_tr + p.m * (p.s - s) ** 2 for p in parts)
    return m, s, i_ax, i_tr


def _cyl(rho: float, r_out: float, r_in: float, s0: float, length: float) -> _Part:
    """A tube (``r_in`` = 0: a solid cylinder) of density ``rho`` from ``s0``."""
    m = rho * math.pi * (r_out**2 - r_in**2) * length
    r2 = r_out**2 + r_in**2
    return _Part(m, s0 + 0.5 * length, 0.5 * m * r2, m * (r2 / 4.0 + length**2 / 12.0))


def check_body(spec: Mapping[str, Any] | None) -> dict[str, Any]:
    """A body spec checked: ``kind`` in :data:`~pencore.paper.bodies.BODY_KINDS` and its
    keys (one-line :class:`~pencore.InputError` naming the bad one). ``None``: the solid body."""
    if spec is None:
        return {"kind": "solid"}
    if not isinstance(spec, Mapping):
        raise InputError(f"attribution body must be a mapping with a kind, got {spec!r}")
    kind = spec.get("kind")
    if kind not in BODY_KINDS:
        raise InputError(
            f"attribution body kind must be one of {', '.join(BODY_KINDS)}, got {kind!r}"
        )
    check_keys(spec, ("kind", *_KEYS[kind]), f"attribution body {kind}")
    out: dict[str, Any] = {"kind": kind}
    for k in _KEYS[kind]:
        if k not in spec:
            if k in _OPTIONAL.get(kind, ()):
                continue
            raise InputError(f"attribution body {kind}: missing {k}")
        v = spec[k]
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            raise InputError(f"attribution body {kind}: {k} must be a finite number, got {v!r}")
        out[k] = float(v)
    if "lc_over_l" in out and not 0.0 < out["lc_over_l"] < 1.0:
        raise InputError(
            f"attribution body {kind}: lc_over_l must be in (0, 1), got {out['lc_over_l']!r}"
        )
    if "i_transverse_factor" in out and not out["i_transverse_factor"] > 0.0:
        raise InputError(
            f"attribution body {kind}: i_transverse_factor must be > 0, "
            f"got {out['i_transverse_factor']!r}"
        )
    return out


def _layout(p: Projectile) -> tuple[_Part, float, float, float, float]:
    """The solid steel nose as a part, and the shank's start, length, radius, density."""
    nose = Projectile("nose", p.diameter, p.nose).outline_mass_properties()
    if len(p.shank) != 1:
        raise InputError(f"attribution body: {p.name} must have one shank segment")
    cyl = p.shank[0]
    part = _Part(nose.mass, nose.lc, nose.i_axial, nose.i_transverse)
    return part, p.nose_length, cyl.length, p.radius, cyl.density


def _target_lc_over_l(key: str, lc_over_l_p2: float) -> float:
    """#2's ``Lc/L`` moved to ``lc_over_l_p2``; the others by the same amount."""
    return TABLE3[key][2] + (lc_over_l_p2 - TABLE3["p2"][2])


def _slugs(p: Projectile, lc: float, two: bool) -> tuple[list[_Part], str] | None:
    """Nose + tube + one slug placed to keep ``lc`` (``two``: slugs at both shank ends);
    ``None`` when the slugs cannot reach ``lc`` inside the shank."""
    nose, s0, ls, a, rho = _layout(p)
    m = p.outline_mass_properties().mass
    tube = _cyl(STEEL, a, a - TUBE_WALL, s0, ls)
    mb = m - nose.m - tube.m
    rb = a - TUBE_WALL
    area = math.pi * rb * rb
    moment = m * lc - nose.m * nose.s - tube.m * tube.s
    if mb <= 0.0:
        return None
    if not two:
        h = mb / (BALLAST_DENSITY * area)
        c = moment / mb
        if not (s0 + 0.5 * h <= c <= s0 + ls - 0.5 * h):
            return None
        slug = _cyl(BALLAST_DENSITY, rb, 0.0, c - 0.5 * h, h)
        text = (
            f"solid steel nose; shank a steel tube (wall {TUBE_WALL * 1e3:g} mm) holding one "
            f"{h * 1e3:.0f} mm tungsten-alloy slug ({mb:.2f} kg) centred {c * 1e3:.0f} mm "
            "from the tip"
        )
        return [nose, tube, slug], text

    def moment_of(mf: float) -> tuple[float, _Part, _Part]:
        hf, hr = mf / (BALLAST_DENSITY * area), (mb - mf) / (BALLAST_DENSITY * area)
        f = _cyl(BALLAST_DENSITY, rb, 0.0, s0, hf)
        r = _cyl(BALLAST_DENSITY, rb, 0.0, s0 + ls - hr, hr)
        return f.m * f.s + r.m * r.s, f, r

    lo, hi = 0.0, mb  # more front mass: smaller moment
    if not (moment_of(hi)[0] <= moment <= moment_of(lo)[0]):
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if moment_of(mid)[0] > moment:
            lo = mid
        else:
            hi = mid
    _, f, r = moment_of(0.5 * (lo + hi))
    if f.s + 0.5 * (f.m / (BALLAST_DENSITY * area)) > r.s - 0.5 * (r.m / (BALLAST_DENSITY * area)):
        return None
    text = (
        f"solid steel nose; shank a steel tube (wall {TUBE_WALL * 1e3:g} mm) with tungsten-"
        f"alloy slugs of {f.m:.2f} kg behind the nose and {r.m:.2f} kg at the tail"
    )
    return [nose, tube, f, r], text


def inertia_range(p: Projectile, lc: float) -> tuple[float, float] | None:
    """Least and largest transverse inertia (kg m^2) of a body of ``p``'s outline, mass
    and steel nose with its centre of mass at ``lc`` (m): the ``ballast`` and
    ``end_masses`` constructions; ``None`` when no slug can put the centre there."""
    one, two = _slugs(p, lc, False), _slugs(p, lc, True)
    if one is None:
        return None
    lo = _combine(one[0])[3]
    hi = _combine(two[0])[3] if two is not None else lo
    return lo, hi


def _given(p: Projectile, parts: list[_Part], text: str, buildable: bool) -> Body:
    _, lc, i_ax, i_tr = _combine(parts)
    q = p.with_mass(mass=p.outline_mass_properties().mass, centre_of_mass=lc, inertia=(i_ax, i_tr))
    return Body(q, text, buildable)


def build_body(key: str, spec: Mapping[str, Any] | None = None) -> Body:
    """The projectile ``key`` (``"p1"``..``"p4"``) with the mass distribution ``spec``.

    Parameters
    ----------
    key : str
        One of the paper's projectiles (Table 3).
    spec : mapping, optional
        ``{"kind": ..., ...}`` (module docstring); ``None``: the solid body.

    Returns
    -------
    Body
        The projectile (mass, ``Lc`` and inertias as given or as its segments give), a
        sentence saying how it would be built, and whether it can be.

    Raises
    ------
    InputError
        An unknown kind or key, a value out of range, a projectile not in Table 3.
    """
    if key not in TABLE3:
        raise InputError(
            f"attribution body: projectile must be one of {', '.join(TABLE3)}, got {key!r}"
        )
    s = check_body(spec)
    p = get_projectile(key)
    mp = p.outline_mass_properties()
    nose, s0, ls, a, rho = _layout(p)
    kind = s["kind"]
    if kind == "solid":
        return Body(p, f"solid steel nose, solid shank of {rho:g} kg/m^3 (the fitted body)", True)
    if kind == "lc":
        target = _target_lc_over_l(key, s["lc_over_l"]) * p.length
        m_s = mp.mass - nose.m
        d = 8.0 * (mp.mass * target - nose.m * nose.s - m_s * (s0 + 0.5 * ls))
        d /= math.pi * a * a * ls * ls
        rf, rr = rho - 0.5 * d, rho + 0.5 * d
        if rf > 0.0 and rr > 0.0:
            halves = (Cylinder(0.5 * ls, rf), Cylinder(0.5 * ls, rr))
            q = Projectile(p.name, p.diameter, p.nose, halves, source=p.source)
            ok = max(rf, rr) <= BALLAST_DENSITY
            text = f"solid steel nose; shank front half {rf:.0f}, rear half {rr:.0f} kg/m^3"
            return Body(q, text if ok else text + " (denser than any alloy)", ok)
        built = _slugs(p, target, False)
        if built is None:
            q = p.with_mass(mass=mp.mass, centre_of_mass=target)
            text = "the solid body's inertia moved to this Lc (no slug in the shank reaches it)"
            return Body(q, text, False)
        return _given(p, built[0], built[1], True)
    if kind in ("hollow_shank", "dense_core"):
        m_s = mp.mass - nose.m
        if kind == "hollow_shank":
            wall = STEEL if rho <= STEEL else BALLAST_DENSITY
            ri = a * math.sqrt(1.0 - rho / wall)
            shank = _Part(m_s, s0 + 0.5 * ls, 0.5 * m_s * (a * a + ri * ri), 0.0)
            text = (
                f"solid steel nose; shank a {'steel' if wall == STEEL else 'tungsten-alloy'} "
                f"tube, bore {2e3 * ri:.1f} mm (mean {rho:g} kg/m^3)"
            )
        else:
            if not ALUMINIUM < rho < BALLAST_DENSITY:
                raise InputError(
                    f"attribution body dense_core: {key}'s shank density {rho:g} kg/m^3 "
                    f"is not between aluminium's and the ballast's"
                )
            rc2 = a * a * (rho - ALUMINIUM) / (BALLAST_DENSITY - ALUMINIUM)
            i_ax = (
                0.5 * math.pi * ls * (BALLAST_DENSITY * rc2 * rc2 + ALUMINIUM * (a**4 - rc2 * rc2))
            )
            shank = _Part(m_s, s0 + 0.5 * ls, i_ax, 0.0)
            text = (
                f"solid steel nose; shank a tungsten-alloy core of {2e3 * math.sqrt(rc2):.1f} mm "
                f"in an aluminium sleeve (mean {rho:g} kg/m^3)"
            )
        d_ax = shank.i_ax - 0.5 * m_s * a * a
        q = p.with_mass(
            mass=mp.mass,
            centre_of_mass=mp.lc,
            inertia=(mp.i_axial + d_ax, mp.i_transverse + 0.5 * d_ax),
        )
        return Body(q, text, True)
    if kind == "skin":
        q = p.with_mass(
            mass=mp.mass,
            centre_of_mass=mp.lc,
            inertia=(2.0 * mp.i_axial, mp.i_transverse + 0.5 * mp.i_axial),
        )
        return Body(q, "limit: every station's mass on the skin (not buildable)", False)
    if kind == "axis":
        ia = AXIS_FRACTION * mp.i_axial
        q = p.with_mass(
            mass=mp.mass,
            centre_of_mass=mp.lc,
            inertia=(ia, mp.i_transverse - 0.5 * (mp.i_axial - ia)),
        )
        return Body(q, "limit: every station's mass on the axis (not buildable)", False)
    if kind in ("ballast", "end_masses"):
        built = _slugs(p, mp.lc, kind == "end_masses")
        if built is None:
            raise InputError(f"attribution body {kind}: no slug keeps {key}'s centre of mass")
        return _given(p, built[0], built[1], True)
    if kind == "outline":
        return _outline(key)
    # given: the inverse step's mass properties
    lc = _target_lc_over_l(key, s["lc_over_l"]) * p.length if "lc_over_l" in s else mp.lc
    i_tr = s["i_transverse_factor"] * mp.i_transverse
    rng = inertia_range(p, lc)
    ok = rng is not None and rng[0] <= i_tr <= rng[1]
    reach = (
        "no tungsten-alloy slug in the shank reaches this Lc"
        if rng is None
        else f"buildable I_t at this Lc: {rng[0]:.3f}-{rng[1]:.3f} kg m^2"
    )
    q = p.with_mass(mass=mp.mass, centre_of_mass=lc, inertia=(mp.i_axial, i_tr))
    text = f"given: Lc/L {lc / p.length:.4f}, I_t {i_tr:.3f} kg m^2 ({reach})"
    return Body(q, text, ok)


def _outline(key: str) -> Body:
    """The outline fitted to ``key``'s mass and ``Lc/L`` alone (Newton on d, shank length)."""
    rho, m_t, lcl_t = TABLE3[key]
    p = get_projectile(key)
    x = [p.diameter, p.shank[0].length]

    def build(d: float, ls: float) -> Projectile:
        nose = OgiveNose(crh=TABLE3_CRH, density=TABLE3_NOSE_DENSITY)
        return Projectile(key, d, nose, (Cylinder(ls, rho),), source=p.source)

    def res(d: float, ls: float) -> tuple[float, float]:
        mp = build(d, ls).outline_mass_properties()
        return mp.mass - m_t, mp.lc_over_l - lcl_t

    for _ in range(30):
        r0 = res(*x)
        h = 1e-7
        j = [[(a - b) / h for a, b in zip(res(x[0] + h, x[1]), r0, strict=True)],
             [(a - b) / h for a, b in zip(res(x[0], x[1] + h), r0, strict=True)]]  # fmt: skip
        det = j[0][0] * j[1][1] - j[1][0] * j[0][1]
        dx0 = (-r0[0] * j[1][1] + r0[1] * j[1][0]) / det
        dx1 = (-r0[1] * j[0][0] + r0[0] * j[0][1]) / det
        x = [x[0] + dx0, x[1] + dx1]
        if abs(dx0) + abs(dx1) < 1e-13:
            break
    q = build(*x)
    text = (
        f"solid body of #{key[1:]}'s own outline: d {x[0] * 1e3:.2f} mm, shank "
        f"{x[1] * 1e3:.1f} mm (its mass and Lc/L exactly; the joint fit: "
        f"d {p.diameter * 1e3:.2f} mm, shank {p.shank[0].length * 1e3:.1f} mm)"
    )
    return Body(q, text, True)
