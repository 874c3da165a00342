"""Free-surface resistance ramps and the window columns (the crater: test_crater.py).

* off (the default) changes nothing, to the last bit;
* the free-surface ramp leaves elements far from a free face unchanged, and on a thick
  slab (rear face never reached) it is the half-space's front-face ramp.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from pencore import get_projectile, get_target, simulate
from pencore.errors import TargetError
from pencore.inputs.library import target_from_dict
from pencore.inputs.target import Layer, Target
from pencore.kernels.dynamics import contact_loads
from pencore.run.initial import initial_state

CONCRETE = get_target("concrete").medium
P2 = get_projectile("p2")


def half_space(**kw) -> Target:
    return Target.half_space(replace(CONCRETE, **kw))


def test_off_is_bit_identical():
    a = simulate("p2", "concrete", 350.0, 30.0, 1.0)
    b = simulate("p2", half_space(crater_depth=0.0, free_surface_depth=0.0), 350.0, 30.0, 1.0)
    for v in ("tip_x", "tip_y", "vel_x", "vel_y", "omega_3", "work"):
        assert np.array_equal(a[v].values, b[v].values)
    assert half_space().kernel_arrays(P2.diameter)[0].shape[1] == 2


def test_free_surface_far_from_faces_is_unchanged():
    # an element more than k_f d from every free face carries the full stress
    t = target_from_dict(
        {"name": "slab", "layers": [{"medium": "concrete", "thickness": 3.0,
                                     "free_surface_depth": 1.0}]}
    )  # fmt: skip
    pr_on = t.kernel_arrays(P2.diameter)
    pr_off = Target("plain", (Layer(CONCRETE, 3.0),)).kernel_arrays(P2.diameter)
    rings = P2.rings(48, 24, 4).as_array()
    y = initial_state(P2, rings, 300.0, math.radians(20.0), 0.0, 0.0, None, 0.0, "cm")
    y[1] -= 1.5  # body around 1.5 m deep: > 1 caliber from both faces
    f_on = contact_loads(y, rings, *pr_on, 1e-3, 0)
    f_off = contact_loads(y, rings, *pr_off, 1e-3, 0)
    assert np.array_equal(f_on[0], f_off[0]) and np.array_equal(f_on[1], f_off[1])
    # and an element within the zone of the rear face is reduced
    y[1] -= 1.5 - 0.05
    assert abs(contact_loads(y, rings, *pr_on, 1e-3, 0)[0][0]) < abs(
        contact_loads(y, rings, *pr_off, 1e-3, 0)[0][0]
    )


def test_free_surface_on_a_thick_slab_is_the_half_space_front_ramp():
    # the rear face is never reached, so only the front-face ramp acts, as on a
    # half-space with the same zone: the same trajectory to round-off
    slab = Target("slab", (Layer(replace(CONCRETE, free_surface_depth=1.5), 3.0),))
    a = simulate("p2", slab, 400.0, 15.0)
    b = simulate("p2", half_space(free_surface_depth=1.5), 400.0, 15.0)
    np.testing.assert_allclose(a.tip_y.values, b.tip_y.values, rtol=1e-12, atol=0)


def test_free_surface_raises_the_residual_speed():
    plain = Target("slab", (Layer(CONCRETE, 0.6),))
    fs = plain.with_windows(free_surface_depth=1.0)
    v_plain = simulate("p2", plain, 600.0).attrs["residual_velocity"]
    v_fs = simulate("p2", fs, 600.0).attrs["residual_velocity"]
    assert v_fs > v_plain


def test_windows_need_the_diameter():
    with pytest.raises(TargetError, match="diameter"):
        half_space(crater_depth=2.0).kernel_arrays()
    with pytest.raises(TargetError, match="mass, nose"):
        half_space(crater_depth=2.0).kernel_arrays(P2.diameter)


def test_yaml_keys_and_their_limits():
    from pencore.errors import InputError

    medium = {"name": "c", "coefficients": [283.5e6, 0.0, 1960.0], "crater_depth": 2.0}
    t = target_from_dict({"name": "t", "layers": [{"medium": medium}]})
    assert t.medium.crater_depth == 2.0 and t.medium.free_surface_depth == 0.0
    t = target_from_dict(
        {"name": "t", "layers": [{"medium": "concrete", "thickness": 1.0, "crater_depth": 1.5}]}
    )
    assert t.medium.crater_depth == 1.5 and t.medium.coefficients == CONCRETE.coefficients
    with pytest.raises(InputError, match="crater depth"):
        target_from_dict({"name": "t", "layers": [{"medium": "concrete", "crater_depth": -1}]})
    with pytest.raises(InputError, match="free-surface depth"):
        replace(CONCRETE, free_surface_depth=1e3)


def test_finite_sphere_factor_is_hill_and_tends_to_one():
    from pencore.kernels.windows import finite_sphere_factor

    a, ratio = 0.01, 5.0
    denom = 1.0 + 3.0 * math.log(ratio)
    assert finite_sphere_factor(0.0, a, ratio) == 0.0
    # plastic zone just reaching the face (b = c): 3 ln(c/a) / (1 + 3 ln(c/a))
    assert finite_sphere_factor((ratio - 1.0) * a, a, ratio) == pytest.approx(
        3.0 * math.log(ratio) / denom, rel=1e-14
    )
    # fully plastic shell, b < c: 2 Y ln(b/a) over the infinite medium's pressure
    b = 2.0 * a
    assert finite_sphere_factor(b - a, a, ratio) == pytest.approx(
        3.0 * math.log(2.0) / denom, rel=1e-14
    )
    d = np.linspace(0.0, 40.0 * ratio * a, 400)
    f = np.array([finite_sphere_factor(x, a, ratio) for x in d])
    assert np.all(np.diff(f) > 0.0) and f[-1] < 1.0
    # far from the face the deficit is (c/b)^3 / (1 + 3 ln(c/a))
    bb = a + d[-1]
    assert 1.0 - f[-1] == pytest.approx((ratio * a / bb) ** 3 / denom, rel=1e-9)


def test_finite_sphere_far_from_every_face_is_the_half_space_law():
    ratio = 5.0
    slab = Target("slab", (Layer(replace(CONCRETE, plastic_zone_ratio=ratio), 40.0),))
    plain = Target("plain", (Layer(CONCRETE, 40.0),))
    mp = P2.mass_properties()
    on = slab.kernel_arrays(P2.diameter, mp.mass, P2.nose_length, mp.lc, P2.nose)
    off = plain.kernel_arrays(P2.diameter)
    rings = P2.rings(48, 24, 4).as_array()
    y = initial_state(P2, rings, 300.0, math.radians(20.0), 0.0, 0.0, None, 0.0, "cm")
    y[1] -= 20.0  # about 20 m from both faces, c = 0.24 m
    f_on = contact_loads(y, rings, *on, 1e-3, 0)
    f_off = contact_loads(y, rings, *off, 1e-3, 0)
    a, c = 0.5 * P2.diameter, ratio * 0.5 * P2.diameter
    bound = (c / 19.0) ** 3 / (1.0 + 3.0 * math.log(ratio))  # nearest element >= 19 m away
    assert bound < 1e-5
    np.testing.assert_allclose(f_on[0], f_off[0], rtol=bound, atol=bound * abs(f_off[0][0]))
    assert not np.array_equal(f_on[0], f_off[0])  # reduced, by less than the bound
    # near the rear face the load falls
    y[1] -= 20.0 - 0.05
    assert abs(contact_loads(y, rings, *on, 1e-3, 0)[0][0]) < abs(
        contact_loads(y, rings, *off, 1e-3, 0)[0][0]
    )
    assert a < c


def test_plastic_zone_ratio_must_exceed_one():
    with pytest.raises(TargetError, match="plastic_zone_ratio"):
        replace(CONCRETE, plastic_zone_ratio=0.5)
