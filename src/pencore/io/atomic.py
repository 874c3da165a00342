"""Atomic, durable file writes: a file is either complete on disk or not there at all.

:func:`atomic_path` hands out a temporary path next to the destination; when the
``with`` block succeeds the temporary file is flushed to the disk (``fsync``), renamed
onto the destination (``os.replace``, atomic on POSIX file systems), and the directory
entry is flushed too. When the block fails, for whatever reason (disk full, quota or
file-size limit, permission, the netCDF library's own ``RuntimeError``, Ctrl-C, SIGTERM),
the temporary file is removed and the failure is raised as one :class:`~pencore.WriteError` whose
message names the path and the cause in words.

Only a regular file (or nothing) is replaced: a destination that is a directory, a
device, a FIFO or a socket, or that is one of the run's own inputs (``protect``), is
refused with a :class:`~pencore.WriteError` before anything is written.

Temporary files are named ``.<name>.pencore-tmp-<pid>-<random>`` (``<name>`` cut to
:data:`TEMP_NAME_CHARS` characters, so that a long file name still leaves room). A run killed with
SIGKILL cannot remove its own; the next write to the same destination removes every such
file whose process no longer exists (a temporary file of a live process, e.g. a parallel
job, is left alone).
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
import shutil
import signal
import stat
import threading
from collections.abc import Iterable, Iterator
from pathlib import Path

from pencore.errors import WriteError, hint_keywords

__all__ = [
    "atomic_path",
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

_CAUSES = {
    errno.ENOSPC: "disk full",
    errno.EDQUOT: "disk quota exceeded",
    errno.EFBIG: "file too large (file-size limit)",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.EROFS: "read-only file system",
    errno.ENOENT: "directory does not exist",
    errno.ENOTDIR: "a parent is not a directory",
    errno.EISDIR: "is a directory",
}


def describe_os_error(exc: BaseException) -> str:
    """The cause of a write failure in words (``"disk full"``, ``"permission denied"``)."""
    code = getattr(exc, "errno", None)
    if code in _CAUSES:
        return _CAUSES[code]
    if isinstance(exc, OSError) and code is not None:
        name = errno.errorcode.get(code, str(code))
        return f"{name}: {exc.strerror or exc}"
    text = " ".join(str(exc).split()) or type(exc).__name__
    return f"{type(exc).__name__}: {text}"


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


def check_replaceable(
    path: str | os.PathLike[str], protect: Iterable[str | os.PathLike[str]] = ()
) -> None:
    """Refuse a destination that is not a regular file or that is one of ``protect``.

    Parameters
    ----------
    path : path-like
        The destination (it may not exist yet).
    protect : iterable of path-like
        Files the destination must not be (a run's own inputs); compared as files
        (device and inode), so another spelling or a hard link of an input is refused
        too.

    Raises
    ------
    WriteError
        One line naming the path and what it is.
    """
    try:
        st = os.lstat(path)
    except (FileNotFoundError, NotADirectoryError):  # nothing there to replace
        return
    except OSError as exc:
        raise WriteError(f"cannot write {_quote(path)}: {describe_os_error(exc)}") from None
    except ValueError:  # an embedded NUL
        raise WriteError(f"cannot write {_quote(path)}: the name holds a NUL character") from None
    if stat.S_ISLNK(st.st_mode):
        # renaming onto it would replace the link itself, not the file it points to
        raise WriteError(
            f"cannot write {_quote(path)}: it is a symbolic link (to "
            f"{_quote(os.readlink(path))}); only a regular file is replaced: give the file "
            "it points to, or another name",
            errno.EEXIST,
        )
    if not stat.S_ISREG(st.st_mode):
        raise WriteError(
            f"cannot write {_quote(path)}: it is {file_kind(st.st_mode)}, not a regular file; "
            "only a regular file is replaced",
            errno.EEXIST,
        )
    for other in protect:
        try:
            o = os.stat(other)
        except OSError:
            continue
        if (o.st_dev, o.st_ino) == (st.st_dev, st.st_ino):
            raise WriteError(
                f"cannot write {_quote(path)}: it is an input of this run "
                f"({_quote(other)}); choose another output name",
                errno.EEXIST,
            )


def _quote(path: str | os.PathLike[str]) -> str:
    text = str(path)
    return repr(text) if len(text) <= 200 else repr("..." + text[-197:])


def file_kind(mode: int) -> str:
    """What a file of this ``st_mode`` is, in words (``"a directory"``, ``"a FIFO"``,
    ...), for messages that refuse anything but a regular file."""
    for test, word in (
        (stat.S_ISDIR, "a directory"),
        (stat.S_ISFIFO, "a FIFO"),
        (stat.S_ISCHR, "a character device"),
        (stat.S_ISBLK, "a block device"),
        (stat.S_ISSOCK, "a socket"),
    ):
        if test(mode):
            return word
    return "not a regular file"


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
) -> Iterator[Path]:
    """Write ``path`` atomically: yield a temporary path to write to (see the module).

    Parameters
    ----------
    path : path-like
        Destination. Its directory must exist.
    mode : int
        Permission bits of the finished file, before the umask.
    protect : iterable of path-like
        Files ``path`` must not be (the run's own inputs), see :func:`check_replaceable`.

    Raises
    ------
    WriteError
        A destination that is not a regular file or is protected (before anything is
        written, see :func:`check_replaceable`); any failure to write, with the
        temporary file removed. ``KeyboardInterrupt``
        and ``SystemExit`` (SIGTERM) pass through, also after the clean-up.
    """
    path = Path(path)
    protect = tuple(protect)
    check_replaceable(path, protect)
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


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
