"""The crater region reduces to Forrestal et al. (1994) in its limit.

In normal, frictionless impact on a half-space, pencore with ``crater_depth: k`` gives
:func:`pencore.closedform.forrestal_crater_depth` (``F = c z`` for ``z < k d``) to within the
solver's own error, which is the ring discretisation of the nose: the no-crater depth
against its exact closed form is off by 2.4e-4 at the default 48 nose rings and 1.1e-5 at
192 (O(n^-2)), and tightening rtol from 1e-5 to 1e-7 moves the crater depths by < 6e-5
(measured over concrete_crh3 at 300 and 900 m/s, k = 0 and 2). Hence a 5e-4 tolerance at
the default numerics, and 6e-5 at 192 rings to show the error is the rings', not the
crater's.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad

from pencore import closedform, get_projectile, get_target, simulate
from pencore.errors import TargetError
from pencore.inputs.library import projectile_from_dict
from pencore.inputs.numerics import Numerics
from pencore.inputs.target import Layer, Target
from pencore.kernels.crater import crater_shape, element_factor, fill_reference, nose_resistance
from pencore.kernels.dynamics import contact_loads, quat_to_matrix
from pencore.kernels.forces import default_model, model_loads
from pencore.run.initial import initial_state

CONCRETE = get_target("concrete").medium
CONE = projectile_from_dict(
    {"name": "cone30", "diameter": 0.0762,
     "nose": {"kind": "cone", "half_angle_deg": 30.0, "density": 7850.0},
     "shank": [{"length": 0.5, "density": 7850.0}]}
)  # fmt: skip
FLAT = projectile_from_dict(
    {"name": "flat", "diameter": 0.0762, "nose": {"kind": "flat", "density": 7850.0},
     "shank": [{"length": 0.4, "density": 7850.0}]}
)  # fmt: skip


def crater(k: float, medium=CONCRETE) -> Target:
    return Target.half_space(replace(medium, crater_depth=k))


def test_shape_is_forrestal_linear_force():
    # g(s) F_full(V) = c z along every trajectory of m dV^2/dz = -2 c z, c fixed by
    # continuity at k d: check the identity on such a trajectory
    p = get_projectile("concrete_crh3")
    a0, a2 = CONCRETE.coefficients[0], CONCRETE.coefficients[2]
    m, a, ns, kd = p.mass_properties().mass, p.radius, p.nose_factor(), 2.0 * p.diameter
    beta = math.pi * a * a * ns * a2 * kd / m
    v1 = 400.0
    c = math.pi * a * a * (a0 + ns * a2 * v1 * v1) / kd
    for z in np.linspace(0.0, kd, 7):
        v2 = v1 * v1 + c * (kd * kd - z * z) / m
        full = math.pi * a * a * (a0 + ns * a2 * v2)
        assert crater_shape(z / kd, beta) * full == pytest.approx(c * z, rel=1e-12, abs=1e-9)
    assert crater_shape(0.0, beta) == 0.0 and crater_shape(1.0, beta) == 1.0
    assert crater_shape(-0.1, beta) == 0.0 and crater_shape(1.5, beta) == 1.0


def _loads(p, target, z, v=500.0, obliquity=0.0, n_nose=48, tip=False):
    """State, rings and loads with the lowest band point (``tip``: the nose tip) ``z`` (m)
    below the face."""
    rings = p.rings(n_nose, n_nose // 2, 4).as_array()
    mp = p.mass_properties()
    bounds, coef, fric = target.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc, p.nose)
    y = initial_state(p, rings, v, math.radians(obliquity), 0.0, 0.0, None, 0.0, "cm")
    if tip:
        y[1] -= y[1] + quat_to_matrix(y[3:7])[1, 0] * mp.lc  # the tip on the face
    y[1] -= z
    return y, rings, model_loads(y, rings, bounds, coef, fric, 1e-3, 0, default_model())


def _forrestal(p, medium, kd, z, v):
    """Forrestal's crater force ``c z = g(s) pi a^2 (a0 + N* a2 V^2)`` (N)."""
    a0, a2 = medium.coefficients[0], medium.coefficients[2]
    m, a, ns = p.mass_properties().mass, p.radius, p.nose_factor()
    beta = math.pi * a * a * ns * a2 * kd / m
    return crater_shape(z / kd, beta) * math.pi * a * a * (a0 + ns * a2 * v * v)


