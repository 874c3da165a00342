"""The solver against closed forms, symmetries, energy and its own convergence."""

import math

import numpy as np
import pytest
import xarray as xr
from scipy.interpolate import CubicHermiteSpline

import pencore
from pencore import closedform
from pencore.inputs.geometry import ConeNose, Cylinder, OgiveNose, Projectile
from pencore.inputs.library import MEDIA
from pencore.inputs.target import Layer, Medium, Target
from pencore.kernels.dynamics import contact_loads
from pencore.run.impact import prepare
from pencore.run.initial import _axis_quaternion

SOIL = MEDIA["soil"]
# Symmetries hold exactly for the equations, but two runs of mirrored or rotated cases
# take adaptive step sequences that differ at round-off level (the kernel's sums run in
# another order), and on some CPUs they differ by a step or two over a run. So the two
# runs differ by up to the sum of their integration errors, and that is the tolerance:
# each run's error is measured against the same case at 100x tighter rtol (whose own
# error is >20x smaller for this 2nd-order pair), and the symmetry defect must stay
# within 1.5x the sum (the 1.5 covers the reference's own error).
REF = dict(rtol=1e-7, max_travel=0.01)
NOSES = {
    "ogive_crh3": OgiveNose(3.0, 7850.0),
    "hemisphere": OgiveNose(0.5, 7850.0),
    "cone_30": ConeNose(math.radians(30.0), 7850.0),
}


def _body(nose):
    return Projectile("t", 0.095, nose, (Cylinder(0.5, 5150.0),))


def _embedded_state(velocity):
    """Axis along -y, moving along the axis, centre of mass 3 m deep."""
    y = np.zeros(14)
    y[3:7] = _axis_quaternion(0.0)
    y[1] = -3.0
    y[8] = -velocity
    return y


@pytest.mark.parametrize("name", list(NOSES))
@pytest.mark.parametrize("velocity", [100.0, 800.0, 2000.0])
def test_axial_force_equals_nose_factor_closed_form(name, velocity):
    p = _body(NOSES[name])
    pr = prepare(p, "soil")
    fb, mb, _ = contact_loads(
        _embedded_state(velocity), pr.rings, pr.bounds, pr.coef, pr.fric, pr.numerics.eps, 0
    )
    exact = closedform.axial_force(p, SOIL, velocity)
    assert -fb[0] == pytest.approx(exact, rel=5e-3)
    # no lateral force or moment at zero angle of attack
    assert abs(fb[1]) + abs(fb[2]) < 1e-6 * exact
    assert np.abs(mb).max() < 1e-6 * exact


@pytest.mark.parametrize("name", list(NOSES))
@pytest.mark.parametrize("velocity", [280.0, 1200.0])
def test_normal_depth_matches_closed_form(name, velocity):
    """Reference: the exact 1-D DAFL solution (nose-entry phase integrated exactly by
    quadrature, then the log formula), see pencore.closedform."""
    p = _body(NOSES[name])
    ds = pencore.simulate(p, "soil", velocity)
    ref = closedform.depth(p, SOIL, velocity)
    assert float(ds.penetration_depth) == pytest.approx(ref, rel=2e-3)
    assert ds.attrs["outcome"] == "stopped"


def test_axisymmetric_normal_impact_stays_on_axis():
    ds = pencore.simulate("p2", "soil", 1000.0)
    assert np.abs(ds.tip_x.values).max() < 1e-9
    assert np.abs(ds.tip_z.values).max() < 1e-9
    assert ds.attrs["reversed"] == 0


def _on_grid(ds, t, name):
    """Centre-of-mass coordinate ``cm_x``/``cm_y``/``cm_z`` at times ``t``: cubic Hermite
    interpolation with the saved velocities (O(h^4), far below the integration error
    compared here)."""
    vel = {"cm_x": "vel_x", "cm_y": "vel_y", "cm_z": "vel_z"}[name]
    spline = CubicHermiteSpline(ds.time.values, ds[name].values, ds[vel].values)
    return spline(t)


def _common_times(*runs, n=2000):
    """Times inside every run, short of the stop (detected at step ends, so two runs
    may stop a step apart)."""
    return np.linspace(0.0, 0.98 * min(r.time.values[-1] for r in runs), n)


def _error(run, ref, t, names=("cm_x", "cm_y", "cm_z")):
    """Largest integration error of ``run`` on ``t`` against the tighter ``ref`` (m)."""
    return max(np.abs(_on_grid(run, t, k) - _on_grid(ref, t, k)).max() for k in names)


MIRROR_CASES = [
    (500.0, dict(yaw=2.0)),
    (900.0, dict(omega=20.0)),
    (700.0, dict(yaw=1.0, omega=-10.0)),
]


