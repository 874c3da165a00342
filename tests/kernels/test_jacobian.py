"""The closed-form velocity Jacobian (pencore.kernels.jacobian) against finite differences, its
symmetry, and the trajectories it gives against the finite-difference Jacobian's."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pencore
from pencore.kernels.forces import default_model, rhs_model
from pencore.kernels.jacobian import load_jacobian, model_load_jacobian, velocity_jacobian
from pencore.run.impact import _run, prepare
from pencore.run.initial import initial_state

EPS = 1e-3
G0 = np.zeros(3)
CASES = [  # projectile, velocity (m/s), obliquity, yaw (deg), omega (rad/s)
    ("p2", 1000.0, 45.0, 0.0, 0.0),
    ("p4", 800.0, 30.0, 2.0, 0.0),
    ("p1", 600.0, 10.0, -3.0, 20.0),
]


def _states(case):
    name, v, obl, yaw, omega = case
    pr = prepare(name, "soil")
    y0 = initial_state(
        pr.projectile, pr.rings, v, math.radians(obl), math.radians(yaw), omega, None, 0.0, "cm"
    )
    run = _run(pr, y0, v, False)
    return pr, run.ys[1 :: max(1, run.ys.shape[0] // 20)]


def _rhs(pr, y):
    return rhs_model(
        y, pr.mass, pr.inertia, G0, pr.rings, pr.bounds, pr.coef, pr.fric, EPS, 0, default_model()
    )


def _best_central_difference_error(ja, rhs, y):
    """Largest difference between the velocity columns of ``ja`` and central differences
    of ``rhs`` (state -> derivative), relative to each block's (translation, rotation,
    power) largest entry, for the best of four steps: 1e-3 .. 1e-6 m/s, x 2.5 rad/s for
    the spin (why the best of four: test_velocity_jacobian_matches_central_differences)."""
    best = np.inf
    for step in (1e-3, 1e-4, 1e-5, 1e-6):
        jc = np.zeros((14, 14))
        for c in range(7, 13):
            dl = step if c < 10 else 2.5 * step
            yp, ym = y.copy(), y.copy()
            yp[c] += dl
            ym[c] -= dl
            jc[:, c] = (rhs(yp) - rhs(ym)) / (2 * dl)
        err = max(
            np.abs(ja[rows, 7:13] - jc[rows, 7:13]).max() / np.abs(jc[rows, 7:13]).max()
            for rows in (slice(7, 10), slice(10, 13), slice(13, 14))
        )
        best = min(best, err)
    return best


def _assert_symmetric_dissipative(d):
    """``d`` (6 x 6 load Jacobian) is symmetric and negative semi-definite to round-off."""
    scale = np.abs(d).max()
    assert np.abs(d - d.T).max() <= 1e-12 * scale
    assert np.linalg.eigvalsh(0.5 * (d + d.T)).max() <= 1e-12 * scale


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c[0]}-{c[2]:g}deg")
def test_velocity_jacobian_matches_central_differences(case):
    # central differences have two errors: truncation (the smoothed step's band edges
    # are kinks of the integrand; a step that crosses one loses accuracy) and round-off
    # (1e-16 |F| / step, with |F| ~ 1e7 N). Neither step size suits every state, so the
    # best of four steps (1e-3 .. 1e-6 m/s, x 2.5 rad/s for the spin) is compared: on
    # these states it agrees with the closed form to <= 6e-5 of each block's largest
    # entry; 1e-3 allows for that and fails any missing or mis-signed term (O(1))
    pr, states = _states(case)
    checked = 0
    for y in states:
        f0, clear = _rhs(pr, y)
        if clear > 0.0:
            continue
        ja = np.zeros((14, 14))
        velocity_jacobian(
            ja, y, f0, pr.mass, pr.inertia, G0, pr.rings, pr.bounds, pr.coef, pr.fric, EPS,
            default_model(),
        )  # fmt: skip
        best = _best_central_difference_error(ja, lambda u: _rhs(pr, u)[0], y)
        assert best <= 1e-3, (y, best)
        checked += 1
    assert checked >= 10


def test_load_jacobian_is_symmetric_and_dissipative():
    # the frictionless DAFL is -grad of a dissipation function of the body velocities:
    # d(loads)/du = -sum w B^T S B with S a Gram matrix of G' >= 0 (pencore.kernels.jacobian).
    # The shank bands' step width depends on the lateral spin w2, w3
    # (pencore.kernels.bands.band_eps), which adds terms to those two columns only: the
    # block of (v1, v2, v3, w1) is the dissipation function's at every state, and with
    # w2 = w3 = 0 (no widening) the whole matrix is
    pr, states = _states(CASES[1])
    checked = 0
    for y in states:
        if _rhs(pr, y)[1] > 0.0:
            continue
        d = load_jacobian(y, pr.rings, pr.bounds, pr.coef, EPS)
        assert np.abs(d[:, 4:]).max() > 0.0  # a turning state
        _assert_symmetric_dissipative(d[:4, :4])
        y0 = y.copy()
        y0[11:13] = 0.0
        _assert_symmetric_dissipative(load_jacobian(y0, pr.rings, pr.bounds, pr.coef, EPS))
        checked += 1
    assert checked >= 10


def test_analytic_and_finite_difference_jacobians_give_one_trajectory():
    # the Jacobian only enters the Rosenbrock stages (a W-method: order 2 for any
    # matrix), so the two differ by the error control's accuracy; the convergence
    # table shows depth moving 3e-4 relative between rtol 1e-5 and 1e-7, and 1e-3
    # fails a wrong Jacobian (a 10 % error in it costs steps, a sign error diverges)
    runs = {
        jac: pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, jacobian=jac)
        for jac in ("analytic", "finite_difference")
    }
    for q in ("penetration_depth", "path_length", "final_deviation"):
        a, f = float(runs["analytic"][q]), float(runs["finite_difference"][q])
        assert abs(a / f - 1.0) < 1e-3, (q, a, f)
    # the closed form replaces the six right-hand-side calls of each Jacobian
    assert runs["analytic"].attrs["n_rhs"] < 0.75 * runs["finite_difference"].attrs["n_rhs"]


def test_the_crater_runs_one_trajectory_with_either_jacobian():
    # with a crater the closed form holds each element's factor fixed (its dependence on
    # the axial speed is left out): still a W-method, so the two Jacobians differ by the
    # error control's accuracy, as above; the finite differences take far more steps
    from dataclasses import replace

    al = pencore.get_target("aluminium").medium
    plate = pencore.Target("plate", (pencore.Layer(replace(al, crater_depth=2.0), 0.02),))
    runs = {
        jac: pencore.simulate("al_ogive_var4340", plate, 700.0, obliquity=45.0, jacobian=jac)
        for jac in ("analytic", "finite_difference")
    }
    assert {r.attrs["outcome"] for r in runs.values()} == {"perforated"}
    a, f = (float(runs[j].attrs["residual_velocity"]) for j in ("analytic", "finite_difference"))
    assert abs(a / f - 1.0) < 1e-3, (a, f)
    assert runs["analytic"].sizes["time"] < runs["finite_difference"].sizes["time"]


# ------------------------------------------------------------ point loads (panels, cavity)

POINT_MODELS = {
    "cavity": dict(shank={"kind": "cavity", "delta_ref": 5e-3}),
    "panels": dict(emulation={"surface": "panels"}),
}


def _point_states(kind):
    """States of a p2 run at 45 deg with the model's kernel tuple at each: the cavity
    model's loads depend on the tip path so far, so each state ends its own run."""
    pr = prepare("p2", "soil", **POINT_MODELS[kind])
    y0 = initial_state(
        pr.projectile, pr.rings, 1000.0, math.radians(45.0), 0.0, 0.0, None, 0.0, "cm"
    )
    out = []
    for t_end in (2e-4, 4e-4, 7e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2):
        pr_t = prepare("p2", "soil", t_max=t_end, **POINT_MODELS[kind])
        run = _run(pr_t, y0, 1000.0, False)
        model = pr_t.model
        if run.path is not None:
            model = (model[0], model[1], model[2], run.path, np.array([run.path.shape[0]]))
        out.append((run.ys[-1], model))
    return pr, out


