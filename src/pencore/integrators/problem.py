"""The prepared problem: everything an integrator needs that does not change from one
impact to the next.

:func:`pencore.prepare` builds a :class:`Problem` once from a projectile, a target,
numerics and the model choices; every integrator (:mod:`~pencore.integrators.rosenbrock`,
:mod:`~pencore.integrators.explicit`, :mod:`~pencore.integrators.scipy_ivp`) takes it with
the initial state of one impact, so a search of hundreds of runs resolves names and
builds the kernel arrays once. SI units throughout.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from pencore.inputs.geometry import Projectile
from pencore.inputs.models import Emulation, ShankModel
from pencore.inputs.numerics import Numerics
from pencore.inputs.target import Target
from pencore.kernels.forces import default_model
from pencore.kernels.state import body_reach

__all__ = ["Problem"]


@dataclass
class Problem:
    """A projectile, a target and numerics, resolved into the compiled kernels' arrays.

    Attributes
    ----------
    projectile, target, numerics
        The resolved inputs.
    rings : ndarray, shape (n, 6)
        The projectile's surface rings (body axes, m): the geometry the initial state,
        the reach and the Dataset use.
    bounds, coef, fric : ndarray
        The target's layer bounds (m), resistance coefficients (SI, per layer) and
        friction tables, as :meth:`pencore.inputs.target.Target.kernel_arrays` builds them.
    mass : float
        Mass (kg).
    inertia : ndarray, shape (3,)
        Principal moments of inertia about the centre of mass (kg m^2): axial,
        transverse, transverse.
    lc : float
        Distance (m) from the nose tip to the centre of mass.
    shank, emulation
        The shank contact model and the paper-emulation numerics.
    kernel_rings : ndarray or None
        The rings the ring kernel loads under a non-default model (None: ``rings``).
    model : tuple of ndarray or None
        The kernel tuple of :mod:`pencore.kernels.forces` (None: the DAFL on rings).
    regime_warned : bool
        True once a run of this problem has warned that it is outside the rigid regime
        (:func:`pencore.inputs.regime.warn_outside`): a search warns at most once.
    """

    projectile: Projectile
    target: Target
    numerics: Numerics
    rings: np.ndarray
    bounds: np.ndarray
    coef: np.ndarray
    fric: np.ndarray
    mass: float
    inertia: np.ndarray
    lc: float
    shank: ShankModel = ShankModel()
    emulation: Emulation = Emulation()
    kernel_rings: np.ndarray | None = None
    model: tuple[np.ndarray, ...] | None = None
    regime_warned: bool = False

    @property
    def loaded_rings(self) -> np.ndarray:
        """The rings the ring kernel loads (``kernel_rings`` under a model, else ``rings``)."""
        return self.rings if self.model is None else self.kernel_rings

    @property
    def kernel_model(self) -> tuple[np.ndarray, ...]:
        """The kernel tuple of :mod:`pencore.kernels.forces` (default: DAFL on rings)."""
        return default_model() if self.model is None else self.model

    @property
    def gravity(self) -> np.ndarray:
        """Gravitational acceleration vector (m/s^2), along ``-y``."""
        return np.array([0.0, -self.numerics.gravity, 0.0])

    @property
    def n_gauss(self) -> int:
        """Gauss points of the friction integral; 0 (no friction pass) when frictionless."""
        return self.numerics.n_gauss if not self.target.frictionless else 0

    @cached_property
    def band_length(self) -> float:
        """Meridian length (m) of the shortest surface band (``w / r`` of the loaded
        rings): the finest scale on which the contact loads vary as the body moves."""
        rings = self.loaded_rings
        r = rings[:, 1]
        return float(np.min(rings[r > 0.0, 4] / r[r > 0.0]))

    @cached_property
    def thin_layers(self) -> np.ndarray:
        """The layers and gaps thinner than twice ``numerics.max_travel``, shape (k, 3):
        top and bottom heights ``y`` (m) and the half-width ``max(thickness,
        band_length) / 2`` (m), the most a step may move the body across one
        (:func:`pencore.kernels.state.layer_travel_bound`). None for a half-space or
        layers all thicker, whose steps are bounded by ``numerics.max_travel`` alone.

        Half the thickness keeps a plate from being stepped over; a layer thinner than
        the shortest band is resolved at the band scale, on which its load varies (each
        band's share of a layer ramps over the band's height,
        :func:`pencore.kernels.bands.band_half_height`), so a 1-um foil does not take a
        million steps. The bound vanishes with the ring spacing."""
        limit = 2.0 * self.numerics.max_travel
        band = self.band_length
        rows = [
            (top, bottom, 0.5 * max(lay.thickness, band))
            for lay, (top, bottom) in zip(self.target.layers, self.target.levels, strict=True)
            if lay.thickness < limit
        ]
        return np.array(rows, dtype=float).reshape(len(rows), 3)

    @property
    def reach(self) -> float:
        """Largest distance (m) from the centre of mass to a surface ring."""
        return body_reach(self.rings)

    def load_args(self) -> tuple:
        """The arguments after the state of the compiled right-hand side
        (:func:`pencore.kernels.forces.rhs_model`): mass, inertia, gravity, rings,
        bounds, coef, fric, eps, n_gauss, model."""
        return (
            self.mass,
            self.inertia,
            self.gravity,
            self.loaded_rings,
            self.bounds,
            self.coef,
            self.fric,
            self.numerics.eps,
            self.n_gauss,
            self.kernel_model,
        )

    def atol(self, velocity: float) -> np.ndarray:
        """Absolute tolerances of the 13 state components for an impact at ``velocity``
        (m/s): 1 % of ``rtol`` times the scale of each (body length, 1, impact speed,
        impact speed / length)."""
        length = self.projectile.length
        return (
            self.numerics.rtol
            * np.array([length] * 3 + [1.0] * 4 + [velocity] * 3 + [velocity / length] * 3)
            * 1e-2
        )

    def stall_distance(self, chunk_steps: int) -> float:
        """Distance (m) under which ``chunk_steps`` accepted steps count as stalled: 1 % of
        the body length, unless the steps are bounded that short, by the user's
        ``max_travel`` or near a thin layer (the smallest half-width of
        :attr:`thin_layers`: a fine ring mesh through a foil)."""
        travel = self.numerics.max_travel
        thin = self.thin_layers
        if thin.shape[0]:
            travel = min(travel, float(thin[:, 2].min()))
        return min(1e-2 * self.projectile.length, 0.1 * chunk_steps * travel)
