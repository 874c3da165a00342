"""Plausibility warnings (:data:`pencore.inputs.limits.PLAUSIBLE`): each likely slip of
unit at each door is one :class:`pencore.PlausibilityWarning` naming the value and the
slip, the run goes on, the usual filters silence it, and the values of the library and
of the shipped configuration raise none."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

import pencore
from pencore.cli.main import main
from pencore.inputs.limits import LIMITS, PLAUSIBLE, looks_like_radians, plausible_markdown
from pencore.measured.shots import SHOT_COLUMNS, read_shot_table
from pencore.workflowconfig.config_check import check_config, read_config

REPO = Path(__file__).resolve().parents[2]
STEEL = pencore.OgiveNose(3.0, 7850.0)


def _warned(call) -> str:
    """The one PlausibilityWarning ``call`` issues (it must issue exactly one)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    found = [w for w in caught if issubclass(w.category, pencore.PlausibilityWarning)]
    assert len(found) == 1, [str(w.message) for w in caught]
    text = str(found[0].message)
    assert "\n" not in text
    return text


def _concrete_slab(thickness: float, **windows) -> pencore.Target:
    medium = pencore.get_target("concrete").medium
    return pencore.Target("slab", (pencore.Layer(medium, thickness),)).with_windows(**windows)


def _aluminium_plate(thickness: float) -> pencore.Target:
    medium = pencore.get_target("aluminium").medium
    return pencore.Target("plate", (pencore.Layer(medium, thickness),))


#: (case, call, words the warning must hold): one per likely slip.
SLIPS = {
    "soil coefficients in MPa (a0)": (
        lambda: pencore.Medium("mpa", (17.18, 0.0, 4119.9)),
        ["a0 17.18 Pa", "MPa given for Pa"],
    ),
    "soil coefficients in MPa (a2)": (
        lambda: pencore.Medium("mpa", (1.718e7, 0.0, 0.0041199)),
        ["a2 0.0041199", "MPa given for Pa"],
    ),
    "speed in km/s": (
        lambda: pencore.prepare("p2", "soil") and pencore.simulate("p2", "soil", 1.4),
        ["velocity 1.4 m/s", "km/s given for m/s"],
    ),  # fmt: skip
    "obliquity in radians": (
        lambda: pencore.simulate("p2", "soil", 300.0, obliquity=0.5236),
        ["obliquity 0.5236 deg", "radians? (30.0 deg"],
    ),
    "yaw in radians": (
        lambda: pencore.simulate("p2", "soil", 300.0, yaw=-0.0873),
        ["yaw -0.0873 deg", "radians? (-5.0 deg"],
    ),
    "diameter in cm": (
        lambda: pencore.Projectile("x", 9.5, STEEL),
        ["diameter 9.5 m", "cm or mm given for m"],
    ),
    "density in g/cm3": (
        lambda: pencore.Projectile("x", 0.095, pencore.OgiveNose(3.0, 7.85)),
        ["density 7.85 kg/m^3", "g/cm^3"],
    ),
    "medium density in g/cm3": (
        lambda: pencore.Medium("m", (1.718e7, 0.0, 4119.9), density=1.86),
        ["medium density 1.86", "g/cm^3"],
    ),
    "spin in rpm": (
        lambda: pencore.simulate("p2", "soil", 300.0, omega=3000.0, t_max=1e-4),
        ["omega 3000 rad/s", "rpm"],
    ),
    "layer in mm": (lambda: pencore.Layer(None, 250.0), ["thickness 250 m", "mm given for m"]),
    "thin plate on the half-space law": (
        lambda: pencore.prepare("p2", _concrete_slab(0.33)),
        ["plate thickness 3.47", "calibres", "no near-surface option"],
    ),
    "measured mass in tonnes": (
        lambda: pencore.get_projectile("p2").with_mass(mass=0.025),
        ["mass 0.025 kg, solid outline 23.16 kg", "tonnes given for kg"],
    ),
    "measured mass in pounds": (
        lambda: pencore.get_projectile("p2").with_mass(mass=51.0),
        ["mass 51 kg", "pounds given for kg"],
    ),
    "yield strength in kPa": (
        lambda: pencore.metal_law(68.9e9, 0.33, 276e3, 0.05, 2710.0, inertia="incompressible"),
        ["E / Y 249638", "kPa given for Pa"],
    ),
    "metal law fitted to a speed in km/s": (
        lambda: pencore.metal_law(200e9, 0.29, 250e6, 0.1, 7850.0, max_speed=2.0),
        ["max_speed 2 m/s", "km/s given for m/s"],
    ),
    "azimuth in radians": (
        lambda: pencore.simulate("p2", "soil", 300.0, azimuth=0.785, t_max=1e-4),
        ["azimuth 0.785 deg", "radians? (45.0 deg"],
    ),
    "start in cm": (
        lambda: pencore.simulate("p2", "soil", 300.0, start=(20.0, 0.0, 0.0), t_max=1e-4),
        ["start coordinate 20 m", "cm or mm given for m"],
    ),
    "gravity in g": (
        lambda: pencore.prepare("p2", "soil", gravity=1.0),
        ["gravity 1 m/s^2", "in g"],
    ),
    "gravity in ft/s^2": (
        lambda: pencore.prepare("p2", "soil", gravity=32.2),
        ["gravity 32.2 m/s^2", "ft/s^2"],
    ),
    "ballistic-limit plate in mm": (
        lambda: pencore.ballistic_limit(
            "p2", _aluminium_plate(10.0), lo=50.0, hi=60.0, tol=20.0, scan=None
        ),
        ["plate thickness 10 m", "mm given for m"],
    ),
}