@pytest.mark.parametrize("z_over_kd", [0.0005, 0.05, 0.3, 0.6, 0.95])
@pytest.mark.parametrize("n_nose", [48, 192])
def test_normal_entry_axial_force_is_c_z(z_over_kd, n_nose):
    # whatever part of the nose is embedded (z < L_n for all but the last) and whatever the
    # rings, the axial force is Forrestal's c z = g(s) pi a^2 (a0 + N* a2 V^2) with the
    # exact N*: each element's factor divides by the rings' own quadrature of the
    # normal-entry resistance (round-off only)
    p = get_projectile("concrete_crh3")
    kd = 2.0 * p.diameter
    y, _, (fb, mb, _) = _loads(p, crater(2.0), z_over_kd * kd, n_nose=n_nose, tip=True)
    v = float(np.linalg.norm(y[7:10]))
    assert -fb[0] == pytest.approx(_forrestal(p, CONCRETE, kd, z_over_kd * kd, v), rel=1e-9)
    assert abs(fb[1]) < 1e-9 * abs(fb[0]) and abs(mb[2]) < 1e-9 * abs(fb[0])


def _exact_resistance(p, medium, z, v):
    """The frictionless DAFL axial resistance (N) of a tangent-ogive nose tip-first to
    ``z`` (m) in normal entry, by adaptive quadrature along the axis of its profile
    ``r(s) = sqrt(R^2 - (L - s)^2) - (R - a)`` (independent of the kernel's nose columns,
    which integrate in the meridian angle): ``int 2 pi r r' sigma(V n_a) ds``,
    ``n_a = r' / sqrt(1 + r'^2)``."""
    a, ln = p.radius, p.nose_length
    ro = 2.0 * p.nose.crh * a
    coef = medium.coefficients

    def integrand(s):
        q = math.sqrt(ro * ro - (ln - s) ** 2)
        r, dr = q - (ro - a), (ln - s) / q
        na = dr / math.sqrt(1.0 + dr * dr)
        return 2.0 * math.pi * r * dr * sum(c * (v * na) ** k for k, c in enumerate(coef))

    return quad(integrand, 0.0, min(z, ln), epsabs=0.0, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize("z_cal", [0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0])
def test_crater_factor_is_the_same_on_every_ring_mesh(z_cal):
    # the factor Forrestal's law puts on the DAFL in normal entry, the crater load over the
    # exact profile's resistance at the same tip depth, g(s) F_full / R(z), on 1x and 4x
    # the rings: within the integrator's tolerance (rtol 1e-5) from 0.001 to 1 calibre
    # (it was 8.6 against 23.2 at 0.01 calibre with the rings' own resistance at the tip's
    # depth standing in for R); and R is the profile's, by an independent quadrature
    p = get_projectile("al_ogive_var4340")
    al = get_target("aluminium").medium
    z, v = z_cal * p.diameter, 500.0
    kd = 2.0 * p.diameter
    r = _exact_resistance(p, al, z, v)
    lam = [-_loads(p, crater(2.0, al), z, v, n_nose=n, tip=True)[2][0][0] / r for n in (48, 192)]
    assert lam[1] == pytest.approx(lam[0], rel=Numerics().rtol)
    assert lam[0] == pytest.approx(_forrestal(p, al, kd, z, v) / r, rel=1e-8)
    bounds = crater(2.0, al).kernel_arrays(p.diameter, 1.0, p.nose_length, 0.0, p.nose)[0]
    coef = np.array([al.coefficients])
    assert nose_resistance(z, v, bounds, coef, 0) == pytest.approx(r, rel=1e-9)


def test_the_rings_reference_tends_to_the_profile():
    # what the element factor divides by, the rings' own normal-entry resistance, tends to
    # the exact profile's (second order in the rings) where the rings resolve the depth
    p = get_projectile("al_ogive_var4340")
    al = get_target("aluminium").medium
    z = 0.1 * p.diameter
    r = _exact_resistance(p, al, z, 500.0)
    err = [
        abs(-_loads(p, Target.half_space(al), z, n_nose=n, tip=True)[2][0][0] / r - 1.0)
        for n in (48, 96, 192)
    ]
    assert err[2] < err[1] < err[0] < 0.05 and err[2] < err[0] / 10.0


def _ring_sum(p, target, y, rings, bounds, coef, fric):
    """The crater loads rebuilt ring by ring: each ring's DAFL loads (the ring alone,
    without the crater) times :func:`element_factor` at its centre's depth and its distance
    from the tip, with the rings' reference of :func:`fill_reference`."""
    plain_b, plain_c, plain_f = Target.half_space(CONCRETE).kernel_arrays()
    rot = quat_to_matrix(y[3:7])
    va = float(rot[:, 0] @ y[7:10])
    tab = np.empty((3, rings.shape[0]))
    fill_reference(tab, 0, *(np.ascontiguousarray(rings[:, k]) for k in range(5)), bounds,
                   coef, va, 1e-3)  # fmt: skip
    f, m = np.zeros(3), np.zeros(3)
    for j in range(rings.shape[0]):
        fj, mj, _ = contact_loads(y, rings[j : j + 1], plain_b, plain_c, plain_f, 1e-3, 0)
        height = y[1] + rot[1, 0] * rings[j, 0]
        lam = element_factor(height, bounds[0, 9] - rings[j, 0], va, bounds, coef, 0, tab, 0)
        f += lam * fj
        m += lam * mj
    return f, m


@pytest.mark.parametrize(("obliquity", "z_over_kd"), [(30.0, 0.4), (60.0, 0.05), (80.0, 0.3)])
def test_oblique_loads_are_the_dafl_loads_scaled_element_by_element(obliquity, z_over_kd):
    # oblique or yawed entry: each ring carries the factor of the normal entry that puts it
    # at its own depth (z_e = its depth + its distance from the tip), on its own DAFL load
    p = get_projectile("concrete_crh3")
    kd = 2.0 * p.diameter
    t = crater(2.0)
    y, rings, (fb, mb, _) = _loads(p, t, z_over_kd * kd, obliquity=obliquity, tip=True)
    mp = p.mass_properties()
    bounds, coef, fric = t.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc, p.nose)
    f, m = _ring_sum(p, t, y, rings, bounds, coef, fric)
    np.testing.assert_allclose(fb, f, rtol=1e-9, atol=1e-9 * abs(fb[0]))
    np.testing.assert_allclose(mb, m, rtol=1e-9, atol=1e-9 * abs(fb[0]) * p.diameter)


