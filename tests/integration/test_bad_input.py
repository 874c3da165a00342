"""A catalogue of bad inputs: every one stops with one line naming the value.

Three doors: the Python API (``pencore.simulate`` raises ``InputError``), YAML files
(``pencore simulate --projectile FILE`` exits 2), and the command line (exits 2). Each
case asserts the exception or exit status, a one-line message that names the offending
value, no traceback, no file left behind, and a time bound (a hang guard: every case is
refused before any integration, in well under a second). The workflow configuration's
catalogue is in ``tests/studies/test_config_check.py``.
"""

from __future__ import annotations

import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from helpers import assert_one_line_error

import pencore
from pencore.cli.main import main
from pencore.inputs import geometry, laws, library, target
from pencore.inputs.numerics import resolve_numerics

HANG_GUARD_S = 20.0  # refused before integrating: measured < 0.1 s each

# ---------------------------------------------------------------- API


API_CASES = [
    # impact conditions
    (dict(velocity=0.0), "velocity", "0.0"),
    (dict(velocity=-5.0), "velocity", "-5.0"),
    (dict(velocity=math.nan), "velocity", "nan"),
    (dict(velocity=math.inf), "velocity", "inf"),
    (dict(velocity=1e300), "velocity", "1e+300"),
    (dict(velocity=2e4), "velocity", "20000.0"),
    (dict(velocity="280"), "velocity", "'280'"),
    (dict(velocity=True), "velocity", "True"),
    (dict(velocity=None), "velocity", "None"),
    (dict(velocity=[280.0]), "velocity", "[280.0]"),
    (dict(velocity=500.0, obliquity=90.0), "obliquity", "90.0"),
    (dict(velocity=500.0, obliquity=-95.0), "obliquity", "-95.0"),
    (dict(velocity=500.0, obliquity=math.nan), "obliquity", "nan"),
    (dict(velocity=500.0, obliquity="45"), "obliquity", "'45'"),
    (dict(velocity=500.0, obliquity=60.0, yaw=40.0), "obliquity + yaw", "40.0"),
    (dict(velocity=500.0, yaw=math.inf), "yaw", "inf"),
    (dict(velocity=500.0, yaw=False), "yaw", "False"),
    (dict(velocity=500.0, omega=1e300), "omega", "1e+300"),
    (dict(velocity=500.0, omega=-2e4), "omega", "-20000.0"),
    (dict(velocity=500.0, omega=math.nan), "omega", "nan"),
    (dict(velocity=500.0, azimuth=math.inf), "azimuth", "inf"),
    (dict(velocity=500.0, azimuth=720.0), "azimuth", "720.0"),
    (dict(velocity=500.0, start=(0.0, 0.0)), "start", "(0.0, 0.0)"),
    (dict(velocity=500.0, start=(math.nan, 0.0, 0.0)), "start x", "nan"),
    (dict(velocity=500.0, start=(0.0, 1e6, 0.0)), "start y", "1000000.0"),
    (dict(velocity=500.0, start="0 0 0"), "start", "'0 0 0'"),
    (dict(velocity=500.0, start=(0.0, 0.0, True)), "start z", "True"),
    (dict(velocity=500.0, start=(0.0, 600.0, 0.0)), "t_max", "600"),
    (dict(velocity=50.0, start=(0.0, 100.0, 0.0)), "start height", "100"),
    (dict(velocity=500.0, stop_at_reversal="yes"), "stop_at_reversal", "'yes'"),
    # numerics
    (dict(velocity=500.0, numerics="fast"), "numerics", "'fast'"),
    (dict(velocity=500.0, numerics=3), "numerics", "3"),
    (dict(velocity=500.0, n_nose=2.5), "n_nose", "2.5"),
    (dict(velocity=500.0, n_nose=0), "n_nose", "0"),
    (dict(velocity=500.0, n_shank=-1), "n_shank", "-1"),
    (dict(velocity=500.0, n_face=True), "n_face", "True"),
    (dict(velocity=500.0, n_gauss=0), "n_gauss", "0"),
    (dict(velocity=500.0, jacobian_age=0), "jacobian_age", "0"),
    (dict(velocity=500.0, jacobian_age=2.5), "jacobian_age", "2.5"),
    (dict(velocity=500.0, jacobian="analytical"), "jacobian", "'analytical'"),
    (dict(velocity=500.0, eps=-1.0), "eps", "-1.0"),
    (dict(velocity=500.0, eps=math.nan), "eps", "nan"),
    (dict(velocity=500.0, rtol=0.0), "rtol", "0.0"),
    (dict(velocity=500.0, rtol=0.5), "rtol", "0.5"),
    (dict(velocity=500.0, rtol="1e-5"), "rtol", "'1e-5'"),
    (dict(velocity=500.0, max_travel=0.0), "max_travel", "0.0"),
    (dict(velocity=500.0, v_stop=-1.0), "v_stop", "-1.0"),
    (dict(velocity=500.0, t_max=0.0), "t_max", "0.0"),
    (dict(velocity=500.0, t_max=1e6), "t_max", "1000000.0"),
    (dict(velocity=500.0, max_steps=0), "max_steps", "0"),
    (dict(velocity=500.0, max_steps=1e12), "max_steps", "1000000000000.0"),
    (dict(velocity=500.0, max_wall=0.0), "max_wall", "0.0"),
    (dict(velocity=500.0, h_min=0.0), "h_min", "0.0"),
    (dict(velocity=500.0, gravity=math.nan), "gravity", "nan"),
    (dict(velocity=500.0, gravity=1e12), "gravity", "1000000000000.0"),
    (dict(velocity=500.0, gravity=-9.81), "gravity", "-9.81"),
    (dict(velocity=500.0, method="rk45"), "method", "'rk45'"),
    (dict(velocity=500.0, method="radau"), "did you mean 'Radau'", "'radau'"),
    (dict(velocity=500.0, rtoll=1e-3), "did you mean 'rtol'", "'rtoll'"),
    (dict(velocity=500.0, bogus=1.0), "unknown key", "'bogus'"),
    (dict(velocity=500.0, numerics={"epss": 1e-3}), "did you mean 'eps'", "'epss'"),
]


