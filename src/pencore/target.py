"""Targets: media with a polynomial normal-resistance law and a friction law, in layers.

The target occupies the half-space ``y <= 0``; the free surface is ``y = 0``. Layers are
planar and stacked downwards. The last layer is semi-infinite (the paper's targets) or
finite: then the target is a plate (or a stack of plates) with nothing behind it, and a
projectile that clears its rear face has perforated it. Air gaps between plates are
layers without a medium (:meth:`Layer.gap`); surface elements in a gap, or below the
rear face of the last plate, carry no load.

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

from .validate import InputError, number

__all__ = ["Medium", "Layer", "Target", "TargetError"]


class TargetError(InputError):
    """A target definition that cannot be used."""


def _check(key: str, value: float, what: str) -> float:
    try:
        return number(value, key, what)
    except InputError as exc:
        raise TargetError(str(exc)) from None


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
        what = f"medium {self.name!r}"
        if isinstance(self.coefficients, str) or not hasattr(self.coefficients, "__iter__"):
            raise TargetError(f"{what}: coefficients must be a list [a0, a1, a2, ...]")
        c = tuple(_check("coefficient", x, f"{what} a{i}") for i, x in enumerate(self.coefficients))
        if not c:
            raise TargetError(f"{what}: coefficients must be a non-empty list [a0, a1, a2, ...]")
        if not any(x > 0.0 for x in c):
            raise TargetError(
                f"{what}: every resistance coefficient is zero, so nothing resists the "
                f"projectile; give a0 (Pa) or a2 (kg/m^3) > 0"
            )
        object.__setattr__(self, "coefficients", c)
        sp = tuple(_check("friction_speed", x, what) for x in self.friction_speeds)
        mu = tuple(_check("friction", m, what) for m in self.friction_mu)
        if len(sp) != len(mu) or not sp:
            raise TargetError(f"{what}: friction table needs equal, non-empty speed and mu lists")
        if any(b <= a for a, b in zip(sp, sp[1:], strict=False)):
            raise TargetError(f"{what}: friction speeds must increase, got {sp!r}")
        if not math.isnan(self.density):
            _check("medium_density", self.density, what)
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
    """A medium and its thickness (m); ``inf`` for a semi-infinite last layer.

    ``medium=None`` is an air gap (no load): see :meth:`gap`.
    """

    medium: Medium | None
    thickness: float = math.inf

    @classmethod
    def gap(cls, thickness: float) -> Layer:
        """An air gap of ``thickness`` (m) between two plates."""
        return cls(None, thickness)

    @property
    def is_gap(self) -> bool:
        return self.medium is None


@dataclass(frozen=True)
class Target:
    """A layered half-space, or a stack of plates, below ``y = 0``."""

    name: str
    layers: tuple[Layer, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        layers = tuple(self.layers)
        if not layers:
            raise TargetError(f"target {self.name!r} has no layers")
        what = f"target {self.name!r}"
        for k, lay in enumerate(layers):
            if not isinstance(lay, Layer):
                raise TargetError(f"{what}: layer {k} must be a Layer, got {lay!r}")
            last = k == len(layers) - 1
            if lay.is_gap and (k == 0 or last):
                raise TargetError(
                    f"{what}: layer {k} is a gap; a gap must lie between two layers of a "
                    "medium (the first layer starts at the surface y = 0)"
                )
            if not lay.is_gap and not isinstance(lay.medium, Medium):
                raise TargetError(f"{what}: layer {k} medium must be a Medium or None (gap)")
            if last and math.isinf(lay.thickness) and lay.thickness > 0:
                continue
            if math.isinf(lay.thickness):
                raise TargetError(f"{what}: only the last layer may be infinite (layer {k})")
            _check("thickness", lay.thickness, f"{what} layer {k}")
        object.__setattr__(self, "layers", layers)

    @classmethod
    def half_space(cls, medium: Medium) -> Target:
        return cls(medium.name, (Layer(medium),))

    @property
    def medium(self) -> Medium:
        """The top medium."""
        return self.layers[0].medium

    @property
    def solid_layers(self) -> tuple[Layer, ...]:
        """The layers that are not gaps."""
        return tuple(lay for lay in self.layers if not lay.is_gap)

    @property
    def frictionless(self) -> bool:
        return all(lay.medium.frictionless for lay in self.solid_layers)

    @property
    def thickness(self) -> float:
        """Total thickness (m), gaps included; ``inf`` for a semi-infinite target."""
        return math.fsum(lay.thickness for lay in self.layers)

    @property
    def finite(self) -> bool:
        """True when the last layer is finite (the target can be perforated)."""
        return math.isfinite(self.layers[-1].thickness)

    @property
    def rear_face(self) -> float:
        """Height ``y`` (m) of the rear face of the last plate; ``-inf`` if semi-infinite."""
        return -self.thickness

    def kernel_arrays(self) -> tuple[np.ndarray, ...]:
        """Arrays for the compiled kernel.

        Gaps are left out (their elements carry no load), so consecutive rows need not
        touch.

        Returns
        -------
        bounds : (n, 2) float
            ``y_top, y_bottom`` of each layer of a medium (m); the last bottom is
            ``-inf`` for a semi-infinite target, the rear face otherwise.
        coef : (n, p) float
            Resistance coefficients, zero-padded.
        fric : (n, k, 2) float
            Friction tables (speed, mu), padded by repeating the last row.
        """
        solid = self.solid_layers
        n = len(solid)
        p = max(len(lay.medium.coefficients) for lay in solid)
        k = max(len(lay.medium.friction_speeds) for lay in solid)
        bounds = np.empty((n, 2))
        coef = np.zeros((n, p))
        fric = np.empty((n, k, 2))
        top = 0.0
        j = 0
        for lay in self.layers:
            bottom = top - lay.thickness
            if lay.is_gap:
                top = bottom
                continue
            bounds[j] = top, bottom
            c = lay.medium.coefficients
            coef[j, : len(c)] = c
            sp, mu = lay.medium.friction_speeds, lay.medium.friction_mu
            for i in range(k):
                ii = min(i, len(sp) - 1)
                fric[j, i] = (sp[ii] + (i - ii) * 1.0, mu[ii])
            top = bottom
            j += 1
        return bounds, coef, fric
