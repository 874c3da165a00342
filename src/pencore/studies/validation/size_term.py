"""The size term of the concrete law, a declared fit: its rows, its function, its constants.

Every rigid cavity-expansion law gives the same ``X/d`` at every scale for geometrically
similar shots, while the measured ``X/d`` of Wu et al.'s scaled series (CRH 2, 450 m/s,
40 MPa, 10.1 to 203 mm; ``config/concrete_scaled_series.csv``) rises from 7.7 to 12.1, and the
76.2 mm Sandia/WES shots come out 20-48 % shallow. No size-effect law of the penetration
resistance could be read here (searched: Bazant-type size effects on ``S``, scale-effect
corrections of Kong, Wu, Fang et al.), so the term is a declared fit of the form of Bazant's
size-effect law (:class:`pencore.inputs.target.SizeTerm`)::

    S(fc, d) = S(fc) f(d),   f(d) = ((1 + d_ref / d0) / (1 + d / d0)) ** 0.5

with ``d_ref`` declared (25 mm, amid the 12.9-30.5 mm rods the ``S(fc)`` forms were fitted
to) and one constant, ``d0``, fitted per ``S(fc)`` form and crater option.

The fit (:func:`fit_size_term`). For each row named in the constants file
(``pencore/inputs/data/concrete_size_term.yaml``: the Sandia/WES family of
``config/concrete_ogive_shots.csv`` without Gran & Frew 1997, whose compiled mass no steel
body of the outline can have, and Wu et al.'s series), the factor ``f_i`` on ``a0`` that
makes the model's exact 1-D normal-impact depth (:func:`pencore.closedform.depth`, which
pencore's 3-D run meets within 2e-3) equal the measured depth (Brent's method on
``ln(depth / measured)``, ``xtol = rtol = 1e-10``); then ``d0`` minimises
``sum (ln f(d_i) - ln f_i)^2`` (scipy's ``least_squares``, ``xtol = ftol = gtol = 1e-12``).
A row the option cannot score is left out and counted (Forrestal's 2-caliber crater is
shorter than the nose of a CRH above 4.25). No other row enters; the integrator judges the
term one source left out at a time on the rows it was not fitted to.

Run ``python -m pencore.studies.validation.size_term`` from the repository's root to print
the constants the file should hold.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pencore.closedform import depth
from pencore.errors import InputError, PlausibilityWarning, hint_keywords
from pencore.inputs.laws import CRATERS, S_MODELS, concrete_law, size_term_constants
from pencore.measured.shots import read_body_shot_table
from pencore.studies.validation.bodies import body_projectile

__all__ = [
    "SizeFit",
    "fit_rows",
    "implied_factor",
    "implied_factors",
    "fit_d0",
    "fit_size_term",
    "fit_all",
]

#: Tolerances of the two solves (see the module notes).
BRENT_TOL = 1e-10
LSQ_TOL = 1e-12


@dataclass(frozen=True)
class SizeFit:
    """A fitted size term.

    Attributes
    ----------
    d0 : float
        Transitional diameter (m).
    rows_used : int
        Rows in the fit.
    rows_skipped : tuple of str
        Rows the option cannot score (compilation Numbers).
    rms_log_factor : float
        Root mean square of ``ln f(d_i) - ln f_i`` at the optimum.
    rms_log_factor_without : float
        The same with no size term (``f = 1``).
    """

    d0: float
    rows_used: int
    rows_skipped: tuple[str, ...]
    rms_log_factor: float
    rms_log_factor_without: float


def fit_rows(root: str | Path = ".") -> pd.DataFrame:
    """The rows the constants file names, read from its shot files (paths relative to
    ``root``, the repository), in its order.

    Raises
    ------
    InputError
        A named row that is in no file, or a file that cannot be read (one line).
    """
    spec = size_term_constants()
    frames = [read_body_shot_table(Path(root) / f) for f in spec["files"]]
    shots = pd.concat(frames, ignore_index=True).set_index("row", drop=False)
    wanted = [str(r) for r in spec["rows"]]
    missing = [r for r in wanted if r not in shots.index]
    if missing:
        raise InputError(f"size-term fit: rows {missing} are in none of {spec['files']}")
    return shots.loc[wanted].reset_index(drop=True)


def implied_factor(row: pd.Series, s_model: str, crater: str) -> float:
    """The factor on ``a0`` of the law ``(s_model, crater)`` that makes
    :func:`pencore.closedform.depth` meet the row's measured depth; NaN when the option
    cannot score the row (a crater shorter than the nose) or no factor in 0.02-50 does."""
    p = body_projectile(row, f"row {row['row']}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)  # fc beyond 108 MPa: as built
        base = concrete_law(
            row["fc_pa"],
            row["target_density_kg_m3"],
            s_model=s_model,
            crater=crater,
            size_term="none",
        )
    a0, _, a2 = base.coefficients
    v, measured = float(row["striking_velocity_m_s"]), float(row["depth_m"])

    def misfit(f: float) -> float:
        return math.log(depth(p, replace(base, coefficients=(a0 * f, 0.0, a2)), v) / measured)

    from scipy.optimize import brentq

    try:
        lo, hi = misfit(0.02), misfit(50.0)
    except InputError:
        return math.nan
    if not lo > 0.0 > hi:
        return math.nan
    return float(brentq(misfit, 0.02, 50.0, xtol=BRENT_TOL, rtol=BRENT_TOL))


def fit_size_term(
    shots: pd.DataFrame, s_model: str, crater: str, d_ref: float, exponent: float = 0.5
) -> SizeFit:
    """Fit ``d0`` of the size term to ``shots`` for the law ``(s_model, crater)`` (module
    notes).

    Parameters
    ----------
    shots : pandas.DataFrame
        Body shot rows (:func:`fit_rows`).
    s_model, crater : str
        The options of :func:`pencore.inputs.laws.concrete_law`.
    d_ref : float
        Reference diameter (m), where ``f = 1``.
    exponent : float
        Of the size-effect law (Bazant: 1/2).

    Returns
    -------
    SizeFit
    """
    f = implied_factors(shots, s_model, crater)
    return fit_d0(shots["diameter_m"].to_numpy(float), f, shots["row"], d_ref, exponent)


def implied_factors(shots: pd.DataFrame, s_model: str, crater: str) -> np.ndarray:
    """:func:`implied_factor` of every row (NaN where the option cannot score it)."""
    return np.array([implied_factor(r, s_model, crater) for _, r in shots.iterrows()])


def fit_d0(
    diameter: np.ndarray,
    factor: np.ndarray,
    rows: Sequence[Any],
    d_ref: float,
    exponent: float = 0.5,
) -> SizeFit:
    """Fit ``d0`` to the implied factors ``factor`` (NaN: a row left out) of shots of the
    given ``diameter`` (m); ``rows`` names them (module notes)."""
    from scipy.optimize import least_squares

    f = np.asarray(factor, dtype=float)
    ok = np.isfinite(f)
    d = np.asarray(diameter, dtype=float)[ok]
    lf = np.log(f[ok])

    def residual(x: np.ndarray) -> np.ndarray:
        d0 = math.exp(x[0])
        return exponent * np.log((1.0 + d_ref / d0) / (1.0 + d / d0)) - lf

    sol = least_squares(
        residual, [math.log(d_ref)], xtol=LSQ_TOL, ftol=LSQ_TOL, gtol=LSQ_TOL, method="lm"
    )
    return SizeFit(
        d0=float(math.exp(sol.x[0])),
        rows_used=int(ok.sum()),
        rows_skipped=tuple(str(r) for r, k in zip(rows, ok, strict=True) if not k),
        rms_log_factor=float(np.sqrt(np.mean(sol.fun**2))),
        rms_log_factor_without=float(np.sqrt(np.mean(lf**2))),
    )


def fit_all(
    root: str | Path = ".",
    s_models: Sequence[str] = S_MODELS,
    craters: Sequence[str] = CRATERS,
) -> dict[str, SizeFit]:
    """:func:`fit_size_term` for every ``s_model/crater`` pair, on :func:`fit_rows`, with
    the constants file's ``d_ref`` and ``exponent``."""
    spec = size_term_constants()
    shots = fit_rows(root)
    return {
        f"{s}/{c}": fit_size_term(shots, s, c, spec["d_ref_m"], spec["exponent"])
        for s in s_models
        for c in craters
    }


if __name__ == "__main__":  # pragma: no cover - prints the constants the file should hold
    for key, fit in fit_all().items():
        print(
            f"  {key}: {{d0_m: {fit.d0:.10g}, rows_used: {fit.rows_used}, "
            f"rows_skipped: {list(fit.rows_skipped)}, rms_log_factor: "
            f"{fit.rms_log_factor:.4f}, rms_log_factor_without: "
            f"{fit.rms_log_factor_without:.4f}}}"
        )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
