"""Closed-form and one-dimensional references for normal, frictionless penetration.

These verify the 3-D solver; they are not part of it.

For a frictionless body at zero yaw moving along its axis at speed ``V`` into a
half-space with ``sigma_n = a0 + a1 Vn + a2 Vn^2`` (Vn = V na on the nose), the axial
force on the embedded part of the nose (tip depth ``z``) is::

    F(z, V) = a0 A(z) + a1 V B1(z) + a2 V^2 B2(z),
    A(z) = pi r(z)^2,  Bk(z) = int_0^z 2 pi r na^(k+1) dl

(the shank carries no axial load: na = 0 there, and its a0 cancels around the ring).
Fully embedded, ``A = pi a^2`` and ``B2 = pi a^2 N*`` with the nose factor ``N*``, giving
the familiar ``F = pi a^2 (a0 + N* a2 V^2)`` of the cavity-expansion literature and,
for ``a1 = 0``, the tunnel-phase depth ``(m / (2 pi a^2 N* a2)) ln(1 + N* a2 V1^2 / a0)``.

The nose-entry phase is integrated exactly: with ``a1 = 0``, ``m d(V^2)/dz = -2 F`` is
linear in ``V^2`` and solved by quadrature (:func:`nose_entry_speed`), so
:func:`depth` is the exact depth of the DAFL model for normal impact, up to quadrature
error, including the entry phase.

Three-term laws (``a1 != 0``, the cavity-expansion form ``Y (A + B V/c + C V^2/c^2)`` of
the metal-target literature) add the linear nose factor ``N1 = B1 / (pi a^2)``; the
tunnel phase ``m V dV = -pi a^2 (a0 + a1 N1 V + a2 N* V^2) dz`` integrates in closed form
(:func:`tunnel_depth`: a logarithm and an arctangent), and the entry phase, no longer
linear in ``V^2``, is integrated numerically over the same band profile
(:func:`nose_entry_speed`, scipy's ``solve_ivp`` at ``rtol = 1e-10``).
"""

from __future__ import annotations

import math

import numpy as np

from pencore.errors import InputError, hint_keywords
from pencore.inputs.geometry import Projectile
from pencore.inputs.target import Medium

__all__ = [
    "linear_nose_factor",
    "axial_force",
    "tunnel_depth",
    "nose_entry_speed",
    "depth",
    "speed_at_depth",
    "forrestal_crater_depth",
]


def _coeffs3(medium: Medium) -> tuple[float, float, float]:
    c = list(medium.coefficients) + [0.0, 0.0, 0.0]
    if any(x != 0.0 for x in c[3:]):
        raise InputError("closed forms need sigma_n = a0 + a1 Vn + a2 Vn^2 (no higher terms)")
    if not medium.frictionless:
        raise InputError("closed forms are frictionless")
    return c[0], c[1], c[2]


def _coeffs(medium: Medium) -> tuple[float, float]:
    a0, a1, a2 = _coeffs3(medium)
    if a1 != 0.0:
        raise InputError("this closed form needs sigma_n = a0 + a2 Vn^2 (a1 = 0)")
    return a0, a2


def linear_nose_factor(projectile: Projectile, n: int = 4000) -> float:
    """Linear nose factor ``N1`` (dimensionless) of a projectile's nose.

    The axial force of the term ``a1 Vn`` on the fully embedded nose at zero yaw is
    ``pi a^2 a1 N1 V``. ``N1 = int 2 pi r na^2 dl / (pi a^2)`` over the nose (``na`` the
    axial component of the unit normal), by the same band quadrature as the entry profile
    (``n`` bands; for a tangent ogive of CRH 3 the value converges to 1e-7 by
    ``n = 4000``). A flat nose has ``N1 = 1``, a hemisphere ``2/3``.

    Parameters
    ----------
    projectile : Projectile
        The body.
    n : int, default 4000
        Bands of the quadrature.

    Returns
    -------
    float
        ``N1`` (dimensionless).

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> hemi = pencore.Projectile("hemi", 0.03, pencore.OgiveNose(0.5, 7850.0))
    >>> print(f"{closedform.linear_nose_factor(hemi):.4f}")
    0.6667
    """
    _, _, b1, _ = _entry_profile(projectile, n)
    a = projectile.radius
    return float(b1[-1] / (math.pi * a * a))


def axial_force(projectile: Projectile, medium: Medium, velocity: float) -> float:
    """Axial resistance on the fully embedded nose: ``pi a^2 (a0 + a1 N1 V + a2 N* V^2)``.

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    velocity : float
        Speed along the axis (m/s).

    Returns
    -------
    float
        The force (N).

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    >>> print(f"{closedform.axial_force(p2, soil, 280.0) / 1e3:.1f} kN")
    365.3 kN
    """
    a0, a1, a2 = _coeffs3(medium)
    a = projectile.radius
    lin = a1 * linear_nose_factor(projectile) * velocity if a1 != 0.0 else 0.0
    return math.pi * a * a * (a0 + lin + projectile.nose_factor() * a2 * velocity**2)


