"""Shank contact models and paper-emulation numerics, selectable per run.

Two small option sets, passed to :func:`pencore.simulate` (and :func:`pencore.prepare`)
as ``shank=`` and ``emulation=`` (an object, a mapping of its fields, or for ``shank``
just the model name). The defaults are pencore's model and numerics, unchanged to the
last bit.

Shank contact models (:class:`ShankModel`)
------------------------------------------
The DAFL as the paper writes it (Eqs 6-7, 11) loads every surface element inside the
target whose normal velocity is ``Vn >= 0``. On the shank this gives, at zero angle of
attack, ``a0`` all round (it cancels), and at any sideways motion a jump of the lateral
force by ``2 a0 r dl`` per ring: a dry-friction-like force that arrests rotation. The
paper names what it leaves out: "wake separation and reattachment" (Bernard & Creighton
1978, 1979; Byers et al. 1978), which trajectory codes of the DAFL family model on the
afterbody (the WES codes PENCO2D/PENCRV3D: Adley et al. 1997, Danielson & Adley 2000;
the Sandia cavity-expansion codes: Longcope, Tabbara & Jung 1999; Warren & Tabbara 2000;
Warren & Poormon 2001). The models here:

``"dafl"`` (default)
    The law as written, on every element (pencore's closed-form ring integrals).
``"cavity"``
    pencore's separation/reattachment form, *modelled on* that family (not copied from
    any one of them): the nose cuts a cavity, the tube of radius ``R_c`` (the body
    radius) around the nose-tip path; a shank element is loaded only where it presses
    into the wall of that cavity, i.e. where its wall intrusion ``delta = d - R_c > 0``
    (``d`` its distance from the tip path) and ``Vn >= 0``, with the resistance building
    from the wall (``axis="tip"``, the default)::

        sigma = sigma_DAFL(Vn) * min(1, delta / delta_ref)

    The ramp is the pressure-expansion curve of an elastic-perfectly-plastic cavity wall
    taken as linear: Lame's elastic cylindrical cavity gives ``u = p R_c / (2 G)``, so
    the wall carries the full DAFL stress once pushed out by about ``delta_ref ~ R_c
    sigma / (2 G)`` (1-5 mm for the soil's 17 MPa and ``G`` of 50-200 MPa, which the
    paper does not give). Nose and flat faces keep the DAFL (the nose is the cutter).
    The wall is not moved by the shank (no memory of earlier intrusions), and
    ``delta_ref -> 0`` is a rigid wall: it differs from the DAFL where a shank element
    moves outwards while still inside the cavity (separated), which the DAFL loads.
    ``axis="shoulder"`` centres the cavity on the path of the nose shoulder (the axis
    point where the nose meets the shank, whose full-radius section cuts the cavity the
    shank runs in) instead of the tip: with a yaw ``a`` the two paths are
    ``nose length x sin(a)`` apart (2.8 mm at 1 deg for these projectiles).
    On rings the shank stress is integrated by the midpoint rule with ``n_phi`` points
    around each ring; on panels at each panel centroid.
``"factor"``
    A plain factor ``f`` on the whole stress of the shank elements (``a0`` and the
    velocity terms). For attribution only: it is a knob, not a model of anything.

The model is per run, not per medium: the cavity belongs to the body's passage, and
each layer's own coefficients still give ``sigma_DAFL``.

Paper-emulation numerics (:class:`Emulation`)
---------------------------------------------
What an ABAQUS/Explicit model with a VDLOAD user subroutine on a finite-element surface
(paper Sect. 3, Figs 3-4) computes, as opposed to pencore's converged solution:

``surface="panels"``
    A faceted surface: the meridian through the band edges of the rings
    (``n_nose``, ``n_shank``, ``n_face`` of :class:`pencore.Numerics`) times
    ``n_circumferential`` sectors gives flat quadrilateral (triangular at the tip)
    panels with their nodes on the true surface; each panel carries one point load at
    its centroid, with its flat-facet normal and area. A coarse facet ring has less
    projected area than the circle (the inscribed polygon: ``(N / 2 pi) sin(2 pi / N)``).
``integrator="explicit"``
    A fixed step ``dt`` of the central-difference (leapfrog) scheme of explicit
    dynamics codes: velocities at half steps, positions and attitude at whole steps,
    loads from the positions and the latest (half-step) velocities, and the pure
    Heaviside of Eq. 7 (``numerics.eps`` is not used). See :mod:`pencore.integrators.explicit`.

Both converge to pencore's default solution as they are refined
(``benchmarks/emulation_convergence.py``).
"""

from __future__ import annotations

import difflib
import json
from collections.abc import Mapping
from dataclasses import asdict, dataclass, fields
from typing import Any

from pencore.errors import InputError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.limits import check_keys, integer, number

__all__ = [
    "ShankModel",
    "Emulation",
    "SHANK_MODELS",
    "SURFACES",
    "INTEGRATORS",
    "shank_model",
    "emulation",
]

SHANK_MODELS = ("dafl", "cavity", "factor")
CAVITY_AXES = ("tip", "shoulder")
SURFACES = ("rings", "panels")
INTEGRATORS = ("adaptive", "explicit")

#: Kernel codes of the shank models and surfaces (index into the tuples above).
SHANK_DAFL, SHANK_CAVITY, SHANK_FACTOR = 0, 1, 2
SURFACE_RINGS, SURFACE_PANELS = 0, 1


def _choice(value: Any, allowed: tuple[str, ...], what: str) -> str:
    if not isinstance(value, str) or value not in allowed:
        hint = difflib.get_close_matches(str(value), allowed, n=1)
        tip = f"; did you mean {brief(hint[0])}?" if hint else ""
        raise InputError(f"{what} must be one of {', '.join(allowed)}, got {brief(value)}{tip}")
    return value


