"""The named options of the concrete law: Li & Chen's S(fc) and crater depth, Forrestal's
crater by name, their closed-form reductions in normal impact, their resolution with the
projectile when a run is prepared, the YAML and command-line doors, and the refusals."""

from __future__ import annotations

import math

import pytest

import pencore
from pencore import closedform
from pencore.cli.main import main
from pencore.errors import InputError, TargetError
from pencore.inputs import laws
from pencore.inputs.gate import load_yaml_text
from pencore.inputs.library import target_from_dict
from pencore.inputs.record import DEFAULT_RECORD_LAW, RECORD_LAWS


def crh3_rod(d: float = 0.0269) -> pencore.Projectile:
    """A CRH-3 tangent ogive rod: nose length ``(d/2) sqrt(4 psi - 1) = (d/2) sqrt(11)``."""
    return pencore.Projectile(
        "crh3", d, pencore.OgiveNose(3.0, 7850.0), (pencore.Cylinder(8 * d, 7850.0),)
    )


def test_li_chen_s_is_72_over_root_fc_in_mpa():
    assert laws.li_chen_s(36e6) == 12.0  # 72 / 6
    assert laws.li_chen_s(16e6) == 18.0  # 72 / 4
    m = laws.concrete_law(36e6, 2300.0, s_model="li_chen")
    assert m.coefficients == (12.0 * 36e6, 0.0, 2300.0)
    assert "S = 72 fc^-0.5 = 12" in m.source and "secondary" in m.source


def test_the_default_law_is_the_records_best_and_every_option_is_selectable_by_name():
    default = laws.concrete_law(40e6, 2300.0)
    opts = RECORD_LAWS[DEFAULT_RECORD_LAW]
    assert default.record_law == DEFAULT_RECORD_LAW and default.fc == 40e6
    named = laws.concrete_law(40e6, 2300.0, **opts)
    assert named == default
    assert default.coefficients[0] == 82.6 * 40**-0.544 * 40e6  # S(fc) before the size term
    assert default.needs_projectile == (opts["size_term"] == "fit")
    plain = laws.concrete_law(40e6, 2300.0, s_model="forrestal", crater="none", size_term="none")
    assert plain.coefficients == default.coefficients and not plain.needs_projectile
    assert plain.record_law == "forrestal"
    crater = laws.concrete_law(40e6, 2300.0, crater="forrestal", size_term="none")
    assert crater.crater_depth == 2.0 and crater.record_law == "forrestal_crater"
    given = laws.concrete_law(40e6, 2300.0, crater_depth=2.0)  # by number: no size term
    assert crater.coefficients == given.coefficients and given.size_term is None
    assert given.record_law == "" and laws.concrete_law(40e6, 2300.0, s=11.0).record_law == ""
    # a named crater with the fitted size term is a scored law (it was once refused)
    both = laws.concrete_law(40e6, 2300.0, crater="forrestal", size_term="fit")
    assert both.crater_depth == 2.0 and both.record_law == "forrestal_crater_size"


def test_li_chen_crater_depth_of_a_crh3_ogive():
    rod = crh3_rod()
    k = 0.707 + math.sqrt(11.0) / 2.0  # 2.3653: H/d = sqrt(4 psi - 1) / 2 at psi = 3
    assert rod.nose_length / rod.diameter == pytest.approx(math.sqrt(11.0) / 2.0, rel=1e-14)
    m = laws.concrete_law(40e6, 2300.0, crater="li_chen")
    assert m.crater_depth == 0.0 and m.needs_projectile
    r = m.for_projectile(rod.diameter, rod.nose_length)
    assert r.crater_depth == pytest.approx(k, rel=1e-14) and not r.needs_projectile
    assert f"d = {rod.diameter:g} m" in r.source and "crater k = 0.707 + H/d = 2.365" in r.source
    # the closed form resolves the rule with the projectile: Forrestal's form at that k
    for v in (150.0, 400.0, 800.0):  # 150 m/s stops in the crater
        ref = closedform.forrestal_crater_depth(rod, r, v, k)
        assert closedform.depth(rod, m, v) == pytest.approx(ref, rel=1e-14)


def test_li_chen_crater_depth_scales_with_the_nose():
    # a blunter nose (CRH 1) is shorter: k = 0.707 + sqrt(3)/2
    rod = pencore.Projectile("crh1", 0.03, pencore.OgiveNose(1.0, 7850.0))
    m = laws.concrete_law(40e6, 2300.0, crater="li_chen").for_projectile(0.03, rod.nose_length)
    assert m.crater_depth == pytest.approx(0.707 + math.sqrt(3.0) / 2.0, rel=1e-14)