def tunnel_depth(projectile: Projectile, medium: Medium, v1: float) -> float:
    """Distance (m) travelled after full nose embedment from speed ``v1`` (m/s) to rest.

    Two-term law: ``(m / (2 pi a^2 N* a2)) ln(1 + N* a2 V1^2 / a0)``. Three-term law, with
    ``k = N* a2``, ``b = N1 a1``, ``D = 4 k a0 - b^2 > 0``::

        m / (pi a^2) [ ln((k V1^2 + b V1 + a0) / a0) / (2 k)
                       - b / (k sqrt(D)) (atan((2 k V1 + b) / sqrt(D)) - atan(b / sqrt(D))) ]

    (``int V dV / (k V^2 + b V + a0)``); ``D <= 0`` or ``k = 0`` by quadrature.

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    v1 : float
        Speed at full nose embedment (m/s).

    Returns
    -------
    float
        Distance travelled (m).

    Raises
    ------
    InputError
        ``a0 = 0`` (the projectile never stops).

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    >>> print(f"{closedform.tunnel_depth(p2, soil, 270.0):.3f} m")
    3.918 m
    """
    a0, a1, a2 = _coeffs3(medium)
    a = projectile.radius
    m = projectile.mass_properties().mass
    ns = projectile.nose_factor()
    if a0 == 0.0:
        raise InputError("a0 = 0: the projectile never stops")
    if a1 == 0.0:
        return m / (2.0 * math.pi * a * a * ns * a2) * math.log1p(ns * a2 * v1 * v1 / a0)
    k, b = ns * a2, linear_nose_factor(projectile) * a1
    disc = 4.0 * k * a0 - b * b
    scale = m / (math.pi * a * a)
    if k > 0.0 and disc > 0.0:
        r = math.sqrt(disc)
        log_part = math.log1p((k * v1 + b) * v1 / a0) / (2.0 * k)
        atan_part = b / (k * r) * (math.atan((2.0 * k * v1 + b) / r) - math.atan(b / r))
        return scale * (log_part - atan_part)
    from scipy.integrate import quad

    val, _ = quad(lambda v: v / (a0 + b * v + k * v * v), 0.0, v1, epsabs=0.0, epsrel=1e-12)
    return scale * val


