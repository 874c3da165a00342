"""Projectiles given by their measured mass, centre of mass and inertias: what the solver
uses (scaled outline, parallel-axis theorem), the refusals, and the YAML and CLI doors."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pencore
from pencore import closedform
from pencore.cli.main import main
from pencore.errors import GeometryError, InputError
from pencore.inputs.geometry import Cylinder, OgiveNose, Projectile
from pencore.inputs.library import get_projectile, get_target, projectile_from_dict

RHO = 7850.0


def _outline(**given) -> Projectile:
    return Projectile(
        "ogive", 0.03, OgiveNose(3.0, RHO), (Cylinder(0.2, RHO), Cylinder(0.05, 2700.0)), **given
    )


def test_mass_only_scales_the_outline_exactly():
    mo = _outline().mass_properties()
    m = 0.8 * mo.mass
    mp = _outline(mass=m).mass_properties()
    f = m / mo.mass
    assert mp.mass == m
    assert mp.lc == mo.lc
    assert mp.length == mo.length
    assert mp.i_axial == f * mo.i_axial
    assert mp.i_transverse == f * mo.i_transverse


def test_centre_of_mass_moves_the_transverse_inertia_by_the_parallel_axis_theorem():
    mo = _outline().mass_properties()
    lc = mo.lc - 0.01
    mp = _outline(mass=1.0, centre_of_mass=lc).mass_properties()
    f = 1.0 / mo.mass
    assert mp.lc == lc
    assert mp.i_axial == f * mo.i_axial
    assert mp.i_transverse == pytest.approx(f * mo.i_transverse + 1.0 * 0.01**2, rel=1e-14)
    # the rings follow the given centre of mass: x1 = Lc - s
    r_given, r_outline = _outline(centre_of_mass=lc).rings(), _outline().rings()
    np.testing.assert_allclose(r_given.x1 - r_outline.x1, lc - mo.lc, rtol=0, atol=1e-15)


def test_given_inertia_is_used_as_given_and_provenance_says_so():
    p = _outline(mass=1.0, centre_of_mass=0.12, inertia=(1e-4, 4e-3))
    mp = p.mass_properties()
    assert (mp.mass, mp.lc, mp.i_axial, mp.i_transverse) == (1.0, 0.12, 1e-4, 4e-3)
    assert p.mass_provenance() == {
        "mass": "given",
        "centre_of_mass": "given",
        "inertia": "given",
    }
    assert _outline().mass_provenance()["mass"].startswith("derived")
    assert _outline().mass_properties() == _outline().outline_mass_properties()


def test_a_body_given_its_own_derived_properties_runs_bit_identically():
    plain = get_projectile("p2")
    mp = plain.mass_properties()
    given = plain.with_mass(mp.mass, mp.lc, (mp.i_axial, mp.i_transverse))
    assert given.mass_properties() == mp
    kw = dict(obliquity=20.0, yaw=3.0, omega=5.0)
    a = pencore.simulate(plain, "concrete", 300.0, **kw)
    b = pencore.simulate(given, "concrete", 300.0, **kw)
    for name in ("tip_x", "tip_y", "axis_x", "omega_3"):
        np.testing.assert_array_equal(a[name].values, b[name].values)
    assert b.attrs["mass_source"] == "given" and a.attrs["mass_source"].startswith("derived")
    assert b.attrs["i_transverse_kg_m2"] == mp.i_transverse


@pytest.mark.parametrize("mass", [15.0, 30.0])
def test_depth_with_a_given_mass_matches_the_closed_form_with_that_mass(mass):
    """Normal, zero-yaw, frictionless: the exact 1-D DAFL solution scales with the mass
    given, and the solver uses that mass (as the outline-only test of test_impact)."""
    p = get_projectile("p2").with_mass(mass=mass)
    soil = get_target("soil").medium
    ds = pencore.simulate(p, soil, 280.0)
    ref = closedform.depth(p, soil, 280.0)
    assert float(ds.penetration_depth) == pytest.approx(ref, rel=2e-3)
    assert ds.attrs["mass_kg"] == mass
    # and the depth is not the outline's: 23.16 kg would go deeper/shallower by far more
    assert abs(ref / closedform.depth(get_projectile("p2"), soil, 280.0) - 1) > 0.2


@pytest.mark.parametrize(
    ("given", "words"),
    [
        ({"mass": -1.0}, "mass must be in (0, 100000] kg, got -1.0"),
        ({"mass": True}, "mass must be a number of kg"),
        ({"mass": 100.0}, "mass must be at most"),
        ({"centre_of_mass": 0.3}, "centre of mass (tip distance Lc) must be inside the body"),
        ({"inertia": (1e-4,)}, "inertia must be a pair"),
        ({"inertia": "big"}, "inertia must be a pair"),
        ({"inertia": (0.0, 1e-3)}, "axial moment of inertia must be in (0, 1e+06] kg m^2"),
        ({"inertia": (1e-2, 1e-1)}, "axial moment of inertia must be at most m a^2"),
        ({"inertia": (1e-4, 4e-5)}, "at most twice the transverse one"),
        ({"inertia": (1e-4, 1.0)}, "transverse moment of inertia must be at most"),
    ],
)
def test_impossible_mass_properties_are_refused_naming_the_value(given, words):
    with pytest.raises(GeometryError) as exc:
        _outline(**given)
    assert words in str(exc.value)
    assert "\n" not in str(exc.value)


def test_inertia_bounds_hold_for_the_derived_values_of_every_library_projectile():
    for name in pencore.projectile_names():
        p = get_projectile(name)
        mp = p.mass_properties()
        a = p.radius
        arm = max(mp.lc, mp.length - mp.lc)
        assert 0 < mp.i_axial <= mp.mass * a * a
        assert mp.i_axial <= 2 * mp.i_transverse
        assert mp.i_transverse <= mp.i_axial / 2 + mp.mass * arm**2


YAML_BODY = {
    "name": "fuzed",
    "diameter": 0.02,
    "nose": {"kind": "ogive", "crh": 3.0, "density": 7850.0},
    "shank": [{"length": 0.08, "density": 7850.0}],
}


def test_yaml_mass_keys_round_trip():
    d = dict(
        YAML_BODY, mass="0.25", centre_of_mass=0.05, inertia={"axial": 1e-5, "transverse": 2e-4}
    )
    p = projectile_from_dict(d)
    assert (p.mass, p.centre_of_mass, p.inertia) == (0.25, 0.05, (1e-5, 2e-4))
    q = projectile_from_dict(dict(YAML_BODY, mass=0.25))
    assert q == Projectile(
        "fuzed", 0.02, OgiveNose(3.0, 7850.0), (Cylinder(0.08, 7850.0),), "user file", mass=0.25
    )


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        ({"mass": "heavy"}, "mass must be a number of kg"),
        ({"inertia": [1e-5, 2e-4]}, "'inertia' must be a mapping"),
        ({"inertia": {"axial": 1e-5}}, "missing key 'transverse'"),
        ({"inertia": {"axial": 1e-5, "transvers": 1}}, "did you mean 'transverse'"),
        ({"centre_of_mass": 1.0}, "must be inside the body"),
    ],
)
def test_yaml_refusals(extra, words):
    with pytest.raises(InputError, match=None) as exc:
        projectile_from_dict(dict(YAML_BODY, **extra))
    assert words in str(exc.value)


def test_cli_mass_override_of_a_named_projectile(capsys, tmp_path):
    out = tmp_path / "m.nc"
    args = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "280"]
    assert main([*args, "--mass", "20", "--out", str(out)]) == 0
    assert "p2 (20 kg," in capsys.readouterr().out
    import xarray as xr

    with xr.open_dataset(out) as ds:
        assert ds.attrs["mass_kg"] == 20.0
        assert ds.attrs["mass_source"] == "given"
        assert ds.attrs["inertia_source"].startswith("derived: outline distribution scaled")
        ref = closedform.depth(get_projectile("p2").with_mass(20.0), get_target("soil").medium, 280)
        assert float(ds.penetration_depth) == pytest.approx(ref, rel=2e-3)


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        (["--mass", "-3"], "mass must be in (0, 100000] kg"),
        (["--centre-of-mass", "2"], "must be inside the body, in (0, 0.661028) m, got 2.0"),
        (["--inertia", "1", "0.1"], "axial moment of inertia must be at most m a^2"),
    ],
)
def test_cli_refusals_exit_2_with_one_line(extra, words, capsys):
    args = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "280"]
    assert main([*args, *extra]) == 2
    err = capsys.readouterr().err
    assert words in err
    assert err.count("\n") == 1


def test_validation_rods_use_the_mean_measured_mass_of_their_shot_tables():
    import csv
    from pathlib import Path

    root = Path(__file__).resolve().parents[2] / "config"
    masses: dict[str, list[float]] = {}
    for name in ("aluminium_ogive_shots.csv", "aluminium_sphere_shots.csv"):
        with open(root / name) as fh:
            rows = csv.DictReader(line for line in fh if not line.startswith("#"))
            for r in rows:
                masses.setdefault(r["projectile"], []).append(float(r["mass_kg"]))
    assert {k: len(v) for k, v in masses.items()} == {
        "al_ogive_var4340": 20,
        "al_ogive_aermet100": 14,
        "al_sphere_var4340": 31,
    }
    for name, ms in masses.items():
        p = get_projectile(name)
        # the library holds the mean to 7 significant digits (0.05 mg)
        assert p.mass == pytest.approx(math.fsum(ms) / len(ms), abs=5e-8)
        assert p.mass_provenance()["mass"] == "given"
