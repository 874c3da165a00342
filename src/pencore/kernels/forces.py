"""The right-hand side with a selectable shank model and surface (compiled).

:func:`rhs_model` is :func:`pencore.kernels.dynamics.rhs` with one more argument, ``model``, a
tuple of arrays that selects the shank contact model and the surface
(:mod:`pencore.inputs.models`)::

    model = (ipar, cav, pts, path, npath)
    ipar  : (4,) int64   shank model code, surface code, unused, unused
    cav   : (4,) float   delta_ref (m), cavity radius (m), axial coordinate of the point whose
                         path is the cavity axis (m; the tip: lc), path spacing (m)
    pts   : (m, 8) float load points (pencore.kernels.panels): all panels, or the shank ring points
    path  : (k, 4) float nose-tip path samples (x, y, z, arc length; m)
    npath : (1,) int64   rows of ``path`` in use

With the default model (DAFL on rings) it evaluates exactly the operations of
:func:`pencore.kernels.dynamics.rhs`, so default runs are unchanged to the last bit. The
``"factor"`` model needs no code here: the shank rings' (or panels') area weights are
scaled when the arrays are built (:func:`kernel_model`).
"""

from __future__ import annotations

import numba as nb
import numpy as np

from pencore.inputs.geometry import Projectile, Rings
from pencore.inputs.models import SHANK_CAVITY, SURFACE_PANELS, Emulation, ShankModel
from pencore.kernels.cache import use_kernel_cache
from pencore.kernels.contact_points import point_loads, push_path, tip_position
from pencore.kernels.dynamics import contact_loads, equations_of_motion
from pencore.kernels.panels import N_COLUMNS, panel_points, ring_points

__all__ = ["rhs_model", "model_loads", "loads_along", "kernel_model", "default_model"]


@nb.njit(cache=True)
def model_loads(y, rings, bounds, coef, fric, eps, n_gauss, model):
    """Contact force and moment (body frame) and clearance under ``model``.

    A crater region (:mod:`pencore.kernels.crater`) is a factor on each element's stress,
    applied where the elements are summed (:func:`pencore.kernels.dynamics.contact_loads`,
    :func:`pencore.kernels.contact_points.point_loads`)."""
    ipar, cav, pts, path, npath = model
    cavity = ipar[0] == SHANK_CAVITY
    if ipar[1] == SURFACE_PANELS:
        return point_loads(
            y, pts, bounds, coef, fric, eps, n_gauss > 0, cavity, cav, path, npath,
            np.empty((0, 0)),  # no Jacobian
        )  # fmt: skip
    fb, mb, clear = contact_loads(y, rings, bounds, coef, fric, eps, n_gauss)
    if cavity:
        # ``cavity`` (True here), not the literal: one compiled point_loads serves
        # every call site (a literal bool argument compiles a specialisation of its own)
        f2, m2, c2 = point_loads(
            y, pts, bounds, coef, fric, eps, n_gauss > 0, cavity, cav, path, npath,
            np.empty((0, 0)),  # no Jacobian
        )  # fmt: skip
        for k in range(3):
            fb[k] += f2[k]
            mb[k] += m2[k]
        clear = min(clear, c2)
    return fb, mb, clear


@nb.njit(cache=True, nogil=True)
def rhs_model(y, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model):
    """Time derivative of the state and the clearance, as :func:`pencore.kernels.dynamics.rhs`.

    Releases the GIL when called from Python (scipy's integrator calls it so), so that
    Ctrl-C is taken while it runs (:mod:`pencore.integrators.driver`)."""
    fb, mb, clear = model_loads(y, rings, bounds, coef, fric, eps, n_gauss, model)
    return equations_of_motion(y, fb, mb, mass, inertia, gravity), clear


