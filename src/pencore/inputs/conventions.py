"""Readings of the paper's words that pencore offers as named choices: which angle a
"normal impact with yaw" tilts, and which point an initial spin turns the body about.

Kept apart from the solver (standard library and :mod:`pencore.inputs.limits` only) so that
checking a configuration names a bad choice without loading the solver's kernels
(the workflow checks its configuration at every Snakemake start).
"""

from __future__ import annotations

from pencore.errors import InputError, hint_keywords

__all__ = ["YAW_CONVENTIONS", "SPIN_CENTRES", "normal_impact_angles", "impact_angles"]

#: Readings of "normal impact with yaw" (:func:`normal_impact_angles`).
YAW_CONVENTIONS = ("axis_tilted", "velocity_tilted")

#: Points the initial spin ``omega`` turns about (:func:`pencore.run.initial.initial_state`).
SPIN_CENTRES = ("cm", "tip")


def normal_impact_angles(yaw: float, convention: str = "axis_tilted") -> tuple[float, float]:
    """``(obliquity, yaw)`` arguments of :func:`pencore.simulate` for a normal impact with
    yaw ``yaw`` (deg).

    The yaw phi2 is the velocity angle minus the axis angle (paper Fig. 10); for a
    "normal impact with yaw" (paper Figs 13-15) either can be the normal one:

    ``"axis_tilted"``
        The velocity is along the target normal and the axis is tilted by ``yaw``:
        ``obliquity = +yaw``, ``yaw = -yaw``. This reading comes close to the paper's
        deviations for projectile #4 at 0.1 deg (0.16 deg at 280 m/s, 0.24 deg at
        1000 m/s; pencore 0.166 and 0.259).
    ``"velocity_tilted"``
        The axis is along the normal and the velocity is tilted by ``yaw``:
        ``obliquity = 0``, ``yaw = yaw`` (pencore 0.065 and 0.157 deg for the same cases).
    """
    if convention not in YAW_CONVENTIONS:
        raise InputError(
            f"yaw convention must be one of {', '.join(YAW_CONVENTIONS)}, got {convention!r}"
        )
    yaw = float(yaw)
    if convention == "axis_tilted":
        return yaw, -yaw
    return 0.0, yaw


def impact_angles(obliquity: float, yaw: float, convention: str) -> tuple[float, float]:
    """``(obliquity, yaw)`` arguments of :func:`pencore.simulate` for an impact given as an
    obliquity and a yaw (deg) read by ``convention``.

    ``"velocity_tilted"``
        ``obliquity`` is the axis's angle from the target normal and ``yaw`` tilts the
        velocity from the axis (simulate's own reading): returned as they are.
    ``"axis_tilted"``
        ``obliquity`` is the velocity's angle from the normal (the line of fire) and
        ``yaw`` tilts the axis from the velocity (an angle of attack): the axis at
        ``obliquity + yaw``, the velocity at ``obliquity``, so simulate's obliquity is
        ``obliquity + yaw`` and its yaw ``-yaw`` (the two tied). At ``obliquity = 0``
        this is :func:`normal_impact_angles`.
    """
    if convention not in YAW_CONVENTIONS:
        raise InputError(
            f"yaw convention must be one of {', '.join(YAW_CONVENTIONS)}, got {convention!r}"
        )
    obliquity, yaw = float(obliquity), float(yaw)
    if convention == "axis_tilted":
        return obliquity + yaw, -yaw
    return obliquity, yaw


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
