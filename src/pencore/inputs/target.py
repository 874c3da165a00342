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

Near-surface options (all off by default; the paper's model has none).

* ``crater_depth`` (``k_c``, calibers): the near-surface (crater) region of Forrestal et
  al., "An empirical equation for penetration depth of ogive-nose projectiles into
  concrete targets", IJIE 15 (1994) 395-405, and Frew et al., "A spherical
  cavity-expansion penetration model for concrete targets", Int. J. Solids Struct. 35
  (1998) 4235-4250: there the axial force on the nose rises linearly with tip depth,
  ``F = c z``, over a crater of ``k_c d`` (k = 2; Li & Chen, IJIE 28 (2003) 93-116, give
  ``k = 0.707 + H/d``, H the nose length), and takes the cavity-expansion value below.
  pencore multiplies every element's load in the layer by one factor chosen so that the
  axial force is exactly Forrestal's ``c z`` (with ``c`` read off the present depth and
  speed, see :mod:`pencore.kernels.crater`); the depth in normal impact is then
  :func:`pencore.closedform.forrestal_crater_depth`. ``k_c d`` must be at least the nose
  length (the crater ends with the nose embedded).

Two free-surface reductions multiply the stress of an element at distance ``delta`` (m)
from a *free* face of its layer (the target's front face, a face next to an air gap, the
rear face of the last plate), one factor per free face:

