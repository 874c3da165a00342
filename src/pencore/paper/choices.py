"""Checks of the attribution study's configuration: the choices one setting fixes for
:func:`pencore.studies.attribution.disputed.disputed_quantities` (shank model, numerics,
the readings of the paper's yaw, spin centre and "turns back", start height, friction) and
the list of configured settings, and the mass distribution of the paper's projectiles
(:mod:`pencore.paper.bodies`, or the inverse step's fitted one,
:data:`~pencore.paper.choices.INVERSE_BODY`).

Apart from :mod:`pencore.studies.attribution.disputed` so that the workflow's configuration
check, run at every Snakemake start, names a bad choice without loading the solver.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from pencore.errors import InputError
from pencore.inputs.conventions import SPIN_CENTRES, normal_impact_angles
from pencore.inputs.limits import check_keys, number
from pencore.inputs.models import emulation as _emulation
from pencore.inputs.models import shank_model
from pencore.paper.bodies import BODY_KINDS, check_body

__all__ = [
    "CHOICES",
    "INVERSE_BODY",
    "REVERSALS",
    "SETTING_KEYS",
    "check_choices",
    "check_settings",
]

#: Allowed keys of a setting.
CHOICES = (
    "shank",
    "emulation",
    "numerics",
    "start_height",
    "spin_about",
    "yaw_reading",
    "reversal",
    "friction",
    "body",
)

#: The body kind of the inverse step: the mass properties of #2 fitted to the spin numbers
#: (:func:`pencore.studies.attribution.inverse.fit_spin_body`).
INVERSE_BODY = "fit_spin"

#: Readings of "the projectile turns back": its reversal, or its leaving the target.
REVERSALS = ("turns_back", "exits")

#: Keys of one configured setting (``attribution.settings`` of the workflow config).
SETTING_KEYS = ("name", "label", "group", "argued", "choices")


def check_choices(choices: Mapping[str, Any]) -> dict[str, Any]:
    """The choices of one setting, checked, with defaults filled in.

    Raises
    ------
    InputError
        One line naming the bad key or value.
    """
    if not isinstance(choices, Mapping):
        raise InputError(f"attribution setting must be a mapping of choices, got {choices!r}")
    check_keys(choices, CHOICES, "attribution setting")
    s = dict(choices)
    s["shank"] = shank_model(s.get("shank"))
    s["emulation"] = _emulation(s.get("emulation"))
    num = s.get("numerics") or {}
    if not isinstance(num, Mapping):
        raise InputError(f"attribution numerics must be a mapping of overrides, got {num!r}")
    s["numerics"] = dict(num)
    s["start_height"] = number(s.get("start_height", 0.0), "start_height", "attribution")
    s["spin_about"] = s.get("spin_about", "cm")
    if s["spin_about"] not in SPIN_CENTRES:
        raise InputError(
            f"attribution spin_about must be one of {', '.join(SPIN_CENTRES)}, "
            f"got {s['spin_about']!r}"
        )
    s["reversal"] = s.get("reversal", "turns_back")
    if s["reversal"] not in REVERSALS:
        raise InputError(
            f"attribution reversal must be one of {', '.join(REVERSALS)}, got {s['reversal']!r}"
        )
    s["yaw_reading"] = s.get("yaw_reading", "axis_tilted")
    normal_impact_angles(0.1, s["yaw_reading"])  # checks the name
    s["friction"] = number(s.get("friction", 0.0), "friction", "attribution")
    body = s.get("body")
    kinds = (*BODY_KINDS, INVERSE_BODY)
    if isinstance(body, Mapping) and body.get("kind") not in kinds:
        raise InputError(
            f"attribution body kind must be one of {', '.join(kinds)}, got {body.get('kind')!r}"
        )
    if isinstance(body, Mapping) and body.get("kind") == INVERSE_BODY:
        check_keys(body, ("kind",), f"attribution body {INVERSE_BODY}")
        s["body"] = {"kind": INVERSE_BODY}
    else:
        s["body"] = check_body(body)
    return s


def check_settings(settings: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The configured settings, checked (unique names, known keys, valid choices).

    Raises
    ------
    InputError
        One line naming the setting and the bad key or value.
    """
    out = []
    seen = set()
    for i, st in enumerate(settings):
        if not isinstance(st, Mapping):
            raise InputError(f"attribution setting {i + 1} must be a mapping, got {st!r}")
        check_keys(st, SETTING_KEYS, f"attribution setting {i + 1}")
        name = st.get("name")
        if not isinstance(name, str) or not name or name in seen:
            raise InputError(f"attribution setting {i + 1}: missing or duplicate name {name!r}")
        seen.add(name)
        choices = dict(st.get("choices") or {})
        check_choices(choices)  # the checks of the run itself, without running
        out.append(
            {
                "name": name,
                "label": str(st.get("label", name)),
                "group": str(st.get("group", "")),
                "argued": bool(st.get("argued", True)),
                "choices": choices,
            }
        )
    if not out:
        raise InputError("attribution: no settings configured")
    return out
