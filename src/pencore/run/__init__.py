"""The run API: :func:`~pencore.prepare`, :func:`~pencore.simulate`,
:func:`~pencore.run.impact.run_impact`,
the initial state of an impact (:mod:`~pencore.run.initial`), and the trajectory Dataset
(:mod:`~pencore.run.dataset`).

``__all__`` lists the public names; each is imported from its module on first use, so
``import pencore.run.dataset`` does not load the solver.
"""

from pencore._lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "simulate": "impact",
        "prepare": "impact",
        "run_impact": "impact",
        "initial_state": "initial",
        "trajectory_dataset": "dataset",
        "final_slope": "dataset",
        "body_loads": "loads",
    },
)
del attach