def _entry_profile(projectile: Projectile, n: int = 4000) -> tuple[np.ndarray, ...]:
    """Tip depth z, A(z), B1(z), B2(z) on a fine grid over the nose length."""
    rings = projectile.rings(n_nose=n, n_shank=1, n_face=max(1, n // 10))
    sel = rings.part != 1
    sel &= rings.na > 0  # nose surface and blunt face, not the rear face
    x1 = rings.x1[sel]
    mp = projectile.mass_properties()
    s = mp.lc - x1  # distance from the tip
    order = np.argsort(s, kind="stable")
    s, na, w = s[order], rings.na[sel][order], rings.w[sel][order]
    # band contributions, accumulated by tip depth (a band is loaded once its axial
    # position is below the surface)
    da = 2.0 * np.pi * w * na  # d(projected area) = 2 pi r dl na
    db1 = 2.0 * np.pi * w * na**2
    db = 2.0 * np.pi * w * na**3
    return s, np.cumsum(da), np.cumsum(db1), np.cumsum(db)


def nose_entry_speed(
    projectile: Projectile, medium: Medium, velocity: float
) -> tuple[float, float]:
    """Speed when the nose is fully embedded, and the tip depth reached.

    Solves ``m d(V^2)/dz = -2 (a0 A(z) + a1 B1(z) V + a2 B2(z) V^2)`` over the nose
    length: exactly per band piece when ``a1 = 0`` (linear in ``V^2``), else numerically
    (scipy's ``solve_ivp``).

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    velocity : float
        Impact speed (m/s).

    Returns
    -------
    tuple of float
        The speed (m/s) and the tip depth (m, the nose length); ``(0, z_stop)`` if the
        projectile stops before full embedment.

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    >>> v1, z = closedform.nose_entry_speed(p2, soil, 280.0)
    >>> print(f"{v1:.1f} m/s at {z:.4f} m")
    274.3 m/s at 0.1575 m
    """
    a0, a1, a2 = _coeffs3(medium)
    m = projectile.mass_properties().mass
    z, area, b1, b2 = _entry_profile(projectile)
    ln = projectile.nose_length
    if ln == 0.0:
        return velocity, 0.0
    if a1 != 0.0:
        return _entry_three_term(z, area, b1, b2, (a0, a1, a2), m, ln, velocity)
    # piecewise-constant A, B2 between band positions; exact exponential update of V^2
    v2 = velocity * velocity
    zprev = 0.0
    for k in range(len(z)):
        dz = z[k] - zprev
        if dz > 0.0:
            ak = area[k - 1] if k > 0 else 0.0
            bk = b2[k - 1] if k > 0 else 0.0
            v2, stopped_at = _advance(v2, ak, bk, a0, a2, m, dz)
            if stopped_at is not None:
                return 0.0, zprev + stopped_at
        zprev = z[k]
    dz = ln - zprev
    if dz > 0.0:
        v2, stopped_at = _advance(v2, area[-1], b2[-1], a0, a2, m, dz)
        if stopped_at is not None:
            return 0.0, zprev + stopped_at
    return math.sqrt(v2), ln


def _entry_three_term(z, area, b1, b2, coeffs, m, ln, velocity) -> tuple[float, float]:
    """Entry phase of a three-term law: ``du/dz = -2 (a0 A + a1 B1 sqrt(u) + a2 B2 u) / m``
    for ``u = V^2``, with ``A, B1, B2`` interpolated linearly between the band positions of
    the profile, integrated by scipy's ``solve_ivp`` (RK45, ``rtol = 1e-10``) to the end of
    the nose or to rest (``u = 0``)."""
    from scipy.integrate import solve_ivp

    a0, a1, a2 = coeffs
    zp = np.concatenate(([0.0], z))
    ap, b1p, b2p = (np.concatenate(([0.0], c)) for c in (area, b1, b2))

    def rhs(zz, y):
        u = max(y[0], 0.0)
        ak, b1k, b2k = (np.interp(zz, zp, c) for c in (ap, b1p, b2p))
        return [-2.0 * (a0 * ak + a1 * b1k * math.sqrt(u) + a2 * b2k * u) / m]

    def rest(_z, y):
        return y[0]

    rest.terminal = True
    rest.direction = -1
    sol = solve_ivp(rhs, (0.0, ln), [velocity * velocity], rtol=1e-10, atol=1e-9, events=rest)
    if sol.status == 1:
        return 0.0, float(sol.t_events[0][0])
    return math.sqrt(max(float(sol.y[0, -1]), 0.0)), ln


def _advance(v2, a, b, a0, a2, m, dz):
    """V^2 after dz with constant A = a, B2 = b; or the distance to rest."""
    k = 2.0 * a2 * b / m
    c = 2.0 * a0 * a / m
    if k > 0.0:
        vinf = -c / k
        new = vinf + (v2 - vinf) * math.exp(-k * dz)
        if new <= 0.0:
            return 0.0, math.log((v2 - vinf) / (-vinf)) / k
        return new, None
    new = v2 - c * dz
    if new <= 0.0:
        return 0.0, v2 / c if c > 0 else dz
    return new, None


def depth(projectile: Projectile, medium: Medium, velocity: float) -> float:
    """Tip depth at rest for a normal, zero-yaw, frictionless impact on a half-space.

    The exact nose-entry phase (:func:`~pencore.closedform.nose_entry_speed`) plus the
    tunnel-phase closed form (:func:`~pencore.closedform.tunnel_depth`); with a crater
    region (``medium.crater_depth`` calibers) Forrestal's form
    (:func:`~pencore.closedform.forrestal_crater_depth`), which is pencore's crater
    (:mod:`pencore.kernels.crater`) in this limit. :func:`~pencore.simulate` gives the
    same depth for such an impact (``tests/test_closedform.py``). A medium whose law
    depends on the projectile (Li & Chen's crater depth, a size term) is first resolved for
    it (:meth:`~pencore.inputs.target.Medium.for_projectile`), as a run is; the other
    functions here take the medium as given.

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    velocity : float
        Impact speed (m/s).

    Returns
    -------
    float
        Tip depth at rest (m).

    Raises
    ------
    InputError
        A medium with a free-surface reduction (no closed form).

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    >>> print(f"{closedform.depth(p2, soil, 280.0):.3f} m")
    4.152 m
    """
    if medium.free_surface_depth > 0.0:
        raise InputError("closed forms have no free-surface reduction")
    medium = medium.for_projectile(projectile.diameter, projectile.nose_length)
    if medium.crater_depth > 0.0:
        return forrestal_crater_depth(projectile, medium, velocity, medium.crater_depth)
    v1, z = nose_entry_speed(projectile, medium, velocity)
    if v1 == 0.0:
        return z
    return z + tunnel_depth(projectile, medium, v1)


def speed_at_depth(projectile: Projectile, medium: Medium, velocity: float, z: float) -> float:
    """Speed at a tip depth past the nose, normal frictionless impact on a half-space.

    The nose-entry speed (:func:`~pencore.closedform.nose_entry_speed`) followed by the
    tunnel-phase solution ``V^2 = (V1^2 + a0/(N* a2)) exp(-2 pi a^2 N* a2 (z - L_n)/m)
    - a0/(N* a2)`` (two-term law).

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    velocity : float
        Impact speed (m/s).
    z : float
        Tip depth (m), at least the nose length.

    Returns
    -------
    float
        Speed (m/s); 0 once the body has stopped.

    Raises
    ------
    InputError
        ``z`` inside the nose-entry phase.

    Examples
    --------
    >>> import pencore
    >>> from pencore import closedform
    >>> p2, soil = pencore.get_projectile("p2"), pencore.get_target("soil").medium
    >>> print(f"{closedform.speed_at_depth(p2, soil, 280.0, 1.0):.1f} m/s")
    228.2 m/s
    """
    a0, a2 = _coeffs(medium)
    v1, zn = nose_entry_speed(projectile, medium, velocity)
    if z < zn:
        raise InputError(f"z = {z!r} m is inside the nose-entry phase (nose length {zn!r} m)")
    if v1 == 0.0:
        return 0.0
    a = projectile.radius
    m = projectile.mass_properties().mass
    v2, stopped = _advance(
        v1 * v1, math.pi * a * a, math.pi * a * a * projectile.nose_factor(), a0, a2, m, z - zn
    )
    return 0.0 if stopped is not None else math.sqrt(v2)


def forrestal_crater_depth(
    projectile: Projectile, medium: Medium, velocity: float, k: float = 2.0
) -> float:
    """Tip depth at rest with Forrestal's crater region, normal frictionless impact.

    The crater region is a total force linear in tip depth, ``F = c z``
    for ``z < k d`` (Forrestal et al., IJIE 15 (1994) 395-405; k = 2 there), and
    ``F = pi a^2 (a0 + N* a2 V^2)`` below. ``c`` follows from continuity at ``z = k d``,
    ``c k d = pi a^2 (a0 + N* a2 V1^2)``, and the work ``c (k d)^2 / 2`` of the crater
    phase, which give (derived here from those two conditions)::

        V1^2 = (m V0^2 - k d pi a^2 a0) / (m + k d pi a^2 N* a2)

    and the depth ``k d`` plus the tunnel-phase depth from ``V1`` (Forrestal's Eq. for
    ``P``). When ``V1^2 <= 0`` the body stops in the crater, where Forrestal's ``c`` is not
    defined; the same constant of the motion that makes the model local
    (:mod:`pencore.kernels.crater`), ``c k d (1 + beta) = pi a^2 (a0 + N* a2 V0^2)`` with
    ``beta = k d pi a^2 N* a2 / m``, gives ``z = sqrt(m V0^2 / c)`` (continuous with the
    ``V1 = 0`` case; it is Li & Chen's shallow-penetration formula, IJIE 28 (2003) 93-116,
    Eq. 15a, in dimensional form). Assumes the nose is embedded at ``z = k d``
    (``k d >= L_n``).

    Parameters
    ----------
    projectile : Projectile
        The body (:class:`~pencore.Projectile`; a library projectile:
        ``pencore.get_projectile("p2")``).
    medium : Medium
        The target material (``pencore.get_target("soil").medium``); its resistance law
        ``a0 + a1 Vn + a2 Vn^2`` (Pa).
    velocity : float
        Impact speed (m/s).
    k : float, default 2
        Depth of the crater region in calibers.

    Returns
    -------
    float
        Tip depth at rest (m).

    Raises
    ------
    InputError
        ``k d`` shorter than the nose.

    Examples
    --------
    #2 into the paper's concrete at 500 m/s, with and without the crater region:

    >>> import pencore
    >>> from pencore import closedform
    >>> p2, concrete = pencore.get_projectile("p2"), pencore.get_target("concrete").medium
    >>> crater = closedform.forrestal_crater_depth(p2, concrete, 500.0)
    >>> print(f"{crater:.3f} m, {closedform.depth(p2, concrete, 500.0):.3f} m")
    1.419 m, 1.391 m
    """
    a0, a2 = _coeffs(medium)
    a = projectile.radius
    kd = k * projectile.diameter
    if kd < projectile.nose_length * (1.0 - 1e-12):
        raise InputError(f"k d = {kd!r} m is shorter than the nose ({projectile.nose_length!r} m)")
    m = projectile.mass_properties().mass
    ns = projectile.nose_factor()
    area = math.pi * a * a * kd
    v1sq = (m * velocity**2 - area * a0) / (m + area * ns * a2)
    if v1sq <= 0.0:
        beta = area * ns * a2 / m
        c = math.pi * a * a * (a0 + ns * a2 * velocity**2) / (kd * (1.0 + beta))
        return math.sqrt(m * velocity**2 / c)
    return kd + tunnel_depth(projectile, medium, math.sqrt(v1sq))


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
