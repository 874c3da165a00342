"""Targets: media with a polynomial normal-resistance law and a friction law, in layers.

The target occupies the half-space ``y <= 0``; the free surface is ``y = 0``. Layers are
planar and stacked downwards; the last layer is semi-infinite.

Resistance law (paper Eq. 11), normal stress on a surface element in contact::

    sigma_n = a0 + a1 Vn + a2 Vn^2 + ...      (Pa; Vn in m/s)

Friction law: Coulomb friction ``mu(V_tau) sigma_n`` opposing sliding, with ``mu`` a
piecewise-linear function of the sliding speed ``V_tau`` (m/s), given as a table
(a single row is a constant coefficient). Zero by default.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Medium", "Layer", "Target", "TargetError"]


class TargetError(ValueError):
    """A target definition that cannot be used."""


@dataclass(frozen=True)
class Medium:
    """A target material.

    Parameters
    ----------
    name : str
        Label.
    coefficients : sequence of float
        ``(a0, a1, a2, ...)`` of the resistance law, in Pa, Pa s/m, Pa s^2/m^2 ... .
    friction_speeds, friction_mu : sequence of float
        Table of the friction coefficient against sliding speed (m/s); linear
        interpolation, constant beyond the ends. Default: frictionless.
    density : float
        Mass density (kg/m^3), for reference only (it enters through the coefficients).
    source : str
        Provenance.
    """

    name: str
    coefficients: tuple[float, ...]
    friction_speeds: tuple[float, ...] = (0.0,)
    friction_mu: tuple[float, ...] = (0.0,)
    density: float = float("nan")
    source: str = ""

    def __post_init__(self) -> None:
        c = tuple(float(x) for x in self.coefficients)
        if not c or not all(math.isfinite(x) for x in c):
            raise TargetError(f"medium {self.name!r}: coefficients must be finite, got {c!r}")
        if c[0] < 0.0:
            raise TargetError(f"medium {self.name!r}: a0 must be >= 0 Pa, got {c[0]!r}")
        object.__setattr__(self, "coefficients", c)
        sp = tuple(float(x) for x in self.friction_speeds)
        mu = tuple(float(x) for x in self.friction_mu)
        if len(sp) != len(mu) or not sp:
            raise TargetError(
                f"medium {self.name!r}: friction table needs equal, non-empty speed and mu lists"
            )
        if any(b <= a for a, b in zip(sp, sp[1:], strict=False)):
            raise TargetError(f"medium {self.name!r}: friction speeds must increase, got {sp!r}")
        if any(m < 0.0 or not math.isfinite(m) for m in mu):
            raise TargetError(f"medium {self.name!r}: friction coefficients must be >= 0")
        object.__setattr__(self, "friction_speeds", sp)
        object.__setattr__(self, "friction_mu", mu)

    @property
    def frictionless(self) -> bool:
        return all(m == 0.0 for m in self.friction_mu)

    def sigma_n(self, vn: np.ndarray | float) -> np.ndarray:
        """Normal stress (Pa) at normal velocity ``vn`` (m/s), ignoring the contact test."""
        vn = np.asarray(vn, dtype=float)
        return np.polynomial.polynomial.polyval(vn, self.coefficients)

    def mu(self, v_tau: np.ndarray | float) -> np.ndarray:
        """Friction coefficient at sliding speed ``v_tau`` (m/s)."""
        return np.interp(v_tau, self.friction_speeds, self.friction_mu)

    def with_friction(self, mu: float | Sequence[tuple[float, float]]) -> Medium:
        """A copy with constant friction ``mu`` or a table of (speed m/s, mu) pairs."""
        if isinstance(mu, int | float):
            return Medium(
                self.name, self.coefficients, (0.0,), (float(mu),), self.density, self.source
            )
        sp, m = zip(*mu, strict=True)
        return Medium(self.name, self.coefficients, tuple(sp), tuple(m), self.density, self.source)


@dataclass(frozen=True)
class Layer:
    """A medium and its thickness (m); ``inf`` for the last, semi-infinite layer."""

    medium: Medium
    thickness: float = math.inf


@dataclass(frozen=True)
class Target:
    """A layered half-space below ``y = 0``."""

    name: str
    layers: tuple[Layer, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        layers = tuple(self.layers)
        if not layers:
            raise TargetError(f"target {self.name!r} has no layers")
        for k, lay in enumerate(layers):
            if not (lay.thickness > 0.0):
                raise TargetError(
                    f"target {self.name!r}: layer {k} thickness must be > 0 m, got {lay.thickness}"
                )
            if k < len(layers) - 1 and not math.isfinite(lay.thickness):
                raise TargetError(f"target {self.name!r}: only the last layer may be infinite")
        object.__setattr__(self, "layers", layers)

    @classmethod
    def half_space(cls, medium: Medium) -> Target:
        return cls(medium.name, (Layer(medium),))

    @property
    def medium(self) -> Medium:
        """The top medium."""
        return self.layers[0].medium

    @property
    def frictionless(self) -> bool:
        return all(lay.medium.frictionless for lay in self.layers)

    def kernel_arrays(self) -> tuple[np.ndarray, ...]:
        """Arrays for the compiled kernel.

        Returns
        -------
        bounds : (n, 2) float
            ``y_top, y_bottom`` of each layer (m); the last bottom is ``-inf``.
        coef : (n, p) float
            Resistance coefficients, zero-padded.
        fric : (n, k, 2) float
            Friction tables (speed, mu), padded by repeating the last row.
        """
        n = len(self.layers)
        p = max(len(lay.medium.coefficients) for lay in self.layers)
        k = max(len(lay.medium.friction_speeds) for lay in self.layers)
        bounds = np.empty((n, 2))
        coef = np.zeros((n, p))
        fric = np.empty((n, k, 2))
        top = 0.0
        for j, lay in enumerate(self.layers):
            bottom = top - lay.thickness
            bounds[j] = top, bottom
            c = lay.medium.coefficients
            coef[j, : len(c)] = c
            sp, mu = lay.medium.friction_speeds, lay.medium.friction_mu
            for i in range(k):
                ii = min(i, len(sp) - 1)
                fric[j, i] = (sp[ii] + (i - ii) * 1.0, mu[ii])
            top = bottom
        return bounds, coef, fric
