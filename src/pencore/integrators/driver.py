"""The driver shared by the integrators: the run record, chunking, budgets, Ctrl-C.

The compiled integrators (:mod:`pencore.integrators.rosenbrock`,
:mod:`pencore.integrators.explicit`) advance a run ``CHUNK_STEPS`` accepted steps per
call; the Python side here bounds the run and handles Ctrl-C (:class:`RunGuard`), tests
for stalled steps (:func:`stalled`, unless the body is backing out of the target within
its budget, :func:`leaving`), and keeps the nose-tip path buffer of the cavity
shank model (:func:`start_path`, :func:`reserve_path`, :func:`path_of`).
:class:`RunResult` is what every integrator returns.

Ctrl-C and the wall budget act on a time basis, not between chunks. From the first run
on, SIGINT has a handler (``_on_sigint``) that during a run (:class:`RunGuard`, in
the main thread) only records it (a ``KeyboardInterrupt`` raised while numba code runs
surfaces as a ``SystemError`` instead) and outside runs raises ``KeyboardInterrupt`` as
Python's own does; during a run its arrival is also written to a pipe
(:func:`signal.set_wakeup_fd`) that a watcher thread (``_watch``, one per process)
waits on; the compiled calls release the GIL (``nogil``), so the watcher raises the
run's stop flag at once, and the compiled integrators read that flag before every step
(and every retried step). The watcher also raises the flag when the run's wall budget
is used up (looked at every :data:`WATCH_INTERVAL` s). So

* from the API, Ctrl-C raises ``KeyboardInterrupt`` after the step in progress (a step
  of the default numerics takes ~10 us; with 2000 bands, 64 Gauss points and a
  10 000-row friction table, ~0.4 s), and the wall budget ends the run as
  ``wall_limit`` likewise;
* on the command line (:func:`exit_on_interrupt`), the watcher ends the process at once
  with exit status 130 and one line on stderr, whatever the numerics: nothing is being
  written while a run is integrated (output files are written after the run).

A run outside the main thread (where Python allows no signal handler), or in a process
that ignores SIGINT or has its own handler for it, keeps the process's own SIGINT
handling; its wall budget is still watched on a time basis.
"""

from __future__ import annotations

import contextlib
import math
import os
import select
import signal
import threading
import time
from dataclasses import dataclass

import numpy as np

from pencore.inputs.models import SHANK_CAVITY
from pencore.kernels.contact_points import tip_position

#: Accepted steps per call of the compiled integrator; Ctrl-C and the wall budget do not
#: wait for a call to end (see the module notes), so this only sets how often results
#: are collected and the stall test is made.
CHUNK_STEPS = 500

#: Seconds between the watcher's looks at the wall budgets of running runs (Ctrl-C is
#: taken at once, not at this interval).
WATCH_INTERVAL = 0.05

#: Values of the stop flag the compiled integrators read (``stop[0]``).
STOP_NONE, STOP_INTERRUPT, STOP_WALL = 0, 1, 2


@dataclass
class RunResult:
    """What :func:`~pencore.integrators.rosenbrock.integrate` returns: the accepted states and how
    the run ended."""

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
    #: the right-hand side at each saved state as the Rosenbrock integrator evaluated it
    #: (rows as ``ys``; :func:`pencore.run.loads.body_loads` reads the loads from it), else None
    fs: np.ndarray | None = None


class RunGuard:
    """The stop flag and wall budget of one run, watched on a time basis.

    Use as a context manager around a whole run; the compiled integrators take
    ``stop`` and end their chunk before the next step when ``stop[0]`` is not 0.
    After each compiled call, :meth:`check_interrupt` raises ``KeyboardInterrupt`` if
    Ctrl-C came; leaving the guard does too, for a Ctrl-C that came after the last call.

    Parameters
    ----------
    max_wall : float
        Wall-time budget of the run (s); ``inf`` for none.
    """

    def __init__(self, max_wall: float) -> None:
        self.stop = np.zeros(1, dtype=np.int64)
        self.deadline = time.monotonic() + max_wall if math.isfinite(max_wall) else math.inf
        self._saved: int | None = None

    def __enter__(self) -> RunGuard:
        with _LOCK:
            _ACTIVE.add(self)
        if threading.current_thread() is threading.main_thread() and _start_watcher():
            current = signal.getsignal(signal.SIGINT)
            if current is signal.default_int_handler:
                # once per process: the same as Python's own handler outside a run
                signal.signal(signal.SIGINT, _on_sigint)
                current = _on_sigint
            # a process that ignores SIGINT or handles it its own way keeps doing so
            if current is _on_sigint:
                try:
                    fd = signal.set_wakeup_fd(_PIPE[1], warn_on_full_buffer=False)
                except (ValueError, OSError):  # pragma: no cover - not the main thread
                    pass
                else:
                    self._saved = fd
                    _PIPE[2] = fd
        return self

    def __exit__(self, kind: object, exc: object, tb: object) -> None:
        with _LOCK:
            _ACTIVE.discard(self)
        if self._saved is not None:
            signal.set_wakeup_fd(self._saved)
            _PIPE[2] = -1
        if kind is None:
            self.check_interrupt()

    def check_interrupt(self) -> None:
        """Raise ``KeyboardInterrupt`` when Ctrl-C came during this run."""
        if self.stop[0] == STOP_INTERRUPT:
            raise KeyboardInterrupt

    @property
    def out_of_time(self) -> bool:
        """Whether the wall budget is used up."""
        return self.stop[0] == STOP_WALL or time.monotonic() > self.deadline


