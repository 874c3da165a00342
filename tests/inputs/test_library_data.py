"""The library's data files (src/pencore/inputs/data/media.yaml, projectiles.yaml): every
number a product or a derivation of the parameters beside it, bit for bit, and the
loader's refusals."""

from __future__ import annotations

import math

import pytest
import yaml

from pencore.errors import InputError
from pencore.inputs.geometry import OgiveNose, Projectile
from pencore.inputs.laws import concrete_law, metal_law, soil_law
from pencore.inputs.library import (
    LIBRARY_DATA,
    MEDIA,
    _load_media,
    _validation_projectiles,
    get_projectile,
)


def _raw(name: str) -> dict:
    return yaml.safe_load((LIBRARY_DATA / name).read_text())


def test_media_coefficients_are_their_laws_exactly():
    raw = _raw("media.yaml")
    assert list(raw) == list(MEDIA)
    assert list(raw) == ["soil", "concrete", "aluminium", "aluminium_3term", "aluminium_cavity"]
    # YAML 1.1 reads 10.0e6 (no exponent sign) as text: the loader's plain decimals
    law = {
        k: {p: v if p in ("form", "inertia") else float(v) for p, v in e["law"].items()}
        for k, e in raw.items()
    }
    s, c, al, al3, alc = (law[k] for k in raw)
    assert MEDIA["soil"].coefficients == (s["A"] * s["tau0"], 0.0, s["B"] * s["rho"])
    assert MEDIA["concrete"].coefficients == (c["S"] * c["fc"], 0.0, c["rho"])
    assert MEDIA["aluminium"].coefficients == (al["A"] * al["Y"], 0.0, al["B"] * al["rho"])
    cy = math.sqrt(al3["Y"] / al3["rho"])
    assert MEDIA["aluminium_3term"].coefficients == (
        al3["A"] * al3["Y"],
        al3["B"] * al3["Y"] / cy,
        al3["C"] * al3["rho"],
    )
    for k, v in raw.items():
        assert MEDIA[k].density == v["density"] == law[k]["rho"]
    # the laws from properties give the paper's media
    assert soil_law(s["A"], s["tau0"], s["B"], s["rho"]).coefficients == MEDIA["soil"].coefficients
    assert concrete_law(c["fc"], c["rho"], s=c["S"]).coefficients == MEDIA["concrete"].coefficients
    # the computed aluminium: metal_law's coefficients from the parameters beside them
    computed = metal_law(
        alc["E"], alc["nu"], alc["Y"], alc["n"], alc["rho"], max_speed=alc["max_speed"]
    )
    assert alc["inertia"] == "compressible"
    assert MEDIA["aluminium_cavity"].coefficients == computed.coefficients


@pytest.mark.parametrize("name", ["grout_crh3", "grout_crh4p25"])
def test_grout_rods_by_their_derivation(name):
    # 12.9 mm, 88.9 mm overall: the shank is the length less the tangent ogive's nose,
    # bit for bit; the measured 0.064 kg is given (a solid steel body would weigh 0.08 kg)
    p = get_projectile(name)
    d, crh = p.diameter, p.nose.crh
    assert p.shank[0].length == 0.0889 - d / 2 * math.sqrt(4 * crh - 1)
    assert p.length == pytest.approx(0.0889, rel=1e-12)
    assert p.mass_properties().mass == pytest.approx(0.064, rel=1e-12)
    outline = Projectile("o", d, p.nose, p.shank).mass_properties().mass
    assert 0.078 < outline < 0.082


@pytest.mark.parametrize("name", ["concrete_crh3", "concrete_crh4p25"])
def test_assumed_concrete_rods_weigh_13_kg_by_their_derivation(name):
    p = get_projectile(name)
    d, crh = p.diameter, p.nose.crh
    nose_mass = Projectile("n", d, OgiveNose(crh, 7850.0)).mass_properties().mass
    assert p.shank[0].length == (13.0 - nose_mass) / (7850.0 * math.pi * (d / 2) ** 2)
    assert p.mass_properties().mass == pytest.approx(13.0, rel=1e-12)


def test_every_projectile_entry_is_loaded_with_its_source():
    raw = _raw("projectiles.yaml")
    loaded = _validation_projectiles()
    assert list(loaded) == list(raw)
    for name, p in loaded.items():
        assert p.source == " ".join(raw[name]["source"].split())
        assert p.mass == raw[name].get("mass")


def test_a_bad_data_file_is_refused_naming_the_entry(tmp_path):
    bad = tmp_path / "media.yaml"
    bad.write_text("mud:\n  coefficients: [1.0e6, 0.0, 1000.0]\n  densty: 1500\n")
    with pytest.raises(InputError, match="media library entry 'mud': unknown key 'densty'"):
        _load_media(bad)
    bad.write_text("mud: {coefficients: [], density: 1500}\n")
    with pytest.raises(InputError, match="needs a list 'coefficients'"):
        _load_media(bad)