def test_a_body_deep_below_the_face_with_its_tip_shallow_carries_no_tip_factor():
    # a body turned towards the face, sliding along its axis: the axis 100 deg from the
    # inward normal (the nose up), the tip 0.01 calibre below the face, the rest deeper.
    # Each element carries its own depth's factor: the shank g(z_e / k d) <= 1, not the
    # ~26 of a tip at 0.01 calibre (8.6 on these rings with the rings' resistance) on the
    # whole side, so the crater's load is below the DAFL's
    p = get_projectile("concrete_crh3")
    z = 0.01 * p.diameter
    _, _, (fb, _, _) = _loads(p, crater(2.0), z, obliquity=100.0, tip=True)
    _, _, (f0, _, _) = _loads(p, Target.half_space(CONCRETE), z, obliquity=100.0, tip=True)
    assert 0.0 < np.linalg.norm(fb) < np.linalg.norm(f0)


def test_below_the_crater_the_loads_are_the_dafl():
    p = get_projectile("concrete_crh3")
    _, _, (fb, mb, _) = _loads(p, crater(2.0), 2.5 * p.diameter, obliquity=20.0)
    _, _, (f0, m0, _) = _loads(p, Target.half_space(CONCRETE), 2.5 * p.diameter, obliquity=20.0)
    np.testing.assert_allclose(fb, f0, rtol=1e-12, atol=1e-12 * abs(f0[0]))
    np.testing.assert_allclose(mb, m0, rtol=1e-12, atol=1e-12 * abs(f0[0]))