def _id(kw: dict) -> str:
    return ",".join(f"{k}={v!r}" for k, v in kw.items())[:60]


@pytest.mark.parametrize(("kw", "what", "value"), API_CASES, ids=[_id(c[0]) for c in API_CASES])
def test_api_refuses(kw, what, value):
    t0 = time.monotonic()
    with pytest.raises(pencore.InputError) as info:
        pencore.simulate("p2", "soil", **kw)
    msg = str(info.value)
    assert "\n" not in msg
    assert what in msg and value in msg, msg
    assert time.monotonic() - t0 < HANG_GUARD_S


#: 6061-T6 aluminium's E, nu, Y, n (Pa, -, Pa, -) and density (kg/m^3).
AL = (68.9e9, 0.33, 276e6, 0.05, 2710.0)

API_OBJECT_CASES = [
    (lambda: pencore.simulate(None, "soil", 300.0), "projectile", "None"),
    (lambda: pencore.simulate("p2", None, 300.0), "target", "None"),
    (lambda: pencore.simulate(42, "soil", 300.0), "projectile", "42"),
    (lambda: pencore.simulate("p9", "soil", 300.0), "unknown projectile", "'p9'"),
    (lambda: pencore.simulate("p2", "mud", 300.0), "unknown target", "'mud'"),
    (lambda: pencore.simulate("p2", "soil", 300.0, prepared="x"), "prepared", "'x'"),
    (lambda: pencore.Numerics(rtol=-1.0), "rtol", "-1.0"),
    (lambda: pencore.Numerics(method="fast"), "method", "'fast'"),
    (lambda: resolve_numerics([1, 2]), "numerics", "[1, 2]"),
    (lambda: target.Medium("m", (1e6, 0.0, -10.0)), "a2", "-10.0"),
    (lambda: target.Medium("m", (0.0, 0.0, 0.0)), "every resistance", "zero"),
    (lambda: target.Medium("m", (1e6,), (0.0,), (-0.1,)), "friction", "-0.1"),
    (lambda: target.Medium("m", (1e6,), (0.0, 0.0), (0.1, 0.2)), "increase", "0.0"),
    (lambda: target.Medium("m", "1e6"), "coefficients", "list"),
    (
        lambda: target.Target(
            "slab",
            (
                target.Layer(library.MEDIA["soil"], 1.0),
                target.Layer.gap(0.5),
            ),
        ),
        "gap must lie between",
        "layer 1",
    ),
    (
        lambda: target.Target(
            "t",
            (
                target.Layer(library.MEDIA["soil"]),
                target.Layer(library.MEDIA["soil"]),
            ),
        ),
        "only the last layer",
        "layer 0",
    ),
    (
        lambda: pencore.simulate("p2", target.Target("t", (target.Layer("concrete", 0.1),)), 300.0),
        "layer 0 medium must be a Medium or None (gap), got str 'concrete'",
        "; for a named medium use pencore.get_target('concrete').medium",
    ),
    (
        lambda: target.Target("t", (target.Layer(library.MEDIA["soil"], 1.0), target.Layer(7))),
        "layer 1 medium",
        "got int 7",
    ),
    (lambda: geometry.OgiveNose(0.4, 7850.0), "CRH", "0.4"),
    (lambda: geometry.OgiveNose(1e12, 7850.0), "CRH", "1000000000000.0"),
    (lambda: geometry.OgiveNose(3.0, 1e6), "density", "1000000.0"),
    (lambda: geometry.ConeNose(math.pi, 7850.0), "half-angle", "180"),
    (lambda: geometry.Cylinder(-0.5, 7850.0), "segment length", "-0.5"),
    (
        lambda: geometry.Projectile("x", 1e200, geometry.OgiveNose(3.0, 7850.0)),
        "diameter",
        "1e+200",
    ),
    (
        lambda: geometry.Projectile("x", True, geometry.OgiveNose(3.0, 7850.0)),
        "diameter",
        "True",
    ),
    # laws from material properties: the same number gate, a fit only where it holds
    (lambda: pencore.concrete_law(fc=40e6, densty=2300), "'densty'", "did you mean 'density'"),
    (lambda: pencore.get_projectile("p2").with_mass(mas=20), "'mas'", "did you mean 'mass'"),
    (lambda: laws.medium_from_law("concrete"), "a law must be a mapping", "'concrete'"),
    (lambda: pencore.metal_law(*AL, max_speed=1e-6), "max_speed must be at least", "1e-06"),
    (lambda: pencore.metal_law(*AL, max_speed=0.1), "max_speed must be at least", "0.1"),
    (lambda: pencore.metal_law(*AL, max_speed=2), "max_speed", "2 km/s is 2000 m/s"),
    (
        lambda: pencore.metal_law(*AL, inertia="incompressible", max_speed=-5),
        "max_speed must be in (0, 10000] m/s",
        "-5",
    ),
    (lambda: pencore.concrete_law(40e6, 2300.0, crater_depth="two"), "crater_depth", "'two'"),
]


