"""The whole-ring fast path of :func:`pencore.dynamics.contact_loads` (one layer, no
depth windows, no friction: a band clear of the layer's levels is loaded as a whole ring
without building its region sets) gives exactly the loads of the general path.

The general path is forced by asking for friction quadrature (``n_gauss > 0``) on a
medium with zero friction: every band then goes through the region sets, and the
friction integral adds nothing. The two must agree bit for bit (same operations in the
same order), on states of an oblique entry (bands partial and whole), of a deep turning
run, of a plate being perforated (bands below its bottom face carry nothing), and with
the sharp step (``eps = 0``, one side).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.dynamics import contact_loads
from pencore.solver import _run, initial_state, prepare
from pencore.target import Layer, Medium, Target

SOIL = (1.718e7, 0.0, 4119.9)


def _states(target, velocity, obliquity_deg, yaw_deg=0.0):
    pr = prepare("p2", target)
    y0 = initial_state(
        pr.projectile,
        pr.rings,
        velocity,
        math.radians(obliquity_deg),
        math.radians(yaw_deg),
        0.0,
        None,
        0.0,
        "cm",
    )
    return pr, _run(pr, y0, velocity, False).ys


def _both(pr, y, eps):
    fast = contact_loads(y, pr.rings, pr.bounds, pr.coef, pr.fric, eps, 0)
    general = contact_loads(y, pr.rings, pr.bounds, pr.coef, pr.fric, eps, 4)
    return fast, general


@pytest.mark.parametrize(
    "target, velocity, obliquity",
    [
        (Target("soil0", (Layer(Medium("soil0", SOIL)),)), 1000.0, 45.0),
        (Target("plate", (Layer(Medium("plate", (4.0e8, 0.0, 2400.0)), 0.3),)), 900.0, 20.0),
    ],
)
def test_fast_path_equals_general_path(target, velocity, obliquity):
    pr, ys = _states(target, velocity, obliquity, yaw_deg=1.0)
    assert float(np.abs(pr.fric).max()) == 0.0  # the general path adds no friction
    picked = np.unique(np.linspace(0, len(ys) - 1, 25).astype(int))
    below = 0
    for k in picked:
        for eps in (pr.numerics.eps, 0.0):
            (f1, m1, c1), (f2, m2, c2) = _both(pr, ys[k], eps)
            np.testing.assert_array_equal(f1, f2)
            np.testing.assert_array_equal(m1, m2)
            assert c1 == c2
        if np.isfinite(pr.bounds[0, 1]):
            # tip below the plate's bottom face: some bands carry nothing there
            below += ys[k][1] < pr.bounds[0, 1] - 0.2
    if np.isfinite(pr.bounds[0, 1]):
        assert below > 0, "no state with the nose through the plate was checked"
