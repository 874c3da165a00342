"""Trajectory analysis: slope, inflection points, turning angle, deviation, nose direction.

The public interface; the code lives in :mod:`pencore.analysis.curvature` (slope, curvature,
inflection points), :mod:`pencore.analysis.turning` (turning angle, Eq. 12) and
:mod:`pencore.analysis.deviation` (deviation from the normal, final deviation, nose direction,
reversal).

Conventions (those of :func:`pencore.simulate`): the target is ``y <= 0``, the projectile
moves towards ``+x`` and ``-y``; ``theta`` is the signed angle (degree) from the target
normal ``-y`` to the projectile axis, towards ``+x``. SI units inside; angles come out in
degrees.

The functions are pure: numpy arrays in, floats or arrays out. Those that need several
histories also take an :class:`xarray.Dataset` as written by :func:`pencore.simulate`
(variables ``time``, ``cm_x``, ``cm_y``, ``vel_x``, ``vel_y``, ``vel_z``, ``theta``,
``axis_x``, ``speed``; attributes ``reversed`` and ``impact_velocity_m_s``).

Derivatives along a path are always taken in parametric form, ``x(p)``, ``y(p)``, with
``p`` the time when it is known and the cumulative chord length otherwise, so a path
that is vertical (normal impact, ``dx/dt = 0``) or that turns back in ``x`` is handled;
``np.gradient`` gives second-order differences on the non-uniform grids of an adaptive
integrator. The paper writes "dx/dy" for what is the slope ``dy/dx`` of ``y(x)``; the
code names the quantity correctly.

Definitions chosen here where the paper leaves a choice open:

* **Points 1 and 2 of Eq. 12** (:func:`~pencore.turning_angle`, default ``method="bracket"``):
  the points where the trajectory curvature rises through, and finally falls back
  through, ``fraction`` (default 5 %) of its peak magnitude. The paper places them where
  ``d2y/dx2 = 0`` on the slope plot of Fig. 7(b): the trajectory is straight before entry
  (slope -1 at 45 deg), curves, and becomes straight again, and Points 1 and 2 bracket
  the curved part. Strict zeros of the second derivative are not usable: it is exactly
  zero in free flight, and a solver run has genuine sign changes inside the nose-entry
  transient (the slope rises, dips slightly, then rises again). A threshold at a small
  fraction of the peak finds the edges of the curved part; ``theta`` hardly changes
  where the curvature is small, so the result barely depends on the fraction (for
  projectile #2 at 45 deg and 1000 m/s, fractions 0.01 to 0.1 change it by less than 0.1 %).
* **Final deviation** (:func:`~pencore.final_deviation`): the velocity angle from the normal at
  the last saved state whose speed is still at least ``fraction`` (default 0.1) of the
  impact speed. Very near the stop the lateral part of the constant resistance term
  turns the slow projectile quickly, so the direction at the stop itself is not the
  direction of the trajectory.
"""

from __future__ import annotations

from pencore.analysis.curvature import (
    DEFAULT_BRACKET_FRACTION,
    DEFAULT_REL_THRESHOLD,
    DEFAULT_SPEED_FRACTION,
    STRAIGHT_TOL,
    Inflections,
    d2y_dx2,
    inflection_points,
    inflection_points_ds,
    signed_curvature,
    slope,
    slope_ds,
)
from pencore.analysis.deviation import (
    deviation_from_normal,
    final_deviation,
    final_deviation_arrays,
    final_state_index,
    nose_direction,
    reversed_in_target,
)
from pencore.analysis.turning import TurningAngle, turning_angle, turning_angle_arrays

__all__ = [
    "DEFAULT_REL_THRESHOLD",
    "DEFAULT_BRACKET_FRACTION",
    "DEFAULT_SPEED_FRACTION",
    "STRAIGHT_TOL",
    "Inflections",
    "TurningAngle",
    "slope",
    "slope_ds",
    "signed_curvature",
    "d2y_dx2",
    "inflection_points",
    "inflection_points_ds",
    "turning_angle",
    "turning_angle_arrays",
    "deviation_from_normal",
    "final_state_index",
    "final_deviation",
    "final_deviation_arrays",
    "nose_direction",
    "reversed_in_target",
]