@dataclass(frozen=True)
class ShankModel:
    """How the shank (cylindrical part) is loaded; see the module docstring.

    Attributes
    ----------
    kind : {"dafl", "cavity", "factor"}
        The model.
    factor : float
        ``"factor"``: the factor on the shank stress (1 is the DAFL).
    delta_ref : float
        ``"cavity"``: wall intrusion (m) at which the full DAFL stress is reached.
        Default 5 mm: assumed (Lame estimate with ``G ~ 80 MPa``), not from the paper.
    n_phi : int
        ``"cavity"`` on rings: midpoint-rule points around each shank ring.
    axis : {"tip", "shoulder"}
        ``"cavity"``: the axis point whose path is the cavity's axis.

    Raises
    ------
    InputError
        An unknown ``kind`` or ``axis``, a value out of its range.

    Examples
    --------
    >>> import pencore
    >>> pencore.ShankModel(kind="cavity").describe()
    'cavity(delta_ref=0.005 m)'
    >>> pencore.ShankModel(kind="factor", factor=0.5).describe()
    'factor(f=0.5)'

    ``simulate(..., shank="cavity")`` and ``shank={"kind": "factor", "factor": 0.5}`` build
    the same objects.
    """

    kind: str = "dafl"
    factor: float = 1.0
    delta_ref: float = 5e-3
    n_phi: int = 64
    axis: str = "tip"

    def __post_init__(self) -> None:
        _choice(self.kind, SHANK_MODELS, "shank model")
        _choice(self.axis, CAVITY_AXES, "cavity axis")
        object.__setattr__(self, "factor", number(self.factor, "shank_factor", "shank"))
        object.__setattr__(self, "delta_ref", number(self.delta_ref, "delta_ref", "shank"))
        object.__setattr__(self, "n_phi", integer(self.n_phi, "n_phi", "shank"))

    @property
    def code(self) -> int:
        """The model's number in the compiled kernels (its index in ``SHANK_MODELS``)."""
        return SHANK_MODELS.index(self.kind)

    @property
    def is_default(self) -> bool:
        """True when the shank carries the plain DAFL (also ``factor`` with f = 1 is not
        counted as default: it is the same law, but a different code path)."""
        return self.kind == "dafl"

    def describe(self) -> str:
        """A short label, e.g. ``cavity(delta_ref=0.005 m)``."""
        if self.kind == "factor":
            return f"factor(f={self.factor:g})"
        if self.kind == "cavity":
            where = "" if self.axis == "tip" else ", shoulder path"
            return f"cavity(delta_ref={self.delta_ref:g} m{where})"
        return "dafl"


@dataclass(frozen=True)
class Emulation:
    """Numerics that emulate a finite-element code; see the module docstring.

    Attributes
    ----------
    surface : {"rings", "panels"}
        pencore's closed-form rings (default) or flat panels with a point load each.
    n_circumferential : int
        Panels around the body (``surface="panels"``).
    integrator : {"adaptive", "explicit"}
        ``"adaptive"``: the method of ``numerics.method`` (default Rosenbrock);
        ``"explicit"``: fixed-step central difference with step ``dt``.
    dt : float
        Fixed time step (s) of the explicit integrator.

    Raises
    ------
    InputError
        An unknown ``surface`` or ``integrator``, a value out of its range.

    Examples
    --------
    >>> import pencore
    >>> pencore.Emulation().describe()
    'rings, adaptive'
    >>> pencore.Emulation(surface="panels", integrator="explicit", dt=2e-6).describe()
    'panels x36, explicit dt=2e-06 s'
    """

    surface: str = "rings"
    n_circumferential: int = 36
    integrator: str = "adaptive"
    dt: float = 1e-6

    def __post_init__(self) -> None:
        _choice(self.surface, SURFACES, "emulation surface")
        _choice(self.integrator, INTEGRATORS, "emulation integrator")
        object.__setattr__(
            self,
            "n_circumferential",
            integer(self.n_circumferential, "n_circumferential", "emulation"),
        )
        object.__setattr__(self, "dt", number(self.dt, "dt", "emulation"))

    @property
    def is_default(self) -> bool:
        """True for pencore's own numerics (rings, adaptive integrator)."""
        return self.surface == "rings" and self.integrator == "adaptive"

    def describe(self) -> str:
        """A short label, e.g. ``panels x36, explicit dt=1e-06 s``."""
        parts = []
        if self.surface == "panels":
            parts.append(f"panels x{self.n_circumferential}")
        if self.integrator == "explicit":
            parts.append(f"explicit dt={self.dt:g} s")
        return ", ".join(parts) or "rings, adaptive"


def _from(cls: type, value: Any, what: str) -> Any:
    if value is None:
        return cls()
    if isinstance(value, cls):
        return value
    if isinstance(value, str) and cls is ShankModel:
        return ShankModel(kind=value)
    if isinstance(value, Mapping):
        check_keys(value, [f.name for f in fields(cls)], what)
        return cls(**value)
    raise InputError(
        f"{what} must be a pencore.inputs.models.{cls.__name__} or a mapping of its "
        f"fields, got {brief(value)}"
    )


def shank_model(value: ShankModel | Mapping[str, Any] | str | None) -> ShankModel:
    """A :class:`ShankModel` from an object, a mapping, a model name, or ``None``."""
    return _from(ShankModel, value, "shank")


def emulation(value: Emulation | Mapping[str, Any] | None) -> Emulation:
    """An :class:`Emulation` from an object, a mapping of its fields, or ``None``."""
    return _from(Emulation, value, "emulation")


def to_json(obj: ShankModel | Emulation) -> str:
    """The options as JSON (dataset attributes)."""
    return json.dumps(asdict(obj))


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
