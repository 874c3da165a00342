"""Contact force and moment (paper Eqs 5-11) and the rigid-body equations (Eqs 2-4).

Everything here is compiled with numba and works on plain arrays; :mod:`pencore.run.impact`
wraps it for users.

State vector ``y`` (length 14, SI units)::

    y[0:3]   centre-of-mass position in the fixed frame (m)
    y[3:7]   attitude quaternion (w, x, y, z), body -> fixed frame
    y[7:10]  centre-of-mass velocity in the fixed frame (m/s)
    y[10:13] angular velocity in the body frame (rad/s); body axis 1 is the symmetry axis
    y[13]    work done on the body by the contact stresses (J)

Force law on a surface element with outward normal ``n`` moving at ``u`` (paper Eqs 6-9)::

    Vn = u . n,  sigma_n = a0 + a1 Vn + a2 Vn^2 + ...
    traction = -H(Vn) sigma_n n  -  mu(|u_t|) H(Vn) sigma_n u_t / |u_t|

with ``u_t = u - Vn n`` the sliding velocity. The paper's Eq. 9 builds the tangential
direction as ``m x n``, whose length is ``|u_t|/|u|``; we use the unit direction (the
Coulomb law the text describes) and the sign that opposes sliding.

Contact (Eq. 7 plus the free surface): an element carries load when it is inside a
layer (``y <= 0``) and ``Vn >= 0``. On each surface ring every quantity is affine in
``cos(phi)`` and ``sin(phi)``, so the loaded part of the ring is a union of arcs whose
ends are found exactly and the normal stress is integrated over them in closed form.

The unilateral condition makes the force discontinuous where ``Vn`` changes sign over a
whole ring at once: on a cylinder at zero angle of attack ``Vn = 0`` everywhere and
``H = 1`` loads all around, while any sideways velocity unloads one half, so the lateral
force on a shank ring jumps from 0 to ``2 a0 r dl`` (a dry-friction-like force). The
solver smooths the step over a normal-velocity band of half-width ``eps`` (m/s)::

    H_eps(Vn) = clip((Vn + eps) / (2 eps), 0, 1)

which tends to Eq. 7 as ``eps -> 0`` (``eps = 0`` is the sharp law). The band is integrated
in closed form too. The default ``eps`` comes from the convergence study
(``benchmarks/convergence.py``); the implicit integrator keeps the stiff band stable.

Band immersion ramp: each ring stands for the band of surface around it (meridian length
``dl = w / r``). Testing only the ring's own line against the free surface switches a
band on all at once as the line crosses it: on a ring parallel to the surface (normal
impact) the whole ring jumps in, and on a tilted one the loaded arc opens like
``sqrt(depth)``. Either makes the force non-smooth once per ring, and the step control
then resolves every crossing (most of the steps and rejections of an oblique entry). The
share of the band below the surface is instead ramped linearly over the band's height
range ``+-hb`` (:func:`pencore.kernels.bands.band_half_height`: the band's largest half-extent
around the ring). That share is exact for a shank band at any attitude and for any band at normal
impact; elsewhere (a nose band at an angle, whose extent varies around the ring) the
ramp is somewhat wider than the band. The ramp is affine in ``cos(phi - phiy)``, so the
ramped arcs are integrated in closed form as well (:func:`pencore.kernels.arcs.band_regions`,
``pencore.kernels.arcs._poly_arc_moments``); the ramp vanishes with the ring spacing and the
mesh convergence becomes second order (``benchmarks/convergence.py``).

Shank band step width: on a cylindrical band the normal velocity at a given angle varies
along the band's length with the lateral spin, by up to ``+-dl/2 sqrt(w2^2 + w3^2)``.
The step is widened to that spread (:func:`pencore.kernels.bands.band_eps`: the half-width of
the same variance, ``sqrt(eps^2 + s^2)``), so each shank ring's load turns over smoothly
as the point of zero lateral velocity sweeps along the shank, as the band's integral
does, instead of flipping sides at once (the a0 term's ``2 a0 r dl``) once per ring. It
vanishes with the ring spacing, leaves runs without lateral spin unchanged to the bit,
and halves the mesh error of the turning angle and the deviation
(``benchmarks/convergence.py``).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.arcs import (
    _MAXD,
    _MAXI,
    TWO_PI,
    _intersect,
    _level_arc,
    _poly_arc_integrals,
    _poly_arc_moments,
    _poly_centred_arc_integrals,
    ring_height_terms,
    side_poly,
)
from pencore.kernels.bands import band_eps, band_half_height
from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.crater import element_factor, fill_reference, has_crater
from pencore.kernels.friction import _friction_ring, _leggauss
from pencore.kernels.wholering import whole_ring_integrals
from pencore.kernels.windows import depth_factor

# ---------------------------------------------------------------- rotations


@nb.njit(cache=True)
def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix (body -> fixed) of a quaternion (w, x, y, z); normalises ``q``."""
    n = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    w, x, y, z = q[0] / n, q[1] / n, q[2] / n, q[3] / n
    r = np.empty((3, 3))
    # diagonal as w^2 + x^2 - y^2 - z^2 (not 1 - 2(y^2 + z^2)): exact zeros for the
    # quarter turns, so an axisymmetric impact starts exactly on axis
    r[0, 0] = w * w + x * x - y * y - z * z
    r[0, 1] = 2 * (x * y - w * z)
    r[0, 2] = 2 * (x * z + w * y)
    r[1, 0] = 2 * (x * y + w * z)
    r[1, 1] = w * w - x * x + y * y - z * z
    r[1, 2] = 2 * (y * z - w * x)
    r[2, 0] = 2 * (x * z - w * y)
    r[2, 1] = 2 * (y * z + w * x)
    r[2, 2] = w * w - x * x - y * y + z * z
    return r


