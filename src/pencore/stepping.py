"""Pieces shared by the integrators (:mod:`pencore.integrate`, :mod:`pencore.explicit`).

Outcome codes, the run record :class:`RunResult`, the stopping test, small compiled
helpers (LU solve, quaternion normalisation), SIGINT deferral, and the numba cache
guard: numba keys a cached function on its own source file only, but the integrators
inline the force kernels of other modules, so every kernel cache is dropped when any
kernel source has changed (:func:`_invalidate_stale_caches`, run on import), wherever
numba keeps them (``__pycache__`` next to the sources, ``NUMBA_CACHE_DIR``, or the
user-wide cache of a read-only install).
"""

from __future__ import annotations

import contextlib
import hashlib
import math
import signal
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numba as nb
import numpy as np

from .bands import band_half_height

#: Modules whose compiled functions inline others' (their caches go stale together).
KERNEL_MODULES = (
    "windows",
    "bands",
    "arcs",
    "friction",
    "wholering",
    "dynamics",
    "jacobian",
    "contact_points",
    "forces",
    "stepping",
    "integrate",
    "explicit",
)


def _kernel_cache_dir(here: Path) -> Path | None:
    """The directory numba caches the kernels of ``here`` in: the first of its cache
    locators that applies (``NUMBA_CACHE_DIR``, then ``__pycache__`` when writable,
    then the user-wide cache), as :class:`numba.core.caching.CacheImpl` chooses."""
    try:
        from numba.core import caching

        impl = getattr(caching, "CacheImpl", None) or caching._CacheImpl
        classes = impl._locator_classes
    except (ImportError, AttributeError):  # another numba layout: the default place
        return here / "__pycache__"
    source = str(here / "dynamics.py")
    for cls in classes:
        try:
            locator = cls.from_function(_kernel_cache_dir, source)
        except Exception:  # a locator that does not apply to a plain source file
            continue
        if locator is not None:
            return Path(locator.get_cache_path())
    return None


def _invalidate_stale_caches() -> None:
    """Drop the numba caches of every kernel module when any kernel source changed."""
    here = Path(__file__).parent
    cache_dir = _kernel_cache_dir(here)
    if cache_dir is None:
        return  # numba will not cache here either
    h = hashlib.sha256()
    for name in KERNEL_MODULES:
        f = here / f"{name}.py"
        if f.exists():
            h.update(f.read_bytes())
    digest = h.hexdigest()
    stamp = cache_dir / "kernels.kernel-hash"
    try:
        if stamp.exists() and stamp.read_text() == digest:
            return
        for name in KERNEL_MODULES[1:]:  # windows inlines nothing from elsewhere
            for f in cache_dir.glob(f"{name}.*.nb[ic]"):
                f.unlink()
        cache_dir.mkdir(exist_ok=True)
        stamp.write_text(digest)
    except OSError:  # read-only install: numba falls back to compiling in memory
        pass


_invalidate_stale_caches()

#: Outcome names, indexed by the integer codes the compiled integrator returns.
OUTCOMES = (
    "stopped",
    "exited",
    "time_limit",
    "reversed",
    "step_limit",
    "step_underflow",
    "non_finite",
    "running",
    "perforated",
)
STEP_LIMIT = 4
STEP_UNDERFLOW = 5
NON_FINITE = 6
RUNNING = 7
#: The whole body is below the rear face of a finite target, moving away from it.
PERFORATED = 8

#: Indices into the float state array ``sf`` of :func:`pencore.integrate.integrate_chunk`.
SF_T, SF_H, SF_T_CONTACT, SF_CLEAR, SF_ERR = 0, 1, 2, 3, 4
#: Indices into the integer state array ``si``.
SI_ENTERED, SI_REV, SI_N_RHS, SI_N_REJ, SI_N_JAC = 0, 1, 2, 3, 4

NY = 14


@nb.njit(cache=True)
def _lu(a, piv):
    n = a.shape[0]
    for k in range(n):
        p = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                p = i
        piv[k] = p
        if p != k:
            for j in range(n):
                tmp = a[k, j]
                a[k, j] = a[p, j]
                a[p, j] = tmp
        akk = a[k, k]
        for i in range(k + 1, n):
            a[i, k] /= akk
            f = a[i, k]
            if f != 0.0:
                for j in range(k + 1, n):
                    a[i, j] -= f * a[k, j]


