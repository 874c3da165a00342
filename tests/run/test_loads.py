"""The loads of a trajectory (pencore.run.loads, the Dataset's load variables) against the
closed form of the axial force and against the momentum balance of the run itself."""

import numpy as np
import pytest

import pencore
from pencore import closedform
from pencore.inputs.library import MEDIA
from pencore.kernels.dynamics import quat_to_matrix
from pencore.run.dataset import STANDARD_GRAVITY
from pencore.run.impact import run_impact
from pencore.run.loads import body_loads

SOIL = MEDIA["soil"]


@pytest.mark.parametrize("velocity", [280.0, 1000.0])
def test_axial_force_once_embedded_is_the_closed_form(velocity):
    """Normal impact of the frictionless ogive p2: once the whole nose is in, the axial
    force at each saved state is pi a^2 (a0 + N* a2 V^2) at that state's speed. 5e-3 is
    the ring quadrature's error on the nose factor at the default mesh (the same bound as
    the kernel's own test, tests/run/test_impact.py); the shank carries no axial load and
    nothing lateral acts."""
    p = pencore.get_projectile("p2")
    ds = pencore.simulate(p, "soil", velocity)
    embedded = -ds.tip_y.values > p.nose_length + 0.05  # past the band ramps too
    speed = ds.speed.values[embedded]
    assert embedded.sum() > 20
    exact = np.array([closedform.axial_force(p, SOIL, v) for v in speed])
    np.testing.assert_allclose(ds.axial_force.values[embedded], exact, rtol=5e-3)
    assert ds.lateral_force.values.max() <= 1e-6 * ds.axial_force.values.max()
    # the deceleration is the axial force over the mass, in m/s^2 and in g
    np.testing.assert_array_equal(
        ds.deceleration.values, ds.axial_force.values / ds.attrs["mass_kg"]
    )
    np.testing.assert_allclose(
        ds.deceleration_g.values * STANDARD_GRAVITY, ds.deceleration.values, rtol=1e-15
    )
    # the force grows as the nose goes in and falls with the speed: its peak lies between
    # the closed form at the impact speed and at the speed once the nose is in
    peak = ds.attrs["peak_axial_force_N"]
    assert peak == ds.axial_force.values.max()
    assert exact[0] * (1 - 5e-3) <= peak <= closedform.axial_force(p, SOIL, velocity) * (1 + 5e-3)
    assert ds.attrs["peak_deceleration_g"] == peak / ds.attrs["mass_kg"] / STANDARD_GRAVITY


@pytest.mark.parametrize(
    "impact", [(1000.0, 45.0), (280.0, 0.0), (600.0, 20.0)], ids=["oblique", "normal", "20deg"]
)
@pytest.mark.parametrize("rtol", [1e-5, 1e-8])
def test_impulse_of_the_loads_is_the_momentum_change(impact, rtol):
    """m dv/dt = F + m g along a run: the impulse of the contact force (trapezoid over the
    saved states) plus gravity's equals the change of momentum m (v_k - v_0) at every saved
    state, within the sum of the local errors the step control allows up to it: each
    accepted step keeps the RMS over the 13 components of its scaled error estimate at or
    below 1, so one velocity component's local error is at most sqrt(13) (atol + rtol
    |v|). A differencing of the velocities would not meet this; a 1 % error in the loads
    exceeds it about 50 times (1e-2 of m |dv| against about 1e-4)."""
    velocity, obliquity = impact
    pr = pencore.prepare("p2", "soil", rtol=rtol)
    run = run_impact("p2", "soil", velocity, obliquity, prepared=pr)
    fb = body_loads(pr, run)[:, 0:3]
    force = np.array([quat_to_matrix(y[3:7]) @ f for y, f in zip(run.ys, fb, strict=True)])
    m, g = pr.mass, pr.gravity
    h = np.diff(run.ts)[:, None]
    v = run.ys[:, 7:10]
    momentum = m * (v[1:] - v[0])
    impulse = np.cumsum(h * (0.5 * (force[1:] + force[:-1]) + m * g), axis=0)
    atol = pr.atol(velocity)[7:10]
    allowed = np.cumsum(
        np.sqrt(13.0) * m * (atol + rtol * np.maximum(np.abs(v[1:]), np.abs(v[:-1]))), axis=0
    )
    assert np.all(np.abs(momentum - impulse) <= allowed)
    # and the balance is not met by a load 1 % off
    off = np.cumsum(h * (0.5 * 1.01 * (force[1:] + force[:-1]) + m * g), axis=0)
    assert not np.all(np.abs(momentum - off) <= allowed)


def test_oblique_run_has_lateral_loads_and_peaks_in_attributes():
    ds = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0)
    for name, units in [
        ("axial_force", "N"),
        ("lateral_force", "N"),
        ("deceleration", "m s-2"),
        ("deceleration_g", "1"),
    ]:
        assert ds[name].attrs["units"] == units and ds[name].attrs["long_name"]
        assert ds[name].dims == ("time",)
    assert ds.attrs["peak_lateral_force_N"] == ds.lateral_force.values.max() > 0.0
    i = int(np.argmax(np.abs(ds.deceleration.values)))
    assert ds.attrs["time_of_peak_deceleration_s"] == ds.time.values[i]
    assert ds.attrs["peak_deceleration_m_s2"] == abs(ds.deceleration.values[i])