#: Reentrant: the SIGINT handler takes it in the main thread, which may hold it already.
_LOCK = threading.RLock()
_ACTIVE: set[RunGuard] = set()
#: The watcher's pipe (read end, write end) and the wakeup fd it replaced (-1: none).
_PIPE: list[int] = []
#: The line the watcher prints before ending the process on Ctrl-C (command line only).
_EXIT_LINE: list[str] = []


def _on_sigint(signum: int, frame: object) -> None:
    """pencore's SIGINT handler (installed in place of Python's own on the first run):
    during a run, raise the stop flags (an exception raised while compiled code may be
    on the stack would surface as numba's ``SystemError``); otherwise what Python's
    handler does, ``KeyboardInterrupt``."""
    with _LOCK:
        guards = list(_ACTIVE)
    if not guards:
        raise KeyboardInterrupt
    for guard in guards:
        guard.stop[0] = STOP_INTERRUPT


def exit_on_interrupt(line: str | None, status: int = 130) -> None:
    """Make Ctrl-C during a run end the process at once (for the command line).

    The watcher thread writes ``line`` and a newline to stderr and ends the process with
    ``status`` (``os._exit``, without unwinding: call this only where nothing is
    being written while a run is integrated). A Ctrl-C outside a run is an ordinary
    ``KeyboardInterrupt``. ``line=None`` restores the default (``KeyboardInterrupt``
    after the step in progress).
    """
    _EXIT_LINE[:] = [] if line is None else [f"{line}\n", str(int(status))]


def _start_watcher() -> bool:
    """Start the watcher thread once per process; False where it cannot run (no
    :func:`signal.set_wakeup_fd` on pipes, e.g. Windows: Ctrl-C then waits for the
    compiled call to return, and the wall budget is looked at between calls)."""
    if _PIPE:
        return True
    if os.name != "posix":
        return False
    with _LOCK:
        if not _PIPE:
            rfd, wfd = os.pipe()
            os.set_blocking(wfd, False)
            _PIPE[:] = [rfd, wfd, -1]
            threading.Thread(target=_watch, name="pencore-watcher", daemon=True).start()
    return True


def _watch() -> None:
    """Take SIGINTs from the wakeup pipe and raise the stop flags (or end the process,
    see :func:`exit_on_interrupt`); raise the flag of runs past their wall budget."""
    rfd = _PIPE[0]
    while True:
        with _LOCK:
            busy = bool(_ACTIVE)
        ready, _, _ = select.select([rfd], [], [], WATCH_INTERVAL if busy else 1.0)
        with _LOCK:
            guards = list(_ACTIVE)
        if ready:
            data = os.read(rfd, 512)
            forward = _PIPE[2]
            if forward >= 0:  # the wakeup fd the run replaced (an event loop's) hears too
                with contextlib.suppress(OSError):
                    os.write(forward, data)
            if signal.SIGINT in data and guards:
                if _EXIT_LINE:
                    os.write(2, _EXIT_LINE[0].encode())
                    os._exit(int(_EXIT_LINE[1]))
                for guard in guards:
                    guard.stop[0] = STOP_INTERRUPT
        now = time.monotonic()
        for guard in guards:
            if guard.stop[0] == STOP_NONE and now > guard.deadline:
                guard.stop[0] = STOP_WALL


def stalled(ys: np.ndarray, stall_distance: float) -> bool:
    """True when the states ``ys`` of a chunk moved the centre of mass less than
    ``stall_distance`` (m) and changed its speed by less than 1 %."""
    moved = float(np.linalg.norm(ys[-1, :3] - ys[0, :3]))
    v0, v1 = (float(np.linalg.norm(ys[i, 7:10])) for i in (0, -1))
    return moved < stall_distance and abs(v1 - v0) < 0.01 * v0


def leaving(ys: np.ndarray, depth: float, steps_left: int) -> bool:
    """True when the states ``ys`` of a chunk back the body out of the target at a pace
    that takes it out within ``steps_left`` accepted steps: the centre of mass rose over
    the chunk, and at that rise per chunk the deepest point, ``depth`` (m) below the top
    face at the chunk's end, reaches the face within the budget.

    A body sliding back out of its hole (a frictionless shank has no axial resistance)
    keeps its speed while the lateral contact creeps in the smoothed step, whose
    stiffness holds the steps to ~1e-7 s: 500 of them move it less than 1 % of its
    length (:func:`stalled`), yet it leaves the target in a few thousand steps. Such a
    chunk is progress, not chatter."""
    rise = float(ys[-1, 1] - ys[0, 1])
    if not (rise > 0.0 and ys[-1, 8] > 0.0):
        return False
    return max(depth, 0.0) / rise * ys.shape[0] <= steps_left


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
