"""Point-load contact kernel (panels and shank ring points) and the nose-tip path.

Compiled with numba. The force law on one load point (rows of
:mod:`pencore.kernels.panels`) is the one of :mod:`pencore.kernels.dynamics` (paper Eqs 6-11)
taken at a
single point: with ``u`` the point's velocity and ``Vn = u . n``::

    traction * area = -h(Vn) sigma(Vn) A n  -  mu(|u_t|) h(Vn) sigma(Vn) A u_t / |u_t|

with ``h`` the smoothed step of half-width ``eps`` (``eps = 0``: the pure Heaviside of
Eq. 7, ``h(0) = 1``), inside a layer (``y <= 0``) only.

Cavity shank model (:class:`pencore.inputs.models.ShankModel`, ``"cavity"``): a shank point's
stress is multiplied by ``min(1, delta / delta_ref)`` where ``delta = d - R_c`` is its
intrusion into the wall of the cavity cut by the nose: ``d`` is its distance from the
path of the cavity's axis point (the nose tip, or the nose shoulder; called "the tip"
below, at body axial coordinate ``lc``), a polyline through samples taken at *accepted*
steps only (:func:`push_path`) plus the current tip as a last, virtual vertex, so a
rejected step leaves no trace. The search is local: a binary search on the path's arc
length for the point's own arc position (the tip's minus the point's axial distance
behind the tip), then a descent over neighbouring segments; the points of a ring (same
axial position) start from the previous point's segment.

Path buffer ``path`` (rows: x, y, z, arc length s; m), ``npath[0]`` rows in use.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.crater import element_factor, fill_reference, has_crater
from pencore.kernels.dynamics import body_velocity, quat_to_matrix
from pencore.kernels.friction import friction_coefficient
from pencore.kernels.windows import depth_factor

#: Most samples :func:`push_path` adds per accepted step (the rest is the virtual vertex).
MAX_SAMPLES_PER_STEP = 32


@nb.njit(cache=True)
def tip_position(y, lc):
    """Position (m, fixed frame) of the axis point at body coordinate ``lc`` (the nose
    tip when ``lc`` is the tip-to-centre-of-mass distance) in state ``y``."""
    rot = quat_to_matrix(y[3:7])
    return np.array([y[0] + lc * rot[0, 0], y[1] + lc * rot[1, 0], y[2] + lc * rot[2, 0]])


@nb.njit(cache=True)
def tip_velocity(y, lc):
    """Velocity (m/s, fixed frame) of that axis point: ``v + R (w x (lc, 0, 0))``."""
    rot = quat_to_matrix(y[3:7])
    b2 = y[12] * lc  # w x (lc, 0, 0) = (0, w3 lc, -w2 lc)
    b3 = -y[11] * lc
    return np.array(
        [
            y[7] + rot[0, 1] * b2 + rot[0, 2] * b3,
            y[8] + rot[1, 1] * b2 + rot[1, 2] * b3,
            y[9] + rot[2, 1] * b2 + rot[2, 2] * b3,
        ]
    )


@nb.njit(cache=True)
def _append(path, npath, p):
    n = npath[0]
    dx = p[0] - path[n - 1, 0]
    dy = p[1] - path[n - 1, 1]
    dz = p[2] - path[n - 1, 2]
    path[n, 0] = p[0]
    path[n, 1] = p[1]
    path[n, 2] = p[2]
    path[n, 3] = path[n - 1, 3] + math.sqrt(dx * dx + dy * dy + dz * dz)
    npath[0] = n + 1


@nb.njit(cache=True)
def push_path(path, npath, y0, y1, h, lc, spacing):
    """Extend the tip path after the accepted step ``y0 -> y1`` of length ``h`` (s).

    The tip's motion over the step is the cubic Hermite curve through its positions and
    velocities at both ends; points on it at most ``spacing`` (m) apart (at most
    :data:`MAX_SAMPLES_PER_STEP`) are appended when they are at least ``spacing`` from
    the last sample. The caller keeps room for them (``path`` rows).
    """
    p0 = tip_position(y0, lc)
    p1 = tip_position(y1, lc)
    u0 = tip_velocity(y0, lc)
    u1 = tip_velocity(y1, lc)
    chord = math.sqrt((p1[0] - p0[0]) ** 2 + (p1[1] - p0[1]) ** 2 + (p1[2] - p0[2]) ** 2)
    k = min(MAX_SAMPLES_PER_STEP, max(1, int(math.ceil(chord / spacing))))
    q = np.empty(3)
    for i in range(1, k + 1):
        t = i / k
        h00 = (1.0 + 2.0 * t) * (1.0 - t) ** 2
        h10 = t * (1.0 - t) ** 2
        h01 = t * t * (3.0 - 2.0 * t)
        h11 = t * t * (t - 1.0)
        for c in range(3):
            q[c] = h00 * p0[c] + h10 * h * u0[c] + h01 * p1[c] + h11 * h * u1[c]
        n = npath[0]
        d2 = (q[0] - path[n - 1, 0]) ** 2 + (q[1] - path[n - 1, 1]) ** 2
        d2 += (q[2] - path[n - 1, 2]) ** 2
        if d2 >= spacing * spacing and n < path.shape[0]:
            _append(path, npath, q)


@nb.njit(cache=True)
def _seg_dist2(px, py, pz, path, j, n, tip):
    """Squared distance from the point to segment ``j`` of the path (vertex ``n`` is the
    virtual one, the current tip)."""
    ax, ay, az = path[j, 0], path[j, 1], path[j, 2]
    if j + 1 < n:
        bx, by, bz = path[j + 1, 0], path[j + 1, 1], path[j + 1, 2]
    else:
        bx, by, bz = tip[0], tip[1], tip[2]
    ex, ey, ez = bx - ax, by - ay, bz - az
    wx, wy, wz = px - ax, py - ay, pz - az
    ll = ex * ex + ey * ey + ez * ez
    t = 0.0
    if ll > 0.0:
        t = min(1.0, max(0.0, (wx * ex + wy * ey + wz * ez) / ll))
    dx, dy, dz = wx - t * ex, wy - t * ey, wz - t * ez
    return dx * dx + dy * dy + dz * dz


@nb.njit(cache=True)
def path_distance(px, py, pz, s_target, j_start, path, n, tip):
    """Distance (m) from a point to the tip path, searched near arc length ``s_target``
    (or from segment ``j_start`` if >= 0). Returns ``(distance, segment)``."""
    if j_start >= 0:
        j = min(j_start, n - 1)
    else:  # last sample with s <= s_target
        lo, hi = 0, n - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if path[mid, 3] <= s_target:
                lo = mid
            else:
                hi = mid - 1
        j = lo
    d = _seg_dist2(px, py, pz, path, j, n, tip)
    while j > 0:
        dl = _seg_dist2(px, py, pz, path, j - 1, n, tip)
        if dl < d:
            j -= 1
            d = dl
        else:
            break
    while j < n - 1:
        dr = _seg_dist2(px, py, pz, path, j + 1, n, tip)
        if dr < d:
            j += 1
            d = dr
        else:
            break
    return math.sqrt(d), j


@nb.njit(cache=True)
def point_loads(y, pts, bounds, coef, fric, eps, with_friction, cavity, cav, path, npath, dload):
    """Resultant force and moment of point loads, and optionally their velocity Jacobian.

    Parameters
    ----------
    y : (14,) state (see :mod:`pencore.kernels.dynamics`).
    pts : (m, 8) load points (:mod:`pencore.kernels.panels`).
    bounds, coef, fric : layer arrays (:meth:`pencore.inputs.target.Target.kernel_arrays`).
    eps : float
        Half-width (m/s) of the smoothed contact step; 0 for the pure Heaviside.
    with_friction : bool
        Include the friction stresses.
    cavity : bool
        Apply the cavity shank model to points flagged as shank.
    cav : (4,) float
        ``delta_ref`` (m), cavity radius ``R_c`` (m), body axial coordinate ``lc`` of the
        cavity's axis point (m), path spacing (m).
    path, npath : the tip path (module docstring).
    dload : (6, 6) or (0, 0) float
        If (6, 6), the derivatives of the body-frame force and moment (rows) against the
        body-frame velocity and angular velocity (columns) are added to it: a point's
        load is ``-A G(vn) g`` with ``g = (n, p x n)``, ``vn = g . (v, w)`` and the area
        ``A`` a function of the position only, so its derivative is ``-A G'(vn) g g^T``
        (exact for the smoothed step, ``eps > 0``, without friction; the caller checks).

    Returns
    -------
    force_body, moment_body : (3,) N and N m (body frame, moment about the centre of mass)
    clearance : float
        Lowest load point above the free surface (m).
    """
    rot = quat_to_matrix(y[3:7])
    v1, v2, v3 = body_velocity(rot, y)
    w1, w2, w3 = y[10], y[11], y[12]
    f = np.zeros(3)
    mom = np.zeros(3)
    clearance = np.inf
    nlay = bounds.shape[0]
    ncoef = coef.shape[1]
    nt = fric.shape[1]
    delta_ref, r_cav, lc = cav[0], cav[1], cav[2]
    n = npath[0]
    tip = np.zeros(3)
    s_tip = 0.0
    if cavity:
        tip = tip_position(y, lc)
        dx, dy, dz = tip[0] - path[n - 1, 0], tip[1] - path[n - 1, 1], tip[2] - path[n - 1, 2]
        s_tip = path[n - 1, 3] + math.sqrt(dx * dx + dy * dy + dz * dz)
    reg = eps if eps > 0.0 else 1e-9
    crater = has_crater(bounds)
    ref = np.empty((2 + nlay if crater else 0, pts.shape[0]))
    if crater:  # the points' normal-entry reference (pencore.kernels.crater.fill_reference)
        npt = pts.shape[0]
        fill_reference(
            ref, 0, pts[:, 0], np.zeros(npt), pts[:, 3], np.zeros(npt),
            pts[:, 6] / (2.0 * math.pi), bounds, coef, v1, eps,
        )  # fmt: skip
    j_prev = np.int64(-1)
    x1_prev = np.nan
    for i in range(pts.shape[0]):
        px, py, pz = pts[i, 0], pts[i, 1], pts[i, 2]
        height = y[1] + rot[1, 0] * px + rot[1, 1] * py + rot[1, 2] * pz
        if height < clearance:
            clearance = height
        lay = -1
        for k in range(nlay):
            if height <= bounds[k, 0] and height >= bounds[k, 1]:
                lay = k
                break
        if lay < 0:
            continue
        nx, ny, nz = pts[i, 3], pts[i, 4], pts[i, 5]
        ux = v1 + w2 * pz - w3 * py
        uy = v2 + w3 * px - w1 * pz
        uz = v3 + w1 * py - w2 * px
        vn = ux * nx + uy * ny + uz * nz
        if eps > 0.0:
            hw = min(max((vn + eps) / (2.0 * eps), 0.0), 1.0)
        else:
            hw = 1.0 if vn >= 0.0 else 0.0
        if hw == 0.0:
            continue
        area = pts[i, 6] * hw
        if bounds.shape[1] >= 5:
            area *= depth_factor(height, bounds, lay)
            if bounds[lay, 2] > 0.0:  # the crater factor at the point's own depth
                area *= element_factor(height, bounds[lay, 9] - px, v1, bounds, coef, lay, ref, 0)
        if cavity and pts[i, 7] > 0.0:
            qx = y[0] + rot[0, 0] * px + rot[0, 1] * py + rot[0, 2] * pz
            qy = y[1] + rot[1, 0] * px + rot[1, 1] * py + rot[1, 2] * pz
            qz = y[2] + rot[2, 0] * px + rot[2, 1] * py + rot[2, 2] * pz
            start = j_prev if px == x1_prev else -1
            d, j_prev = path_distance(qx, qy, qz, s_tip - (lc - px), start, path, n, tip)
            x1_prev = px
            delta = d - r_cav
            if delta <= 0.0:
                continue
            area *= min(1.0, delta / delta_ref)
        sig = 0.0
        vp = 1.0
        for c in range(ncoef):
            sig += coef[lay, c] * vp
            vp *= vn
        if dload.shape[0] == 6:
            dsig = 0.0
            vp = 1.0
            for c in range(1, ncoef):
                dsig += c * coef[lay, c] * vp
                vp *= vn
            # d(hw sigma)/dvn; hw's slope is 1 / (2 eps) inside the band, 0 outside
            gp = hw * dsig
            if -eps < vn < eps:
                gp += sig / (2.0 * eps)
            g = (nx, ny, nz, py * nz - pz * ny, pz * nx - px * nz, px * ny - py * nx)
            a_pos = area / hw  # the position-dependent area, without the step
            for a in range(6):
                for b in range(6):
                    dload[a, b] -= a_pos * gp * g[a] * g[b]
        fx = -area * sig * nx
        fy = -area * sig * ny
        fz = -area * sig * nz
        if with_friction:
            tx, ty, tz = ux - vn * nx, uy - vn * ny, uz - vn * nz
            vt = math.sqrt(tx * tx + ty * ty + tz * tz)
            mu = friction_coefficient(fric, lay, nt, vt)
            if mu > 0.0:
                sc = -mu * area * sig / math.sqrt(vt * vt + reg * reg)
                fx += sc * tx
                fy += sc * ty
                fz += sc * tz
        f[0] += fx
        f[1] += fy
        f[2] += fz
        mom[0] += py * fz - pz * fy
        mom[1] += pz * fx - px * fz
        mom[2] += px * fy - py * fx
    return f, mom, clearance


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
