"""The driver shared by the integrators: the run record, chunking, budgets, Ctrl-C.

The compiled integrators (:mod:`pencore.integrators.rosenbrock`,
:mod:`pencore.integrators.explicit`) advance a run ``CHUNK_STEPS`` accepted steps per
call; between calls the Python side here holds Ctrl-C while compiled code runs
(:func:`defer_sigint`), tests for stalled steps (:func:`stalled`), and keeps the nose-tip
path buffer of the cavity shank model (:func:`start_path`, :func:`reserve_path`,
:func:`path_of`). :class:`RunResult` is what every integrator returns.
"""

from __future__ import annotations

import contextlib
import signal
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from pencore.inputs.models import SHANK_CAVITY
from pencore.kernels.contact_points import tip_position

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
def defer_sigint() -> Iterator[None]:
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


def stalled(ys: np.ndarray, stall_distance: float) -> bool:
    """True when the states ``ys`` of a chunk moved the centre of mass less than
    ``stall_distance`` (m) and changed its speed by less than 1 %."""
    moved = float(np.linalg.norm(ys[-1, :3] - ys[0, :3]))
    v0, v1 = (float(np.linalg.norm(ys[i, 7:10])) for i in (0, -1))
    return moved < stall_distance and abs(v1 - v0) < 0.01 * v0


def start_path(model: tuple[np.ndarray, ...], y0: np.ndarray) -> tuple[np.ndarray, ...]:
    """``model`` with a fresh tip path holding the tip of ``y0`` (cavity model only)."""
    if model[0][0] != SHANK_CAVITY:
        return model
    path = np.zeros((1024, 4))
    path[0, :3] = tip_position(np.asarray(y0, dtype=float), float(model[1][2]))
    return (model[0], model[1], model[2], path, np.ones(1, dtype=np.int64))


def reserve_path(model: tuple[np.ndarray, ...], free: int) -> tuple[np.ndarray, ...]:
    """``model`` whose path buffer has at least ``free`` unused rows (cavity model only;
    the buffer doubles as it fills, so nothing large is preallocated)."""
    if model[0][0] != SHANK_CAVITY:
        return model
    path, npath = model[3], model[4]
    if path.shape[0] - int(npath[0]) >= free:
        return model
    bigger = np.zeros((max(2 * path.shape[0], int(npath[0]) + free), 4))
    bigger[: int(npath[0])] = path[: int(npath[0])]
    return (model[0], model[1], model[2], bigger, npath)


def path_of(model: tuple[np.ndarray, ...]) -> np.ndarray | None:
    """The used rows of the tip path (cavity model), else None."""
    if model[0][0] != SHANK_CAVITY:
        return None
    return model[3][: int(model[4][0])].copy()
