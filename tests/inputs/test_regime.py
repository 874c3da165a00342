"""The rigid regime: the declared bound against the rods Piekutowski et al. (1999) call rigid
or deformed, the verdict's arithmetic, the warning (fires, does not fire, once per prepared
problem, one line), the assumed strength, and the projectile's strength through the doors."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import pandas as pd
import pytest
import yaml

import pencore
from pencore.errors import GeometryError, InputError, PlausibilityWarning, RigidRegimeWarning
from pencore.inputs.library import projectile_from_dict
from pencore.inputs.regime import regime_constants, rigid_regime

ROOT = Path(__file__).resolve().parents[2]
SPEC = regime_constants()
ROD_STEELS = yaml.safe_load((ROOT / "config/aluminium_projectiles.yaml").read_text())


def rod(name: str = "al_ogive_var4340", strength: float | None = None) -> pencore.Projectile:
    """A Piekutowski rod with its steel's yield strength (p. 724) unless told otherwise."""
    p = pencore.get_projectile(name)
    y = ROD_STEELS[name]["tensile_yield_strength_pa"] if strength is None else strength
    return pencore.Projectile(p.name, p.diameter, p.nose, p.shank, yield_strength=y)


def al_shots() -> pd.DataFrame:
    return pd.read_csv(ROOT / "config/aluminium_ogive_shots.csv", comment="#")


def ratio(row: pd.Series) -> float:
    return rigid_regime(rod(row["projectile"]), pencore.get_target("aluminium"),
                        float(row["striking_velocity_m_s"])).ratio  # fmt: skip


def test_the_bound_calls_every_deformed_rod_deformed_and_one_rigid_rod_too():
    shots = al_shots()
    verdict = [ratio(r) <= SPEC["bound"] for _, r in shots.iterrows()]
    wrong = shots.loc[[v != r for v, r in zip(verdict, shots["rigid"], strict=True)], "shot"]
    # the one disagreement is on the safe side: AerMet 100 at 1786 m/s, rigid by the authors
    assert list(wrong) == ["4-1843"]
    assert not any(v for v, r in zip(verdict, shots["rigid"], strict=True) if not r)


@pytest.mark.parametrize(
    ("shot", "text"),
    [("4-1798", "4.80"), ("4-1829", "5.57"), ("4-1843", "5.75"), ("8-0117", "5.92")],
)
def test_the_ratios_the_constants_file_quotes(shot, text):
    row = al_shots().set_index("shot").loc[shot]
    row["shot"] = shot
    assert f"{ratio(row):.2f}" == text
    header = (ROOT / "src/pencore/inputs/data/rigid_regime.yaml").read_text()
    assert f"{text} ({row['striking_velocity_m_s']:.0f} m/s)" in header.replace("\n# ", " ")


def test_the_assumed_strength_is_the_strongest_rod_steel():
    strongest = max(v["tensile_yield_strength_pa"] for v in ROD_STEELS.values()
                    if "tensile_yield_strength_pa" in v)  # fmt: skip
    assert SPEC["assumed_yield_strength_pa"] == strongest == 1.72e9
    plain = pencore.get_projectile("al_ogive_var4340")
    v = rigid_regime(plain, pencore.get_target("aluminium"), 1000.0)
    assert not v.strength_given and v.strength == strongest


def test_the_verdict_arithmetic():
    medium = pencore.concrete_law(40e6, 2400.0)
    p = rod("al_ogive_var4340", strength=1.3e9)
    v = rigid_regime(p, medium, 1200.0)
    stress = medium.coefficients[0] + 2400.0 * 1200.0**2
    assert v.stress == pytest.approx(stress, rel=1e-15)
    assert v.ratio == pytest.approx(stress / 1.3e9, rel=1e-15)
    assert v.rigid and v.margin == pytest.approx(SPEC["bound"] / v.ratio - 1, rel=1e-15)
    # the limit speed is where the tip stress reaches the bound
    assert float(medium.sigma_n(v.limit_speed)) == pytest.approx(SPEC["bound"] * 1.3e9, rel=1e-12)
    above = rigid_regime(p, medium, v.limit_speed * 1.001)
    assert not above.rigid and above.margin < 0
    # a layered target: the layer of the largest tip stress counts (at 1200 m/s the soil's
    # 2.215 x 1860 kg/m3 inertia outweighs the concrete's strength)
    soil = pencore.soil_law(1.718, 10e6, 2.215, 1860.0)
    t = pencore.Target("two", (pencore.Layer(medium, 0.5), pencore.Layer(soil)))
    both = rigid_regime(p, t, 1200.0)
    assert both.medium == "soil" and both.stress == float(soil.sigma_n(1200.0))
    assert both.stress > stress


def test_the_warning_fires_outside_and_not_inside():
    al = pencore.get_target("aluminium")
    with warnings.catch_warnings():
        warnings.simplefilter("error", RigidRegimeWarning)
        pencore.simulate(rod(), al, 1237.0)  # rigid by the authors and by the bound
    with pytest.warns(RigidRegimeWarning) as caught:
        pencore.simulate(rod(), al, 1365.0)  # bent by the authors
    msg = str(caught[0].message)
    assert "\n" not in msg and issubclass(caught[0].category, PlausibilityWarning)
    assert "nose-tip stress in aluminium is 6.35 GPa, 5.57 times" in msg
    assert "yield strength 1140 MPa, above the bound 5.5" in msg
    with pytest.warns(RigidRegimeWarning, match=r"1720 MPa \(assumed\)"):
        pencore.simulate("al_ogive_var4340", al, 2500.0)