@pytest.mark.parametrize("case", list(SLIPS))
def test_each_slip_warns_once_naming_value_and_slip(case):
    call, words = SLIPS[case]
    text = _warned(call)
    for w in words:
        assert w in text, text


def test_a_warning_never_stops_a_run():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pencore.PlausibilityWarning)
        ds = pencore.simulate("p2", "soil", 1.4)
    assert ds.attrs["outcome"] == "stopped"
    assert ds.penetration_depth.item() >= 0.0


def test_filters_silence_and_escalate_it():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.simplefilter("ignore", pencore.PlausibilityWarning)
        pencore.Projectile("x", 9.5, STEEL)
    assert not caught
    with warnings.catch_warnings():
        warnings.simplefilter("error", pencore.PlausibilityWarning)
        with pytest.raises(pencore.PlausibilityWarning, match="diameter 9.5 m"):
            pencore.Projectile("x", 9.5, STEEL)


def test_a_plate_with_a_near_surface_option_or_thick_enough_is_plausible():
    with warnings.catch_warnings():
        warnings.simplefilter("error", pencore.PlausibilityWarning)
        pencore.prepare("p2", _concrete_slab(0.33, crater_depth=2.0))
        pencore.prepare("p2", _concrete_slab(0.5))  # 5.3 calibres
        pencore.prepare("p2", "soil")


def test_library_and_shipped_configuration_raise_no_warning():
    """The values pencore ships (library objects, config/config.yaml, the measured shot
    tables) are all plausible: a warning there would be noise."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", pencore.PlausibilityWarning)
        for name in pencore.projectile_names():
            pencore.get_projectile(name)
        for name in pencore.target_names():
            pencore.get_target(name)
        check_config(read_config([REPO / "config/config.yaml"]), REPO)
        for shots in ("aluminium_ogive_shots.csv", "aluminium_sphere_shots.csv"):
            read_shot_table(REPO / "config" / shots)


@pytest.mark.parametrize(
    ("angle", "flagged"),
    [(0.5236, True), (0.785, True), (0.26, True), (1.047, True), (-0.52, True),
     (0.5235987755982988, True), (0.79056, False), (0.7905612, False),
     (0.0, False), (0.5, False), (1.0, False), (1.5, False), (0.3, False), (0.1, False),
     (5.0, False), (30.0, False), (45.0, False)],
)  # fmt: skip
def test_radians_rule(angle, flagged):
    assert looks_like_radians(angle) is flagged


def test_cli_prints_one_warning_line_and_runs(capsys):
    status = main(["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "1.4"])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 0
    assert len(err) == 1, err
    assert err[0].startswith("pencore: warning: velocity 1.4 m/s is implausible"), err


def test_workflow_config_ensemble_mean_and_thickness_list_warn():
    config = read_config([REPO / "config/config.yaml"])
    case = config["ensemble"]["cases"][0]
    case["velocity_m_s"] = {"dist": "normal", "mean": 1.4, "sd": 0.15}
    text = _warned(lambda: check_config(config, REPO))
    assert "ensemble.cases[0].velocity_m_s" in text and "velocity 1.4 m/s" in text
    config = read_config([REPO / "config/config.yaml"])
    config["perforation"]["ballistic_limit"]["thickness_m"] = [0.5, 500.0]
    text = _warned(lambda: check_config(config, REPO))
    assert "thickness_m" in text and "thickness 500 m" in text


def test_shot_table_in_mm_warns_naming_the_row(tmp_path):
    rows = [",".join(SHOT_COLUMNS),
            "s1,al_ogive_var4340,600.0,120.0,0.5,0.0,true,1,725,paper"]  # fmt: skip
    path = tmp_path / "shots.csv"
    path.write_text("\n".join(rows) + "\n")
    text = _warned(lambda: read_shot_table(path))
    assert "row 1" in text and "measured depth 120 m" in text and "mm" in text


def test_docs_list_every_plausible_range():
    table = plausible_markdown()
    for key in PLAUSIBLE:
        assert f"| `{key}` |" in table
        if key in LIMITS:
            assert LIMITS[key].describe()[3:] in table
    assert len(table.splitlines()) == len(PLAUSIBLE) + 2
    page = (REPO / "docs/user-guide/errors.md").read_text()
    assert "```{include} ../_generated/plausible.md" in page
    generator = (REPO / "docs/_ext/pencore_docs.py").read_text()
    assert '"plausible.md": plausible_table' in generator


def test_a_study_of_thin_plates_on_the_half_space_law_silences_only_that_warning():
    from pencore.inputs.limits import half_space_plates

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with half_space_plates():
            pencore.prepare("p2", _concrete_slab(0.33))
            pencore.Projectile("x", 9.5, STEEL)
    assert [str(w.message).split(" is ")[0] for w in caught] == ["diameter 9.5 m"]