# ---------------------------------------------------------------- contact loads


@nb.njit(cache=True, inline="always")
def body_velocity(rot, y):
    """Velocity of the centre of mass in the body frame, ``R^T y[7:10]`` (m/s)."""
    v1 = rot[0, 0] * y[7] + rot[1, 0] * y[8] + rot[2, 0] * y[9]
    v2 = rot[0, 1] * y[7] + rot[1, 1] * y[8] + rot[2, 1] * y[9]
    v3 = rot[0, 2] * y[7] + rot[1, 2] * y[8] + rot[2, 2] * y[9]
    return v1, v2, v3


@nb.njit(cache=True, inline="always")
def ring_velocity_terms(x1, r, na, nr, v1, v2, v3, w2, w3):
    """Normal velocity on a ring, ``Vn = av + bc cos(phi) + bs sin(phi) = av + kv
    cos(phi - phi0)``: returns ``(q, av, bc, bs, kv)`` with ``q = nr x1 - na r`` the
    lever of the spin terms (body frame, SI units). The angle ``phi0 = atan2(bs, bc)``
    is left to the caller: only partial arcs need it."""
    q = nr * x1 - na * r
    av = na * v1
    bc = nr * v2 + w3 * q
    bs = nr * v3 - w2 * q
    return q, av, bc, bs, math.sqrt(bc * bc + bs * bs)


@nb.njit(cache=True, inline="always")
def near_level(lo, hi, bounds):
    """Whether the height range ``[lo, hi]`` (m) of a band comes within a relative 1e-9
    of a finite layer level (top or bottom) in ``bounds``: there its regions may be
    partial arcs or ramps, which need the arcs' angles."""
    for lay in range(bounds.shape[0]):
        for edge in range(2):
            level = bounds[lay, edge]
            if not (abs(level) < np.inf):
                continue
            tol = 1e-9 * (abs(lo) + abs(hi) + abs(level) + 1e-3)
            if lo - tol <= level <= hi + tol:
                return True
    return False


@nb.njit(cache=True, inline="always")
def arc_angles(need, yc, ys, bc, bs, kv):
    """The angles of a ring's height and normal-velocity terms and the height's cosine
    and sine, ``(phiy, phi0, cos phiy, sin phiy)``, when ``need``; else ``(0, 0, 1,
    0)``. They orient partial arcs and ramps only: a band clear of every layer level
    (:func:`near_level`) is loaded on whole-ring regions, whose centred integrals need
    no angle, so their trigonometry is skipped there. ``phi0`` is 0 when ``kv = 0``,
    as its cosine and sine ``(bc, bs) / kv`` are then taken to be ``(1, 0)``."""
    if not need:
        return 0.0, 0.0, 1.0, 0.0
    phiy = math.atan2(ys, yc)
    phi0 = math.atan2(bs, bc) if kv > 0.0 else 0.0
    return phiy, phi0, math.cos(phiy), math.sin(phiy)