def test_a_run_with_li_chens_options_meets_the_closed_form_and_records_what_it_used():
    rod = crh3_rod()
    m = laws.concrete_law(40e6, 2300.0, s_model="li_chen", crater="li_chen")
    ds = pencore.simulate(rod, m, 400.0)
    # the solver meets the exact 1-D depth within 2e-3 in normal impact
    assert float(ds.penetration_depth) == pytest.approx(closedform.depth(rod, m, 400.0), rel=2e-3)
    recorded = ds.attrs["inputs_json"]
    assert "resolved for d = 0.0269 m" in recorded and '"crater_depth": 2.365' in recorded


def test_kernel_arrays_refuse_an_unresolved_rule():
    t = pencore.Target.half_space(laws.concrete_law(40e6, 2300.0, crater="li_chen"))
    with pytest.raises(TargetError, match="resolve it first"):
        t.kernel_arrays(0.03, 1.0, 0.05, 0.1)


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        (dict(s_model="li"), "s_model must be one of forrestal, li_chen, got 'li'"),
        (dict(crater="deep"), "crater must be one of none, forrestal, li_chen, got 'deep'"),
        (dict(crater=2), "crater must be one of none, forrestal, li_chen, got 2"),
        (dict(s=10.0, s_model="li_chen"), "give s or s_model, not both (s = 10.0)"),
        (dict(crater="li_chen", crater_depth=2.0), "give crater or crater_depth, not both"),
    ],
)
def test_bad_options_are_refused_in_one_line_naming_the_value(kwargs, words):
    with pytest.raises(TargetError) as exc:
        laws.concrete_law(40e6, 2300.0, **kwargs)
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_yaml_round_trip_and_refusal():
    doc = load_yaml_text(
        "law: concrete\nfc: 40.0e6\ndensity: 2300\ns_model: li_chen\ncrater: li_chen\n", "test"
    )
    medium = target_from_dict(doc).medium
    assert medium == laws.concrete_law(40e6, 2300.0, s_model="li_chen", crater="li_chen")
    with pytest.raises(InputError, match="crater must be one of none, forrestal, li_chen"):
        target_from_dict({"law": "concrete", "fc": 40e6, "density": 2300, "crater": "yes"})


def test_cli_law_round_trip_and_refusal(capsys):
    args = ["law", "concrete", "--fc", "40e6", "--density", "2300"]
    assert main([*args, "--s-model", "li_chen", "--crater", "li_chen"]) == 0
    out = capsys.readouterr().out
    assert "S = 72 fc^-0.5 = 11.38" in out and "0.707 + H/d calibers" in out
    mapping = out.split("as a target file, or a layer's medium: ")[1].strip()
    assert target_from_dict(load_yaml_text(mapping, "cli")).medium == laws.concrete_law(
        40e6, 2300.0, s_model="li_chen", crater="li_chen"
    )
    assert main([*args, "--crater", "forrestal"]) == 0
    assert "crater:  2 calibers" in capsys.readouterr().out
    assert main([*args, "--s", "9", "--s-model", "li_chen"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "give s or s_model, not both" in err


def test_the_guide_states_the_options_as_the_code_has_them():
    """docs/user-guide/own-projectile-and-target.md types these numbers."""
    from pathlib import Path

    from pencore.inputs.target import LI_CHEN_CRATER

    root = Path(__file__).resolve().parents[2]
    page = " ".join((root / "docs/user-guide/own-projectile-and-target.md").read_text().split())
    assert laws.li_chen_s(1e6) == 72.0 and "$S = 72 f_c^{-1/2}$" in page
    assert laws.forrestal_s(1e6) == 82.6 and "$S = 82.6 f_c^{-0.544}$" in page
    assert LI_CHEN_CRATER == 0.707 and "$k = 0.707 + H/d$ calibers" in page
    assert (
        laws.FORRESTAL_CRATER == 2.0 and "over 2 calibers (Forrestal et al., IJIE 15, 1994)" in page
    )
    # a CRH-4.25 tangent ogive is exactly 2 calibers long: longer noses do not fit the crater
    nose = pencore.Projectile("n", 0.02, pencore.OgiveNose(4.25, 7850.0)).nose_length
    assert nose / 0.02 == pytest.approx(2.0, rel=1e-14) and "(CRH above 4.25)" in page
