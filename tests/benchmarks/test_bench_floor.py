"""The arithmetic-floor kernel of ``benchmarks/bench_floor.py`` computes the loads it
claims to: on a wholly immersed state (every ring a whole ring of one layer) it is the
same arithmetic as :func:`pencore.kernels.dynamics.contact_loads`, so the floor the README
quotes is a floor of *this* kernel's work and not of a cheaper, different sum."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pencore.kernels.dynamics import contact_loads
from pencore.run.impact import _run, prepare
from pencore.run.initial import initial_state


@pytest.fixture(scope="module")
def floor(load_benchmark):
    return load_benchmark("bench_floor")


@pytest.fixture(scope="module")
def immersed():
    """p2 in soil, 45 deg and 1000 m/s: its last accepted state (deep, fully immersed,
    still turning) and one at nose entry."""
    pr = prepare("p2", "soil")
    y0 = initial_state(
        pr.projectile, pr.rings, 1000.0, math.radians(45.0), 0.0, 0.0, None, 0.0, "cm"
    )
    run = _run(pr, y0, 1000.0, False)
    return pr, run.ys


def test_floor_equals_full_kernel_when_immersed(floor, immersed):
    pr, ys = immersed
    eps = pr.numerics.eps
    loads = [contact_loads(y, pr.rings, pr.bounds, pr.coef, pr.fric, eps, 0) for y in ys]
    deep = [k for k, (_, _, clear) in enumerate(loads) if clear < -0.5]
    # the deep state with the largest lateral load, and the last one
    turning = max(deep, key=lambda k: math.hypot(loads[k][0][1], loads[k][0][2]))
    for k in (turning, len(ys) - 1):
        f, m, clear = loads[k]
        assert clear < -0.5  # every band well below the surface: no partial rings
        y = ys[k]
        ff, mf = floor.floor_loads(y, pr.rings, pr.bounds, pr.coef, eps)
        scale = np.abs(np.concatenate([f, m])).max()
        # same operations in the same order: equal to round-off of a sum of 77 rings
        assert np.abs(np.concatenate([ff - f, mf - m])).max() <= 1e-12 * scale
    f = loads[turning][0]
    assert math.hypot(f[1], f[2]) > 1e-3 * abs(f[0])  # a lateral load: spin terms used


def test_floor_differs_at_entry(floor, immersed):
    """At entry the rings crossing the surface are partial, which the floor integrates
    as whole rings: its loads then differ (it is a floor of the work, not a model)."""
    pr, ys = immersed
    eps = pr.numerics.eps
    y = ys[20]
    f, m, clear = contact_loads(y, pr.rings, pr.bounds, pr.coef, pr.fric, eps, 0)
    ff, mf = floor.floor_loads(y, pr.rings, pr.bounds, pr.coef, eps)
    assert np.abs(ff - f).max() > 1e-3 * np.abs(f).max()


def test_vectorised_floor_equals_scalar_floor(floor, immersed):
    """The vectorised floor (rings as columns, fastmath) computes the scalar floor's
    loads on every state, entry included. Its sums are reassociated, and each side of
    the smoothed step carries up to ``V / (2 eps)`` (5e5 at 1000 m/s) times the net
    load, the two sides cancelling: over ~150 ring sides round-off allows about
    sqrt(150) x 1.1e-16 x 5e5 ~ 7e-10 of the largest load (measured up to 1.3e-10)."""
    pr, ys = immersed
    eps = pr.numerics.eps
    cols = np.ascontiguousarray(pr.rings.T)
    buf = np.zeros((9, cols.shape[1]))
    for k in np.linspace(0, len(ys) - 1, 15).astype(int):
        f, m = floor.floor_loads(ys[k], pr.rings, pr.bounds, pr.coef, eps)
        fs, ms = floor.floor_loads_simd(ys[k], cols, pr.bounds[0, 0], pr.coef, eps, buf)
        scale = np.abs(np.concatenate([f, m])).max()
        assert np.abs(np.concatenate([fs - f, ms - m])).max() <= 1e-9 * scale