def test_loads_do_not_change_the_trajectory():
    """The loads are evaluated after the run: the states are those of run_impact, bit for
    bit."""
    ds = pencore.simulate("p2", "soil", 700.0, obliquity=20.0)
    run = run_impact("p2", "soil", 700.0, 20.0)
    np.testing.assert_array_equal(ds.vel_x.values, run.ys[:, 7])
    np.testing.assert_array_equal(ds.time.values, run.ts)


def test_cavity_model_loads_see_the_path_of_their_step():
    """The cavity shank model's loads depend on the nose-tip path so far; rebuilding the path
    from the saved states gives, at the last state, the loads the integrator's own path
    gives (the path it ended with)."""
    from pencore.kernels.forces import model_loads

    pr = pencore.prepare("p2", "soil", shank="cavity")
    run = run_impact("p2", "soil", 600.0, 20.0, prepared=pr)
    loads = body_loads(pr, run)
    _, _, _, rings, bounds, coef, fric, eps, n_gauss, model = pr.load_args()
    path = run.path
    final = (model[0], model[1], model[2], path.copy(), np.array([path.shape[0]]))
    fb, mb, _ = model_loads(run.ys[-1], rings, bounds, coef, fric, eps, n_gauss, final)
    np.testing.assert_allclose(loads[-1, :3], fb, rtol=1e-9, atol=1e-9 * np.abs(fb).max())
    np.testing.assert_allclose(loads[-1, 3:], mb, rtol=1e-9, atol=1e-9 * np.abs(mb).max())


def test_explicit_emulation_loads_are_those_of_its_pure_contact_step():
    """The explicit scheme integrates the discontinuous contact step (eps = 0, whatever
    numerics.eps says): its loads are that law's, not the smoothed law's."""
    from pencore.kernels.forces import loads_along

    pr = pencore.prepare("p2", "soil", emulation={"integrator": "explicit", "dt": 2e-5})
    assert pr.numerics.eps > 0.0
    run = run_impact("p2", "soil", 300.0, 30.0, prepared=pr)
    loads = body_loads(pr, run)
    _, _, _, rings, bounds, coef, fric, eps, n_gauss, model = pr.load_args()

    def along(e):
        from pencore.integrators.driver import reserve_path, start_path
        from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP

        m = reserve_path(start_path(model, run.ys[0]), run.ys.shape[0] * MAX_SAMPLES_PER_STEP + 1)
        return loads_along(run.ts, run.ys, rings, bounds, coef, fric, e, n_gauss, m)

    np.testing.assert_array_equal(loads, along(0.0))
    assert not np.array_equal(loads, along(eps))  # the smoothed law is another load


@pytest.mark.parametrize(
    "kw", [{}, {"shank": "factor"}, {"emulation": {"surface": "panels"}}], ids=str
)
def test_loads_read_from_the_integrators_derivatives_are_the_evaluated_ones(kw):
    """A Rosenbrock run's loads come from the right-hand side each step started from,
    solved back through Newton's and Euler's equations: the same force and moment as
    evaluating the loads again at each saved state, to rounding. The derivative was taken
    before the step's quaternion was normalised (a relative 1e-16 apart); through the
    attitude that moves an element's normal velocity by about 2 u |v| (u the unit
    roundoff), and the contact step smoothed over eps = 1e-3 m/s turns that into a
    relative change of the element's stress up to 2 u |v| / eps: the bound, times 2."""
    import math

    from pencore.integrators.driver import reserve_path, start_path
    from pencore.integrators.rosenbrock import integrate
    from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP
    from pencore.kernels.forces import loads_along
    from pencore.run.initial import initial_state

    pr = pencore.prepare("p2", "soil", **kw)
    y0 = initial_state(pr.projectile, pr.rings, 800.0, math.radians(30.0), 0.0, 10.0, None)
    run = integrate(pr, y0, 800.0, keep_derivatives=True)
    assert run.fs is not None and run.fs.shape == run.ys.shape
    # the same run, bit for bit, as the one without the derivatives a search takes
    bare = integrate(pr, y0, 800.0)
    assert bare.fs is None
    np.testing.assert_array_equal(bare.ys, run.ys)
    _, _, _, rings, bounds, coef, fric, eps, n_gauss, model = pr.load_args()
    m = reserve_path(start_path(model, run.ys[0]), run.ys.shape[0] * MAX_SAMPLES_PER_STEP + 1)
    again = loads_along(run.ts, run.ys, rings, bounds, coef, fric, eps, n_gauss, m)
    read = body_loads(pr, run)
    bound = 4.0 * np.finfo(float).eps * 800.0 / pr.numerics.eps
    for cols in (slice(0, 3), slice(3, 6)):
        scale = np.abs(again[:, cols]).max()
        assert scale > 0.0
        np.testing.assert_allclose(read[:, cols], again[:, cols], rtol=0, atol=bound * scale)
    # and a force 1 % off is not within it
    force_scale = np.abs(again[:, 0:3]).max()
    assert not np.allclose(read[:, 0:3], 1.01 * again[:, 0:3], rtol=0, atol=bound * force_scale)
