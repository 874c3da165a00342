"""Where a rigid body's answer stops meaning anything: the rigid regime.

pencore's projectile is rigid. At high speed against strong targets real noses deform or
erode (Piekutowski et al. 1999 bend and erode their rods above 1.24-1.82 km/s into
aluminium; rigid predictions of the concrete shots above 1500 m/s run deep). No published
criterion could be read here, so pencore declares one (:data:`REGIME_FILE`, with its
provenance)::

    R = sigma_n(V) / Y  <=  bound

``sigma_n(V) = a0 + a1 V + a2 V^2`` is the normal stress the target's law puts on the nose
tip at the striking speed (the rigid model's stagnation stress, the largest it puts on the
nose), ``Y`` the projectile's yield strength (``yield_strength`` of
:class:`~pencore.inputs.geometry.Projectile`).
The bound (5.5) is set on the rods Piekutowski et al. call rigid or deformed; it is a
judgement on the nose's load, not a model of erosion: outside it pencore still answers, and
warns (:class:`~pencore.errors.RigidRegimeWarning`) once per prepared problem.

Without a given strength the check assumes the strongest rod steel of those shots
(:data:`REGIME_FILE` ``assumed_yield_strength_pa``, AerMet 100), so it warns only where no
steel of those shots would stay rigid; the verdict says the strength was assumed.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from pencore.errors import RigidRegimeWarning, hint_keywords
from pencore.inputs.geometry import Projectile
from pencore.inputs.limits import _caller_level
from pencore.inputs.target import Medium, Target

__all__ = ["REGIME_FILE", "RigidRegime", "regime_constants", "rigid_regime", "warn_outside"]

#: The declared bound and the assumed strength, with their provenance.
REGIME_FILE = Path(__file__).parent / "data" / "rigid_regime.yaml"


@lru_cache(maxsize=1)
def regime_constants() -> dict[str, Any]:
    """:data:`REGIME_FILE` as a mapping (``bound``, ``assumed_yield_strength_pa``, ...)."""
    import yaml

    return yaml.safe_load(REGIME_FILE.read_text())


@dataclass(frozen=True)
class RigidRegime:
    """The rigid-regime verdict of one impact.

    Attributes
    ----------
    rigid : bool
        True when ``ratio <= bound``.
    ratio : float
        ``R = sigma_n(V) / Y`` (dimensionless).
    bound : float
        The declared bound on ``R``.
    stress : float
        ``sigma_n(V)`` at the nose tip (Pa), of the layer where it is largest.
    strength : float
        ``Y`` (Pa), given or assumed.
    strength_given : bool
        False when ``Y`` is the assumed one.
    limit_speed : float
        The striking speed (m/s) at which ``R`` reaches the bound (0: already at rest).
    medium : str
        The medium the verdict is for.
    """

    rigid: bool
    ratio: float
    bound: float
    stress: float
    strength: float
    strength_given: bool
    limit_speed: float
    medium: str

    @property
    def margin(self) -> float:
        """``bound / ratio - 1``: > 0 inside the regime (how much more stress it takes),
        < 0 outside."""
        return self.bound / self.ratio - 1.0

    def message(self, velocity: float) -> str:
        """The one-line warning for a run at ``velocity`` (m/s) outside the regime."""
        y = f"{self.strength / 1e6:.4g} MPa" + ("" if self.strength_given else " (assumed)")
        return (
            f"rigid regime: at {velocity:g} m/s the nose-tip stress in {self.medium} is "
            f"{self.stress / 1e9:.3g} GPa, {self.ratio:.3g} times the projectile's yield "
            f"strength {y}, above the bound {self.bound:g} (nose deformation or erosion "
            f"likely above {self.limit_speed:.4g} m/s; the rigid depth is not to be trusted)"
        )


def _limit_speed(coefficients: tuple[float, ...], level: float) -> float:
    """Smallest speed ``V >= 0`` with ``sum a_k V^k = level`` (inf if none)."""
    c = np.array(coefficients, dtype=float)
    if c[0] >= level:
        return 0.0
    c = c.copy()
    c[0] -= level
    roots = np.roots(c[::-1])
    real = [r.real for r in roots if abs(r.imag) <= 1e-9 * max(1.0, abs(r)) and r.real > 0.0]
    return float(min(real)) if real else math.inf


def rigid_regime(projectile: Projectile, target: Target | Medium, velocity: float) -> RigidRegime:
    """The rigid-regime verdict of a projectile striking a target at ``velocity``.

    Parameters
    ----------
    projectile : Projectile
        The body; its ``yield_strength`` (Pa) if given, else the assumed one.
    target : Target or Medium
        Resolved for the projectile (:meth:`pencore.inputs.target.Target.for_projectile`);
        every solid layer is checked at the striking speed and the largest stress counts.
    velocity : float
        Striking speed (m/s).

    Returns
    -------
    RigidRegime

    Examples
    --------
    >>> import pencore
    >>> from pencore.inputs.regime import rigid_regime
    >>> rod = pencore.get_projectile("al_ogive_var4340")
    >>> rod = pencore.Projectile(rod.name, rod.diameter, rod.nose, rod.shank,
    ...                          yield_strength=1.14e9)
    >>> al = pencore.get_target("aluminium")
    >>> v = rigid_regime(rod, al, 1237.0)
    >>> print(v.rigid, f"{v.ratio:.2f}", f"{v.limit_speed:.0f} m/s")
    True 4.80 1353 m/s
    >>> rigid_regime(rod, al, 1365.0).rigid
    False
    """
    spec = regime_constants()
    bound = float(spec["bound"])
    given = projectile.yield_strength is not None
    y = float(projectile.yield_strength) if given else float(spec["assumed_yield_strength_pa"])
    media = [target] if isinstance(target, Medium) else [lay.medium for lay in target.solid_layers]
    stresses = [float(m.sigma_n(velocity)) for m in media]
    k = int(np.argmax(stresses))
    ratio = stresses[k] / y
    return RigidRegime(
        rigid=ratio <= bound,
        ratio=ratio,
        bound=bound,
        stress=stresses[k],
        strength=y,
        strength_given=given,
        limit_speed=min(_limit_speed(m.coefficients, bound * y) for m in media),
        medium=media[k].name,
    )


def warn_outside(projectile: Projectile, target: Target | Medium, velocity: float) -> bool:
    """Warn (:class:`~pencore.errors.RigidRegimeWarning`, one line) when the impact is
    outside the rigid regime; return True if it warned."""
    verdict = rigid_regime(projectile, target, velocity)
    if verdict.rigid:
        return False
    warnings.warn(verdict.message(velocity), RigidRegimeWarning, stacklevel=_caller_level())
    return True


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