@nb.njit(cache=True)
def _solve(lu, piv, b):
    n = lu.shape[0]
    x = b.copy()
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = x[k]
            x[k] = x[p]
            x[p] = tmp
    for i in range(n):
        for j in range(i):
            x[i] -= lu[i, j] * x[j]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, n):
            x[i] -= lu[i, j] * x[j]
        x[i] /= lu[i, i]
    return x


@nb.njit(cache=True)
def _normalise(y):
    n = math.sqrt(y[3] ** 2 + y[4] ** 2 + y[5] ** 2 + y[6] ** 2)
    for k in range(3, 7):
        y[k] /= n


@nb.njit(cache=True)
def body_reach(rings):
    """Largest distance (m) from the centre of mass to a ring: the free-flight step bound."""
    reach = 0.0
    for i in range(rings.shape[0]):
        rr = math.sqrt(rings[i, 0] ** 2 + rings[i, 1] ** 2)
        if rr > reach:
            reach = rr
    return reach


@nb.njit(cache=True)
def body_top(y, rings):
    """Height ``y`` (m) of the highest point of the surface bands in state ``y``."""
    n = math.sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    w, x, yq, z = y[3] / n, y[4] / n, y[5] / n, y[6] / n
    r10 = 2 * (x * yq + w * z)
    r11 = w * w - x * x + yq * yq - z * z
    r12 = 2 * (yq * z - w * x)
    rk = math.sqrt(r11 * r11 + r12 * r12)
    top = -np.inf
    for i in range(rings.shape[0]):
        r = rings[i, 1]
        # the top of the band the ring stands for
        hb = band_half_height(r10, rk, r, rings[i, 2], rings[i, 3], rings[i, 4])
        h = y[1] + r10 * rings[i, 0] + rk * r + hb
        if h > top:
            top = h
    return top


@nb.njit(cache=True)
def perforated(y, rings, bounds):
    """True when the target is finite and every surface ring of state ``y`` lies below
    the rear face of its last plate (``bounds[-1, 1]``) while the centre of mass moves
    away from it (``vy < 0``): no element can be loaded again (no gravity-driven return
    is followed). Always False for a semi-infinite target (rear face ``-inf``)."""
    rear = bounds[bounds.shape[0] - 1, 1]
    if not (rear > -np.inf) or y[8] >= 0.0:
        return False
    return body_top(y, rings) < rear


@nb.njit(cache=True)
def speed_of(y):
    """Speed (m/s) of the centre of mass in state ``y``."""
    return math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2)


@nb.njit(cache=True)
def _stop_code(y, t, t_max, entered, clear, v_stop):
    """The outcome code if the run must end at this accepted state, else ``RUNNING``."""
    speed = speed_of(y)
    if entered and speed < v_stop:
        return 0
    if entered and clear > 0.0:
        return 1
    if t >= t_max:
        return 2
    return RUNNING


#: Accepted steps per call of the compiled integrator: a call takes well under a second
#: on any machine (~0.1 ms per step here), so Ctrl-C and the wall budget act within it.
CHUNK_STEPS = 500


@dataclass
class RunResult:
    """What :func:`integrate` returns: the accepted states and how the run ended."""

    ts: np.ndarray
    ys: np.ndarray
    outcome: str
    reversed: bool
    t_first_contact: float
    n_rhs: int
    n_rejected: int
    last_error_norm: float
    #: nose-tip path samples (x, y, z, arc length; m) of the cavity shank model, else None
    path: np.ndarray | None = None
    #: Jacobians built (finite-difference ones also count their calls in ``n_rhs``)
    n_jacobians: int = 0


@contextlib.contextmanager
def _defer_sigint() -> Iterator[None]:
    """Hold SIGINT while compiled code runs, and deliver it on return.

    A Ctrl-C that arrives inside a compiled call is otherwise handled at the first
    Python callback numba makes, where it surfaces as a ``SystemError`` instead of a
    ``KeyboardInterrupt``. Held for one chunk (~0.1 s), it is raised as a clean
    ``KeyboardInterrupt`` between chunks. (Unix; elsewhere a no-op.)
    """
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _stalled(ys: np.ndarray, stall_distance: float) -> bool:
    moved = float(np.linalg.norm(ys[-1, :3] - ys[0, :3]))
    v0, v1 = (float(np.linalg.norm(ys[i, 7:10])) for i in (0, -1))
    return moved < stall_distance and abs(v1 - v0) < 0.01 * v0
