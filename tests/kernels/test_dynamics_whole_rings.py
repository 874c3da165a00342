"""The whole-ring fast path of :func:`pencore.kernels.dynamics.contact_loads` (one layer, no
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

from pencore.inputs.target import Layer, Medium, Target
from pencore.kernels.dynamics import contact_loads
from pencore.run.impact import _run, prepare
from pencore.run.initial import initial_state

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


@pytest.mark.parametrize(
    "target, velocity, obliquity",
    [
        (Target("soil0", (Layer(Medium("soil0", SOIL)),)), 1000.0, 45.0),
        (Target("plate", (Layer(Medium("plate", (4.0e8, 0.0, 2400.0)), 0.3),)), 900.0, 20.0),
    ],
)
def test_jacobian_fast_path_equals_general_path(target, velocity, obliquity):
    """The same for the velocity Jacobian (:func:`pencore.kernels.jacobian.load_jacobian`, whose
    whole rings go through :func:`pencore.kernels.wholering.whole_ring_moments`). The general
    path is forced by depth-window columns that are all off (lengths 0: a factor of
    exactly 1), which the fast path does not take."""
    from pencore.kernels.jacobian import load_jacobian

    pr, ys = _states(target, velocity, obliquity, yaw_deg=1.0)
    assert pr.bounds.shape[1] < 5
    windows_off = np.hstack([pr.bounds, np.zeros((pr.bounds.shape[0], 3))])
    eps = pr.numerics.eps
    for k in np.unique(np.linspace(0, len(ys) - 1, 25).astype(int)):
        fast = load_jacobian(ys[k], pr.rings, pr.bounds, pr.coef, eps)
        general = load_jacobian(ys[k], pr.rings, windows_off, pr.coef, eps)
        np.testing.assert_array_equal(fast, general)


@pytest.mark.parametrize("ncoef", [1, 3, 8])
@pytest.mark.parametrize("eps", [1e-3, 0.0])
def test_whole_ring_integrals_equal_one_ring_form(ncoef, eps):
    """:func:`pencore.kernels.wholering.whole_ring_integrals` (rings innermost, vectorised) gives
    bit for bit what :func:`pencore.kernels.arcs._poly_centred_arc_integrals` gives ring by ring
    and side by side, for laws of 1 to 8 terms, the smoothed and the sharp step, and
    rings unloaded (empty arc), wholly loaded, partly loaded and without lateral
    velocity (``kv = 0``, above and below the level), with mixed step widths."""
    from pencore.kernels.arcs import _MAXD, _poly_centred_arc_integrals, side_poly
    from pencore.kernels.wholering import whole_ring_integrals

    rng = np.random.default_rng(ncoef)
    coef = rng.uniform(0.5, 2.0, (1, ncoef)) * 10.0 ** np.arange(ncoef)[::-1]
    n = 40
    av = rng.uniform(-3.0, 3.0, n)
    kv = rng.uniform(0.0, 3.0, n)
    av[:4] = [5.0, -5.0, 2e-4, -2e-4]  # wholly loaded, unloaded, near the step
    kv[:4] = [1.0, 1.0, 0.0, 0.0]  # the last two without lateral velocity
    ang = rng.uniform(-np.pi, np.pi, n)
    epsr = np.where(rng.uniform(size=n) < 0.5, eps, np.sqrt(eps**2 + 1e-6)) if eps else 0.0
    tab = np.vstack([av, kv, np.cos(ang), np.sin(ang), np.broadcast_to(epsr, n)])
    nside = 2 if eps > 0 else 1
    out = np.empty((3, n))
    whole_ring_integrals(np.ascontiguousarray(tab), n, coef, nside, out)
    poly = np.zeros(_MAXD)
    se = np.zeros(_MAXD + 2)
    scj = np.zeros(_MAXD + 2)
    for m in range(n):
        s = [0.0, 0.0, 0.0]
        for side in range(nside):
            level, deg = side_poly(coef, 0, tab[4, m], side, poly)
            r = _poly_centred_arc_integrals(
                poly, deg, av[m], kv[m], tab[2, m], tab[3, m], level, se, scj
            )
            s = [s[0] + r[0], s[1] + r[1], s[2] + r[2]]
        np.testing.assert_array_equal(out[:, m], s)
    assert np.any(out[0] == 0.0) and np.any(out[0] != 0.0)
