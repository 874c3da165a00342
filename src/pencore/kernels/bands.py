"""What the band a surface ring stands for spans (compiled).

Each ring of :mod:`pencore.inputs.geometry` (weight ``w = r dl``) stands for the band of meridian
length ``dl`` around it. Two properties of that band enter the contact loads
(:func:`pencore.kernels.dynamics.contact_loads`) and their Jacobian
(:mod:`pencore.kernels.jacobian`):
the half of the height range it spans across its width (:func:`band_half_height`: the
width of its immersion ramp), and, on a cylindrical band, the spread of its normal
velocity along it under lateral spin (:func:`band_eps`: the width of its contact step).
"""

from __future__ import annotations

import math

import numba as nb

from pencore.kernels.cache import use_kernel_cache

__all__ = ["band_half_height", "band_eps"]


@nb.njit(cache=True)
def band_half_height(r10, rk, r, na, nr, w):
    """Half the height range (m) spanned across its width by the band a ring stands for.

    A ring of weight ``w = r dl`` stands for the band of meridian length ``dl`` around it;
    a point at meridian offset ``s`` from the ring is ``s (r10 nr - na rk cos(phi -
    phiy))`` higher than the ring point at the same angle (``r10``: axial, ``rk``:
    radial rate of height). The largest magnitude over the ring,
    ``dl/2 (|r10 nr| + |na| rk)``, is the half-height of the band's immersion ramp
    (:func:`pencore.kernels.dynamics.contact_loads`); 0 for a band lying in a horizontal plane."""
    if r <= 0.0:
        return 0.0
    return 0.5 * (w / r) * (abs(r10 * nr) + abs(na) * rk)


@nb.njit(cache=True, inline="always")
def band_eps(eps, r, na, w, w2, w3):
    """Half-width (m/s) of the smoothed contact step on a ring's band, and its rate.

    On a cylindrical band (``na = 0``: the shank) the normal velocity has no axial
    term, and across the band's length ``dl = w / r`` it varies at a given angle by up
    to ``+-s``, ``s = dl/2 sqrt(w2^2 + w3^2)`` (the lateral velocity ``(v2 + w3 x1, v3
    - w2 x1)`` is affine in ``x1``). The step integrated over the band is the ring's
    step box-filtered over that spread; it is replaced by one linear step of the same
    variance, half-width ``sqrt(eps^2 + s^2)``. Without it the load of each shank
    ring flips sides at once (``2 a0 r dl``, the a0 term) as the point of zero lateral
    velocity sweeps over the ring, one jump per ring, each of which the step control
    resolves. The widening vanishes with the ring spacing, so the converged loads are
    unchanged. Other rings, and the sharp law (``eps = 0``), keep ``eps``.

    Returns
    -------
    epsr : float
        The band's half-width (m/s).
    rate : float
        ``d epsr / d w2 = rate * w2`` and likewise for ``w3`` (m^2/s; 0 when unchanged).
    """
    if na != 0.0 or eps <= 0.0 or r <= 0.0:
        return eps, 0.0
    c = 0.5 * w / r
    c2 = c * c
    s2 = c2 * (w2 * w2 + w3 * w3)
    if s2 == 0.0:
        return eps, 0.0  # exactly eps (and a zero gradient) without lateral spin
    epsr = math.sqrt(eps * eps + s2)
    return epsr, c2 / epsr


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
