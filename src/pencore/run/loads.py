"""The loads on the body along a run: the contact force and moment at each saved state,
and the axial deceleration in m/s^2 and in units of standard gravity.

The loads are those of the solver's own right-hand side, not differences of the saved
velocities, so they carry no differencing error and no step-size noise:

* a Rosenbrock run keeps the right-hand side it starts each step from
  (:attr:`pencore.integrators.driver.RunResult.fs`), and the loads are read back from it
  through the equations of motion (:func:`loads_from_derivatives`): free, and the very
  force and moment the integrator used, to rounding;
* otherwise (the cavity shank model, whose loads depend on the tip path a step extends;
  the explicit emulation; scipy's integrators)
  :func:`pencore.kernels.forces.loads_along` evaluates
  :func:`~pencore.kernels.forces.model_loads` once at each saved state, about a third of a
  Rosenbrock step's work.

:func:`~pencore.run.impact.run_impact` and the searches do not ask for loads.
"""

from __future__ import annotations

import numpy as np

from pencore.errors import hint_keywords
from pencore.integrators.driver import RunResult, reserve_path, start_path
from pencore.integrators.problem import Problem
from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP
from pencore.kernels.forces import loads_along
from pencore.run.dataset import rotation_matrices

__all__ = ["body_loads", "loads_from_derivatives"]


def loads_from_derivatives(
    ys: np.ndarray, fs: np.ndarray, mass: float, inertia: np.ndarray, gravity: np.ndarray
) -> np.ndarray:
    """Body-frame contact force and moment from states and their time derivatives.

    Newton's and Euler's equations of :func:`pencore.kernels.dynamics.equations_of_motion`
    solved for the loads: ``F = m R^T (dv/dt - g)`` and ``M_1 = I_1 dw_1/dt - (I_2 - I_3)
    w_2 w_3`` (and cyclically), ``R`` the body-to-fixed rotation of each state.

    Parameters
    ----------
    ys, fs : (k, 14) ndarray
        States and their time derivatives (SI units).
    mass : float
        Mass (kg).
    inertia : (3,) ndarray
        Principal moments of inertia about the centre of mass (kg m^2), body axes.
    gravity : (3,) ndarray
        Gravity (m/s^2), fixed frame.

    Returns
    -------
    (k, 6) ndarray
        As :func:`body_loads`.
    """
    rot = rotation_matrices(ys[:, 3:7])
    out = np.empty((ys.shape[0], 6))
    out[:, 0:3] = np.einsum("kji,kj->ki", rot, mass * (fs[:, 7:10] - gravity))
    i1, i2, i3 = inertia
    w1, w2, w3 = ys[:, 10], ys[:, 11], ys[:, 12]
    out[:, 3] = i1 * fs[:, 10] - (i2 - i3) * w2 * w3
    out[:, 4] = i2 * fs[:, 11] - (i3 - i1) * w3 * w1
    out[:, 5] = i3 * fs[:, 12] - (i1 - i2) * w1 * w2
    return out


def body_loads(problem: Problem, run: RunResult) -> np.ndarray:
    """Contact force and moment at each saved state of ``run`` (SI units, body frame).

    Parameters
    ----------
    problem : pencore.integrators.problem.Problem
        What ``run`` was integrated with (:func:`pencore.prepare`).
    run : pencore.integrators.driver.RunResult
        Its saved times ``ts`` (s) and states ``ys``.

    Returns
    -------
    (k, 6) ndarray
        Columns 0-2: contact force (N) along body axes 1-3 (axis 1 the symmetry axis,
        towards the nose; a resisting force is negative along it); columns 3-5: contact
        moment about the centre of mass (N m), body axes. Gravity is not a contact load
        and is not included.

    Examples
    --------
    >>> import pencore
    >>> from pencore.run.impact import run_impact
    >>> from pencore.run.loads import body_loads
    >>> pr = pencore.prepare("p2", "soil")
    >>> run = run_impact("p2", "soil", 280.0, prepared=pr)
    >>> f = body_loads(pr, run)
    >>> f.shape == (run.ts.size, 6), bool(f[:, 0].min() < 0.0)
    (True, True)
    """
    mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model = problem.load_args()
    if run.fs is not None and problem.shank.kind != "cavity":
        return loads_from_derivatives(run.ys, run.fs, mass, inertia, gravity)
    if problem.emulation.integrator == "explicit":
        eps = 0.0  # the explicit scheme integrates the pure contact step (H(0) = 1)
    model = start_path(model, run.ys[0])
    model = reserve_path(model, run.ys.shape[0] * MAX_SAMPLES_PER_STEP + 1)
    return loads_along(run.ts, run.ys, rings, bounds, coef, fric, eps, n_gauss, model)


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