CASES = [
    ("concrete_crh3", 2.0, 100.0),  # stops in the crater (V1^2 < 0 below 123 m/s)
    ("concrete_crh3", 2.0, 300.0),
    ("concrete_crh3", 3.0, 900.0),
    ("concrete_crh4p25", 2.0, 300.0),
    ("concrete_crh4p25", 0.707 + 2.0, 600.0),  # Li & Chen's k = 0.707 + H/d
    ("cone", 2.0, 400.0),
    ("flat", 1.0, 400.0),
]


@pytest.mark.parametrize(("name", "k", "v"), CASES)
def test_normal_depth_is_forrestal(name, k, v):
    p = {"cone": CONE, "flat": FLAT}.get(name) or get_projectile(name)
    d = float(simulate(p, crater(k), v).penetration_depth)
    assert d == pytest.approx(closedform.forrestal_crater_depth(p, CONCRETE, v, k), rel=5e-4)


def test_forrestal_limit_converges_with_the_rings():
    p = get_projectile("concrete_crh3")
    ref = closedform.forrestal_crater_depth(p, CONCRETE, 300.0, 2.0)
    fine = float(simulate(p, crater(2.0), 300.0, numerics=Numerics(n_nose=192)).penetration_depth)
    assert fine == pytest.approx(ref, rel=6e-5)


def test_soil_and_the_closed_form_depth():
    soil = get_target("soil").medium
    p = get_projectile("p2")
    d = float(simulate("p2", crater(2.0, soil), 600.0).penetration_depth)
    assert d == pytest.approx(closedform.depth(p, replace(soil, crater_depth=2.0), 600.0), rel=5e-4)


def test_the_crater_reduces_the_depth_against_no_crater_by_the_lost_work():
    # a crater takes less work than the full law over k d, so it goes deeper, and the
    # gain grows with k; k -> L_n / d is the smallest crater allowed
    p = get_projectile("concrete_crh3")
    depths = [closedform.depth(p, replace(CONCRETE, crater_depth=k), 400.0) for k in (0, 2, 3)]
    assert depths[0] < depths[1] < depths[2]


def test_a_crater_shorter_than_the_nose_is_refused():
    p = get_projectile("concrete_crh3")  # nose 1.66 calibers
    with pytest.raises(TargetError, match=r"crater_depth 1\.0 calibers is shorter than the nose"):
        simulate(p, crater(1.0), 300.0)


@pytest.mark.parametrize("k", [2.0, 10.0])
def test_a_plate_thinner_than_the_crater_takes_a_slice_of_its_load(k):
    # the reference of the crater factor is the medium's half-space (Forrestal's c z is a
    # half-space's force): a foil inside the crater region takes the half-space's
    # factor on its own load, so its energy loss is proportional to its thickness (the
    # thin-plate limit) and below the loss without the crater. Against the plate's own
    # load as reference, a 1-um foil took 62 % of the energy at k = 2, a loss per
    # thickness 1e4 times the slice's. The loss per thickness of these crater runs
    # scatters by 2.4e-3 relative over rtol 1e-7..1e-9 (measured with each element's
    # factor: 1335.5-1338.6 m/s per m at 1-100 um): 1 % separates the two by far
    v0, rtol = 300.0, 1e-8
    al = get_target("aluminium").medium

    def loss(t: float, kc: float) -> float:
        medium = replace(al, crater_depth=kc)
        plate = Target("plate", (Layer(medium, t),))
        vr = simulate("p2", plate, v0, rtol=rtol).attrs["residual_velocity"]
        return v0 - vr

    thin, thick = loss(1e-5, k), loss(1e-4, k)
    assert thin == pytest.approx(0.1 * thick, rel=1e-2)
    assert 0.0 < thick < loss(1e-4, 0.0)
