"""Paper-emulation numerics (pencore.inputs.models.Emulation): the faceted panel surface and
the fixed-step explicit integrator converge to pencore's default solution as refined."""

import math

import numpy as np
import pytest

import pencore
from pencore.inputs.geometry import Cylinder, OgiveNose, Projectile
from pencore.inputs.target import Medium, Target
from pencore.kernels.panels import panel_points

CASE = dict(velocity=1000.0, obliquity=45.0)  # the oblique benchmark of the README


def _rel(ds, ref, name):
    return abs(float(ds[name]) / float(ref[name]) - 1.0)


def test_panels_tile_the_faceted_body():
    """Panel areas sum to the faceted surface, and the nose panels' projected area on
    the axis is the inscribed polygon's, (N / 2) a^2 sin(2 pi / N)."""
    p = Projectile("t", 0.095, OgiveNose(3.0, 7850.0), (Cylinder(0.5, 5150.0),))
    a = p.radius
    for n in (8, 16, 36):
        pts = panel_points(p, 24, 12, 4, n)
        nose = (pts[:, 7] == 0) & (pts[:, 3] > 0.0)
        projected = float((pts[nose, 6] * pts[nose, 3]).sum())
        assert projected == pytest.approx(0.5 * n * a * a * math.sin(2 * math.pi / n), rel=1e-12)
        rear = pts[:, 3] < -0.5
        assert float(pts[rear, 6].sum()) == pytest.approx(projected, rel=1e-12)
        shank = pts[:, 7] == 1
        # the shank facets: N flat strips of width 2 a sin(pi / N) along the 0.5 m shank
        assert float(pts[shank, 6].sum()) == pytest.approx(
            0.5 * n * 2 * a * math.sin(math.pi / n), rel=1e-12
        )
        assert np.allclose(np.linalg.norm(pts[:, 3:6], axis=1), 1.0)


def test_panel_axial_force_is_a0_times_the_polygon_area():
    """Embedded nose moving along its axis with sigma = a0 only: every nose panel is
    loaded, so the axial force is a0 times the projected (polygon) area, and the
    lateral force and moment vanish."""
    from pencore.kernels.forces import model_loads
    from pencore.run.impact import prepare
    from pencore.run.initial import _axis_quaternion

    a0 = 17.18e6
    t = Target.half_space(Medium("a0-only", (a0,)))
    n = 16
    pr = prepare("p2", t, emulation={"surface": "panels", "n_circumferential": n})
    y = np.zeros(14)
    y[3:7] = _axis_quaternion(0.0)
    y[1] = -3.0
    y[8] = -500.0
    fb, mb, _ = model_loads(y, pr.kernel_rings, pr.bounds, pr.coef, pr.fric, 1e-3, 0, pr.model)
    area = 0.5 * n * pr.projectile.radius**2 * math.sin(2 * math.pi / n)
    assert -fb[0] == pytest.approx(a0 * area, rel=1e-9)
    assert abs(fb[1]) + abs(fb[2]) < 1e-9 * abs(fb[0])
    assert np.abs(mb).max() < 1e-9 * abs(fb[0]) * pr.projectile.length


def test_panels_converge_to_the_rings():
    """Refining the panels (bands along the axis and around, together, x2 each time)
    takes the oblique depth and path to the converged ring solution with the polygon's
    second-order error: it falls 3.5-4.5x per refinement, to < 0.6 % with 48 around."""
    ref = pencore.simulate("p2", "soil", **CASE, n_nose=96, n_shank=48, rtol=1e-7, max_travel=0.02)
    errs = {"penetration_depth": [], "path_length": []}
    for m in (1, 2, 4):
        ds = pencore.simulate(
            "p2",
            "soil",
            **CASE,
            n_nose=12 * m,
            n_shank=6 * m,
            emulation={"surface": "panels", "n_circumferential": 12 * m},
        )
        for k in errs:
            errs[k].append(_rel(ds, ref, k))
    for k, e in errs.items():
        assert e[0] > e[1] > e[2], (k, e)
        assert 3.5 < e[0] / e[1] < 4.5 and 3.5 < e[1] / e[2] < 4.5, (k, e)
        assert e[2] < 6e-3, (k, e)


