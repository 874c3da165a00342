"""Time integration of a trajectory.

=================  ==============================================================
module             contents
=================  ==============================================================
``problem``        :class:`problem.Problem`: what every integrator takes
``driver``         the run record, chunking, Ctrl-C, the cavity model's tip path
``rosenbrock``     the compiled Rosenbrock/W pair (default)
``explicit``       the fixed-step central-difference scheme (paper emulation)
``scipy_ivp``      scipy's ``solve_ivp`` on the same right-hand side (reference)
=================  ==============================================================

Each integrator is ``integrate(problem, y0, velocity, *, stop_at_reversal)`` and
returns a :class:`driver.RunResult`.
"""

from pencore._lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Problem": "problem",
        "RunResult": "driver",
    },
)
del attach

import pencore.kernels  # noqa: E402,F401  (numba set up before the compiled modules)
