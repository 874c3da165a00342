"""The loads on the body along a run: the contact force and moment at each saved state,
and the axial deceleration in m/s^2 and in units of standard gravity.

The loads are those of the solver's own right-hand side
(:func:`pencore.kernels.forces.loads_along` calls :func:`~pencore.kernels.forces.model_loads`,
the force and moment the integrator's :func:`~pencore.kernels.forces.rhs_model` uses), evaluated
once at each saved state: they are not differences of the saved velocities, so they carry
no differencing error and no step-size noise. One evaluation per saved state costs about a
third of a Rosenbrock step's work (a step evaluates the right-hand side twice and builds a
Jacobian); :func:`~pencore.run.impact.run_impact` and the searches do not pay it.
"""

from __future__ import annotations

import numpy as np

from pencore.integrators.driver import RunResult, reserve_path, start_path
from pencore.integrators.problem import Problem
from pencore.kernels.contact_points import MAX_SAMPLES_PER_STEP
from pencore.kernels.forces import loads_along

__all__ = ["body_loads"]


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
    _, _, _, rings, bounds, coef, fric, eps, n_gauss, model = problem.load_args()
    if problem.emulation.integrator == "explicit":
        eps = 0.0  # the explicit scheme integrates the pure contact step (H(0) = 1)
    model = start_path(model, run.ys[0])
    model = reserve_path(model, run.ys.shape[0] * MAX_SAMPLES_PER_STEP + 1)
    return loads_along(run.ts, run.ys, rings, bounds, coef, fric, eps, n_gauss, model)