def test_a_prepared_problem_warns_once():
    pr = pencore.prepare(rod(), "aluminium")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for v in (1400.0, 1500.0, 1600.0):
            pencore.simulate(rod(), "aluminium", v, prepared=pr)
    assert [c.category for c in caught].count(RigidRegimeWarning) == 1


def test_the_strength_through_the_yaml_door_and_the_dataset():
    d = {
        "name": "r",
        "diameter": 0.03,
        "nose": {"kind": "ogive", "crh": 3, "density": 7850},
        "shank": [{"length": 0.2, "density": 7850}],
        "yield_strength": "1.3e9",
    }
    p = projectile_from_dict(d)
    assert p.yield_strength == 1.3e9
    ds = pencore.simulate(p, "concrete", 300.0)
    assert json.loads(ds.attrs["inputs_json"])["projectile"]["yield_strength"] == 1.3e9
    plain = pencore.simulate("p2", "concrete", 300.0)
    assert "yield_strength" not in json.loads(plain.attrs["inputs_json"])["projectile"]
    with pytest.raises(
        InputError, match=r"yield strength Y must be in \[100000, 1e\+10\] Pa, got -1"
    ) as exc:
        projectile_from_dict({**d, "yield_strength": -1})
    assert "-1" in str(exc.value) and "\n" not in str(exc.value)
    with pytest.raises(GeometryError, match=r"yield strength Y must be in .* Pa, got 0.0"):
        pencore.Projectile("x", 0.03, pencore.OgiveNose(3.0, 7850.0), yield_strength=0.0)


def test_wus_scaled_series_is_inside_the_regime():
    from pencore.measured.shots import read_body_shot_table
    from pencore.studies.validation.bodies import body_projectile

    wu = pd.read_csv(ROOT / "config/concrete_scaled_series.csv", comment="#")
    for (_, r), (_, b) in zip(wu.iterrows(),
                              read_body_shot_table(ROOT / "config/concrete_scaled_series.csv")
                              .iterrows(), strict=True):  # fmt: skip
        p = body_projectile(b, "rod")
        p = pencore.Projectile(p.name, p.diameter, p.nose, p.shank, mass=p.mass,
                               yield_strength=r["projectile_yield_pa"])  # fmt: skip
        medium = pencore.concrete_law(r["fc_pa"], r["target_density_kg_m3"])
        assert rigid_regime(p, medium, r["striking_velocity_m_s"]).rigid


def test_the_guide_states_the_criterion():
    """docs/user-guide/own-projectile-and-target.md types these numbers."""
    page = " ".join((ROOT / "docs/user-guide/own-projectile-and-target.md").read_text().split())
    assert f"must not exceed a bound of {SPEC['bound']:g}" in page
    assert f"pencore assumes {SPEC['assumed_yield_strength_pa'] / 1e6:g} MPa" in page
    shots = al_shots().set_index("shot")
    only = shots.loc["4-1843"]  # the one rigid rod the bound calls deformed (test above)
    assert f"one rigid rod ({only['striking_velocity_m_s']} m/s) deformed too" in page


def test_a_search_judges_its_answer_not_its_bracket():
    # the scans up to 3000 m/s run many speeds outside the regime: only an answer outside
    # it warns, once (pencore.search.regime)
    al = pencore.get_target("aluminium").medium

    def caught(thickness: float):
        plate = pencore.Target("plate", (pencore.Layer(al, thickness),))
        with warnings.catch_warnings(record=True) as c:
            warnings.simplefilter("always")
            r = pencore.ballistic_limit(rod(), plate, lo=100.0, hi=3000.0, tol=50.0)
        return r, [w for w in c if w.category is RigidRegimeWarning]

    r, w = caught(0.03)  # v_bl about 400 m/s: inside
    assert r.hi < 500.0 and w == []
    r, w = caught(0.4)  # v_bl about 1660 m/s: outside (1353 m/s for this rod)
    assert r.hi > 1353.0 and len(w) == 1
    assert str(w[0].message).startswith(f"rigid regime: at {r.hi:g} m/s")


def test_the_command_line_takes_the_strength_and_warns_in_one_line(capsys):
    from pencore.cli.main import main

    args = ["simulate", "--projectile", "al_ogive_var4340", "--target", "aluminium"]
    assert main([*args, "--velocity", "1365", "--yield-strength", "1.14e9"]) == 0
    err = capsys.readouterr().err
    assert err.startswith("pencore: warning: rigid regime: at 1365 m/s") and err.count("\n") == 1
    assert main([*args, "--velocity", "1365"]) == 0  # 1720 MPa assumed: inside the bound
    assert "rigid regime" not in capsys.readouterr().err
    assert main([*args, "--velocity", "1365", "--yield-strength", "1140"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "yield strength Y must be in [100000, 1e+10] Pa" in err