@nb.njit(cache=True)
def loads_along(ts, ys, rings, bounds, coef, fric, eps, n_gauss, model):
    """Contact force and moment (body frame) at each saved state of a run: the loads of
    :func:`rhs_model` itself, evaluated once per row of ``ys`` (no differencing).

    ``ts`` (k,) and ``ys`` (k, 14) are a run's accepted times (s) and states. With the
    cavity shank model the nose-tip path is rebuilt from the states as the integrator
    built it (:func:`pencore.kernels.contact_points.push_path` after each step, the step
    length taken as ``ts[j] - ts[j - 1]``), so each state sees the path it was integrated
    with; ``model``'s path buffer must then hold ``k * MAX_SAMPLES_PER_STEP + 1`` rows.

    Returns
    -------
    (k, 6) ndarray
        Force (N, body axes 1-3; axis 1 the symmetry axis towards the nose) and moment
        about the centre of mass (N m, body axes).
    """
    n = ys.shape[0]
    out = np.empty((n, 6))
    cavity = model[0][0] == SHANK_CAVITY
    path, npath = model[3], model[4]
    lc, spacing = model[1][2], model[1][3]
    if cavity and n > 0:
        p0 = tip_position(ys[0], lc)
        for c in range(3):
            path[0, c] = p0[c]
        path[0, 3] = 0.0
        npath[0] = 1
    for j in range(n):
        if cavity and j > 0:
            push_path(path, npath, ys[j - 1], ys[j], ts[j] - ts[j - 1], lc, spacing)
        fb, mb, _ = model_loads(ys[j], rings, bounds, coef, fric, eps, n_gauss, model)
        for c in range(3):
            out[j, c] = fb[c]
            out[j, 3 + c] = mb[c]
    return out


def default_model() -> tuple[np.ndarray, ...]:
    """The kernel tuple of the default model (DAFL on rings)."""
    return (
        np.zeros(4, dtype=np.int64),
        np.zeros(4),
        np.zeros((0, N_COLUMNS)),
        np.zeros((1, 4)),
        np.ones(1, dtype=np.int64),
    )


def kernel_model(
    projectile: Projectile,
    rings: Rings,
    shank: ShankModel,
    emulation: Emulation,
    n_nose: int,
    n_shank: int,
    n_face: int,
) -> tuple[np.ndarray, tuple[np.ndarray, ...]]:
    """The ring array for :func:`pencore.kernels.dynamics.contact_loads` and the model tuple.

    Returns
    -------
    kernel_rings : (n, 5) float
        All rings (default and ``"factor"``, with the shank weights scaled by ``f``), the
        rings other than the shank (``"cavity"`` on rings; the shank goes to points), or
        all rings unused by the loads (panels).
    model : tuple
        See the module docstring; the path buffer holds one row, filled by the caller.
    """
    arr = rings.as_array()
    shank_rows = rings.part == 1
    ipar = np.zeros(4, dtype=np.int64)
    ipar[0] = shank.code
    cav = np.zeros(4)
    a = projectile.radius
    cav[0] = shank.delta_ref
    cav[1] = a
    cav[2] = projectile.mass_properties().lc
    if shank.axis == "shoulder":
        cav[2] -= projectile.nose_length
    cav[3] = 0.1 * a  # path samples a tenth of the radius apart
    pts = np.zeros((0, N_COLUMNS))
    if emulation.surface == "panels":
        ipar[1] = SURFACE_PANELS
        n_circ = emulation.n_circumferential
        pts = panel_points(projectile, n_nose, n_shank, n_face, n_circ)
        # the cavity is cut by the faceted nose: its shank load points (panel centroids)
        # sit at a cos(pi / N) from the axis, which is where the wall is
        on_shank = pts[:, 7] > 0.0
        if on_shank.any():
            cav[1] = float(np.hypot(pts[on_shank, 1], pts[on_shank, 2]).mean())
        if shank.kind == "factor":
            pts[on_shank, 6] *= shank.factor
    elif shank.kind == "cavity":
        pts = ring_points(rings, shank.n_phi, 1)
        arr = np.ascontiguousarray(arr[~shank_rows])
    elif shank.kind == "factor":
        arr = arr.copy()
        arr[shank_rows, 4] *= shank.factor
    return arr, (ipar, cav, pts, np.zeros((1, 4)), np.ones(1, dtype=np.int64))


use_kernel_cache(globals())  # pencore's cache for the compiled functions above
