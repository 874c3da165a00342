"""Bodies of Table 3's outline with other mass distributions (pencore.paper.bodies): each has
the stated mass and centre of mass, the inertias its construction gives, and says whether
it could be built."""

from __future__ import annotations

import math

import pytest

import pencore
from pencore.inputs.library import TABLE3
from pencore.paper.bodies import BALLAST_DENSITY, build_body, inertia_range

SAME_MASS_AND_LC = ("hollow_shank", "dense_core", "skin", "axis", "ballast", "end_masses")


def _mp(key, spec):
    return build_body(key, spec).projectile.mass_properties()


@pytest.mark.parametrize("key", ["p2", "p4"])
@pytest.mark.parametrize("kind", SAME_MASS_AND_LC)
def test_redistributions_keep_mass_and_centre_of_mass(key, kind):
    solid = pencore.get_projectile(key).mass_properties()
    mp = _mp(key, {"kind": kind})
    assert mp.mass == pytest.approx(solid.mass, rel=1e-12)
    assert mp.lc == pytest.approx(solid.lc, rel=1e-9)
    # every body's inertias inside what a body of revolution of this outline can have
    assert 0.0 < mp.i_axial <= 2.0 * mp.i_transverse


@pytest.mark.parametrize("key", ["p2", "p4"])
def test_radial_limits_order_and_the_transverse_shift(key):
    """Moving mass outwards at fixed axial distribution raises I_axial, and I_transverse by
    half as much (a ring's diametral inertia is half its polar one): axis < core < solid <
    tube < skin; the skin doubles the solid's axial inertia."""
    solid = pencore.get_projectile(key).mass_properties()
    order = [_mp(key, {"kind": k}) for k in ("axis", "dense_core")]
    order += [solid] + [_mp(key, {"kind": k}) for k in ("hollow_shank", "skin")]
    ia = [m.i_axial for m in order]
    assert ia == sorted(ia)
    for m in order:
        assert m.i_transverse - solid.i_transverse == pytest.approx(
            0.5 * (m.i_axial - solid.i_axial), rel=1e-9, abs=1e-15
        )
    assert order[-1].i_axial == pytest.approx(2.0 * solid.i_axial, rel=1e-12)


def test_hollow_shank_bore_gives_the_table_density():
    """#2's steel tube: its bore leaves steel on 5150/7850 of the section, and its axial
    inertia is the tube's closed form m (a^2 + ri^2) / 2."""
    p = pencore.get_projectile("p2")
    solid = p.mass_properties()
    a, ls = p.radius, p.shank[0].length
    ri = a * math.sqrt(1.0 - 5150.0 / 7850.0)
    m_s = 5150.0 * math.pi * a * a * ls
    mp = _mp("p2", {"kind": "hollow_shank"})
    assert mp.i_axial - solid.i_axial == pytest.approx(0.5 * m_s * ri * ri, rel=1e-9)
    assert "bore 55.7 mm" in build_body("p2", {"kind": "hollow_shank"}).description


@pytest.mark.parametrize("key", ["p2", "p3", "p4"])
def test_axial_limits_bracket_the_solid_body(key):
    solid = pencore.get_projectile(key).mass_properties()
    lo, hi = inertia_range(pencore.get_projectile(key), solid.lc)
    assert lo == pytest.approx(_mp(key, {"kind": "ballast"}).i_transverse, rel=1e-12)
    assert hi == pytest.approx(_mp(key, {"kind": "end_masses"}).i_transverse, rel=1e-12)
    assert lo < solid.i_transverse < hi


@pytest.mark.parametrize("lcl", [0.5245, 0.525, 0.5255, 0.55, 0.60, 0.65])
def test_lc_case_has_the_stated_centre_and_mass(lcl):
    """The two-density shank: #2 has the stated Lc/L and the solid body's mass; #4's Lc/L
    moves by the same amount from its Table 3 value."""
    for key in ("p2", "p4"):
        b = build_body(key, {"kind": "lc", "lc_over_l": lcl})
        mp = b.projectile.mass_properties()
        assert mp.mass == pytest.approx(pencore.get_projectile(key).mass_properties().mass)
        assert mp.lc_over_l == pytest.approx(TABLE3[key][2] + lcl - 0.525, abs=1e-12)
    assert build_body("p2", {"kind": "lc", "lc_over_l": lcl}).buildable


def test_lc_beyond_two_halves_is_a_ballast_slug_and_beyond_any_slug_not_buildable():
    b = build_body("p2", {"kind": "lc", "lc_over_l": 0.70})
    assert b.buildable and "slug" in b.description
    assert b.projectile.mass_properties().lc_over_l == pytest.approx(0.70, abs=1e-12)
    far = build_body("p2", {"kind": "lc", "lc_over_l": 0.80})
    assert not far.buildable
    assert inertia_range(pencore.get_projectile("p2"), 0.80 * far.projectile.length) is None


def test_every_buildable_density_is_at_most_the_ballast():
    b = build_body("p4", {"kind": "lc", "lc_over_l": 0.65})  # #4 rear half 19 681 kg/m^3
    assert max(c.density for c in b.projectile.shank) > BALLAST_DENSITY
    assert not b.buildable


@pytest.mark.parametrize("key", ["p1", "p2", "p3", "p4"])
def test_own_outline_reproduces_its_table3_row_exactly(key):
    _, m, lcl = TABLE3[key]
    mp = _mp(key, {"kind": "outline"})
    assert mp.mass == pytest.approx(m, rel=1e-9)
    assert mp.lc_over_l == pytest.approx(lcl, abs=1e-9)


def test_given_inertia_of_the_solid_body_is_the_solid_body():
    solid = pencore.get_projectile("p2").mass_properties()
    mp = _mp("p2", {"kind": "given", "i_transverse_factor": 1.0})
    assert (mp.mass, mp.lc, mp.i_axial, mp.i_transverse) == (
        solid.mass, solid.lc, solid.i_axial, solid.i_transverse,
    )  # fmt: skip


@pytest.mark.parametrize(
    "key, spec, needle",
    [
        ("p2", {"kind": "hollow"}, "kind must be one of"),
        ("p2", {"kind": "lc"}, "missing lc_over_l"),
        ("p2", {"kind": "lc", "lc_over_l": 1.2}, r"lc_over_l must be in \(0, 1\)"),
        ("p2", {"kind": "lc", "lc_over_l": "x"}, "finite number"),
        ("p2", {"kind": "given", "i_transverse_factor": 0.0}, "must be > 0"),
        ("p2", {"kind": "skin", "depth": 1}, "depth"),
        ("p9", None, "one of p1, p2, p3, p4"),
    ],
)
def test_bad_specs_are_one_line_input_errors(key, spec, needle):
    with pytest.raises(pencore.InputError, match=needle) as e:
        build_body(key, spec)
    assert "\n" not in str(e.value)
