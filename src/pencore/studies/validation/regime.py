"""The rigid-regime criterion judged on measured shots: each row's verdict beside the error
of the model's exact 1-D depth, so that one can see whether the criterion separates the
failures (:mod:`pencore.inputs.regime` states the criterion).

A row needs the body shot columns (:data:`pencore.measured.shots.BODY_SHOT_COLUMNS`) and the
projectile's yield strength in ``projectile_yield_pa`` (Pa; a row without one is judged
with the assumed strength, as a run is). The depth is :func:`pencore.closedform.depth`
(which pencore's 3-D run meets within 2e-3 in normal impact) with the concrete law of the
given options; a row the option cannot score gets NaN.
"""

from __future__ import annotations

import math
import warnings

import pandas as pd

from pencore.closedform import depth
from pencore.errors import InputError, PlausibilityWarning, hint_keywords
from pencore.inputs.geometry import Projectile
from pencore.inputs.laws import concrete_law
from pencore.inputs.regime import rigid_regime
from pencore.studies.validation.bodies import body_projectile

__all__ = ["regime_rows", "regime_split"]


def regime_rows(shots: pd.DataFrame, **law: str) -> pd.DataFrame:
    """Per row: ``row``, ``ratio`` (``R``), ``rigid`` (the verdict), ``limit_speed_m_s``,
    ``error`` (1-D depth over the measured one, minus 1) with ``concrete_law(fc, density,
    **law)``.

    Parameters
    ----------
    shots : pandas.DataFrame
        Body shot rows with ``projectile_yield_pa``.
    **law : str
        Options of :func:`pencore.inputs.laws.concrete_law` (``s_model``, ``crater``,
        ``size_term``).
    """
    out = []
    for _, r in shots.iterrows():
        body = body_projectile(r, f"row {r['row']}")
        y = r.get("projectile_yield_pa", math.nan)
        y = float(y) if pd.notna(y) else None
        p = Projectile(body.name, body.diameter, body.nose, body.shank, mass=body.mass,
                       yield_strength=y)  # fmt: skip
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", PlausibilityWarning)  # fc beyond the built range
            medium = concrete_law(r["fc_pa"], r["target_density_kg_m3"], **law)
        v = float(r["striking_velocity_m_s"])
        verdict = rigid_regime(p, medium.for_projectile(p.diameter, p.nose_length), v)
        try:
            err = depth(p, medium, v) / float(r["depth_m"]) - 1.0
        except InputError:
            err = math.nan
        out.append(
            {
                "row": r["row"],
                "ratio": verdict.ratio,
                "rigid": verdict.rigid,
                "limit_speed_m_s": verdict.limit_speed,
                "error": err,
            }
        )
    return pd.DataFrame(out)


def regime_split(rows: pd.DataFrame) -> pd.DataFrame:
    """Rows flagged and not (index ``flagged``, ``kept``): count and median ``error``."""
    g = rows.assign(group=rows["rigid"].map({True: "kept", False: "flagged"}))
    return g.groupby("group")["error"].agg(["size", "median"]).rename(columns={"size": "rows"})


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
