"""Atomic, durable file writes: a file is either complete on disk or not there at all.

:func:`atomic_path` hands out a temporary path next to the destination; when the
``with`` block succeeds the temporary file is flushed to the disk (``fsync``), renamed
onto the destination (``os.replace``, atomic on POSIX file systems), and the directory
entry is flushed too. When the block fails, for whatever reason (disk full, quota or
file-size limit, permission, the netCDF library's own ``RuntimeError``, Ctrl-C, SIGTERM),
the temporary file is removed and the failure is raised as one :class:`~pencore.WriteError` whose
message names the path and the cause in words.

Only what the output gate allows is replaced (:func:`pencore.io.outputs.check_destination`:
a regular file, or nothing, that is writable, has a suffix the writer knows and is none of
the call's inputs); anything else is refused with a :class:`~pencore.WriteError` before
anything is written. A finished write is recorded in the open call
(:func:`pencore.io.outputs.note_written`), so that an interrupted command can say what
is on disk.

Temporary files are named ``.<name>.pencore-tmp-<pid>-<random>`` (``<name>`` cut to
:data:`TEMP_NAME_CHARS` characters, so that a long file name still leaves room). A run killed with
SIGKILL cannot remove its own; the next write to the same destination removes every such
file whose process no longer exists (a temporary file of a live process, e.g. a parallel
job, is left alone).
"""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
import signal
import threading
from collections.abc import Iterable, Iterator
from pathlib import Path

from pencore.errors import WriteError, hint_keywords
from pencore.io.outputs import (
    check_destination,
    check_replaceable,
    describe_os_error,
    file_kind,
    note_written,
)

__all__ = [
    "atomic_path",
    "atomic_write_text",
    "check_replaceable",
    "describe_os_error",
    "file_kind",
    "TEMP_MARK",
    "TEMP_NAME_CHARS",
]

TEMP_MARK = ".pencore-tmp-"
#: Characters of the destination's name kept in its temporary file's name (a name of up
#: to 255 bytes, the usual file-system limit, then still has a temporary file).
TEMP_NAME_CHARS = 100


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, owned by someone else
        return True
    return True


def _clean_stale_temps(path: Path) -> None:
    """Remove temporary files of ``path`` left by processes that no longer exist."""
    prefix = _temp_prefix(path)
    try:
        candidates = list(path.parent.glob(f"{prefix}*"))
    except OSError:
        return
    for tmp in candidates:
        pid_text = tmp.name[len(prefix) :].split("-", 1)[0]
        if pid_text.isdigit() and int(pid_text) != os.getpid() and not _pid_alive(int(pid_text)):
            with contextlib.suppress(OSError):
                tmp.unlink()


def _temp_prefix(path: Path) -> str:
    return f".{path.name[:TEMP_NAME_CHARS]}{TEMP_MARK}"


def _fsync_dir(directory: Path) -> None:
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:  # platforms without directory handles
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


class _Terminated(BaseException):
    """SIGTERM arrived during a write (raised by the temporary handler)."""


@contextlib.contextmanager
def _sigterm_raises() -> Iterator[None]:
    """While writing, turn SIGTERM into an exception so the temporary file is removed;
    the previous handler is restored (and re-delivered the signal) afterwards."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: object) -> None:
        raise _Terminated()

    previous = signal.signal(signal.SIGTERM, handler)
    try:
        yield
    except _Terminated:
        signal.signal(signal.SIGTERM, previous)
        if callable(previous):
            previous(signal.SIGTERM, None)
        raise SystemExit(128 + signal.SIGTERM) from None
    finally:
        signal.signal(signal.SIGTERM, previous)


@contextlib.contextmanager
def atomic_path(
    path: str | os.PathLike[str],
    mode: int = 0o666,
    protect: Iterable[str | os.PathLike[str]] = (),
    suffixes: Iterable[str] | None = None,
) -> Iterator[Path]:
    """Write ``path`` atomically: yield a temporary path to write to (see the module).

    Parameters
    ----------
    path : path-like
        Destination. Its directory must exist.
    mode : int
        Permission bits of the finished file, before the umask.
    protect : iterable of path-like
        Files ``path`` must not be (the run's own inputs), see
        :func:`~pencore.io.outputs.check_replaceable`.
    suffixes : iterable of str, optional
        The suffixes the writer knows (e.g. ``(".nc",)``); None: any.

    Raises
    ------
    WriteError
        A destination that is not a regular file or is protected (before anything is
        written, see :func:`~pencore.io.outputs.check_replaceable`); any failure to write, with the
        temporary file removed. ``KeyboardInterrupt``
        and ``SystemExit`` (SIGTERM) pass through, also after the clean-up.
    """
    protect = tuple(protect)
    path = check_destination(path, suffixes, protect)
    _clean_stale_temps(path)
    tmp = path.parent / f"{_temp_prefix(path)}{os.getpid()}-{secrets.token_hex(4)}"
    try:
        with _sigterm_raises():
            try:
                yield tmp
                with open(tmp, "rb+") as f:
                    os.fsync(f.fileno())
                os.chmod(tmp, mode & ~_umask())
                check_replaceable(path, protect)  # it may have changed while writing
                os.replace(tmp, path)
                note_written(path)
            except BaseException:
                with contextlib.suppress(OSError):
                    tmp.unlink()
                raise
        _fsync_dir(path.parent)
    except (KeyboardInterrupt, SystemExit, GeneratorExit):
        raise
    except WriteError:
        raise
    except Exception as exc:
        cause = describe_os_error(exc)
        if not isinstance(exc, OSError):
            # the netCDF/HDF5 library reports ENOSPC and EFBIG as its own RuntimeError
            if _nearly_full(path.parent):
                cause = f"disk full ({cause})"
            elif _size_limited():
                cause = f"file too large for the file-size limit, ulimit -f ({cause})"
        raise WriteError(
            f"cannot write {str(path)!r}: {cause}", getattr(exc, "errno", None)
        ) from None


def _size_limited() -> bool:
    try:
        import resource
    except ImportError:  # not POSIX
        return False
    return resource.getrlimit(resource.RLIMIT_FSIZE)[0] != resource.RLIM_INFINITY


def _nearly_full(directory: Path) -> bool:
    try:
        return shutil.disk_usage(directory).free < (1 << 20)
    except OSError:
        return False


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def atomic_write_text(
    path: str | os.PathLike[str],
    text: str,
    suffixes: Iterable[str] | None = None,
    protect: Iterable[str | os.PathLike[str]] = (),
) -> Path:
    """Write ``text`` (UTF-8) to ``path`` through :func:`atomic_path`; returns the path."""
    with atomic_path(path, protect=protect, suffixes=suffixes) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    return Path(path)


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
