"""The concrete law's size term: its reduction to 1 at the reference diameter, its closed
form in normal impact, its resolution with the projectile in a run, the doors and the
refusals, its rows (the scaled series as compiled), and the fit function reproducing the
stored constants."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import pytest

import pencore
from pencore import closedform
from pencore.cli.main import main
from pencore.errors import InputError, TargetError
from pencore.inputs import laws
from pencore.inputs.gate import load_yaml_text
from pencore.inputs.library import target_from_dict
from pencore.inputs.target import SizeTerm
from pencore.measured.shots import read_body_shot_table
from pencore.studies.validation import size_term

ROOT = Path(__file__).resolve().parents[3]
SPEC = laws.size_term_constants()


def test_the_factor_is_one_at_the_reference_diameter_and_falls_with_size():
    t = SizeTerm(d_ref=0.025, d0=0.0173)
    assert t.factor(0.025) == 1.0
    assert t.factor(0.1) == math.sqrt((1 + 0.025 / 0.0173) / (1 + 0.1 / 0.0173))
    sizes = [0.005, 0.0129, 0.025, 0.0762, 0.2, 1.0]
    f = [t.factor(d) for d in sizes]
    assert all(a > b for a, b in zip(f, f[1:], strict=False))
    # well above d0 the law falls as d^-1/2 (Bazant's asymptote)
    assert t.factor(100.0) / t.factor(400.0) == pytest.approx(2.0, rel=1e-3)
    with pytest.raises(TargetError, match="d0 must be a positive number of m, got -1"):
        SizeTerm(d_ref=0.025, d0=-1)


@pytest.mark.parametrize(("s_model", "crater"), [("forrestal", "none"), ("li_chen", "li_chen")])
def test_the_fitted_law_reduces_to_the_plain_law_at_d_ref(s_model, crater):
    plain = laws.concrete_law(40e6, 2400.0, s_model=s_model, crater=crater, size_term="none")
    sized = laws.concrete_law(40e6, 2400.0, s_model=s_model, crater=crater, size_term="fit")
    assert sized.coefficients == plain.coefficients and sized.needs_projectile
    d_ref, nose = SPEC["d_ref_m"], 0.04
    at_ref = sized.for_projectile(d_ref, nose)
    assert at_ref.coefficients == plain.for_projectile(d_ref, nose).coefficients
    d0 = SPEC["constants"][f"{s_model}/{crater}"]["d0_m"]
    big = sized.for_projectile(0.2, nose)
    f = math.sqrt((1 + d_ref / d0) / (1 + 0.2 / d0))
    assert big.coefficients[0] == pytest.approx(plain.coefficients[0] * f, rel=1e-15)
    assert big.coefficients[2] == plain.coefficients[2]
    assert f"S = {plain.coefficients[0] / 40e6 * f:.4g}" in big.source


def test_closed_form_and_run_use_the_resolved_law():
    rod = pencore.Projectile(
        "rod", 0.1, pencore.OgiveNose(2.0, 7850.0), (pencore.Cylinder(0.65, 7850.0),)
    )
    sized = laws.concrete_law(40e6, 2400.0, size_term="fit")
    plain = laws.concrete_law(40e6, 2400.0, size_term="none")
    f = sized.size_term.factor(0.1)
    by_hand = replace(plain, coefficients=(plain.coefficients[0] * f, 0.0, 2400.0))
    ref = closedform.depth(rod, by_hand, 450.0)
    assert closedform.depth(rod, sized, 450.0) == ref
    assert ref > closedform.depth(rod, plain, 450.0)  # a 100 mm rod meets less resistance
    ds = pencore.simulate(rod, sized, 450.0)
    assert float(ds.penetration_depth) == pytest.approx(ref, rel=2e-3)
    assert ds.attrs["law_resolved"].startswith("resolved for concrete: d = 0.1 m")
    assert f"S = {plain.coefficients[0] / 40e6 * f:.4g}" in ds.attrs["law_resolved"]
    medium = json.loads(ds.attrs["inputs_json"])["target"]["layers"][0]["medium"]
    assert medium["coefficients"][0] == pytest.approx(plain.coefficients[0] * f, rel=1e-15)
    assert "law_resolved" not in pencore.simulate(rod, plain, 450.0).attrs


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        (dict(size_term="yes"), "size_term must be one of none, fit, got 'yes'"),
        (dict(size_term="fit", s=10.0), "not with a given s (s = 10.0)"),
        (dict(size_term="fit", crater_depth=2.0), "not with a given crater_depth"),
    ],
)
def test_bad_size_options_are_refused_in_one_line(kwargs, words):
    with pytest.raises(TargetError) as exc:
        laws.concrete_law(40e6, 2400.0, **kwargs)
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_yaml_and_cli_round_trips(capsys):
    doc = load_yaml_text("law: concrete\nfc: 40.0e6\ndensity: 2400\nsize_term: fit\n", "test")
    assert target_from_dict(doc).medium == laws.concrete_law(40e6, 2400.0, size_term="fit")
    with pytest.raises(InputError, match="size_term must be one of none, fit, got 1"):
        target_from_dict({"law": "concrete", "fc": 40e6, "density": 2400, "size_term": 1})
    args = ["law", "concrete", "--fc", "40e6", "--density", "2400", "--size-term", "fit"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "a0 above is at d_ref = 0.025 m" in out
    mapping = out.split("as a target file, or a layer's medium: ")[1].strip()
    assert target_from_dict(load_yaml_text(mapping, "cli")).medium == laws.concrete_law(
        40e6, 2400.0, size_term="fit"
    )


def test_the_scaled_series_is_as_its_header_says():
    wu = read_body_shot_table(ROOT / "config/concrete_scaled_series.csv")
    assert sorted(wu["row"].astype(int)) == list(range(693, 700))
    assert set(wu["crh"]) == {2.0} and set(wu["striking_velocity_m_s"]) == {450.0}
    assert set(wu["fc_pa"]) == {40e6}
    scaled = wu["mass_kg"] / wu["diameter_m"] ** 3
    assert scaled.max() / scaled.min() - 1 < 0.002  # "mass / d^3 within 0.2 %"
    xd = (wu["depth_m"] / wu["diameter_m"]).round(2)
    assert (xd.min(), xd.max()) == (7.7, 12.1)
    assert (wu["depth_m"] / wu["target_thickness_m"]).max() < 0.62


def test_the_fit_rows_are_the_named_ones():
    rows = size_term.fit_rows(ROOT)
    assert len(rows) == len(SPEC["rows"]) == 111
    assert not {"165", "166", "167"} & set(rows["row"])  # Gran & Frew 1997 left out
    assert rows["set"].str.startswith("wu2020").sum() == 7


@pytest.mark.parametrize("key", sorted(SPEC["constants"]))
def test_the_fit_function_reproduces_the_stored_constants(key):
    s_model, crater = key.split("/")
    fit = size_term.fit_size_term(
        size_term.fit_rows(ROOT), s_model, crater, SPEC["d_ref_m"], SPEC["exponent"]
    )
    stored = SPEC["constants"][key]
    # Brent's method at 1e-10 and least squares at 1e-12 fix d0 far below the 10
    # significant digits stored
    assert fit.d0 == pytest.approx(stored["d0_m"], rel=1e-8)
    assert fit.rows_used == stored["rows_used"]
    assert list(fit.rows_skipped) == stored["rows_skipped"]
    assert round(fit.rms_log_factor, 4) == stored["rms_log_factor"]
    assert round(fit.rms_log_factor_without, 4) == stored["rms_log_factor_without"]
    assert fit.rms_log_factor < fit.rms_log_factor_without


def test_a_named_crater_goes_with_the_fit():
    m = laws.concrete_law(40e6, 2400.0, crater="forrestal", size_term="fit")
    assert m.crater_depth == 2.0
    assert m.size_term.d0 == SPEC["constants"]["forrestal/forrestal"]["d0_m"]


def test_the_guide_states_what_the_fit_does_on_its_rows():
    """docs/user-guide/own-projectile-and-target.md types these numbers."""
    import numpy as np

    from pencore.studies.validation.bodies import body_projectile

    page = (ROOT / "docs/user-guide/own-projectile-and-target.md").read_text()
    page = " ".join(page.split())
    rows = size_term.fit_rows(ROOT)
    stats: dict[str, list[float]] = {"small_fit": [], "small": [], "big_fit": [], "big": []}
    for key in SPEC["constants"]:
        s_model, crater = key.split("/")
        err: dict[str, list[float]] = {k: [] for k in stats}
        for _, r in rows.iterrows():
            p = body_projectile(r, "rod")
            try:
                e = {
                    st: closedform.depth(
                        p,
                        laws.concrete_law(
                            r["fc_pa"], r["target_density_kg_m3"], s_model=s_model,
                            crater=crater, size_term=st,
                        ),
                        r["striking_velocity_m_s"],
                    ) / r["depth_m"] - 1.0
                    for st in ("fit", "none")
                }  # fmt: skip
            except InputError:  # a crater shorter than the nose
                continue
            if r["diameter_m"] == 0.0129:
                err["small_fit"].append(e["fit"])
                err["small"].append(e["none"])
            if r["diameter_m"] >= 0.0762:
                err["big_fit"].append(abs(e["fit"]))
                err["big"].append(abs(e["none"]))
        for k in stats:
            stats[k].append(round(100 * abs(float(np.median(err[k])))))
    rng = {k: f"{min(v)}-{max(v)} %" for k, v in stats.items()}
    assert f"76.2-203 mm shots from {rng['big']} down to {rng['big_fit']}" in page
    assert f"the plain law meets within {max(stats['small'])} %" in page
    assert f"{rng['small_fit']} shallow" in page
    xd = read_body_shot_table(ROOT / "config/concrete_scaled_series.csv")
    xd = (xd["depth_m"] / xd["diameter_m"]).round(1)
    assert f"penetrates {xd.iloc[0]} calibers at 10.1 mm and {xd.iloc[-1]} at 203 mm" in page
    assert f"1 at $d_{{ref}}$ = {SPEC['d_ref_m'] * 1e3:g} mm" in page