def _rhs_model(pr, y, model):
    return rhs_model(
        y, pr.mass, pr.inertia, G0, pr.kernel_rings, pr.bounds, pr.coef, pr.fric, EPS, 0, model
    )


@pytest.mark.parametrize("kind", sorted(POINT_MODELS))
def test_point_load_jacobian_matches_central_differences(kind):
    # as for the rings (above): best of four central-difference steps, 1e-3 of each
    # block's largest entry; the point loads have the same kinks (the band edges)
    pr, states = _point_states(kind)
    checked = 0
    for y, model in states:
        f0, clear = _rhs_model(pr, y, model)
        if clear > 0.0:
            continue
        ja = np.zeros((14, 14))
        velocity_jacobian(
            ja, y, f0, pr.mass, pr.inertia, G0, pr.kernel_rings, pr.bounds, pr.coef, pr.fric,
            EPS, model,
        )  # fmt: skip
        best = _best_central_difference_error(ja, lambda u, m=model: _rhs_model(pr, u, m)[0], y)
        assert best <= 1e-3, (kind, y, best)
        # every point load is -A G'(vn) g g^T: symmetric, negative semi-definite
        _assert_symmetric_dissipative(
            model_load_jacobian(y, pr.kernel_rings, pr.bounds, pr.coef, pr.fric, EPS, model)
        )
        checked += 1
    assert checked >= 6


@pytest.mark.parametrize("kind", sorted(POINT_MODELS))
def test_point_models_give_one_trajectory_with_either_jacobian(kind):
    # as test_analytic_and_finite_difference_jacobians_give_one_trajectory, for the
    # point-load models; the closed form saves the six calls of each Jacobian
    runs = {
        jac: pencore.simulate(
            "p2",
            "soil",
            1600.0,
            45.0,
            start=(-1.0, 1.0, 0.0),
            jacobian=jac,
            **POINT_MODELS[kind],
        )  # fmt: skip
        for jac in ("analytic", "finite_difference")
    }
    assert runs["analytic"].attrs["outcome"] == runs["finite_difference"].attrs["outcome"]
    for q in ("penetration_depth", "path_length"):
        a, f = float(runs["analytic"][q]), float(runs["finite_difference"][q])
        assert abs(a / f - 1.0) < 1e-3, (q, a, f)
    assert runs["analytic"].attrs["n_rhs"] < 0.75 * runs["finite_difference"].attrs["n_rhs"]
