"""Coulomb friction on the loaded arcs of a ring (compiled with numba).

The tangential traction ``-mu(|u_t|) H(Vn) sigma_n u_t / |u_t|`` opposes sliding
(paper Eqs 6-9, with the unit sliding direction: see :mod:`pencore.kernels.dynamics`); ``mu`` is
piecewise linear in the sliding speed, from the table of
:meth:`pencore.inputs.target.Target.kernel_arrays`. It has no closed form over an arc, so
:func:`pencore.kernels.dynamics.contact_loads` integrates it by Gauss-Legendre quadrature on
pieces of at most 45 degrees of each loaded arc. SI units throughout.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from pencore.kernels.cache import use_kernel_cache


@nb.njit(cache=True)
def _leggauss(n):
    """Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n); empty for n <= 0."""
    x = np.empty(max(n, 0))
    w = np.empty(max(n, 0))
    for i in range(n):
        z = math.cos(math.pi * (i + 0.75) / (n + 0.5))
        for _ in range(100):
            p1 = 1.0
            p2 = 0.0
            for j in range(1, n + 1):
                p3 = p2
                p2 = p1
                p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j
            pp = n * (z * p1 - p2) / (z * z - 1.0)
            z1 = z
            z = z1 - p1 / pp
            if abs(z - z1) < 1e-15:
                break
        x[i] = -z
        w[i] = 2.0 / ((1.0 - z * z) * pp * pp)
    return x, w


@nb.njit(cache=True)
def friction_coefficient(fric, lay, nt, vt):
    """Friction coefficient of layer ``lay`` at sliding speed ``vt`` (m/s): the
    piecewise-linear table ``fric[lay, :nt]`` of (speed, mu) rows, constant beyond its
    ends, found by bisection so that a long table costs little."""
    if vt <= fric[lay, 0, 0]:
        return fric[lay, 0, 1]
    if vt >= fric[lay, nt - 1, 0]:
        return fric[lay, nt - 1, 1]
    # bisection for fric[k] <= vt < fric[k + 1] (the speeds increase strictly)
    k, kh = 0, nt - 1
    while kh - k > 1:
        mid = (k + kh) // 2
        if vt < fric[lay, mid, 0]:
            kh = mid
        else:
            k = mid
    t = (vt - fric[lay, k, 0]) / (fric[lay, k + 1, 0] - fric[lay, k, 0])
    return fric[lay, k, 1] + t * (fric[lay, k + 1, 1] - fric[lay, k, 1])


@nb.njit(cache=True)
def _friction_ring(
    f, mom, lo, hi, n, gx, gw, x1, r, na, nr, w, v1, v2, v3, w1, w2, w3, coef, lay, fric, eps,
    alpha=1.0, beta=0.0, cy=1.0, sy=0.0,
):  # fmt: skip
    """Add the friction force and moment (body frame, N and N m) of ring ``(x1, r, na,
    nr)``, weight ``w`` (m), over the loaded arcs ``lo[:n], hi[:n]`` (rad) of layer
    ``lay`` to ``f`` and ``mom``; ``gx, gw`` from :func:`_leggauss`, the body velocities
    ``v, w`` in m/s and rad/s, the band ramp ``chi = alpha - beta cos(phi - phiy)``
    given by ``alpha, beta, cy, sy``."""
    ncoef = coef.shape[1]
    nt = fric.shape[1]
    reg = eps if eps > 0.0 else 1e-9
    for m in range(n):
        length = hi[m] - lo[m]
        npieces = int(math.ceil(length / (0.25 * math.pi)))
        h = length / npieces
        for p in range(npieces):
            a = lo[m] + p * h
            for g in range(gx.shape[0]):
                phi = a + 0.5 * h * (gx[g] + 1.0)
                dphi = 0.5 * h * gw[g]
                c = math.cos(phi)
                s = math.sin(phi)
                # point, normal, velocity (body frame)
                px, py, pz = x1, r * c, r * s
                nx, ny, nz = na, nr * c, nr * s
                ux = v1 + w2 * pz - w3 * py
                uy = v2 + w3 * px - w1 * pz
                uz = v3 + w1 * py - w2 * px
                vn = ux * nx + uy * ny + uz * nz
                if eps > 0.0:
                    hw = min(max((vn + eps) / (2.0 * eps), 0.0), 1.0)
                else:
                    hw = 1.0 if vn >= 0.0 else 0.0
                if beta != 0.0 or alpha != 1.0:
                    hw *= alpha - beta * (cy * c + sy * s)
                if hw == 0.0:
                    continue
                sig = 0.0
                vp = 1.0
                for k in range(ncoef):
                    sig += coef[lay, k] * vp
                    vp *= vn
                tx = ux - vn * nx
                ty = uy - vn * ny
                tz = uz - vn * nz
                vt = math.sqrt(tx * tx + ty * ty + tz * tz)
                mu = friction_coefficient(fric, lay, nt, vt)
                scale = -mu * hw * sig * w * dphi / math.sqrt(vt * vt + reg * reg)
                fx, fy, fz = scale * tx, scale * ty, scale * tz
                f[0] += fx
                f[1] += fy
                f[2] += fz
                mom[0] += py * fz - pz * fy
                mom[1] += pz * fx - px * fz
                mom[2] += px * fy - py * fx


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
