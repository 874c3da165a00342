"""Depth windows of the contact stress (compiled): the free-surface ramps.

The forms and their sources are in :mod:`pencore.inputs.target`; the lengths come in the extra
columns of the layer array of :meth:`pencore.inputs.target.Target.kernel_arrays`, which exist
only when a window is on (so the paper's runs never evaluate this). The crater region is a
factor on each element's stress too, but of the element's depth and its distance from the
nose tip together (:mod:`pencore.kernels.crater`).
"""

from __future__ import annotations

import math

import numba as nb

from pencore.kernels.cache import use_kernel_cache

__all__ = ["depth_factor", "finite_sphere_factor"]


@nb.njit(cache=True)
def finite_sphere_factor(distance, radius, ratio):
    """Quasi-static cavity pressure in a finite sphere over that in an infinite medium.

    Hill, *The Mathematical Theory of Plasticity* (1950), ch. V: a spherical cavity of
    radius ``a`` in an elastic-perfectly-plastic sphere of outer radius ``b`` with a free
    outer surface, plastic out to ``c``, needs ``p = 2 Y ln(c/a) + (2 Y / 3)(1 - c^3/b^3)``
    (``c < b``), and ``p = 2 Y ln(b/a)`` once the plastic zone reaches the free surface
    (``c >= b``); the infinite medium, ``p = (2 Y / 3)(1 + 3 ln(c/a))``. With the element
    at the cavity wall and the free face ``distance`` (m) away, ``b = a + distance``::

        F = (3 ln(min(c, b)/a) + 1 - min(c, b)^3 / b^3) / (1 + 3 ln(c/a))

    ``radius`` is ``a`` (m), ``ratio`` is ``c/a`` (> 1; the infinite medium's, e.g.
    ``(E / (3 (1 - nu) Y))^(1/3)``). ``F`` is 0 at the face, rises monotonically and
    tends to 1 as ``(c/b)^3`` far from it. (Hill's formulas were written from the
    textbook solution, not re-read from the book for this work; their two limits, the
    infinite medium and the fully plastic shell, agree at ``b = c``, which the tests check.)
    """
    b = radius + max(distance, 0.0)
    c = ratio * radius
    m = min(c, b)
    num = 3.0 * math.log(m / radius) + 1.0 - (m / b) ** 3
    return max(0.0, num / (1.0 + 3.0 * math.log(ratio)))


@nb.njit(cache=True)
def depth_factor(height, bounds, lay):
    """Load factor in [0, 1] of an element at ``height`` (m) in layer ``lay``.

    1 unless ``bounds`` has the window columns of
    :meth:`pencore.inputs.target.Target.kernel_arrays`: then the product, over the free
    faces of the layer, of pencore's ramps ``min(1, distance to the face / f)`` (length
    ``f`` in m; 0 is off) and of the finite-sphere factors
    (:func:`finite_sphere_factor`; ratio 0 is off). See :mod:`pencore.inputs.target`.
    """
    if bounds.shape[1] < 5:
        return 1.0
    g = 1.0
    top = bounds[lay, 0]
    ztop = bounds[lay, 3]
    if ztop > 0.0:
        g *= min(1.0, max(top - height, 0.0) / ztop)
    zbot = bounds[lay, 4]
    if zbot > 0.0:
        g *= min(1.0, max(height - bounds[lay, 1], 0.0) / zbot)
    if bounds.shape[1] < 9:
        return g  # the ramp columns only (older layer arrays, tests)
    rtop = bounds[lay, 6]
    if rtop > 0.0:
        g *= finite_sphere_factor(top - height, bounds[lay, 8], rtop)
    rbot = bounds[lay, 7]
    if rbot > 0.0:
        g *= finite_sphere_factor(height - bounds[lay, 1], bounds[lay, 8], rbot)
    return g


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