@pytest.mark.parametrize("velocity, kw", MIRROR_CASES)
def test_mirror_symmetry(velocity, kw):
    """yaw/omega -> -yaw/-omega mirrors x, to within the two runs' integration errors."""
    flip = {k: -v for k, v in kw.items()}
    plus = pencore.simulate("p4", "soil", velocity, **kw)
    minus = pencore.simulate("p4", "soil", velocity, **flip)
    ref_plus = pencore.simulate("p4", "soil", velocity, **REF, **kw)
    ref_minus = pencore.simulate("p4", "soil", velocity, **REF, **flip)
    t = _common_times(plus, minus, ref_plus, ref_minus)
    budget = 1.5 * (_error(plus, ref_plus, t) + _error(minus, ref_minus, t))
    assert np.abs(_on_grid(minus, t, "cm_x") + _on_grid(plus, t, "cm_x")).max() <= budget
    assert np.abs(_on_grid(minus, t, "cm_y") - _on_grid(plus, t, "cm_y")).max() <= budget
    assert np.abs(_on_grid(minus, t, "cm_z") - _on_grid(plus, t, "cm_z")).max() <= budget
    path_budget = 1.5 * sum(
        abs(float(a.path_length) - float(b.path_length))
        for a, b in ((plus, ref_plus), (minus, ref_minus))
    )
    assert abs(float(minus.path_length) - float(plus.path_length)) <= path_budget
    # the case is not trivially symmetric: the path leaves the axis by far more than the
    # tolerance, so a sign error in the lateral physics would fail the test
    assert abs(plus.tip_x.values[-1]) > 10 * budget


def test_rotation_about_the_normal_rotates_the_trajectory():
    """Turning the impact by 37 deg about the normal turns the path, to within the two
    runs' integration errors (see REF)."""
    kw = dict(obliquity=30.0, yaw=2.0, omega=3.0)
    a = pencore.simulate("p2", "soil", 800.0, **kw)
    b = pencore.simulate("p2", "soil", 800.0, azimuth=37.0, **kw)
    ref_a = pencore.simulate("p2", "soil", 800.0, **REF, **kw)
    ref_b = pencore.simulate("p2", "soil", 800.0, azimuth=37.0, **REF, **kw)
    c, s = math.cos(math.radians(37.0)), math.sin(math.radians(37.0))
    t = _common_times(a, b, ref_a, ref_b)
    budget = 1.5 * (_error(a, ref_a, t) + _error(b, ref_b, t))
    xa, ya, za = (_on_grid(a, t, k) for k in ("cm_x", "cm_y", "cm_z"))
    xb, yb, zb = (_on_grid(b, t, k) for k in ("cm_x", "cm_y", "cm_z"))
    assert np.abs(c * xa + s * za - xb).max() <= budget
    assert np.abs(-s * xa + c * za - zb).max() <= budget
    assert np.abs(ya - yb).max() <= budget
    for name in ("path_length", "penetration_depth"):
        err = abs(float(a[name]) - float(ref_a[name])) + abs(float(b[name]) - float(ref_b[name]))
        assert abs(float(b[name]) - float(a[name])) <= 1.5 * err + 1e-12


def _energy_error(ds):
    ke = ds.kinetic_energy.values
    return abs(ke[0] - ke[-1] + ds.work.values[-1]) / ke[0]


def test_energy_balance_frictionless():
    ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    assert ds.kinetic_energy.values[-1] < 0.01 * ds.kinetic_energy.values[0]
    assert _energy_error(ds) < 1e-3


def test_friction_dissipates_more():
    rough = Target.half_space(SOIL.with_friction(0.1))
    smooth = pencore.simulate("p2", "soil", 600.0, obliquity=20.0)
    ds = pencore.simulate("p2", rough, 600.0, obliquity=20.0)
    assert _energy_error(ds) < 1e-3  # the work integral includes the friction stresses
    assert float(ds.path_length) < 0.95 * float(smooth.path_length)
    # at the same time the rough run has lost more kinetic energy
    t = min(ds.time.values[-1], smooth.time.values[-1]) * 0.5
    ke_rough = np.interp(t, ds.time.values, ds.kinetic_energy.values)
    ke_smooth = np.interp(t, smooth.time.values, smooth.kinetic_energy.values)
    assert ke_rough < ke_smooth


def test_velocity_dependent_friction_lies_between_its_bounds():
    hi = Target.half_space(SOIL.with_friction(0.2))
    lo = Target.half_space(SOIL.with_friction(0.05))
    table = Target.half_space(SOIL.with_friction([(0.0, 0.2), (100.0, 0.05)]))
    d = [float(pencore.simulate("p2", t, 500.0).path_length) for t in (hi, table, lo)]
    assert d[0] < d[1] < d[2]