* ``plastic_zone_ratio`` (``c/a``): the quasi-static pressure of a spherical cavity of
  radius ``a`` (the projectile radius) in an elastic-perfectly-plastic sphere whose free
  outer surface is ``b = a + delta`` away, over that in an infinite medium (Hill, *The
  Mathematical Theory of Plasticity*, 1950, ch. V)::

      F = (3 ln(min(c, b)/a) + 1 - min(c, b)^3 / b^3) / (1 + 3 ln(c/a))

  with ``c/a`` the infinite medium's plastic-zone ratio, ``(E / (3 (1 - nu) Y))^(1/3)``
  for an elastic-perfectly-plastic solid. 0 at the face; far from every face it tends to
  1 as ``(c/b)^3`` (the half-space law). Trajectory codes of this family reduce the stress
  near free faces (Warren & Poormon, IJIE 25 (2001) 993-1022; Warren, Hanchak & Poormon,
  IJIE 30 (2004) 1307-1331); their functions could not be read for this work, so this is
  the textbook finite-target cavity solution, not theirs, applied to the whole normal
  stress (pencore's choice: Hill's solution is the static term's).
* ``free_surface_depth`` (``k_f``, calibers): pencore's own linear ramp
  ``min(1, delta / (k_f d))``, with no source; kept as a simple, documented knob.

The ring kernel evaluates the free-surface factor at the centre of each surface ring
(exact for a ring parallel to the surface, i.e. normal incidence); the load-point kernels
at each point.

Parts that depend on the projectile (off by default). A medium may carry a law whose
numbers need the projectile: the crater depth of Li & Chen (``crater_rule="li_chen"``:
``k = 0.707 + H/d`` calibers, H the nose length) and a size term
(:class:`SizeTerm`: the static coefficient ``a0`` times ``f(d)``). Such a medium is
resolved for a projectile by :meth:`Medium.for_projectile` (what
:func:`pencore.run.impact.prepare` and :func:`pencore.closedform.depth` do): the result
is a plain medium whose ``source`` states the diameter, the factor and the resolved
numbers, so a run's Dataset records what was used. The kernels never see the rule.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from pencore.errors import InputError, TargetError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.geometry import ConeNose, Nose, OgiveNose, nose_axial_moments
from pencore.inputs.limits import as_float, count, number, plausible
from pencore.inputs.record import RECORD_LAWS

__all__ = [
    "WINDOW_COLUMNS",
    "LI_CHEN_CRATER",
    "SizeTerm",
    "Medium",
    "Layer",
    "Target",
]


#: Most resistance coefficients a medium may have: the compiled kernels hold the stress
#: polynomial, its smoothed step (one degree more) and the Jacobian's moments (three
#: more) in arrays of ``pencore.kernels.arcs._MAXD + 2`` entries (tests/run/test_impact.py checks).
MAX_COEFFICIENTS = 8

#: Columns of the layer array when a near-surface option is on
#: (:meth:`Target.kernel_arrays`): ten of the windows, then the crater's nose (kind,
#: parameter, length) and its full-nose moments (``pencore.kernels.crater.COL_NOSE``,
#: ``COL_MOMENTS``; tests/kernels/test_crater.py checks the layout).
WINDOW_COLUMNS = 13 + MAX_COEFFICIENTS


def _nose_columns(nose: Nose, a: float, nose_length: float) -> np.ndarray:
    """The crater's nose columns of a layer row (``pencore.kernels.crater``): kind (1
    ogive, 2 cone, 3 flat), parameter (ogive radius ``2 CRH a``, m; cone ``tan`` of the
    half-angle; 0), length (m), and the full-nose moments ``J_k`` (m^2)."""
    if isinstance(nose, OgiveNose):
        head = (1.0, 2.0 * nose.crh * a, nose_length)
    elif isinstance(nose, ConeNose):
        head = (2.0, math.tan(nose.half_angle), nose_length)
    else:
        head = (3.0, 0.0, 0.0)
    return np.concatenate([head, nose_axial_moments(nose, a, MAX_COEFFICIENTS)])


#: Li & Chen's crater depth ``k = 0.707 + H/d`` (their Eq. 25): the 0.707 calibers of the
#: Prandtl slip depth of a flat punch, plus the nose length over the diameter. Source:
#: Q.M. Li & X.W. Chen, "Dimensionless formulae for penetration depth of concrete target
#: impacted by a non-deformable projectile", IJIE 28 (2003) 93-116, as quoted (secondary)
#: by github.com/endofwave/engineering-tools, content/series-a/a4-penetration-depth.
LI_CHEN_CRATER = 0.707
#: Crater rules a medium may carry ("" : the crater depth as given).
CRATER_RULES = ("", "li_chen")


@dataclass(frozen=True)
class SizeTerm:
    """A size term on the static resistance: ``a0(d) = a0 f(d)``, of the form of
    Bazant's size-effect law (Z.P. Bazant, "Size effect in blunt fracture: concrete, rock,
    metal", J. Eng. Mech. 110 (1984) 518-535: a nominal strength falling as
    ``(1 + D/D0)^-1/2``), normalised to 1 at a reference diameter:
    ``f(d) = ((1 + d_ref / d0) / (1 + d / d0)) ** exponent``.

    Parameters
    ----------
    d_ref : float
        Reference diameter (m) at which the law without the term holds (``f = 1``).
    d0 : float
        Transitional diameter (m) of the size-effect law: ``f`` falls as ``d^-exponent``
        well above it and tends to a constant well below it.
    exponent : float
        0.5 in Bazant's law.
    source : str
        Where the constants come from (a fit: which rows, which function, when).
    s_ref : float
        The medium's ``S`` at ``d_ref`` (dimensionless; NaN when not known), for reporting
        the resolved ``S = s_ref f(d)``.

    Examples
    --------
    >>> from pencore.inputs.target import SizeTerm
    >>> t = SizeTerm(d_ref=0.025, d0=0.05, exponent=0.5)
    >>> print(f"{t.factor(0.025):.3f} {t.factor(0.2):.3f}")
    1.000 0.548
    """

    d_ref: float
    d0: float
    exponent: float = 0.5
    source: str = ""
    s_ref: float = float("nan")

    def __post_init__(self) -> None:
        for key in ("d_ref", "d0"):
            v = as_float(getattr(self, key), allow_str=False)
            if v is None or not (math.isfinite(v) and v > 0.0):
                raise TargetError(
                    f"size term: {key} must be a positive number of m, got "
                    f"{brief(getattr(self, key))}"
                )
            object.__setattr__(self, key, v)
        e = as_float(self.exponent, allow_str=False)
        if e is None or not 0.0 <= e <= 1.0:
            raise TargetError(f"size term: exponent must be in [0, 1], got {brief(self.exponent)}")
        object.__setattr__(self, "exponent", e)

    def factor(self, diameter: float) -> float:
        """``f(d)`` (dimensionless) at the projectile ``diameter`` (m); 1 at ``d_ref``."""
        return ((1.0 + self.d_ref / self.d0) / (1.0 + diameter / self.d0)) ** self.exponent


def _check(key: str, value: float, what: str, plausibility: bool = True) -> float:
    try:
        return number(value, key, what, plausibility=plausibility)
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
    crater_depth : float
        Near-surface (crater) region in projectile calibers (0: off); see the module
        docstring.
    free_surface_depth : float
        Free-surface reduction zone in calibers (0: off); pencore's own linear ramp, see
        the module docstring.
    plastic_zone_ratio : float
        Free-surface reduction from the spherical cavity in a finite sphere (Hill 1950):
        the plastic-zone radius over the cavity radius, ``c/a`` of the half-space law
        (0: off; otherwise > 1); see the module docstring.
    crater_rule : {"", "li_chen"}
        ``"li_chen"``: the crater depth is Li & Chen's ``0.707 + H/d`` calibers, set by
        :meth:`for_projectile` (then ``crater_depth`` must be 0); ``""``: as given.
    size_term : SizeTerm, optional
        A size term on ``a0``, applied by :meth:`for_projectile`.
    fc : float
        The unconfined compressive strength a concrete law was computed from (Pa; NaN:
        none), for the depth band (:mod:`pencore.inputs.record`).
    record_law : str
        The concrete record's name of the law this medium is
        (:data:`pencore.inputs.record.RECORD_LAWS`; empty: none), set by
        :func:`~pencore.inputs.laws.concrete_law` and cleared when a window option changes:
        a run into it carries the law's depth band from comparable measured shots.

    Raises
    ------
    TargetError
        A coefficient, friction table or option out of its range (the message names it).

    Examples
    --------
    The paper's soil (Table 1): ``sigma_n = A tau0 + B rho Vn^2``:

    >>> import pencore
    >>> soil = pencore.Medium("soil", (1.718 * 10e6, 0.0, 2.215 * 1860.0), density=1860.0)
    >>> soil.coefficients
    (17180000.0, 0.0, 4119.9)
    >>> soil.coefficients == pencore.get_target("soil").medium.coefficients
    True
    """

    name: str
    coefficients: tuple[float, ...]
    friction_speeds: tuple[float, ...] = (0.0,)
    friction_mu: tuple[float, ...] = (0.0,)
    density: float = float("nan")
    source: str = ""
    crater_depth: float = 0.0
    free_surface_depth: float = 0.0
    plastic_zone_ratio: float = 0.0
    crater_rule: str = ""
    size_term: SizeTerm | None = None
    fc: float = float("nan")
    record_law: str = ""

    def __post_init__(self) -> None:
        what = f"medium {brief(self.name)}"
        if not isinstance(self.record_law, str) or (
            self.record_law and self.record_law not in RECORD_LAWS
        ):
            raise TargetError(
                f"{what}: record_law must be empty or one of {', '.join(RECORD_LAWS)}, "
                f"got {brief(self.record_law)}"
            )
        fc = as_float(self.fc, allow_str=False)
        if fc is None or not (math.isnan(fc) or (math.isfinite(fc) and fc > 0.0)):
            raise TargetError(
                f"{what}: fc must be a positive number of Pa (or NaN), got {brief(self.fc)}"
            )
        object.__setattr__(self, "fc", fc)
        if self.crater_rule not in CRATER_RULES:
            raise TargetError(
                f"{what}: crater_rule must be 'li_chen' or empty, got {brief(self.crater_rule)}"
            )
        if self.size_term is not None and not isinstance(self.size_term, SizeTerm):
            raise TargetError(f"{what}: size_term must be a SizeTerm, got {brief(self.size_term)}")
        for key in ("crater_depth", "free_surface_depth", "plastic_zone_ratio"):
            object.__setattr__(self, key, _check(key, getattr(self, key), what))
        if 0.0 < self.plastic_zone_ratio <= 1.0:
            raise TargetError(
                f"{what}: plastic_zone_ratio must be 0 (off) or > 1 (the plastic zone "
                f"encloses the cavity), got {self.plastic_zone_ratio!r}"
            )
        if isinstance(self.coefficients, str) or not hasattr(self.coefficients, "__iter__"):
            raise TargetError(f"{what}: coefficients must be a list [a0, a1, a2, ...]")
        c = tuple(_check("coefficient", x, f"{what} a{i}") for i, x in enumerate(self.coefficients))
        if not c:
            raise TargetError(f"{what}: coefficients must be a non-empty list [a0, a1, a2, ...]")
        if len(c) > MAX_COEFFICIENTS:
            raise TargetError(
                f"{what}: {len(c)} resistance coefficients given; the solver supports at "
                f"most {MAX_COEFFICIENTS} (a0 .. a{MAX_COEFFICIENTS - 1}: a polynomial of "
                f"degree {MAX_COEFFICIENTS - 1} in the normal velocity)"
            )
        if not any(x > 0.0 for x in c):
            raise TargetError(
                f"{what}: every resistance coefficient is zero, so nothing resists the "
                f"projectile; give a0 (Pa) or a2 (kg/m^3) > 0"
            )
        object.__setattr__(self, "coefficients", c)
        for i, key in ((0, "a0"), (2, "a2")):
            if len(c) > i:
                plausible(c[i], key, what)
        for table in (self.friction_speeds, self.friction_mu):
            if hasattr(table, "__len__") and not isinstance(table, str) and len(table) > 1:
                try:
                    count(table, "friction_rows", what)
                except InputError as exc:
                    raise TargetError(str(exc)) from None
        sp = tuple(_check("friction_speed", x, what) for x in self.friction_speeds)
        mu = tuple(_check("friction", m, what) for m in self.friction_mu)
        if len(sp) != len(mu) or not sp:
            raise TargetError(f"{what}: friction table needs equal, non-empty speed and mu lists")
        if any(b <= a for a, b in zip(sp, sp[1:], strict=False)):
            raise TargetError(f"{what}: friction speeds must increase, got {brief(sp)}")
        if not math.isnan(self.density):
            _check("medium_density", self.density, what)
        object.__setattr__(self, "friction_speeds", sp)
        object.__setattr__(self, "friction_mu", mu)
        if self.crater_rule and self.crater_depth > 0.0:
            raise TargetError(
                f"{what}: give crater_depth or the crater rule {self.crater_rule!r}, not both "
                f"(crater_depth = {self.crater_depth:g})"
            )

    @property
    def needs_projectile(self) -> bool:
        """True when a part of the law depends on the projectile (a crater rule or a size
        term): resolve it with :meth:`for_projectile` before a run."""
        return bool(self.crater_rule) or self.size_term is not None

    def for_projectile(self, diameter: float, nose_length: float) -> Medium:
        """This medium resolved for a projectile: the crater rule's depth and the size
        term's factor applied, as a plain medium whose ``source`` says what was used.

        Parameters
        ----------
        diameter : float
            Projectile diameter ``d`` (m).
        nose_length : float
            Nose length ``H`` (m).

        Returns
        -------
        Medium
            Itself when nothing depends on the projectile; otherwise a copy with
            ``crater_depth = 0.707 + H/d`` (rule ``li_chen``) and ``a0`` times ``f(d)``
            (size term), with no rule and no size term left.

        Examples
        --------
        >>> import pencore
        >>> m = pencore.concrete_law(40e6, 2300.0, crater="li_chen")
        >>> r = m.for_projectile(0.0269, 0.0269 * 1.75**0.5)
        >>> print(f"k = {r.crater_depth:.4f}")
        k = 2.0299
        """
        if not self.needs_projectile:
            return self
        d = _check("diameter", diameter, f"medium {brief(self.name)}")
        notes = [f"resolved for d = {d:g} m"]
        changes: dict = {"crater_rule": "", "size_term": None}
        if self.crater_rule == "li_chen":
            k = LI_CHEN_CRATER + float(nose_length) / d
            changes["crater_depth"] = k
            notes.append(f"crater k = 0.707 + H/d = {k:.4g} calibers (H = {nose_length:g} m)")
        if self.size_term is not None:
            f = self.size_term.factor(d)
            c = list(self.coefficients)
            c[0] *= f
            changes["coefficients"] = tuple(c)
            s_ref = self.size_term.s_ref
            s_note = f", S = {s_ref * f:.4g}" if math.isfinite(s_ref) else ""
            notes.append(f"size term f(d) = {f:.4g}, a0 = {c[0]:.4g} Pa{s_note}")
        changes["source"] = f"{self.source}; {'; '.join(notes)}"
        return replace(self, **changes)

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
        if isinstance(mu, numbers.Real) or (isinstance(mu, np.ndarray) and mu.ndim == 0):
            # any real scalar (numpy's float32 too); checked against the limits on build
            return replace(self, friction_speeds=(0.0,), friction_mu=(mu,))
        sp, m = zip(*mu, strict=True)
        return replace(self, friction_speeds=tuple(sp), friction_mu=tuple(m))

    @property
    def windowed(self) -> bool:
        """True when a crater or a free-surface reduction is on."""
        return self.crater_depth > 0.0 or self.free_surface_depth > 0.0 or self.free_sphere

    @property
    def free_sphere(self) -> bool:
        """True when the finite-sphere free-surface reduction is on."""
        return self.plastic_zone_ratio > 0.0


@dataclass(frozen=True)
class Layer:
    """A medium and its thickness; ``inf`` for a semi-infinite last layer.

    ``medium=None`` is an air gap (no load): see :meth:`gap`.

    Parameters
    ----------
    medium : Medium or None
        The layer's material; None for an air gap.
    thickness : float, default inf
        Thickness (m), > 0; ``inf`` only for the last layer.

    Raises
    ------
    TargetError
        A thickness that is not a positive number of m.

    Examples
    --------
    >>> import pencore
    >>> concrete = pencore.get_target("concrete").medium
    >>> plate = pencore.Layer(concrete, 0.3)
    >>> print(plate.thickness, pencore.Layer.gap(0.5).is_gap)
    0.3 True
    """

    medium: Medium | None
    thickness: float = math.inf

    def __post_init__(self) -> None:
        # a number of m (inf: semi-infinite); text such as "1" is not one
        v = as_float(self.thickness, allow_str=False)
        if v is None:
            raise TargetError(
                f"layer thickness must be a number of m, got {brief(self.thickness)} "
                f"({type(self.thickness).__name__})"
            )
        if not (math.isinf(v) and v > 0):
            v = _check("thickness", self.thickness, "layer")
        object.__setattr__(self, "thickness", v)

    @classmethod
    def gap(cls, thickness: float) -> Layer:
        """An air gap of ``thickness`` (m) between two plates."""
        return cls(None, thickness)

    @property
    def is_gap(self) -> bool:
        """True for an air gap (no medium)."""
        return self.medium is None


def _not_a_medium(k: int, medium: object) -> str:
    """Why layer ``k``'s ``medium`` is refused, naming what was given; a name gets the
    call that gives its medium."""
    text = (
        f"layer {k} medium must be a Medium or None (gap), "
        f"got {type(medium).__name__} {brief(medium)}"
    )
    if isinstance(medium, str):
        name = brief(medium) if len(medium) <= 30 else "NAME"
        text += f"; for a named medium use pencore.get_target({name}).medium"
    return text


@dataclass(frozen=True)
class Target:
    """A layered half-space, or a stack of plates, below ``y = 0``.

    The first layer starts at the surface ``y = 0``; a target whose last layer has a
    thickness is finite (plates, perforation: :func:`~pencore.ballistic_limit`).

    Parameters
    ----------
    name : str
        Label used in results.
    layers : sequence of Layer
        From the surface down; a gap only between two layers of a medium, ``inf`` only
        for the last layer.

    Raises
    ------
    TargetError
        No layers, a layer that is not a :class:`~pencore.Layer`, a gap first or last, an
        infinite layer that is not the last.

    Examples
    --------
    Two 0.3 m concrete plates 1 m apart:

    >>> import pencore
    >>> concrete = pencore.get_target("concrete").medium
    >>> t = pencore.Target("two-plates", (pencore.Layer(concrete, 0.3),
    ...                                   pencore.Layer.gap(1.0), pencore.Layer(concrete, 0.3)))
    >>> print(t.finite, [layer.thickness for layer in t.layers])
    True [0.3, 1.0, 0.3]
    >>> pencore.Target("empty", ())
    Traceback (most recent call last):
    ...
    pencore.errors.TargetError: target 'empty' has no layers
    """

    name: str
    layers: tuple[Layer, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        what = f"target {brief(self.name)}"
        if isinstance(self.layers, str) or not hasattr(self.layers, "__len__"):
            raise TargetError(
                f"{what}: layers must be a sequence of Layer, got {brief(self.layers)}"
            )
        try:
            count(self.layers, "layers", what)
        except InputError as exc:
            if not self.layers:
                raise TargetError(f"target {brief(self.name)} has no layers") from None
            raise TargetError(str(exc)) from None
        layers = tuple(self.layers)
        for k, lay in enumerate(layers):
            if not isinstance(lay, Layer):
                raise TargetError(f"{what}: layer {k} must be a Layer, got {brief(lay)}")
            last = k == len(layers) - 1
            if lay.is_gap and (k == 0 or last):
                raise TargetError(
                    f"{what}: layer {k} is a gap; a gap must lie between two layers of a "
                    "medium (the first layer starts at the surface y = 0)"
                )
            if not lay.is_gap and not isinstance(lay.medium, Medium):
                raise TargetError(f"{what}: {_not_a_medium(k, lay.medium)}")
            if last and math.isinf(lay.thickness) and lay.thickness > 0:
                continue
            if math.isinf(lay.thickness):
                raise TargetError(f"{what}: only the last layer may be infinite (layer {k})")
            # the layer has judged its plausibility already
            _check("thickness", lay.thickness, f"{what} layer {k}", plausibility=False)
        object.__setattr__(self, "layers", layers)

    @classmethod
    def half_space(cls, medium: Medium) -> Target:
        """The semi-infinite target of one medium, named after it."""
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
    def levels(self) -> tuple[tuple[float, float], ...]:
        """Top and bottom heights ``y`` (m) of every layer and gap, from the surface
        ``y = 0`` down (the last bottom is ``-inf`` for a semi-infinite target)."""
        out = []
        top = 0.0
        for lay in self.layers:
            bottom = top - lay.thickness
            out.append((top, bottom))
            top = bottom
        return tuple(out)

    @property
    def finite(self) -> bool:
        """True when the last layer is finite (the target can be perforated)."""
        return math.isfinite(self.layers[-1].thickness)

    @property
    def rear_face(self) -> float:
        """Height ``y`` (m) of the rear face of the last plate; ``-inf`` if semi-infinite."""
        return -self.thickness

    def with_windows(
        self,
        crater_depth: float | None = None,
        free_surface_depth: float | None = None,
        plastic_zone_ratio: float | None = None,
    ) -> Target:
        """A copy whose media all have the given ``crater_depth`` / ``free_surface_depth``
        (calibers) / ``plastic_zone_ratio`` (None keeps each medium's own)."""
        kw = {}
        if crater_depth is not None:
            kw["crater_depth"] = crater_depth
        if free_surface_depth is not None:
            kw["free_surface_depth"] = free_surface_depth
        if plastic_zone_ratio is not None:
            kw["plastic_zone_ratio"] = plastic_zone_ratio

        def changed(m: Medium) -> dict:
            # a window the law was not scored with: no longer the record's law
            moved = any(getattr(m, k) != v for k, v in kw.items())
            return {**kw, "record_law": ""} if moved else kw

        layers = tuple(
            lay if lay.is_gap else Layer(replace(lay.medium, **changed(lay.medium)), lay.thickness)
            for lay in self.layers
        )
        return Target(self.name, layers)

    @property
    def needs_projectile(self) -> bool:
        """True when a medium's law depends on the projectile (:meth:`Medium.for_projectile`)."""
        return any(lay.medium.needs_projectile for lay in self.solid_layers)

    def for_projectile(self, diameter: float, nose_length: float) -> Target:
        """This target with every medium resolved for a projectile of ``diameter`` (m) and
        nose length ``nose_length`` (m) (:meth:`Medium.for_projectile`); itself when no
        medium depends on the projectile."""
        if not self.needs_projectile:
            return self
        layers = tuple(
            lay
            if lay.is_gap
            else Layer(lay.medium.for_projectile(diameter, nose_length), lay.thickness)
            for lay in self.layers
        )
        return Target(self.name, layers)

    def check_plates(self, diameter: float) -> None:
        """Warn (:class:`~pencore.PlausibilityWarning`) for each finite layer thinner than
        the plausible plate (:data:`~pencore.inputs.limits.PLAUSIBLE` ``"plate"``, in
        calibres of ``diameter`` m) whose medium has no near-surface option: the
        half-space law over-resists through the whole of such a plate."""
        for k, lay in enumerate(self.layers):
            if lay.is_gap or math.isinf(lay.thickness) or lay.medium.windowed:
                continue
            plausible(lay.thickness / diameter, "plate", f"target {brief(self.name)} layer {k}")

    def kernel_arrays(
        self,
        diameter: float | None = None,
        mass: float | None = None,
        nose_length: float | None = None,
        tip: float | None = None,
        nose: Nose | None = None,
    ) -> tuple[np.ndarray, ...]:
        """Arrays for the compiled kernel.

        ``diameter`` (m) of the projectile scales the depth windows (needed only when a
        medium has ``crater_depth`` or ``free_surface_depth``); the crater also needs the
        projectile's ``mass`` (kg), ``nose_length`` (m), ``tip`` (m: axial coordinate
        of the nose tip from the centre of mass) and ``nose`` (its exact profile, from which
        the crater factor's reference resistance is computed).

        Gaps are left out (their elements carry no load), so consecutive rows need not
        touch.

        Returns
        -------
        bounds : (n, 2) or (n, WINDOW_COLUMNS) float
            ``y_top, y_bottom`` of each layer of a medium (m); the last bottom is
            ``-inf`` for a semi-infinite target, the rear face otherwise. With a
            near-surface option on, seven more: crater depth ``k_c d`` (m), free-surface
            zone ``k_f d`` (m) at the top face if it is free (else 0) and at the bottom
            face if it is free (else 0), the projectile mass (kg; 0 without a crater),
            the plastic-zone ratio ``c/a`` at the top face if it is free (else 0) and at
            the bottom face if it is free (else 0), the projectile radius (m) and the
            tip's axial coordinate (m; 0 without a crater), and with a crater the nose's
            kind, parameter, length (m) and full-nose moments (m^2,
            :func:`pencore.inputs.geometry.nose_axial_moments`),
            :data:`~pencore.inputs.target.WINDOW_COLUMNS` in
            all; see
            :func:`pencore.kernels.windows.depth_factor` and
            :func:`pencore.kernels.crater.element_factor`.
        coef : (n, p) float
            Resistance coefficients, zero-padded.
        fric : (n, k, 2) float
            Friction tables (speed, mu), padded by repeating the last row.

        Raises
        ------
        TargetError
            A window without ``diameter``, a crater without ``mass``, ``nose_length``,
            ``tip`` and ``nose``,
            or a crater shorter than the nose (Forrestal's crater ends with the nose
            embedded: ``k d >= L_n``).
        """
        solid = self.solid_layers
        if self.needs_projectile:
            raise TargetError(
                f"target {brief(self.name)}: a medium's law depends on the projectile (a crater "
                "rule or a size term); resolve it first (Target.for_projectile)"
            )
        n = len(solid)
        p = max(len(lay.medium.coefficients) for lay in solid)
        k = max(len(lay.medium.friction_speeds) for lay in solid)
        windowed = any(lay.medium.windowed for lay in solid)
        crater = any(lay.medium.crater_depth > 0.0 for lay in solid)
        if windowed and not (diameter is not None and diameter > 0.0):
            raise TargetError(
                f"target {brief(self.name)}: crater_depth/free_surface_depth need the projectile "
                "diameter (pass diameter= to kernel_arrays)"
            )
        if crater:
            if (
                mass is None or nose_length is None or tip is None or nose is None
                or not mass > 0.0
            ):  # fmt: skip
                raise TargetError(
                    f"target {self.name!r}: crater_depth needs the projectile mass, nose "
                    "length, tip and nose (pass mass=, nose_length=, tip=, nose= to "
                    "kernel_arrays)"
                )
            for lay in solid:
                kc = lay.medium.crater_depth
                if 0.0 < kc * diameter < nose_length * (1.0 - 1e-12):
                    raise TargetError(
                        f"medium {lay.medium.name!r}: crater_depth {kc!r} calibers is shorter "
                        f"than the nose ({nose_length / diameter:.4g} calibers); Forrestal's "
                        "crater region ends with the nose embedded, so crater_depth must be "
                        f">= {nose_length / diameter:.4g} (Forrestal et al. 1994: 2; Li & "
                        "Chen 2003: 0.707 + nose length / d)"
                    )
        bounds = np.zeros((n, WINDOW_COLUMNS if windowed else 2))
        coef = np.zeros((n, p))
        fric = np.empty((n, k, 2))
        j = 0
        layers = self.layers
        for i, (lay, (top, bottom)) in enumerate(zip(layers, self.levels, strict=True)):
            if lay.is_gap:
                continue
            bounds[j, :2] = top, bottom
            if windowed:
                # free faces: the front face, faces next to a gap, the rear face
                free_top = i == 0 or layers[i - 1].is_gap
                free_bottom = i == len(layers) - 1 or layers[i + 1].is_gap
                zone = lay.medium.free_surface_depth * diameter
                bounds[j, 2] = lay.medium.crater_depth * diameter
                bounds[j, 3] = zone if free_top else 0.0
                bounds[j, 4] = zone if free_bottom and math.isfinite(bottom) else 0.0
                bounds[j, 5] = mass if crater else 0.0
                ratio = lay.medium.plastic_zone_ratio
                bounds[j, 6] = ratio if free_top else 0.0
                bounds[j, 7] = ratio if free_bottom and math.isfinite(bottom) else 0.0
                bounds[j, 8] = 0.5 * diameter
                bounds[j, 9] = tip if crater else 0.0
                if crater:
                    bounds[j, 10:] = _nose_columns(nose, 0.5 * diameter, nose_length)
            c = lay.medium.coefficients
            coef[j, : len(c)] = c
            sp, mu = lay.medium.friction_speeds, lay.medium.friction_mu
            for m in range(k):
                mm = min(m, len(sp) - 1)
                fric[j, m] = (sp[mm] + (m - mm) * 1.0, mu[mm])
            j += 1
        return bounds, coef, fric


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