@nb.njit(cache=True)
def contact_loads(y, rings, bounds, coef, fric, eps, n_gauss):
    """Resultant contact force and moment.

    Parameters
    ----------
    y : (14,) state (see module docstring).
    rings : (n, 5) array x1, r, na, nr, w (see :class:`pencore.inputs.geometry.Rings`).
    bounds, coef, fric : layer arrays from :meth:`pencore.inputs.target.Target.kernel_arrays`.
    eps : float
        Half-width of the smoothed contact step (m/s); 0 for the sharp Eq. 7.
    n_gauss : int
        Gauss points per arc piece for the friction integral (0 skips friction).

    Returns
    -------
    force_body : (3,) N, in the body frame.
    moment_body : (3,) N m about the centre of mass, body frame.
    clearance : float
        Lowest point of the surface rings above the free surface (m); <= 0 in contact.
    """
    rot = quat_to_matrix(y[3:7])
    v1, v2, v3 = body_velocity(rot, y)
    w1, w2, w3 = y[10], y[11], y[12]
    ycm = y[1]
    r10, r11, r12 = rot[1, 0], rot[1, 1], rot[1, 2]

    f = np.zeros(3)
    mom = np.zeros(3)
    clearance = np.inf
    nlay = bounds.shape[0]
    poly = np.zeros(_MAXD)
    se = np.zeros(_MAXD + 2)
    scj = np.zeros(_MAXD + 2)
    sdj = np.zeros(_MAXD + 2)

    l1lo = np.empty(_MAXI)
    l1hi = np.empty(_MAXI)
    l2lo = np.empty(_MAXI)
    l2hi = np.empty(_MAXI)
    blo = np.empty(_MAXI)
    bhi = np.empty(_MAXI)
    vlo = np.empty(_MAXI)
    vhi = np.empty(_MAXI)
    slo = np.empty(_MAXI)
    shi = np.empty(_MAXI)
    moments = np.zeros(6)
    rlo = np.empty((4, _MAXI))  # up to 4 regions per ring and layer (see below)
    rhi = np.empty((4, _MAXI))
    rn = np.zeros(4, dtype=np.int64)
    rpar = np.empty((4, 3))  # alpha, beta, signed area weight
    nside = 1 if eps <= 0.0 else 2
    gx, gw = _leggauss(n_gauss)
    # whole-ring fast path: one layer, no depth windows, no friction; a band clear of
    # the layer's levels is then either out of contact or a whole ring of it (alpha 1),
    # so no region sets are built and its integrals are done for all such rings at once
    # (pencore.kernels.wholering, vectorised; same operations per ring: bit-identical)
    # (friction is excluded through `need` below: its quadrature needs every ring's angles)
    simple = nlay == 1 and bounds.shape[1] < 5
    n = rings.shape[0]
    crater = has_crater(bounds)
    # per ring: y0 yk yc ys hb q av bc bs kv cph sph epsr need (and with a crater region,
    # the rings' normal-entry reference of pencore.kernels.crater.fill_reference)
    geo = np.empty((14 + (2 + nlay if crater else 0), n))
    if crater:
        fill_reference(
            geo, 14, rings[:, 0], rings[:, 1], rings[:, 2], rings[:, 3], rings[:, 4], bounds,
            coef, v1, eps,
        )  # fmt: skip
    kind = np.empty(n, dtype=np.int64)  # -1 out of contact, -2 general, else fast slot
    tab = np.empty((5, n))  # the fast rings' av, kv, cos/sin(phi0), epsr
    nf = np.int64(0)
    rk = math.sqrt(r11 * r11 + r12 * r12)  # |d(height)/d(radius)| of a ring point
    for i in range(n):
        x1 = rings[i, 0]
        r = rings[i, 1]
        na = rings[i, 2]
        nr = rings[i, 3]
        w = rings[i, 4]
        y0, yk, yc, ys = ring_height_terms(ycm, r10, r11, r12, x1, r)
        hb = band_half_height(r10, rk, r, na, nr, w)
        low = y0 - yk - hb
        if low < clearance:
            clearance = low
        kind[i] = -1
        if low > bounds[0, 0]:
            continue
        high = y0 + yk + hb
        q, av, bc, bs, kv = ring_velocity_terms(x1, r, na, nr, v1, v2, v3, w2, w3)
        cph = bc / kv if kv > 0.0 else 1.0  # cos(phi0), sin(phi0)
        sph = bs / kv if kv > 0.0 else 0.0
        # friction's quadrature points need the angles on every ring
        need = n_gauss > 0 or yk == 0.0 or near_level(y0 - yk - hb, high, bounds)
        epsr, _ = band_eps(eps, r, na, w, w2, w3)
        if simple and not need:
            if high < bounds[0, 1]:
                continue  # wholly below a plate's bottom face
            kind[i] = nf
            tab[0, nf] = av
            tab[1, nf] = kv
            tab[2, nf] = cph
            tab[3, nf] = sph
            tab[4, nf] = epsr
            nf += 1
        else:
            kind[i] = -2
        for c, v in enumerate((y0, yk, yc, ys, hb, q, av, bc, bs, kv, cph, sph, epsr)):
            geo[c, i] = v
        geo[13, i] = 1.0 if need else 0.0
    wint = np.empty((3, nf))
    if nf > 0:
        whole_ring_integrals(tab, nf, coef, nside, wint)

    # the loads in ring order (the order of the sums is that of the one-ring loop)
    for i in range(n):
        if kind[i] == -1:
            continue
        x1 = rings[i, 0]
        r = rings[i, 1]
        na = rings[i, 2]
        nr = rings[i, 3]
        w = rings[i, 4]
        q = geo[5, i]
        if kind[i] >= 0:
            s0 = wint[0, kind[i]]
            sc = wint[1, kind[i]]
            ss = wint[2, kind[i]]
            f[0] -= w * na * s0
            f[1] -= w * nr * sc
            f[2] -= w * nr * ss
            mom[1] += w * q * ss
            mom[2] -= w * q * sc
            continue
        y0, yk, yc, ys, hb = geo[0, i], geo[1, i], geo[2, i], geo[3, i], geo[4, i]
        av, bc, bs, kv = geo[6, i], geo[7, i], geo[8, i], geo[9, i]
        cph, sph, epsr = geo[10, i], geo[11, i], geo[12, i]
        high = y0 + yk + hb
        need = geo[13, i] != 0.0
        phiy, phi0, cy, sy = arc_angles(need, yc, ys, bc, bs, kv)
        for lay in range(nlay):
            if high < bounds[lay, 1]:
                continue  # wholly below this layer
            # depth windows (free surface) and the crater factor at the ring centre; 1 when off
            wl = w
            if bounds.shape[1] >= 5:
                wl = w * depth_factor(y0, bounds, lay)
                if bounds[lay, 2] > 0.0:
                    wl *= element_factor(y0, bounds[lay, 9] - x1, v1, bounds, coef, lay, geo, 14)
                if wl == 0.0:
                    continue
            # the layer's share of the band: the cores and ramps of
            # pencore.kernels.arcs.band_regions, written out here because the call (even marked
            # inline) makes the right-hand side 14 -> 18 us; the Jacobian calls
            # band_regions, and tests/kernels/test_jacobian.py compares the two forms
            nreg = 0
            for edge in range(2):
                level = bounds[lay, edge]
                if edge == 1 and not (level > -np.inf):
                    break
                we = wl if edge == 0 else -wl
                if y0 - yk >= level + hb:
                    continue
                n = np.int64(0)
                if y0 - yk <= level - hb:
                    n = _level_arc(y0, yk, phiy, level - hb, False, l1lo, l1hi)
                if n > 0:
                    for m in range(n):
                        rlo[nreg, m] = l1lo[m]
                        rhi[nreg, m] = l1hi[m]
                    rn[nreg] = n
                    rpar[nreg, 0] = 1.0
                    rpar[nreg, 1] = 0.0
                    rpar[nreg, 2] = we
                    nreg += 1
                if hb > 0.0 and y0 + yk > level - hb:
                    n1 = _level_arc(y0, yk, phiy, level - hb, True, l1lo, l1hi)
                    n2 = _level_arc(y0, yk, phiy, level + hb, False, l2lo, l2hi)
                    n = _intersect(l1lo, l1hi, n1, l2lo, l2hi, n2, blo, bhi)
                    if n > 0:
                        for m in range(n):
                            rlo[nreg, m] = blo[m]
                            rhi[nreg, m] = bhi[m]
                        rn[nreg] = n
                        rpar[nreg, 0] = (level + hb - y0) / (2.0 * hb)
                        rpar[nreg, 1] = yk / (2.0 * hb)
                        rpar[nreg, 2] = we
                        nreg += 1
            for g in range(nreg):
                alpha, beta, we = rpar[g, 0], rpar[g, 1], rpar[g, 2]
                nb_ = rn[g]
                for m in range(nb_):
                    blo[m] = rlo[g, m]
                    bhi[m] = rhi[g, m]
                ramp = beta != 0.0 or alpha != 1.0
                whole = nb_ == 1 and blo[0] == 0.0 and bhi[0] == TWO_PI
                # --- normal stress, closed form; chi = alpha - beta cos(phi - phiy)
                s0 = 0.0
                sc = 0.0
                ss = 0.0
                for side in range(nside):
                    level, dg = side_poly(coef, lay, epsr, side, poly)
                    if whole and beta == 0.0:
                        # the region is the whole ring: the loaded arc is centred on
                        # phi0, |phi - phi0| <= acos(c), and needs no arc ends
                        a_, b_, c_ = _poly_centred_arc_integrals(
                            poly, dg, av, kv, cph, sph, level, se, scj
                        )
                        s0 += alpha * a_
                        sc += alpha * b_
                        ss += alpha * c_
                        continue
                    nv = _level_arc(av, kv, phi0, level, True, vlo, vhi)
                    ns = _intersect(blo, bhi, nb_, vlo, vhi, nv, slo, shi)
                    if ns == 0:
                        continue
                    if not ramp:
                        a_, b_, c_ = _poly_arc_integrals(
                            poly, dg, av, kv, phi0, cph, sph, slo, shi, ns, se, scj, sdj
                        )
                        s0 += a_
                        sc += b_
                        ss += c_
                    else:
                        for c in range(6):
                            moments[c] = 0.0
                        _poly_arc_moments(
                            poly, dg, av, kv, phi0, cph, sph, slo, shi, ns, se, scj, sdj,
                            moments,
                        )  # fmt: skip
                        # chi (1, cos, sin): cos(phi - phiy) = cy cos(phi) + sy sin(phi)
                        s0 += alpha * moments[0] - beta * (cy * moments[1] + sy * moments[2])
                        sc += alpha * moments[1] - beta * (cy * moments[3] + sy * moments[4])
                        ss += alpha * moments[2] - beta * (cy * moments[4] + sy * moments[5])
                f[0] -= we * na * s0
                f[1] -= we * nr * sc
                f[2] -= we * nr * ss
                mom[1] += we * q * ss
                mom[2] -= we * q * sc
                # --- friction, Gauss quadrature on the loaded arcs
                if n_gauss > 0 and fric[lay, :, 1].max() > 0.0:
                    level = -epsr if epsr > 0.0 else 0.0
                    nv = _level_arc(av, kv, phi0, level, True, vlo, vhi)
                    ns = _intersect(blo, bhi, nb_, vlo, vhi, nv, slo, shi)
                    _friction_ring(
                        f, mom, slo, shi, ns, gx, gw, x1, r, na, nr, we, v1, v2, v3, w1, w2,
                        w3, coef, lay, fric, epsr, alpha, beta, cy, sy,
                    )  # fmt: skip
    return f, mom, clearance