def test_layers_of_one_medium_equal_the_half_space():
    layered = Target("two", (Layer(SOIL, 2.0), Layer(SOIL)))
    a = pencore.simulate("p2", "soil", 700.0, obliquity=20.0)
    b = pencore.simulate("p2", layered, 700.0, obliquity=20.0)
    assert float(b.path_length) == pytest.approx(float(a.path_length), rel=1e-5)


def test_weak_top_layer_lets_the_projectile_go_deeper():
    weak = Medium("weak", (0.2 * SOIL.coefficients[0], 0.0, 0.2 * SOIL.coefficients[2]))
    layered = Target("weak-over-soil", (Layer(weak, 2.0), Layer(SOIL)))
    a = float(pencore.simulate("p2", "soil", 500.0).penetration_depth)
    b = float(pencore.simulate("p2", layered, 500.0).penetration_depth)
    assert b > a + 1.0


@pytest.mark.parametrize("velocity", [1500.0, 1700.0])
def test_convergence_under_step_halving_and_mesh_doubling(velocity):
    """p2 at 45 deg from the Fig. 7 start (-1, 1) m: depth, path and the reversal verdict
    do not change when the step is halved (rtol / 8 for the 2nd-order pair, max_travel / 2)
    or the surface mesh doubled."""
    base = dict(obliquity=45.0, start=(-1.0, 1.0, 0.0))
    num = pencore.Numerics()
    runs = [
        pencore.simulate("p2", "soil", velocity, **base),
        pencore.simulate(
            "p2", "soil", velocity, rtol=num.rtol / 8, max_travel=num.max_travel / 2, **base
        ),
        pencore.simulate(
            "p2", "soil", velocity, n_nose=2 * num.n_nose, n_shank=2 * num.n_shank, **base
        ),
    ]
    ref = runs[0]
    for r in runs[1:]:
        assert r.attrs["reversed"] == ref.attrs["reversed"]
        assert float(r.penetration_depth) == pytest.approx(float(ref.penetration_depth), rel=2e-3)
        assert float(r.path_length) == pytest.approx(float(ref.path_length), rel=2e-3)
    assert ref.attrs["reversed"] == (1 if velocity == 1700.0 else 0)


def test_netcdf_round_trip(tmp_path):
    ds = pencore.simulate("p2", "soil", 600.0, obliquity=30.0, yaw=1.0)
    path = tmp_path / "run.nc"
    ds.to_netcdf(path, engine="netcdf4")
    back = xr.load_dataset(path, engine="netcdf4")
    xr.testing.assert_identical(ds, back)


def test_stop_at_reversal_ends_early():
    full = pencore.simulate("p2", "soil", 1700.0, obliquity=45.0)
    early = pencore.simulate("p2", "soil", 1700.0, obliquity=45.0, stop_at_reversal=True)
    assert full.attrs["reversed"] == 1 and early.attrs["outcome"] == "reversed"
    assert early.sizes["time"] < full.sizes["time"]
    assert early.vel_y.values[-1] >= 0.0 > early.vel_y.values[-2]


def test_gravity_option_pulls_down_in_free_flight():
    a = pencore.simulate("p2", "soil", 300.0, start=(0.0, 2.0, 0.0))
    b = pencore.simulate("p2", "soil", 300.0, start=(0.0, 2.0, 0.0), gravity=9.81)
    assert float(b.penetration_depth) > float(a.penetration_depth)


@pytest.mark.parametrize(
    "kw, match",
    [
        (dict(velocity=-5.0), "velocity"),
        (dict(velocity=0.0), "velocity"),
        (dict(velocity=100.0, obliquity=95.0), "obliquity"),
        (dict(velocity=100.0, eps=-1.0), "eps"),
        (dict(velocity=100.0, bogus=1.0), "bogus"),
    ],
)
def test_bad_arguments_raise_input_error(kw, match):
    with pytest.raises(pencore.InputError, match=match):
        pencore.simulate("p2", "soil", **kw)


def test_friction_table_zero_at_both_ends_still_acts():
    """A mu(V_tau) table that is zero at both ends but not in between must still load."""
    hump = Target.half_space(SOIL.with_friction([(0.0, 0.0), (200.0, 0.2), (400.0, 0.0)]))
    smooth = pencore.simulate("p2", "soil", 500.0)
    ds = pencore.simulate("p2", hump, 500.0)
    assert float(ds.path_length) < 0.9 * float(smooth.path_length)
    assert _energy_error(ds) < 1e-3


