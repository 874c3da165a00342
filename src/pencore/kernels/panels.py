"""Point-load surfaces: flat panels of a faceted body, and points around shank rings.

Both are arrays of *load points* for :func:`pencore.kernels.contact_points.point_loads`, one row
per point, body frame (origin at the centre of mass, axis 1 towards the nose)::

    0:3  position (m)   3:6  unit outward normal   6  area (m^2)   7  1 on the shank else 0

:func:`panel_points` is the faceted surface an explicit finite-element code sees (paper
Sect. 3: a discrete rigid body with a VDLOAD pressure): the meridian polyline through
the band edges of :meth:`pencore.inputs.geometry.Projectile.rings` (see
:meth:`~pencore.inputs.geometry.Projectile.profile`), turned into ``n_circ`` sectors, gives flat
panels with their nodes on the true surface: isosceles trapezoids, triangles at the tip
and the face centres. Each carries one point load at its area centroid, with its facet
normal and area, as one VDLOAD integration point per element would.

:func:`ring_points` puts ``n_phi`` midpoint-rule points around each shank ring of the
closed-form ring surface, for the shank models whose stress is not affine in
``cos(phi)``, ``sin(phi)`` around the ring (:class:`pencore.inputs.models.ShankModel` cavity).
"""

from __future__ import annotations

import numpy as np

from pencore.inputs.geometry import Projectile, Rings

__all__ = ["panel_points", "ring_points", "N_COLUMNS"]

N_COLUMNS = 8


def panel_points(
    projectile: Projectile, n_nose: int, n_shank: int, n_face: int, n_circ: int
) -> np.ndarray:
    """The faceted surface as load points (see the module docstring).

    Parameters
    ----------
    projectile : Projectile
        The body.
    n_nose, n_shank, n_face : int
        Bands along the meridian, as :meth:`pencore.inputs.geometry.Projectile.rings`.
    n_circ : int
        Sectors around the axis; the first node line is at ``phi = 0`` (the plane of body
        axes 1-2, the plane of motion of an in-plane impact), so the facets are symmetric
        about it and, for even ``n_circ``, about the plane across it.

    Returns
    -------
    (n_bands * n_circ - degenerate, 8) float array, band by band from the tip.
    """
    s, r, part = projectile.profile(n_nose, n_shank, n_face)
    lc = projectile.mass_properties().lc
    x1 = lc - s
    phi = 2.0 * np.pi * np.arange(n_circ + 1) / n_circ
    c, sn = np.cos(phi), np.sin(phi)
    c[-1], sn[-1] = c[0], sn[0]
    rows = []
    for k in range(s.size - 1):
        # vertices A (band start, phi_j), B (band start, phi_j+1), C (end, j+1), D (end, j)
        a = np.stack([np.full(n_circ, x1[k]), r[k] * c[:-1], r[k] * sn[:-1]], 1)
        b = np.stack([np.full(n_circ, x1[k]), r[k] * c[1:], r[k] * sn[1:]], 1)
        cc = np.stack([np.full(n_circ, x1[k + 1]), r[k + 1] * c[1:], r[k + 1] * sn[1:]], 1)
        d = np.stack([np.full(n_circ, x1[k + 1]), r[k + 1] * c[:-1], r[k + 1] * sn[:-1]], 1)
        # two triangles ABC, ACD; a degenerate one has zero area and drops out
        t1 = 0.5 * np.cross(b - a, cc - a)
        t2 = 0.5 * np.cross(cc - a, d - a)
        a1 = np.linalg.norm(t1, axis=1)
        a2 = np.linalg.norm(t2, axis=1)
        area = a1 + a2
        keep = area > 0.0
        if not keep.any():
            continue
        cen = (a1[:, None] * (a + b + cc) + a2[:, None] * (a + cc + d)) / (3.0 * area[:, None])
        normal = (t1 + t2) / area[:, None]
        # outward: the meridian normal of the band, (dr, -dx1), turned to the mid-angle
        mid = 0.5 * (phi[:-1] + phi[1:])
        dx1, dr = x1[k + 1] - x1[k], r[k + 1] - r[k]
        ref = np.stack([np.full(n_circ, dr), -dx1 * np.cos(mid), -dx1 * np.sin(mid)], 1)
        flip = np.einsum("ij,ij->i", normal, ref) < 0.0
        normal[flip] *= -1.0
        normal /= np.linalg.norm(normal, axis=1)[:, None]
        block = np.empty((n_circ, N_COLUMNS))
        block[:, 0:3] = cen
        block[:, 3:6] = normal
        block[:, 6] = area
        block[:, 7] = 1.0 if part[k] == 1 else 0.0
        rows.append(block[keep])
    return np.ascontiguousarray(np.concatenate(rows))


def ring_points(rings: Rings, n_phi: int, which: int = 1) -> np.ndarray:
    """Midpoint-rule points around the rings of part ``which`` (1: shank).

    Point ``m`` of a ring sits at ``phi = 2 pi (m + 1/2) / n_phi`` with the ring's normal
    there and area ``w 2 pi / n_phi`` (``w = r dl``), so the points of a ring carry its
    whole area ``2 pi r dl``.

    Returns
    -------
    (n_rings_of_part * n_phi, 8) float array, ring by ring.
    """
    sel = np.flatnonzero(rings.part == which)
    phi = 2.0 * np.pi * (np.arange(n_phi) + 0.5) / n_phi
    c, s = np.cos(phi), np.sin(phi)
    out = np.empty((sel.size * n_phi, N_COLUMNS))
    for i, k in enumerate(sel):
        blk = out[i * n_phi : (i + 1) * n_phi]
        blk[:, 0] = rings.x1[k]
        blk[:, 1] = rings.r[k] * c
        blk[:, 2] = rings.r[k] * s
        blk[:, 3] = rings.na[k]
        blk[:, 4] = rings.nr[k] * c
        blk[:, 5] = rings.nr[k] * s
        blk[:, 6] = rings.w[k] * 2.0 * np.pi / n_phi
        blk[:, 7] = 1.0 if which == 1 else 0.0
    return out