# ---------------------------------------------------------------- equations of motion


@nb.njit(cache=True)
def rhs(y, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss):
    """Time derivative of the state (Newton, Euler with I2 = I3, quaternion kinematics,
    and the power of the contact stresses). Returns ``(dy, clearance)``."""
    fb, mb, clearance = contact_loads(y, rings, bounds, coef, fric, eps, n_gauss)
    return equations_of_motion(y, fb, mb, mass, inertia, gravity), clearance


@nb.njit(cache=True)
def equations_of_motion(y, fb, mb, mass, inertia, gravity):
    """Time derivative of the state under the body-frame contact force ``fb`` (N) and
    moment ``mb`` (N m about the centre of mass) and ``gravity`` (m/s^2, fixed frame)."""
    rot = quat_to_matrix(y[3:7])
    dy = np.empty(14)
    dy[0] = y[7]
    dy[1] = y[8]
    dy[2] = y[9]
    qw, qx, qy, qz = y[3], y[4], y[5], y[6]
    w1, w2, w3 = y[10], y[11], y[12]
    # dq/dt = 0.5 q (x) (0, w)
    dy[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3)
    dy[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2)
    dy[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3)
    dy[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1)
    for k in range(3):
        dy[7 + k] = (rot[k, 0] * fb[0] + rot[k, 1] * fb[1] + rot[k, 2] * fb[2]) / mass + gravity[k]
    i1, i2, i3 = inertia[0], inertia[1], inertia[2]
    dy[10] = (mb[0] + (i2 - i3) * w2 * w3) / i1
    dy[11] = (mb[1] + (i3 - i1) * w3 * w1) / i2
    dy[12] = (mb[2] + (i1 - i2) * w1 * w2) / i3
    # power of the contact stresses: F . v + M . w (body frame)
    v1, v2, v3 = body_velocity(rot, y)
    dy[13] = fb[0] * v1 + fb[1] * v2 + fb[2] * v3 + mb[0] * w1 + mb[1] * w2 + mb[2] * w3
    return dy


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