def test_held_jacobian_keeps_the_solution():
    # the second-order Rosenbrock step is a W-method (order 2 for any Jacobian), so
    # holding the Jacobian for several steps changes the trajectory only at the level
    # of the step error control (rtol 1e-5): path and depth of the benchmark case
    # agree with a fresh Jacobian every step to 1e-4 relative (10 x rtol, as the
    # errors of ~400 steps add up), with fewer right-hand-side calls
    # (finite-difference Jacobians, whose cost the held Jacobian saves)
    runs = {
        age: pencore.simulate(
            "p2", "soil", 1000.0, obliquity=45.0, jacobian_age=age, jacobian="finite_difference"
        )
        for age in (1, 6, 50)
    }
    for age in (6, 50):
        for q in ("path_length", "penetration_depth"):
            fresh, held = float(runs[1][q]), float(runs[age][q])
            assert abs(held / fresh - 1.0) < 1e-4, (age, q, held, fresh)
    assert runs[6].attrs["n_rhs"] < runs[1].attrs["n_rhs"]


def test_path_below_surface_clips_entry_and_skips_flight_above():
    # a tip path that enters at 45 deg, leaves, and re-enters: the length below y = 0
    # is the straight-line geometry, each entry clipped at the surface
    from pencore.run.dataset import _path_below, rotation_matrices

    tip = np.array(
        [[0.0, 1.0, 0.0], [2.0, -1.0, 0.0], [3.0, -2.0, 0.0], [5.0, 1.0, 0.0], [6.0, -3.0, 0.0]]
    )
    below = tip[:, 1] <= 0.0
    expected = (
        math.sqrt(2.0)  # (1, 0) -> (2, -1): the half below the surface
        + math.sqrt(2.0)  # (2, -1) -> (3, -2)
        + 0.75 * math.hypot(1.0, 4.0)  # (5, 1) -> (6, -3): 3/4 of it below
    )
    assert _path_below(tip, below) == pytest.approx(expected, rel=1e-14)
    assert _path_below(tip[:1], below[:1]) == 0.0
    # body axis 1 of a quarter turn about z: (1, 0, 0) -> (0, 1, 0); unnormalised input
    q = np.array([[2.0 * math.cos(math.pi / 4), 0.0, 0.0, 2.0 * math.sin(math.pi / 4)]])
    assert rotation_matrices(q)[0, :, 0] == pytest.approx([0.0, 1.0, 0.0], abs=1e-15)


def test_rotation_matrices_are_the_kernels_bit_for_bit():
    # the Dataset's nose axes and the loads read back use the kernels' rotation exactly
    from pencore.kernels.dynamics import quat_to_matrix
    from pencore.run.dataset import rotation_matrices

    q = np.random.default_rng(7).normal(size=(50, 4)) * 3.0  # unnormalised
    expected = np.stack([quat_to_matrix(row) for row in q])
    assert np.array_equal(rotation_matrices(q), expected)


def test_most_coefficients_the_kernels_hold_and_a_clear_error_beyond():
    # zero-padding the soil law to MAX_COEFFICIENTS terms is the same law: the run must
    # not change (an oblique entry exercises the ramps and the Jacobian's cubic moments,
    # whose scratch is the tightest); one coefficient more is refused by name
    from pencore.errors import TargetError
    from pencore.inputs.target import MAX_COEFFICIENTS
    from pencore.kernels.arcs import _MAXD

    assert MAX_COEFFICIENTS + 4 <= _MAXD + 2
    soil = MEDIA["soil"]
    padded = Medium(
        "soil-padded", soil.coefficients + (0.0,) * (MAX_COEFFICIENTS - len(soil.coefficients))
    )
    a = pencore.simulate("p2", Target("a", (Layer(soil),)), 600.0, 45.0)
    b = pencore.simulate("p2", Target("b", (Layer(padded),)), 600.0, 45.0)
    assert float(b.path_length) == pytest.approx(float(a.path_length), rel=1e-12)
    assert float(b.final_deviation) == pytest.approx(float(a.final_deviation), rel=1e-9)
    with pytest.raises(TargetError, match=r"9 resistance coefficients given.*at most 8"):
        Medium("too-many", (1e7,) * 9)


def test_run_impact_takes_simulates_arguments():
    """run_impact's parameters are simulate's (one signature): the same names, kinds and
    defaults, the same checks; a positional ``start`` is refused as by simulate."""
    import inspect

    from pencore.run.impact import run_impact

    sim, raw = inspect.signature(pencore.simulate), inspect.signature(run_impact)
    assert list(raw.parameters.values()) == list(sim.parameters.values())
    for call in (pencore.simulate, run_impact):
        with pytest.raises(TypeError):
            call("p2", "soil", 300.0, 0.0, 0.0, 0.0, (0.0, 1.0, 0.0))
        with pytest.raises(pencore.InputError, match="velocity"):
            call("p2", "soil", -1.0)
