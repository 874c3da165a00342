"""pencore closed-form: the closed forms beside pencore's run, their numbers the
closedform module's own, the user guide's table generated from the page's own files,
and one-line refusals of what no closed form takes."""

import json
import re
from pathlib import Path

import pytest

import pencore
from pencore import closedform
from pencore.cli.main import main

PAGE = Path(__file__).resolve().parents[2] / "docs/user-guide/own-projectile-and-target.md"


def _page_files(tmp_path):
    """The YAML files the page shows (``# rod30.yaml``, ``# c35.yaml`` blocks), written."""
    text = PAGE.read_text()
    paths = {}
    for name in ("rod30.yaml", "c35.yaml"):
        (block,) = re.findall(rf"```yaml\n# {re.escape(name)}\n(.*?)```", text, re.S)
        paths[name] = tmp_path / name
        paths[name].write_text(block)
    return paths["rod30.yaml"], paths["c35.yaml"]


def _json(capsys):
    return json.loads(capsys.readouterr().out)


def test_the_guide_table_is_the_commands_output(tmp_path, capsys):
    """The user guide's case, from its own files: every number of its table, and the
    closed forms are closedform's to the bit."""
    rod, c35 = _page_files(tmp_path)
    argv = ["closed-form", "--projectile", str(rod), "--target", str(c35), "--velocity", "600"]
    assert main([*argv, "--format", "json"]) == 0
    s = _json(capsys)
    p = pencore.get_projectile(str(rod))
    medium = pencore.get_target(str(c35)).medium
    assert s["model_depth"]["value"] == closedform.depth(p, medium, 600.0)
    assert s["full_nose_depth"]["value"] == closedform.tunnel_depth(p, medium, 600.0)
    assert s["forrestal_crater_depth"]["value"] == closedform.forrestal_crater_depth(
        p, medium, 600.0, 2.0
    )
    assert s["pencore_depth"]["value"] == float(
        pencore.simulate(p, medium, 600.0, loads=False).penetration_depth
    )
    for key in ("pencore_depth", "model_depth", "full_nose_depth", "forrestal_crater_depth"):
        assert s[key]["units"] == "m"
    text = " ".join(PAGE.read_text().split())
    d = s["pencore_depth"]["value"]
    rows = {
        "pencore, 3-D run": (d, None),
        "same model in 1-D (nose entering, then the tunnel)": (s["model_depth"]["value"], 2),
        "whole nose loaded from first contact (Forrestal's formula)": (
            s["full_nose_depth"]["value"],
            1,
        ),
        "Forrestal's form with its crater region (2 calibers)": (
            s["forrestal_crater_depth"]["value"],
            1,
        ),
    }
    for label, (value, decimals) in rows.items():
        rel = "" if decimals is None else f" {100 * (d / value - 1):+.{decimals}f} %"
        assert f"| {label} | {value * 1e3:.1f} |{rel} |" in text, label
    # the numbers, as the page states them
    assert f"{d * 1e3:.1f}" == "262.7" and f"{s['full_nose_depth']['value'] * 1e3:.1f}" == "237.4"
    assert f"+{100 * s['pencore_vs_full_nose_depth']['value']:.1f} %" == "+10.7 %"
    # the text form says the same, with units, and why
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "pencore (3-D run):" in out and "0.262715 m" in out
    assert "pencore +10.7 %" in out and "the whole nose from first contact" in out


def test_csv_rows_have_units_and_no_run_prints_the_forms_alone(capsys):
    argv = ["closed-form", "--projectile", "p2", "--target", "soil", "--velocity", "300"]
    assert main([*argv, "--format", "csv", "--no-run"]) == 0
    rows = [r.split(",") for r in capsys.readouterr().out.splitlines()]
    assert rows[0] == ["name", "value", "units"]
    units = {r[0]: r[-1] for r in rows[1:]}
    assert units["model_depth"] == "m" and units["nose_entry_speed"] == "m s-1"
    # no run, no comparison; soil is no concrete: no crater form
    assert "pencore_depth" not in units and "pencore_vs_model_depth" not in units
    assert "forrestal_crater_depth" not in units
    p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    values = {r[0]: r[1] for r in rows[1:]}
    assert float(values["full_nose_depth"]) == closedform.tunnel_depth(p2, soil, 300.0)


def test_the_crater_option_is_the_models_crater_form(capsys):
    """With the medium's crater region on, the model's 1-D form is Forrestal's crater form
    (pencore's crater in this limit), and no second crater form is printed."""
    argv = ["closed-form", "--projectile", "p2", "--target", "concrete", "--velocity", "300"]
    assert main([*argv, "--crater-depth", "2", "--format", "json"]) == 0
    s = _json(capsys)
    p2, concrete = pencore.get_projectile("p2"), pencore.get_target("concrete").medium
    ref = closedform.forrestal_crater_depth(p2, concrete, 300.0, 2.0)
    assert s["model_depth"]["value"] == ref
    assert "forrestal_crater_depth" not in s
    # the 3-D run with the crater meets it to the integration's accuracy (rtol 1e-5 of
    # the path; 1e-3 allowed for the crater's ring discretisation)
    assert s["pencore_depth"]["value"] == pytest.approx(ref, rel=1e-3)


@pytest.mark.parametrize(
    "extra, target_text, needle",
    [
        (["--free-surface-depth", "2"], "concrete", "no free-surface reduction"),
        (["--plastic-zone-ratio", "3"], "concrete", "plastic_zone_ratio 3"),
        ([], "LAYERED", "half-space of one medium"),
        ([], "FRICTION", "frictionless"),
    ],
)
def test_what_no_closed_form_takes_is_one_line(tmp_path, capsys, extra, target_text, needle):
    files = {
        "LAYERED": "name: two\nlayers:\n  - {medium: concrete, thickness: 0.5}\n"
        "  - {medium: soil}\n",
        "FRICTION": "name: rough\nlayers:\n  - medium: {name: rough, coefficients: "
        "[1.0e7, 0.0, 2000.0], friction: [[0.0, 0.1]]}\n",
    }
    target = target_text
    if target_text in files:
        target = tmp_path / "t.yaml"
        target.write_text(files[target_text])
    argv = ["closed-form", "--projectile", "p2", "--target", str(target), "--velocity", "300"]
    assert main([*argv, *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and needle in err, err


def test_help_lists_the_command(capsys):
    assert main(["--help"]) == 0
    assert "closed-form" in capsys.readouterr().out
    assert main(["closed-form", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "impact speed in m/s" in text and "first contact" in text


def test_a_run_that_would_stop_before_it_starts_is_refused(capsys):
    argv = ["closed-form", "--projectile", "p2", "--target", "soil", "--velocity", "300",
            "--numerics", "v_stop=400"]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "v_stop = 400 m/s is not below the impact speed" in err
    assert main([*argv, "--no-run"]) == 0  # the closed forms alone need no run
