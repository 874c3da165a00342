"""Projectile geometry: bodies of revolution, mass properties and surface quadrature.

A projectile is a chain of axisymmetric segments along its axis, starting at the nose
tip: a nose (tangent ogive, cone or flat face) followed by cylindrical segments. Each
segment has its own density. Everything is SI: metres, kilograms, kg/m^3.

Conventions
-----------
* ``s`` is the axial distance from the nose tip, growing towards the tail (m).
* The body frame has its origin at the centre of mass and its first axis ``e1``
  pointing from the tail to the nose, so a surface point at axial distance ``s`` from
  the tip sits at ``x1 = Lc - s`` (``Lc`` is the tip-to-centre-of-mass distance).
* The surface is described by :class:`Rings`: thin circular bands. On each band the
  outward unit normal is ``n = (na, nr cos(phi), nr sin(phi))`` in the body frame, and
  the area element is ``dA = w dphi`` with ``w = r dl`` (radius times slant width).
  The force kernel integrates the stresses over ``phi`` in closed form, so the only
  surface discretisation error is along the axis.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from pencore.errors import GeometryError, InputError, hint_keywords
from pencore.inputs.gate import brief
from pencore.inputs.limits import LIMITS, count, number, plausible

__all__ = [
    "OgiveNose",
    "ConeNose",
    "FlatNose",
    "Cylinder",
    "Projectile",
    "Rings",
    "MassProperties",
    "nose_factor",
    "nose_axial_moments",
]

_GL_X, _GL_W = np.polynomial.legendre.leggauss(96)


def _check(key: str, value: float, what: str = "", label: str = "") -> float:
    """``value`` as a float within ``pencore.inputs.limits.LIMITS[key]`` (``what`` and
    ``label`` name it in the message, as :func:`pencore.inputs.limits.number`), else
    :class:`GeometryError`."""
    try:
        return number(value, key, what, label=label)
    except InputError as exc:
        raise GeometryError(str(exc)) from None


@dataclass(frozen=True)
class OgiveNose:
    """Tangent-ogive nose of calibre-radius-head ``crh`` (CRH = ogive radius / diameter).

    ``crh = 0.5`` is the hemisphere. Nose length is ``a sqrt(4 crh - 1)`` for the body
    radius ``a``.

    Parameters
    ----------
    crh : float
        Ogive radius over the body diameter (dimensionless), >= 0.5.
    density : float
        Mass density of the nose (kg/m^3).

    Raises
    ------
    GeometryError
        A value that is not a finite number in its range (:data:`pencore.inputs.limits.LIMITS`).

    Examples
    --------
    >>> import pencore
    >>> nose = pencore.OgiveNose(crh=3.0, density=7850.0)
    >>> print(f"{nose.length(0.015):.4f} m")
    0.0497 m
    """

    crh: float
    density: float

    def __post_init__(self) -> None:
        _check("crh", self.crh)
        _check("density", self.density)

    def length(self, a: float) -> float:
        """Nose length (m) for the body radius ``a`` (m)."""
        return a * math.sqrt(4.0 * self.crh - 1.0)

    def radius(self, s: np.ndarray, a: float) -> np.ndarray:
        """Nose radius (m) at distance ``s`` (m) from the tip, body radius ``a`` (m)."""
        ro = 2.0 * self.crh * a
        ln = self.length(a)
        return np.sqrt(np.maximum(ro * ro - (ln - s) ** 2, 0.0)) - (ro - a)

    def rings(self, a: float, n: int) -> tuple[np.ndarray, ...]:
        """Bands uniform in arc length: returns s, r, na, nr, dl."""
        ro = 2.0 * self.crh * a
        ln = self.length(a)
        beta_tip = math.asin(min(ln / ro, 1.0))
        edges = np.linspace(beta_tip, 0.0, n + 1)
        beta = 0.5 * (edges[:-1] + edges[1:])
        s = ln - ro * np.sin(beta)
        r = ro * np.cos(beta) - (ro - a)
        dl = ro * (edges[:-1] - edges[1:])
        return s, r, np.sin(beta), np.cos(beta), dl

    def nodes(self, a: float, n: int) -> tuple[np.ndarray, np.ndarray]:
        """Band edges of :meth:`rings` on the meridian, tip first: ``s, r`` (m), n + 1 each."""
        ro = 2.0 * self.crh * a
        ln = self.length(a)
        beta = np.linspace(math.asin(min(ln / ro, 1.0)), 0.0, n + 1)
        r = np.maximum(ro * np.cos(beta) - (ro - a), 0.0)
        r[0] = 0.0
        return ln - ro * np.sin(beta), r

    def exact_area(self, a: float) -> float:
        """Area of the nose surface (m^2) for the body radius ``a`` (m), in closed form."""
        ro = 2.0 * self.crh * a
        beta_tip = math.asin(min(self.length(a) / ro, 1.0))
        # integral of 2 pi r dl with r = ro cos b - (ro - a), dl = ro db
        return 2.0 * math.pi * ro * (ro * math.sin(beta_tip) - (ro - a) * beta_tip)


@dataclass(frozen=True)
class ConeNose:
    """Conical nose.

    Parameters
    ----------
    half_angle : float
        Half-angle of the cone (rad), in (0, pi/2).
    density : float
        Mass density of the nose (kg/m^3).

    Raises
    ------
    GeometryError
        A value that is not a finite number in its range.

    Examples
    --------
    >>> import math
    >>> import pencore
    >>> nose = pencore.ConeNose(math.radians(20.0), 7850.0)
    >>> print(f"{nose.length(0.015):.4f} m")
    0.0412 m
    """

    half_angle: float
    density: float

    def __post_init__(self) -> None:
        if isinstance(self.half_angle, bool) or not isinstance(self.half_angle, int | float):
            raise GeometryError(
                f"cone half-angle must be a number of rad, got {brief(self.half_angle)}"
            )
        _check("half_angle_deg", math.degrees(self.half_angle))
        _check("density", self.density)

    def length(self, a: float) -> float:
        """Nose length (m) for the body radius ``a`` (m)."""
        return a / math.tan(self.half_angle)

    def radius(self, s: np.ndarray, a: float) -> np.ndarray:
        """Nose radius (m) at distance ``s`` (m) from the tip, body radius ``a`` (m)."""
        return np.asarray(s) * math.tan(self.half_angle)

    def rings(self, a: float, n: int) -> tuple[np.ndarray, ...]:
        """``n`` surface bands of the nose: ``s, r, na, nr, dl`` (m, m, -, -, m) each."""
        ln = self.length(a)
        edges = np.linspace(0.0, ln, n + 1)
        s = 0.5 * (edges[:-1] + edges[1:])
        t = self.half_angle
        return (
            s,
            s * math.tan(t),
            np.full(n, math.sin(t)),
            np.full(n, math.cos(t)),
            np.diff(edges) / math.cos(t),
        )

    def nodes(self, a: float, n: int) -> tuple[np.ndarray, np.ndarray]:
        """Band edges of :meth:`rings` on the meridian, tip first: ``s, r`` (m)."""
        s = np.linspace(0.0, self.length(a), n + 1)
        return s, s * math.tan(self.half_angle)

    def exact_area(self, a: float) -> float:
        """Area of the nose surface (m^2) for the body radius ``a`` (m), in closed form."""
        return math.pi * a * a / math.sin(self.half_angle)


@dataclass(frozen=True)
class FlatNose:
    """Blunt nose: a flat circular face at the tip (zero length).

    Parameters
    ----------
    density : float, default 7850
        Mass density (kg/m^3); the face has no volume, so it only labels the nose.

    Examples
    --------
    >>> import pencore
    >>> pencore.FlatNose().length(0.015)
    0.0
    """

    density: float = 7850.0

    def __post_init__(self) -> None:
        _check("density", self.density)

    def length(self, a: float) -> float:
        """Nose length (m) for the body radius ``a`` (m)."""
        return 0.0

    def radius(self, s: np.ndarray, a: float) -> np.ndarray:
        """Nose radius (m) at distance ``s`` (m) from the tip, body radius ``a`` (m)."""
        return np.zeros_like(np.asarray(s, dtype=float))

    def rings(self, a: float, n: int) -> tuple[np.ndarray, ...]:
        """``n`` surface bands of the nose: ``s, r, na, nr, dl`` (m, m, -, -, m) each."""
        return _disc_rings(a, n, 0.0, +1.0)

    def nodes(self, a: float, n: int) -> tuple[np.ndarray, np.ndarray]:
        """Band edges of :meth:`rings` (the face, centre first): ``s, r`` (m)."""
        return np.zeros(n + 1), np.linspace(0.0, a, n + 1)

    def exact_area(self, a: float) -> float:
        """Area of the nose surface (m^2) for the body radius ``a`` (m), in closed form."""
        return math.pi * a * a


def _disc_rings(a: float, n: int, s0: float, sign: float) -> tuple[np.ndarray, ...]:
    edges = np.linspace(0.0, a, n + 1)
    r = 0.5 * (edges[:-1] + edges[1:])
    return np.full(n, s0), r, np.full(n, sign), np.zeros(n), np.diff(edges)


@dataclass(frozen=True)
class Cylinder:
    """Cylindrical (shank) segment of a projectile, of the body's diameter.

    Parameters
    ----------
    length : float
        Segment length (m), > 0.
    density : float
        Mass density (kg/m^3), > 0.

    Raises
    ------
    GeometryError
        A value that is not a finite number in its range.

    Examples
    --------
    >>> import pencore
    >>> pencore.Cylinder(0.2, 7850.0)
    Cylinder(length=0.2, density=7850.0)
    """

    length: float
    density: float

    def __post_init__(self) -> None:
        _check("length", self.length)
        _check("density", self.density)


@dataclass(frozen=True)
class MassProperties:
    """Mass (kg), tip-to-centre-of-mass distance ``lc`` (m), total length (m), and the
    axial ``i_axial`` and transverse ``i_transverse`` moments of inertia about the
    centre of mass (kg m^2)."""

    mass: float
    lc: float
    length: float
    i_axial: float
    i_transverse: float

    @property
    def lc_over_l(self) -> float:
        return self.lc / self.length


@dataclass(frozen=True)
class Rings:
    """Surface quadrature of a body of revolution (see the module docstring).

    Arrays, one entry per band: ``x1`` axial body coordinate of the band (m, from the
    centre of mass, + towards the nose), ``r`` radius (m), ``na``/``nr`` axial and radial
    components of the outward normal, ``w`` area weight r*dl (m^2 per rad), ``part``
    0 for nose, 1 for shank, 2 for flat faces.
    """

    x1: np.ndarray
    r: np.ndarray
    na: np.ndarray
    nr: np.ndarray
    w: np.ndarray
    part: np.ndarray

    @property
    def area(self) -> float:
        return float(2.0 * np.pi * self.w.sum())

    def as_array(self) -> np.ndarray:
        """(n, 5) float array x1, r, na, nr, w for the compiled kernel."""
        return np.ascontiguousarray(np.stack([self.x1, self.r, self.na, self.nr, self.w], 1))


Nose = OgiveNose | ConeNose | FlatNose


@dataclass(frozen=True)
class Projectile:
    """A rigid body of revolution: a nose followed by cylindrical segments.

    Parameters
    ----------
    name : str
        Label used in results.
    diameter : float
        Body diameter ``d`` (m); every segment has this diameter.
    nose : OgiveNose | ConeNose | FlatNose
        The nose, with its density.
    shank : tuple of Cylinder
        Cylindrical segments from front to back.
    source : str
        Provenance of the numbers (``paper``, ``derived: ...``, ``assumed: ...``).
    mass : float, optional
        Measured mass (kg). Default: the outline's mass (segment densities times volumes).
    centre_of_mass : float, optional
        Measured tip-to-centre-of-mass distance ``Lc`` (m), inside the body's length.
    inertia : (float, float), optional
        Measured moments of inertia ``(i_axial, i_transverse)`` about the centre of mass
        (kg m^2).
    yield_strength : float, optional
        The projectile material's yield strength (Pa). Not used by the rigid-body
        solution; the rigid-regime check (:func:`pencore.inputs.regime.rigid_regime`) compares
        the nose's stress with it (an assumed strength when not given).

    Notes
    -----
    What the solver uses (:meth:`mass_properties`, the one place every path reads the
    mass, ``Lc`` and the inertias from; the surface bands are placed relative to ``Lc``):

    * nothing given: the outline's distribution (segment densities), as computed;
    * ``mass`` only: the outline's distribution scaled by ``f = mass / m_outline``: the same
      ``Lc``, both inertias times ``f`` (a hollow or fuzed body taken as the solid outline
      made lighter or heavier everywhere in proportion);
    * ``centre_of_mass`` without ``inertia``: the (scaled) outline's axial inertia, and its
      transverse inertia moved from the outline's centre of mass to the given one by the
      parallel-axis theorem, ``f I_t + m (Lc - Lc_outline)^2`` (the scaled outline's inertia
      about the given point: the choice adds no distribution the user did not give);
    * ``inertia`` given: used as given.

    A given value is checked against the body's outline: ``mass`` at most the outline
    filled with osmium (the densest element), ``Lc`` strictly inside ``(0, L)``, and the
    inertias of a body of revolution of radius ``a`` and length ``L`` with its centre of
    mass at ``Lc``: ``0 < I_axial <= m a^2`` (all mass within radius ``a``),
    ``I_axial <= 2 I_transverse`` (``I_t = I_axial / 2 + integral x^2 dm``) and
    ``I_transverse <= I_axial / 2 + m max(Lc, L - Lc)^2``.

    Raises
    ------
    GeometryError
        A value out of its range, a nose or segment of the wrong type, a name that is not
        text, a mass, centre of mass or inertia no body of this outline can have (the
        one-line message names it).

    Examples
    --------
    A 30 mm steel projectile with a 3-CRH ogive nose and a 0.2 m shank:

    >>> import pencore
    >>> p = pencore.Projectile(
    ...     "ogive", 0.03, pencore.OgiveNose(crh=3.0, density=7850.0),
    ...     (pencore.Cylinder(0.2, 7850.0),),
    ... )
    >>> mp = p.mass_properties()
    >>> print(f"{mp.mass:.3f} kg, length {p.length:.4f} m, Lc {mp.lc:.4f} m")
    1.261 kg, length 0.2497 m, Lc 0.1359 m
    >>> pencore.Projectile("bad", -0.03, pencore.OgiveNose(3.0, 7850.0))
    Traceback (most recent call last):
    ...
    pencore.errors.GeometryError: diameter must be in [0.0001, 10] m, got -0.03

    The same outline with a measured mass of 1 kg (a hollow body): the outline's
    distribution scaled, so the same ``Lc`` and inertias times 1 / 1.261:

    >>> light = pencore.Projectile(
    ...     "light", 0.03, pencore.OgiveNose(crh=3.0, density=7850.0),
    ...     (pencore.Cylinder(0.2, 7850.0),), mass=1.0,
    ... )
    >>> ml = light.mass_properties()
    >>> ratio = ml.i_transverse / mp.i_transverse
    >>> print(f"{ml.mass:.3f} kg, Lc {ml.lc:.4f} m, I_t ratio {ratio:.4f}")
    1.000 kg, Lc 0.1359 m, I_t ratio 0.7932
    >>> light.mass_provenance()["inertia"]
    'derived: outline distribution scaled by the given mass'
    """

    name: str
    diameter: float
    nose: Nose
    shank: tuple[Cylinder, ...] = field(default_factory=tuple)
    source: str = ""
    mass: float | None = None
    centre_of_mass: float | None = None
    inertia: tuple[float, float] | None = None
    yield_strength: float | None = None

    def __post_init__(self) -> None:
        _check("diameter", self.diameter)
        what = f"projectile {brief(self.name)}"
        if isinstance(self.shank, str) or not hasattr(self.shank, "__len__"):
            raise GeometryError(
                f"{what}: shank must be a sequence of Cylinder, got {brief(self.shank)}"
            )
        try:
            count(self.shank, "shank_segments", what)
        except InputError as exc:
            raise GeometryError(str(exc)) from None
        object.__setattr__(self, "shank", tuple(self.shank))
        if not isinstance(self.nose, OgiveNose | ConeNose | FlatNose):
            raise GeometryError(
                f"{what}: nose must be an OgiveNose, ConeNose or FlatNose, got "
                f"{type(self.nose).__name__} {brief(self.nose)}"
            )
        for k, c in enumerate(self.shank):
            if not isinstance(c, Cylinder):
                raise GeometryError(
                    f"{what}: shank segment {k} must be a Cylinder, got "
                    f"{type(c).__name__} {brief(c)}"
                )
        # a nose of a few calibres, not kilometres (a cone of 1e-6 deg is 2722 km long)
        nose_length = self.nose.length(self.radius)
        if not nose_length <= LIMITS["length"].hi:
            raise GeometryError(
                f"{what}: nose length {nose_length:.4g} m is beyond "
                f"{LIMITS['length'].hi:g} m (the segment-length guard); a cone half-angle "
                "this small is a typo"
            )
        self._check_given(what)

    def _check_given(self, what: str) -> None:
        """Check the given mass, centre of mass and inertias (types and ranges here; the
        bounds that need the outline in :meth:`mass_properties`, called at once)."""
        if self.yield_strength is not None:
            y = _check("yield_strength", self.yield_strength, what)
            object.__setattr__(self, "yield_strength", y)
        if self.mass is not None:
            object.__setattr__(self, "mass", _check("mass", self.mass, what))
        if self.centre_of_mass is not None:
            lc = _check("centre_of_mass", self.centre_of_mass, what)
            object.__setattr__(self, "centre_of_mass", lc)
        if self.inertia is not None:
            pair = self.inertia
            try:
                n = len(pair)
            except TypeError:
                n = -1
            if isinstance(pair, dict | str) or n != 2:
                raise GeometryError(
                    f"{what}: inertia must be a pair (i_axial, i_transverse) in kg m^2, "
                    f"got {brief(pair)}"
                )
            ia = _check("inertia", pair[0], what, "axial moment of inertia")
            it = _check("inertia", pair[1], what, "transverse moment of inertia")
            object.__setattr__(self, "inertia", (ia, it))
        if self.given:
            self.mass_properties()  # the bounds that need the outline, now

    @property
    def radius(self) -> float:
        return 0.5 * self.diameter

    @property
    def nose_length(self) -> float:
        return self.nose.length(self.radius)

    @property
    def length(self) -> float:
        return self.nose_length + sum(c.length for c in self.shank)

    @property
    def given(self) -> bool:
        """Whether any of ``mass``, ``centre_of_mass``, ``inertia`` is given."""
        return not (self.mass is None and self.centre_of_mass is None and self.inertia is None)

    def with_mass(
        self,
        mass: float | None = None,
        centre_of_mass: float | None = None,
        inertia: tuple[float, float] | None = None,
    ) -> Projectile:
        """This body with measured mass properties (``None`` keeps what it has).

        Parameters
        ----------
        mass : float, optional
            Measured mass (kg).
        centre_of_mass : float, optional
            Tip-to-centre-of-mass distance ``Lc`` (m).
        inertia : (float, float), optional
            ``(i_axial, i_transverse)`` about the centre of mass (kg m^2).

        Returns
        -------
        Projectile
            A new projectile; see the class Notes for what is derived.

        Examples
        --------
        >>> import pencore
        >>> p = pencore.get_projectile("p2").with_mass(mass=20.0)
        >>> print(f"{p.mass_properties().mass:.1f} kg")
        20.0 kg
        """
        return replace(
            self,
            mass=self.mass if mass is None else mass,
            centre_of_mass=self.centre_of_mass if centre_of_mass is None else centre_of_mass,
            inertia=self.inertia if inertia is None else inertia,
        )

    def mass_provenance(self) -> dict[str, str]:
        """Where :meth:`mass_properties` takes each quantity from.

        Returns
        -------
        dict of str to str
            Keys ``mass``, ``centre_of_mass``, ``inertia``; values ``"given"`` or
            ``"derived: ..."`` saying how (see the class Notes).
        """
        scaled = self.mass is not None
        if self.inertia is not None:
            inertia = "given"
        elif self.centre_of_mass is not None:
            inertia = (
                "derived: axial from the outline"
                + (" scaled by the given mass" if scaled else "")
                + "; transverse moved to the given centre of mass (parallel-axis theorem)"
            )
        elif scaled:
            inertia = "derived: outline distribution scaled by the given mass"
        else:
            inertia = "derived: outline (segment densities)"
        return {
            "mass": "given" if scaled else "derived: outline (segment densities)",
            "centre_of_mass": "given"
            if self.centre_of_mass is not None
            else "derived: outline (segment densities)",
            "inertia": inertia,
        }

    def mass_properties(self) -> MassProperties:
        """Mass, centre of mass and inertias the solver uses (the class Notes say how given
        and derived values combine; without given values, the outline's).

        Returns
        -------
        MassProperties
            Computed once per (immutable) projectile and kept: every trajectory asks.

        Raises
        ------
        GeometryError
            A given value no body of this outline can have (see the class Notes).
        """
        cached = self.__dict__.get("_mass_properties")
        if cached is not None:
            return cached
        mo = self.outline_mass_properties()
        if not self.given:
            object.__setattr__(self, "_mass_properties", mo)
            return mo
        what = f"projectile {brief(self.name)}"
        length = mo.length
        a = self.radius
        if self.mass is not None:
            rho_max = LIMITS["density"].hi
            m_max = self.volume() * rho_max
            if self.mass > m_max:
                raise GeometryError(
                    f"{what}: mass must be at most {m_max:.4g} kg (the outline filled with "
                    f"osmium, {rho_max:g} kg/m^3), got {brief(self.mass)}"
                )
            m = self.mass
        else:
            m = mo.mass
        f = m / mo.mass
        if self.centre_of_mass is not None:
            lc = self.centre_of_mass
            if not 0.0 < lc < length:
                raise GeometryError(
                    f"{what}: centre of mass (tip distance Lc) must be inside the body, in "
                    f"(0, {length:.6g}) m, got {brief(lc)}"
                )
        else:
            lc = mo.lc
        if self.inertia is not None:
            i_ax, i_tr = self.inertia
            arm = max(lc, length - lc)
            bounds = (
                (
                    i_ax <= m * a * a,
                    f"axial moment of inertia must be at most m a^2 = "
                    f"{m * a * a:.4g} kg m^2 (all mass within the radius), got {brief(i_ax)}",
                ),
                (
                    i_ax <= 2.0 * i_tr,
                    f"axial moment of inertia must be at most twice the "
                    f"transverse one ({2.0 * i_tr:.4g} kg m^2; a body of revolution), got "
                    f"{brief(i_ax)}",
                ),
                (
                    i_tr <= 0.5 * i_ax + m * arm * arm,
                    f"transverse moment of inertia must be "
                    f"at most I_axial / 2 + m max(Lc, L - Lc)^2 = "
                    f"{0.5 * i_ax + m * arm * arm:.4g} kg m^2 (all mass within the length), got "
                    f"{brief(i_tr)}",
                ),
            )
            for ok, msg in bounds:
                if not ok:
                    raise GeometryError(f"{what}: {msg}")
        else:
            i_ax = f * mo.i_axial
            i_tr = f * mo.i_transverse + m * (lc - mo.lc) ** 2
        mp = MassProperties(float(m), float(lc), float(length), float(i_ax), float(i_tr))
        if self.mass is not None:  # accepted: against the solid outline (a tonne or a pound)
            where = f"{what} (mass {m:g} kg, solid outline {mo.mass:.4g} kg)"
            plausible(m / mo.mass, "mass_ratio", where)
        object.__setattr__(self, "_mass_properties", mp)  # a cache, not a field
        return mp

    def outline_mass_properties(self) -> MassProperties:
        """Mass, centre of mass and inertia of the outline with its segment densities, by
        Gauss-Legendre quadrature over thin discs (whatever mass properties are given).

        Each disc of radius ``r`` and thickness ``ds`` contributes ``dm = rho pi r^2 ds``,
        ``dI_axial = dm r^2 / 2`` and ``dI_transverse = dm (r^2/4 + (s - s_c)^2)``.
        Computed once per (immutable) projectile and kept.

        Returns
        -------
        MassProperties
        """
        cached = self.__dict__.get("_outline_mass_properties")
        if cached is not None:
            return cached
        m = m1 = i_ax = m2 = i_disc = 0.0
        for s, (r, ds), rho in self._discs():
            dm = rho * np.pi * r * r * ds
            m += dm.sum()
            m1 += (dm * s).sum()
            m2 += (dm * s * s).sum()
            i_ax += (0.5 * dm * r * r).sum()
            i_disc += (0.25 * dm * r * r).sum()
        if m <= 0.0:
            raise GeometryError("the body has no volume (a flat nose needs a shank)")
        lc = m1 / m
        i_tr = i_disc + m2 - m * lc * lc
        mp = MassProperties(float(m), float(lc), float(self.length), float(i_ax), float(i_tr))
        object.__setattr__(self, "_outline_mass_properties", mp)  # a cache, not a field
        return mp

    def volume(self) -> float:
        """Volume of the outline (m^3), by the quadrature of :meth:`outline_mass_properties`."""
        return float(sum((np.pi * r * r * ds).sum() for _, (r, ds), _ in self._discs()))

    def _discs(self) -> list[tuple[np.ndarray, np.ndarray, float]]:
        """Gauss-Legendre thin discs per segment: ``(s, [r, ds], rho)`` (m, m, m, kg/m^3)."""
        a = self.radius
        parts: list[tuple[np.ndarray, np.ndarray, float]] = []  # s, r*ds-weights, rho
        ln = self.nose_length
        if ln > 0.0:
            s = 0.5 * ln * (_GL_X + 1.0)
            ds = 0.5 * ln * _GL_W
            parts.append((s, np.stack([self.nose.radius(s, a), ds]), self.nose.density))
        s0 = ln
        for cyl in self.shank:
            s = s0 + 0.5 * cyl.length * (_GL_X + 1.0)
            ds = 0.5 * cyl.length * _GL_W
            parts.append((s, np.stack([np.full_like(s, a), ds]), cyl.density))
            s0 += cyl.length
        return parts

    def rings(self, n_nose: int = 48, n_shank: int = 24, n_face: int = 4) -> Rings:
        """Surface bands: ``n_nose`` on the nose, ``n_shank`` per metre-ish of shank
        (at least ``n_shank`` per segment scaled by its length in calibres / 5),
        ``n_face`` on each flat face (blunt nose face, rear face).

        Returns
        -------
        Rings
            Body-frame quadrature relative to the centre of mass.
        """
        if n_nose < 1 or n_shank < 1 or n_face < 1:
            raise GeometryError("ring counts must be >= 1")
        a = self.radius
        lc = self.mass_properties().lc
        blocks: list[tuple[np.ndarray, ...]] = []
        parts: list[np.ndarray] = []
        nose_rings = self.nose.rings(a, n_face if isinstance(self.nose, FlatNose) else n_nose)
        blocks.append(nose_rings)
        parts.append(np.full(len(nose_rings[0]), 2 if isinstance(self.nose, FlatNose) else 0))
        s0 = self.nose_length
        for cyl in self.shank:
            edges = self._shank_edges(cyl, s0, n_shank)
            n = edges.size - 1
            s = 0.5 * (edges[:-1] + edges[1:])
            blocks.append((s, np.full(n, a), np.zeros(n), np.ones(n), np.diff(edges)))
            parts.append(np.ones(n, dtype=int))
            s0 += cyl.length
        blocks.append(_disc_rings(a, n_face, s0, -1.0))
        parts.append(np.full(n_face, 2))
        s, r, na, nr, dl = (np.concatenate(c) for c in zip(*blocks, strict=True))
        return Rings(
            x1=lc - s, r=r, na=na, nr=nr, w=r * dl, part=np.concatenate(parts).astype(np.int8)
        )

    def _shank_edges(self, cyl: Cylinder, s0: float, n_shank: int) -> np.ndarray:
        """Band edges (m from the tip) of a cylindrical segment starting at ``s0``."""
        n = max(1, int(round(n_shank * cyl.length / (5.0 * self.diameter))))
        n = max(n, n_shank // 4)
        return np.linspace(s0, s0 + cyl.length, n + 1)

    def profile(
        self, n_nose: int = 48, n_shank: int = 24, n_face: int = 4
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The meridian of the surface as a polyline through the band edges of
        :meth:`rings` (same counts): from the tip (or the centre of a flat nose face)
        along the side to the centre of the rear face.

        Returns
        -------
        s, r : (k + 1,) float
            Nodes: axial distance from the tip and radius (m).
        part : (k,) int8
            Per segment: 0 nose, 1 shank, 2 flat face (as ``Rings.part``).
        """
        if n_nose < 1 or n_shank < 1 or n_face < 1:
            raise GeometryError("ring counts must be >= 1")
        a = self.radius
        flat = isinstance(self.nose, FlatNose)
        s_n, r_n = self.nose.nodes(a, n_face if flat else n_nose)
        ss, rr = [s_n], [r_n]
        parts = [np.full(s_n.size - 1, 2 if flat else 0)]
        s0 = self.nose_length
        for cyl in self.shank:
            e = self._shank_edges(cyl, s0, n_shank)
            ss.append(e[1:])
            rr.append(np.full(e.size - 1, a))
            parts.append(np.ones(e.size - 1, dtype=int))
            s0 += cyl.length
        face = np.linspace(a, 0.0, n_face + 1)
        ss.append(np.full(n_face, s0))
        rr.append(face[1:])
        parts.append(np.full(n_face, 2))
        return np.concatenate(ss), np.concatenate(rr), np.concatenate(parts).astype(np.int8)

    def exact_area(self) -> float:
        """Closed-form total surface area (m^2), for checking the quadrature."""
        a = self.radius
        side = sum(2.0 * math.pi * a * c.length for c in self.shank)
        return self.nose.exact_area(a) + side + math.pi * a * a

    def nose_factor(self) -> float:
        """Nose factor N* of the frictionless DAFL axial force (see :func:`nose_factor`)."""
        return nose_factor(self.nose)


def nose_factor(nose: Nose) -> float:
    """Dimensionless nose factor N* such that the frictionless axial force on a fully
    embedded nose at zero yaw is ``pi a^2 (a0 + N* a2 V^2)``.

    Tangent ogive: ``N* = (8 psi - 1) / (24 psi^2)`` (hemisphere 1/2);
    cone: ``sin^2(half-angle)``; flat: 1.
    """
    if isinstance(nose, OgiveNose):
        psi = nose.crh
        return (8.0 * psi - 1.0) / (24.0 * psi * psi)
    if isinstance(nose, ConeNose):
        return math.sin(nose.half_angle) ** 2
    return 1.0


def nose_axial_moments(nose: Nose, a: float, n: int) -> np.ndarray:
    """Full-nose moments ``J_k = int 2 pi r n_a^k dr`` (m^2), ``k`` from 0 to ``n - 1``, over the
    exact profile of ``nose`` on a body of radius ``a`` (m): the frictionless DAFL axial
    force on the embedded nose in normal entry at speed ``V`` is ``sum_k a_k V^k J_k``
    (``J_0 = pi a^2``, ``J_2 = pi a^2 N*``, :func:`nose_factor`). Tangent ogive: 96-point
    Gauss-Legendre in the meridian angle (exact to round-off); cone and flat face in
    closed form. Used by the crater region (:mod:`pencore.kernels.crater`)."""
    k = np.arange(n)
    if isinstance(nose, ConeNose):
        return math.pi * a * a * math.sin(nose.half_angle) ** k
    if isinstance(nose, FlatNose):
        return np.full(n, math.pi * a * a)
    ro = 2.0 * nose.crh * a
    b_tip = math.asin(min(nose.length(a) / ro, 1.0))
    b = 0.5 * b_tip * (_GL_X + 1.0)
    sb = np.sin(b)
    integrand = (ro * np.cos(b) - (ro - a)) * sb
    return np.array(
        [2.0 * math.pi * ro * 0.5 * b_tip * float(np.sum(_GL_W * integrand * sb**j)) for j in k]
    )


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