def test_explicit_converges_to_the_adaptive_solution():
    """dt 4 -> 2 -> 1 us with the pure Heaviside on the default rings: the oblique
    path's error halves each time (first order: the shank's lateral load chatters from
    step to step) and the depth's error falls; at 1 us both are within 0.06 % of the
    adaptive solution on the same rings at tight tolerance."""
    ref = pencore.simulate("p2", "soil", **CASE, rtol=1e-8, max_travel=0.01)
    errs = {"penetration_depth": [], "path_length": []}
    for dt in (4e-6, 2e-6, 1e-6):
        ds = pencore.simulate("p2", "soil", **CASE, emulation={"integrator": "explicit", "dt": dt})
        assert ds.attrs["outcome"] == "stopped"
        for k in errs:
            errs[k].append(_rel(ds, ref, k))
    for k, e in errs.items():
        assert e[0] > e[1] > e[2], (k, e)
        assert e[2] < 6e-4, (k, e)
    p = errs["path_length"]
    assert 1.6 < p[0] / p[1] < 2.4 and 1.6 < p[1] / p[2] < 2.4


def test_explicit_energy_balance_and_stops():
    """The leapfrog's work of the loads balances the kinetic energy of the saved
    (half-step) velocities: exactly for translation, to O(dt) for the rotation."""
    ds = pencore.simulate(
        "p2",
        "soil",
        **CASE,
        emulation={
            "surface": "panels",
            "n_circumferential": 16,
            "integrator": "explicit",
            "dt": 2e-6,
        },
    )
    ke = ds.kinetic_energy.values
    assert ds.attrs["outcome"] == "stopped"
    assert ke[-1] < 0.01 * ke[0]
    assert abs(ke[0] - ke[-1] + ds.work.values[-1]) / ke[0] < 1e-3


def test_explicit_normal_impact_matches_the_closed_form():
    from pencore import closedform
    from pencore.inputs.library import MEDIA, get_projectile

    ds = pencore.simulate("p2", "soil", 280.0, emulation={"integrator": "explicit", "dt": 2e-6})
    ref = closedform.depth(get_projectile("p2"), MEDIA["soil"], 280.0)
    assert float(ds.penetration_depth) == pytest.approx(ref, rel=2e-3)
    assert np.abs(ds.tip_x.values).max() < 1e-9


def test_panels_mirror_symmetry():
    """An even number of panels is symmetric about the plane across the plane of
    motion, so yaw -> -yaw mirrors x (within the runs' own integration error)."""
    em = {"surface": "panels", "n_circumferential": 16}
    plus = pencore.simulate("p4", "soil", 500.0, yaw=2.0, emulation=em)
    minus = pencore.simulate("p4", "soil", 500.0, yaw=-2.0, emulation=em)
    ref = pencore.simulate("p4", "soil", 500.0, yaw=2.0, emulation=em, rtol=1e-7, max_travel=0.01)
    err = abs(float(plus.tip_x[-1]) - float(ref.tip_x[-1])) + abs(
        float(plus.tip_y[-1]) - float(ref.tip_y[-1])
    )
    assert abs(float(minus.tip_x[-1]) + float(plus.tip_x[-1])) <= 2 * err + 1e-9
    assert abs(float(minus.tip_y[-1]) - float(plus.tip_y[-1])) <= 2 * err + 1e-9
    assert abs(float(plus.tip_x[-1])) > 100 * (2 * err + 1e-9)


@pytest.mark.slow  # a panel trajectory under scipy's integrator (~6 s)
def test_panels_under_scipy_agree_with_the_compiled_integrator():
    em = {"surface": "panels", "n_circumferential": 24}
    a = pencore.simulate("p2", "soil", 600.0, obliquity=20.0, emulation=em, rtol=1e-7)
    b = pencore.simulate("p2", "soil", 600.0, obliquity=20.0, emulation=em, rtol=1e-7, method="BDF")
    assert float(a.path_length) == pytest.approx(float(b.path_length), rel=1e-4)


@pytest.mark.parametrize(
    "em, match",
    [
        ({"surface": "facets"}, "emulation surface"),
        ({"integrator": "leapfrog"}, "emulation integrator"),
        ({"n_circumferential": 2}, "n_circumferential"),
        ({"dt": 0.0}, "explicit dt"),
        ({"dt": 1e-6, "dtt": 1}, "did you mean 'dt'"),
        ("panels", "emulation must be"),
    ],
)
def test_bad_emulation_options_are_one_line_input_errors(em, match):
    with pytest.raises(pencore.InputError, match=match):
        pencore.simulate("p2", "soil", 300.0, emulation=em)


def test_explicit_needs_no_adaptive_method():
    with pytest.raises(pencore.InputError, match="explicit integrator"):
        pencore.simulate("p2", "soil", 300.0, emulation={"integrator": "explicit"}, method="BDF")


def test_docs_state_the_model_ranges():
    from pathlib import Path

    page = (Path(__file__).resolve().parents[2] / "docs/user-guide/inputs.md").read_text()
    assert "```{include} ../_generated/limits_models.md" in page
