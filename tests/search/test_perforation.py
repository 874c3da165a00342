"""Finite targets and perforation: limits that must hold.

* a slab is a half-space until the tip reaches its rear face;
* for a normal impact, once the tip passes the rear face the nose is only partly loaded
  and the shank carries no axial load, so the residual speed lies between the half-space
  speeds at tip depths H and H + nose length (:func:`pencore.closedform.speed_at_depth`);
* the kinetic energy lost equals the work of the contact stresses;
* the ballistic limit brackets the perforate / no-perforate switch, and there the
  half-space depth lies in [H, H + nose length].
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore import closedform, get_projectile, get_target, simulate
from pencore.errors import TargetError
from pencore.inputs.library import target_from_dict
from pencore.inputs.target import Layer, Target
from pencore.search.perforation import (
    ballistic_limit,
    fit_recht_ipson,
    recht_ipson,
    residual_velocity,
)

CONCRETE = get_target("concrete").medium
P2 = get_projectile("p2")


def slab(h: float) -> Target:
    return Target(f"slab-{h}", (Layer(CONCRETE, h),))


def test_slab_is_a_half_space_until_the_tip_reaches_the_rear_face():
    h = 0.6
    semi = simulate("p2", "concrete", 500.0, 20.0)
    fin = simulate("p2", slab(h), 500.0, 20.0)
    assert fin.attrs["outcome"] == "perforated" and semi.attrs["outcome"] == "stopped"
    # Loads are identical while every ring is above the rear face; a step attempt travels
    # at most max_travel (0.1 m), so rows with the tip 0.1 m above the face come from
    # identical evaluations: the same step sequence, equal to round-off.
    n = int(np.argmax(fin.tip_y.values < -(h - 0.1)))
    assert n > 5
    for v in ("tip_x", "tip_y", "vel_x", "vel_y", "omega_3", "work"):
        np.testing.assert_allclose(fin[v].values[:n], semi[v].values[:n], rtol=1e-12, atol=0)


def test_thick_slab_gives_the_half_space_result():
    # the run stops before the tip reaches the rear face: the whole run is the same
    semi = simulate("p2", "concrete", 400.0)
    fin = simulate("p2", slab(3.0), 400.0)
    assert fin.attrs["outcome"] == "stopped"
    assert float(fin.penetration_depth) == float(semi.penetration_depth)
    assert "residual_velocity" not in fin.attrs


@pytest.mark.parametrize(("h", "v"), [(0.6, 600.0), (1.0, 700.0)])
def test_residual_speed_between_half_space_speeds(h, v):
    ds = simulate("p2", slab(h), v)
    assert ds.attrs["outcome"] == "perforated"
    vr = ds.attrs["residual_velocity"]
    upper = closedform.speed_at_depth(P2, CONCRETE, v, h)
    lower = closedform.speed_at_depth(P2, CONCRETE, v, h + P2.nose_length)
    # the bounds are tens of m/s apart; the solver's ring discretisation moves speeds by
    # ~0.2 % (the 2e-3 depth tolerance of test_physics), hence the 0.5 % slack
    assert lower * (1 - 5e-3) < vr < upper * (1 + 5e-3)
    assert upper - lower > 10.0  # the test is not vacuous
    # normal impact: the body leaves straight
    assert ds.attrs["exit_pitch_deg"] == pytest.approx(0.0, abs=1e-9)
    assert ds.attrs["exit_angle_of_attack_deg"] == pytest.approx(0.0, abs=1e-6)


def test_energy_balance_oblique_perforation():
    ds = simulate("p2", slab(0.5), 500.0, 25.0, 1.0)
    assert ds.attrs["outcome"] == "perforated"
    ke = ds.kinetic_energy.values
    work = ds.work.values
    # KE lost = -(work of the contact stresses); both integrated to rtol = 1e-5 per step,
    # so 1e-4 of the impact energy bounds the accumulated error
    assert ke[0] - ke[-1] == pytest.approx(-work[-1], abs=1e-4 * ke[0])
    vr = ds.attrs["residual_velocity"]
    assert vr == pytest.approx(float(ds.speed[-1]))
    assert 0.0 < vr < 500.0


def test_thin_plate_perforates_thick_plate_does_not():
    assert simulate("p2", slab(0.4), 400.0).attrs["outcome"] == "perforated"
    assert simulate("p2", slab(1.2), 400.0).attrs["outcome"] == "stopped"


def test_no_load_in_an_air_gap():
    t = target_from_dict(
        {
            "name": "two plates",
            "layers": [
                {"medium": "concrete", "thickness": 0.3},
                {"gap": 1.0},
                {"medium": "concrete", "thickness": 0.3},
            ],
        }
    )
    assert t.layers[1].is_gap and t.finite and t.rear_face == pytest.approx(-1.6)
    ds = simulate("p2", t, 600.0)
    assert ds.attrs["outcome"] == "perforated"
    lc = ds.attrs["lc_m"]
    tail_y = ds.cm_y - (P2.length - lc) * ds.axis_y
    inside = (tail_y.values < -0.3) & (ds.tip_y.values > -1.3)
    assert inside.sum() >= 2
    sp = ds.speed.values[inside]
    # no force acts in the gap (gravity is off): the speed is constant to round-off
    np.testing.assert_allclose(sp, sp[0], rtol=1e-12)
    # and both plates slowed it: slower than after the first plate alone
    one = simulate("p2", slab(0.3), 600.0)
    assert (
        ds.attrs["residual_velocity"]
        < sp[0]
        == pytest.approx(one.attrs["residual_velocity"], rel=1e-9)
    )


def test_gap_validation():
    with pytest.raises(TargetError, match="gap"):
        Target("x", (Layer.gap(0.1), Layer(CONCRETE, 1.0)))
    with pytest.raises(TargetError, match="gap"):
        Target("x", (Layer(CONCRETE, 1.0), Layer.gap(0.1)))
    assert not get_target("concrete").finite
    assert get_target("concrete").rear_face == -math.inf


def test_ballistic_limit_brackets_the_switch():
    h = 0.8
    r = ballistic_limit("p2", slab(h), lo=100.0, hi=1500.0, tol=10.0)
    assert r.status == "ok" and r.hi - r.lo <= 10.0
    assert residual_velocity(simulate("p2", slab(h), r.lo)) == 0.0
    assert residual_velocity(simulate("p2", slab(h), r.hi)) > 0.0
    # no perforation if the half-space depth is < H, perforation if it is >= H + L_nose
    # (the finite target resists less than the half-space only once the tip is past H)
    assert closedform.depth(P2, CONCRETE, r.lo) < h + P2.nose_length
    assert closedform.depth(P2, CONCRETE, r.hi) >= h


def test_ballistic_limit_refuses_a_half_space():
    from pencore.errors import InputError

    with pytest.raises(InputError, match="semi-infinite"):
        ballistic_limit("p2", "concrete")


def test_recht_ipson_fit_recovers_its_parameters():
    v = np.linspace(420.0, 1200.0, 9)
    vr = recht_ipson(v, 400.0, 0.9, 2.4)
    fit = fit_recht_ipson(v, vr)
    assert fit["v_bl"] == pytest.approx(400.0, rel=1e-4)
    assert fit["a"] == pytest.approx(0.9, rel=1e-4)
    assert fit["p"] == pytest.approx(2.4, rel=1e-4)
    assert recht_ipson(300.0, 400.0) == 0.0


SLAB_YAML = "name: slab\nlayers:\n  - {medium: concrete, thickness: 0.8}\n"


def test_cli_ballistic_limit(tmp_path, capsys):
    from pencore.cli.main import main

    f = tmp_path / "slab.yaml"
    f.write_text(SLAB_YAML)
    args = ["ballistic-limit", "--projectile", "p2", "--target", str(f), "--tol", "20"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "ballistic limit:" in out and "status:          ok" in out
    # the same search through the API gives the same bracket
    r = ballistic_limit("p2", slab(0.8), tol=20.0)
    assert f"[{r.lo:.6g}, {r.hi:.6g}] m/s" in out


@pytest.mark.parametrize(
    ("extra", "needle"),
    [
        (["--lo", "500", "--hi", "400"], "--lo 500 must be below --hi 400"),
        (["--tol", "-1"], "--tol"),
        (["--crater-depth", "-2"], "crater depth"),
        (["--crater-depth", "1"], "shorter than the nose"),
        (["--plastic-zone-ratio", "0.5"], "plastic_zone_ratio must be 0 (off) or > 1"),
        (["--obliquity", "95"], "--obliquity"),
    ],
)
def test_cli_ballistic_limit_bad_input(tmp_path, capsys, extra, needle):
    from pencore.cli.main import main

    f = tmp_path / "slab.yaml"
    f.write_text(SLAB_YAML)
    assert main(["ballistic-limit", "--projectile", "p2", "--target", str(f), *extra]) == 2
    err = capsys.readouterr().err
    assert needle in err and err.count("\n") == 1


def test_cli_half_space_is_refused(capsys):
    from pencore.cli.main import main

    assert main(["ballistic-limit", "--projectile", "p2", "--target", "concrete"]) == 2
    assert "semi-infinite" in capsys.readouterr().err


def test_cli_simulate_reports_the_residual_velocity(tmp_path, capsys):
    from pencore.cli.main import main

    f = tmp_path / "slab.yaml"
    f.write_text(SLAB_YAML)
    assert main(["simulate", "--projectile", "p2", "--target", str(f), "--velocity", "600"]) == 0
    out = capsys.readouterr().out
    vr = residual_velocity(simulate("p2", slab(0.8), 600.0))
    assert "outcome:" in out and "perforated" in out and f"{vr:.6g} m/s" in out


def test_plates_separated_by_a_wide_gap_act_one_after_the_other():
    # normal impact on two thin plates (2 cm, thinner than the default step travel of
    # 0.1 m, which the solver bounds near each) 2 m apart, more than the body length:
    # the second plate sees the residual speed of the first, so the stack's residual
    # speed is the single plate's applied twice (to the integrators' 1e-3)
    plate = Layer(CONCRETE, 0.02)
    stack = Target("stack", (plate, Layer.gap(2.0), plate))
    v1 = simulate("p2", slab(0.02), 300.0).attrs["residual_velocity"]
    v2 = simulate("p2", slab(0.02), v1).attrs["residual_velocity"]
    vs = simulate("p2", stack, 300.0).attrs["residual_velocity"]
    assert v2 < v1 < 300.0
    assert vs == pytest.approx(v2, rel=1e-3)


def test_scipy_reference_perforates_too():
    # Radau on the same right-hand side: same outcome, residual speed within the
    # integrators' tolerance (rtol 1e-5 per step; 1e-3 covers the accumulated error)
    a = simulate("p2", slab(0.5), 400.0)
    b = simulate("p2", slab(0.5), 400.0, method="Radau")
    assert b.attrs["outcome"] == "perforated"
    assert b.attrs["residual_velocity"] == pytest.approx(a.attrs["residual_velocity"], rel=1e-3)
