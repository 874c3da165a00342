"""Depth windows of the contact stress (compiled): the free-surface ramps.

The forms and their sources are in :mod:`pencore.inputs.target`; the lengths come in the extra
columns of the layer array of :meth:`pencore.inputs.target.Target.kernel_arrays`, which exist
only when a window is on (so the paper's runs never evaluate this). The crater region is not a
window on each element's depth but a factor on a layer's loads
(:mod:`pencore.kernels.crater`).
"""

from __future__ import annotations

import numba as nb

__all__ = ["depth_factor"]


@nb.njit(cache=True)
def depth_factor(height, bounds, lay):
    """Load factor in [0, 1] of an element at ``height`` (m) in layer ``lay``.

    1 unless ``bounds`` has the window columns of
    :meth:`pencore.inputs.target.Target.kernel_arrays`: then the product of the free-surface
    ramps ``min(1, distance to a free face / f)`` (length ``f`` in m; 0 is off). See
    :mod:`pencore.inputs.target`.
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
    return g
