"""The run API: :func:`impact.prepare`, :func:`impact.simulate`, :func:`impact.run_impact`,
the initial state of an impact (:mod:`initial`), and the trajectory Dataset
(:mod:`dataset`).
"""