@pytest.mark.parametrize(("call", "what", "value"), API_OBJECT_CASES)
def test_api_objects_refuse(call, what, value):
    with pytest.raises(pencore.InputError) as info:
        call()
    msg = str(info.value)
    assert "\n" not in msg
    assert what in msg and value in msg, msg


# ---------------------------------------------------------------- YAML files

PROJECTILE = """\
name: my-penetrator
diameter: 0.095
nose: {kind: ogive, crh: 3.0, density: 7850}
shank:
  - {length: 0.50, density: 5150}
"""
TARGET = """\
name: crust-over-soil
layers:
  - thickness: 1.0
    medium: {name: crust, coefficients: [30.0e6, 0.0, 5000.0], friction: 0.1}
  - medium: soil
"""

# (which file, text to replace, replacement, needles in the message)
YAML_CASES = [
    ("p", "diameter: 0.095", "diameter: true", ["diameter", "True"]),
    ("p", "diameter: 0.095", "diameter: -0.095", ["diameter", "-0.095"]),
    ("p", "diameter: 0.095", "diameter: 95", ["diameter", "95"]),
    ("p", "diameter: 0.095", "diameter: abc", ["diameter", "'abc'"]),
    ("p", "diameter: 0.095", "diameter: .nan", ["diameter", "nan"]),
    ("p", "diameter: 0.095", "diamter: 0.095", ["'diamter'", "did you mean 'diameter'"]),
    ("p", "diameter: 0.095\n", "", ["missing key 'diameter'"]),
    ("p", "crh: 3.0", "crh: 1.0e12", ["CRH", "1.0e12"]),
    ("p", "crh: 3.0", "crh: 0.3", ["CRH", "0.3"]),
    ("p", "crh: 3.0", "crh: yes", ["CRH", "True"]),
    ("p", "crh: 3.0", "chr: 3.0", ["'chr'", "did you mean 'crh'"]),
    ("p", "kind: ogive", "kind: spitzer", ["nose kind", "'spitzer'"]),
    ("p", "kind: ogive, crh: 3.0", "kind: cone, crh: 3.0", ["'crh'", "half_angle_deg"]),
    ("p", "density: 7850}", "density: -7850}", ["density", "-7850"]),
    ("p", "density: 7850}", "density: 78500}", ["density", "78500"]),
    ("p", "density: 7850}", "densty: 7850}", ["'densty'", "did you mean 'density'"]),
    ("p", "{length: 0.50, density: 5150}", "{length: 0, density: 5150}", ["length", "0"]),
    ("p", "{length: 0.50, density: 5150}", "{length: 500, density: 5150}", ["length", "500"]),
    ("p", "{length: 0.50, density: 5150}", "{lenght: 0.5, density: 5150}", ["'lenght'"]),
    ("p", "  - {length: 0.50, density: 5150}", "  - 0.5", ["shank", "0.5"]),
    ("p", "nose: {kind: ogive, crh: 3.0, density: 7850}", "nose: ogive", ["nose", "'ogive'"]),
    ("p", "name: my-penetrator", "name: x\ncolour: red", ["'colour'", "unknown key"]),
    ("t", "friction: 0.1", "frictoin: 0.1", ["'frictoin'", "did you mean 'friction'"]),
    ("t", "friction: 0.1", "friction: -0.1", ["friction", "-0.1"]),
    ("t", "friction: 0.1", "friction: 5", ["friction", "5"]),
    ("t", "friction: 0.1", "friction: [[0, 0.1], [0, 0.2]]", ["increase"]),
    ("t", "friction: 0.1", "friction: [[0, 0.1, 3]]", ["friction table"]),
    ("t", "friction: 0.1", "friction: true", ["friction", "True"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "[30.0e6, 0.0, -5000.0]", ["a2", "-5000"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "[0, 0, 0]", ["every resistance coefficient is zero"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "[]", ["coefficients"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "30.0e6", ["coefficients", "'30.0e6'"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "[30.0e6, x, 5000.0]", ["a1", "'x'"]),
    ("t", "[30.0e6, 0.0, 5000.0]", "[.inf, 0, 1]", ["a0", "inf"]),
    ("t", "coefficients", "coeficients", ["did you mean 'coefficients'"]),
    ("t", "thickness: 1.0", "thickness: -1.0", ["thickness", "-1.0"]),
    ("t", "thickness: 1.0", "thickness: 0", ["thickness", "0"]),
    ("t", "thickness: 1.0", "thicknes: 1.0", ["'thicknes'", "did you mean 'thickness'"]),
    (
        "t",
        "  - medium: soil",
        "  - medium: soil\n    thickness: 1.0\n  - gap: 0.5",
        ["layer 2", "gap", "between"],
    ),
    ("t", "  - medium: soil", "  - gap: -0.5\n  - medium: soil", ["thickness", "-0.5"]),
    ("t", "  - medium: soil", "  - {gap: 0.5, medium: soil}", ["unknown key", "'medium'"]),
    ("t", "  - medium: soil", "  - medium: mud", ["unknown medium", "'mud'"]),
    ("t", "  - medium: soil", "  - 42", ["layer 1", "42"]),
    ("t", "  - medium: soil", "  - thickness: 2.0", ["layer 1", "medium"]),
    ("t", "layers:", "layerz:", ["'layerz'"]),
]


def _write_case(tmp_path: Path, which: str, old: str, new: str) -> tuple[Path, Path]:
    p, t = tmp_path / "p.yaml", tmp_path / "t.yaml"
    ptext, ttext = PROJECTILE, TARGET
    if which == "p":
        assert old in ptext
        ptext = ptext.replace(old, new, 1)
    else:
        assert old in ttext
        ttext = ttext.replace(old, new, 1)
    p.write_text(ptext)
    t.write_text(ttext)
    return p, t


def _run_main(capsys, args: list[str]) -> tuple[int, str, str]:
    t0 = time.monotonic()
    status = main(args)
    out, err = capsys.readouterr()
    assert time.monotonic() - t0 < HANG_GUARD_S
    return status, out, err


def test_the_valid_yaml_files_run(tmp_path, capsys):
    # no hang guard here: a valid run may first compile the kernels (a source tree with no
    # build step compiles them in about a minute); the guard is for refusals only
    p, t = _write_case(tmp_path, "p", "", "")
    status = main(["simulate", "--projectile", str(p), "--target", str(t), "--velocity", "200"])
    out, err = capsys.readouterr()
    assert status == 0, err
    assert "penetration depth" in out


@pytest.mark.parametrize(
    ("which", "old", "new", "needles"), YAML_CASES, ids=[f"{c[0]}:{c[2]}"[:50] for c in YAML_CASES]
)
def test_yaml_files_refused(tmp_path, capsys, which, old, new, needles):
    p, t = _write_case(tmp_path, which, old, new)
    out_nc = tmp_path / "out.nc"
    status, _, err = _run_main(
        capsys,
        ["simulate", "--projectile", str(p), "--target", str(t), "--velocity", "300",
         "--out", str(out_nc)],
    )  # fmt: skip
    assert status == 2
    assert_one_line_error(err, *needles, str(p if which == "p" else t))
    assert sorted(x.name for x in tmp_path.iterdir()) == ["p.yaml", "t.yaml"]


# ---------------------------------------------------------------- command line

SIM = ["simulate", "--projectile", "p2", "--target", "soil"]
CLI_CASES = [
    ([*SIM, "--velocity", "1e300"], ["--velocity", "'1e300'"]),
    ([*SIM, "--velocity", "true"], ["--velocity", "'true'"]),
    ([*SIM, "--velocity", "0x10"], ["--velocity", "'0x10'"]),
    ([*SIM, "--velocity", "3: 0"], ["--velocity: velocity must be a number", "'3: 0'"]),
    ([*SIM, "--velocity", "300", "--omega", "1e300"], ["--omega", "'1e300'"]),
    ([*SIM, "--velocity", "300", "--omega", "nan"], ["--omega", "'nan'"]),
    ([*SIM, "--velocity", "300", "--yaw=-inf"], ["--yaw", "'-inf'"]),
    ([*SIM, "--velocity", "300", "--obliquity", "60", "--yaw", "35"], ["obliquity + yaw"]),
    ([*SIM, "--velocity", "300", "--start", "0", "1e6", "0"], ["--start", "'1e6'"]),
    ([*SIM, "--velocity", "300", "--start", "0", "400", "0"], ["t_max", "start height"]),
    ([*SIM, "--velocity", "300", "--start", "0", "1"], ["--start"]),
    ([*SIM, "--velocity", "300", "--numerics", "rtol"], ["--numerics", "'rtol'"]),
    ([*SIM, "--velocity", "300", "--numerics", "rtoll=1e-6"], ["did you mean 'rtol'"]),
    ([*SIM, "--velocity", "300", "--numerics", "rtol=fast"], ["rtol", "'fast'"]),
    ([*SIM, "--velocity", "300", "--numerics", "eps=-1"], ["eps", "-1"]),
    ([*SIM, "--velocity", "300", "--numerics", "n_nose=2.5"], ["n_nose", "2.5"]),
    ([*SIM, "--velocity", "300", "--numerics", "n_gauss=0"], ["n_gauss", "0"]),
    ([*SIM, "--velocity", "300", "--numerics", "gravity=.nan"], ["gravity", "nan"]),
    ([*SIM, "--velocity", "300", "--numerics", "max_steps=true"], ["max_steps", "True"]),
    ([*SIM, "--velocity", "300", "--numerics", "method=rk4"], ["method", "'rk4'"]),
    ([*SIM, "--velocity", "300", "--numerics", "t_max=1e9"], ["t_max", "1000000000.0"]),
    (["simulate", "--projectile", "p2", "--target", "soil.yml", "--velocity", "300"],
     ["soil.yml"]),
    (["simulate", "--projectile", "", "--target", "soil", "--velocity", "300"], ["''"]),
    (["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "300", "--frob"],
     ["--frob"]),
    (["simulat"], ["'simulat'"]),
    (["ballistic-limit", "--projectile", "p2", "--target", "plate.yaml", "--tol", "-5"],
     ["argument --tol: tolerance must be in (0, 10000] m/s, got '-5'"]),
    # a value of an option of several is named by its metavar, as what it is
    (["residual-velocity", "--projectile", "p2", "--target", "soil", "--range", "100", "500",
      "20000"], ["argument --range: N: number of speeds must be in [2, 10000], got '20000'"]),
    (["residual-velocity", "--projectile", "p2", "--target", "soil", "--range", "100", "500",
      "2.5"], ["--range: N: number of speeds must be a whole number, got '2.5'"]),
    (["residual-velocity", "--projectile", "p2", "--target", "soil", "--range", "100", "2e4",
      "3"], ["--range: HI: velocity must be in (0, 10000] m/s, got '2e4'"]),
    ([*SIM, "--velocity", "300", "--start", "0", "0", "5000"], ["--start: Z: start coordinate"]),
    ([*SIM, "--velocity", "300", "--inertia", "1", "-2"], ["--inertia: TRANSVERSE: moment"]),
    (["law", "metal", "--youngs-modulus", "68.9e9", "--poisson-ratio", "0.33",
      "--yield-strength", "276e6", "--hardening-exponent", "0.05", "--density", "2710",
      "--inertia", "incompressible", "--max-speed=-5"], ["max_speed must be in (0, 10000]"]),
]  # fmt: skip


@pytest.mark.parametrize(
    ("args", "needles"), CLI_CASES, ids=[" ".join(a[5:])[:50] for a, _ in CLI_CASES]
)
def test_cli_refuses(tmp_path, capsys, args, needles):
    status, _, err = _run_main(capsys, [*args])
    assert status == 2
    assert_one_line_error(err, *needles)
    assert list(tmp_path.iterdir()) == []


def test_solver_failure_is_one_line_with_status_1(capsys):
    status, _, err = _run_main(
        capsys, [*SIM, "--velocity", "500", "--obliquity", "30", "--numerics", "eps=0"]
    )
    assert status == 1
    assert_one_line_error(err, "solver failed", "chatter", "eps = 0")


@pytest.mark.parametrize(
    "args",
    [
        [*SIM, "--velocity", "-1"],
        [*SIM, "--velocity", "300", "--numerics", "frobnicate=1"],
        ["simulate", "--projectile", "/nonexistent/p.yaml", "--target", "soil", "--velocity", "3"],
    ],
)
def test_no_traceback_from_a_real_process(tmp_path, args):
    """The same promise at the process level (interpreter start-up and exit included)."""
    proc = subprocess.run(
        [sys.executable, "-m", "pencore", *args],
        capture_output=True, text=True, cwd=tmp_path, timeout=120,
    )  # fmt: skip
    assert proc.returncode == 2
    assert_one_line_error(proc.stderr)
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- bounded runs


def test_step_budget_stops_with_the_state(capsys):
    with pytest.raises(pencore.SolverError, match=r"step budget of 50 steps.*centre of mass"):
        pencore.simulate("p2", "soil", 500.0, max_steps=50)


def test_wall_budget_stops_a_run():
    with pytest.raises(pencore.SolverError, match="wall-time budget"):
        pencore.simulate("p2", "soil", 500.0, rtol=1e-10, max_travel=1e-4, max_wall=0.05)


def test_results_grow_instead_of_being_preallocated():
    """A huge step budget costs nothing up front (it used to be preallocated)."""
    ds = pencore.simulate("p2", "soil", 300.0, max_steps=10**9)
    assert ds.attrs["outcome"] == "stopped"
    assert np.isfinite(ds.cm_y.values).all()


def test_docs_state_the_ranges_the_code_checks():
    """The docs' table of valid ranges is generated from the limits the code enforces."""
    page = (Path(__file__).resolve().parents[2] / "docs/user-guide/inputs.md").read_text()
    assert "```{include} ../_generated/limits.md" in page
    generator = (Path(__file__).resolve().parents[2] / "docs/_ext/pencore_docs.py").read_text()
    assert '"limits.md": limits_table' in generator and "limits_markdown(group)" in generator
