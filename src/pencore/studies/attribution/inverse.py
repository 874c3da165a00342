"""The declared inverse step of the attribution study: the mass properties of #2 that
reproduce the paper's spin numbers, and what they do to the numbers not fitted.

Fitted (two parameters, two data): ``Lc/L`` of #2 and its transverse inertia as a factor
``f`` of the solid body's (:func:`pencore.paper.bodies.build_body`, kind ``given``: the
mass and axial inertia stay the solid body's), to

* the deviation alpha of #2 spun at 20 rad/s at 1000 m/s (paper Fig. 16: 2.86 deg), and
* its turn-back at 25 rad/s (paper: yes; and, since alpha at 20 is a deviation, no
  turn-back at 20).

The procedure (:func:`fit_spin_body`): every point of the grid :data:`LC_GRID` x
:data:`FACTOR_GRID` that some body of the outline could have (the outline's bounds,
:class:`pencore.Projectile` Notes) is run at 20 and 25 rad/s; of the points that turn back
at 25 and not at 20 the one with alpha(20) closest to the paper's is kept, and ``f`` is
refined at its ``Lc/L`` by bisection on ``log f`` between the neighbouring grid factors
where alpha(20) crosses the paper's value without turning back at 20 (a refined point
replaces the grid point only when its verdict at 25 is the paper's too). When no grid point
turns back at 25 and not at 20, the point closest in alpha(20) among those that do not turn
back at 20 is kept and the fit is flagged ``reproduced = False``.

Not fitted, and so the fit's test: alpha at 5 rad/s, Vcr, the Table 2 depth, the #4 yaw
deviations and the Fig. 12 trend (:func:`pencore.studies.attribution.disputed.disputed_quantities`
with the fitted body), and the trends of omega_c (Figs 17-18: falls with the impact
velocity and with ``Lc/L``) by :func:`omega_c_trends`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from pencore import analysis
from pencore.errors import GeometryError
from pencore.inputs.target import Target
from pencore.paper.bodies import build_body
from pencore.paper.claims import disputed_values
from pencore.run.impact import prepare, simulate
from pencore.search import critical
from pencore.search.threshold import OMEGA_TOL

__all__ = ["FACTOR_GRID", "FITTED_TO", "LC_GRID", "SpinFit", "fit_spin_body", "omega_c_trends"]

#: ``Lc/L`` of #2 on the coarse grid (Table 3: 0.525).
LC_GRID = tuple(round(0.525 + 0.025 * i, 3) for i in range(18))
#: Transverse inertia factors on the coarse grid.
FACTOR_GRID = tuple(round(2.0 ** (0.5 * i), 4) for i in range(-4, 7))
#: The paper numbers the inverse step is fitted to.
FITTED_TO = ("alpha_20", "turn_back_25")
#: Bisection steps of the refinement of ``f``.
REFINE_STEPS = 10
#: Speeds (m/s) and projectiles of the omega_c trends (Figs 17-18).
OMEGA_C_SPEEDS = (800.0, 1000.0, 1200.0)
#: The omega_c search range (rad/s) of the trends.
OMEGA_C_RANGE = (0.0, 200.0)


@dataclass(frozen=True)
class SpinFit:
    """Result of :func:`fit_spin_body`: the fitted ``Lc/L`` of #2 and transverse-inertia
    factor, alpha(20) (deg) and the turn-back verdicts at 20 and 25 rad/s there, whether
    the two fitted numbers are reproduced, and every grid point as
    ``(lc_over_l, f, alpha20, back20, back25)``."""

    lc_over_l: float
    factor: float
    alpha_20: float
    back_20: bool
    back_25: bool
    reproduced: bool
    grid: list[tuple[float, float, float, bool, bool]] = field(default_factory=list)


def _spins(
    spec: dict[str, Any], target: Target, kw: dict[str, Any], omegas: tuple[float, ...]
) -> list[tuple[float, bool]]:
    """alpha (deg) and the turn-back verdict of #2's body ``spec`` at 1000 m/s for each
    initial spin (rad/s), on one prepared problem (the loads are not needed)."""
    q = build_body("p2", spec).projectile
    pr = prepare(q, target, **kw)
    out = []
    for w in omegas:
        ds = simulate(q, target, 1000.0, omega=w, prepared=pr, loads=False)
        out.append((analysis.final_deviation(ds), bool(ds.attrs["reversed"])))
    return out


def fit_spin_body(target: Target, **kw: Any) -> SpinFit:
    """The inverse step (module docstring) in ``target`` (the study's soil), with
    :func:`pencore.prepare` options ``kw`` (shank model, emulation, numerics)."""
    goal = disputed_values()["alpha"][20.0]
    grid = []
    for x in LC_GRID:
        for f in FACTOR_GRID:
            spec = {"kind": "given", "lc_over_l": x, "i_transverse_factor": f}
            try:
                (a20, b20), (_, b25) = _spins(spec, target, kw, (20.0, 25.0))
            except GeometryError:  # an inertia no body of this outline can have
                continue
            grid.append((x, f, a20, b20, b25))

    def good(g: tuple[float, float, float, bool, bool]) -> bool:
        return not g[3] and (g[4] or not fitted)

    fitted = any(g[4] and not g[3] for g in grid)
    pool = [g for g in grid if good(g)] or grid
    best = min(pool, key=lambda g: abs(g[2] - goal))
    # refine f at this Lc/L where alpha(20) crosses the goal between grid neighbours
    row = sorted((g for g in grid if g[0] == best[0] and not g[3]), key=lambda g: g[1])
    bracket = next(
        ((g0, g1) for g0, g1 in zip(row, row[1:], strict=False)
         if (g0[2] - goal) * (g1[2] - goal) <= 0.0),
        None,
    )  # fmt: skip
    if bracket is not None:
        (lo, a_lo), hi = (bracket[0][1], bracket[0][2]), bracket[1][1]
        for _ in range(REFINE_STEPS):
            mid = math.sqrt(lo * hi)
            spec = {"kind": "given", "lc_over_l": best[0], "i_transverse_factor": mid}
            (m20, mb20), (_, mb25) = _spins(spec, target, kw, (20.0, 25.0))
            g = (best[0], mid, m20, mb20, mb25)
            if mb20:  # turns back at 20 inside the bracket: keep the best so far
                break
            if good(g) and abs(m20 - goal) < abs(best[2] - goal):
                best = g
            if (m20 - goal) * (a_lo - goal) > 0.0:
                lo, a_lo = mid, m20
            else:
                hi = mid
    x, f, a20, b20, b25 = best
    return SpinFit(x, f, a20, b20, b25, bool(b25 and not b20), grid)


def omega_c_trends(fit: SpinFit, target: Target, **kw: Any) -> dict[str, float]:
    """omega_c (rad/s, NaN above ``OMEGA_C_RANGE``) of the fitted body of #2 at
    :data:`OMEGA_C_SPEEDS`, and of #3 with the same recipe (its ``Lc/L`` moved by the same
    amount, the same inertia factor) at 1000 m/s: the Figs 17-18 trends the fit was not
    fitted to (the paper: omega_c falls with the impact speed and with ``Lc/L``)."""
    spec = {"kind": "given", "lc_over_l": fit.lc_over_l, "i_transverse_factor": fit.factor}
    out = {}
    for key, speeds in (("p2", OMEGA_C_SPEEDS), ("p3", (1000.0,))):
        q = build_body(key, spec).projectile
        for v in speeds:
            r = critical.omega_c(q, target, v, *OMEGA_C_RANGE, OMEGA_TOL, scan=9, **kw)
            out[f"{key}_{v:g}"] = float(r.value)
    return out
