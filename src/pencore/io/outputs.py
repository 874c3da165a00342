"""The output gate: what a writer may replace, and what one call has read and written.

Every file pencore writes (``--out``, ``--plot`` and ``--write`` of the command line, the
Python writers :func:`~pencore.io.netcdf.write_netcdf`,
:func:`~pencore.plotting.style.save_figure`, the workflow's scripts) goes through
:func:`pencore.io.atomic.atomic_path`, which asks :func:`check_destination` first. Its
rules, the same for every writer:

- a path is given (not blank) and is text (no NUL character; UTF-8 encodable);
- it names a file: not a path ending in ``/``, not an existing directory, FIFO,
  device or socket, not a symbolic link;
- its suffix is one the writer knows (the message lists them);
- an existing file is writable: a read-only file is one its owner wants kept;
- it is none of the inputs of the same call: the files the writer is told to protect,
  and every file read through the input gate (:func:`note_input`) while a call is open
  (:func:`output_call`, :func:`begin_call`), compared as files (device and inode), so
  another spelling or a hard link of an input is refused too.

A call (one command-line command, one workflow job) also records what it has written
completely (:func:`note_written`), so that an interrupted call can say exactly what is on
disk (:func:`interrupted_message`). Nothing here imports the data stack.
"""

from __future__ import annotations

import contextlib
import contextvars
import errno
import os
import stat
import sys
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from pencore.errors import INTERRUPTED, WriteError

__all__ = [
    "FIGURE_SUFFIXES",
    "TABLE_SUFFIXES",
    "NETCDF_SUFFIXES",
    "YAML_SUFFIXES",
    "TEXT_SUFFIXES",
    "Call",
    "output_call",
    "begin_call",
    "current_call",
    "note_input",
    "note_written",
    "allow_rewrite",
    "written_files",
    "interrupted_message",
    "check_destination",
    "check_replaceable",
    "describe_os_error",
    "file_kind",
]

#: Image formats a figure is written in (from the file's suffix).
FIGURE_SUFFIXES = (".png", ".pdf", ".svg")
#: Formats of a table (a search's or sweep's Dataset): netCDF, or CSV text.
TABLE_SUFFIXES = (".nc", ".csv")
#: netCDF files.
NETCDF_SUFFIXES = (".nc",)
#: YAML data files (the fitted Table-3 geometry).
YAML_SUFFIXES = (".yaml", ".yml")
#: Plain-text reports of the workflow (summaries, HTML tables).
TEXT_SUFFIXES = (".txt", ".html", ".md", ".csv")

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
    errno.ENAMETOOLONG: "file name too long",
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


def _quote(path: str | os.PathLike[str]) -> str:
    text = os.fsdecode(path) if isinstance(path, bytes) else str(path)
    return repr(text) if len(text) <= 200 else repr("..." + text[-197:])


@dataclass
class Call:
    """One call's files: those read through the input gate (``inputs``), those written
    completely (``written``), as paths in the order seen, and the inputs the call is
    meant to rewrite (``rewrites``, :func:`allow_rewrite`)."""

    inputs: list[str] = field(default_factory=list)
    written: list[str] = field(default_factory=list)
    rewrites: list[str] = field(default_factory=list)


_CALL: contextvars.ContextVar[Call | None] = contextvars.ContextVar("pencore_call", default=None)


@contextlib.contextmanager
def output_call(inputs: Iterable[str | os.PathLike[str]] = ()) -> Iterator[Call]:
    """Open a call (one command, one job) for the ``with`` block: the files read in it
    (:func:`note_input`, and ``inputs``) are protected from every writer, and the files
    written are recorded (:func:`interrupted_message`)."""
    call = Call()
    token = _CALL.set(call)
    try:
        for p in inputs:
            note_input(p)
        yield call
    finally:
        _CALL.reset(token)


def begin_call(inputs: Iterable[str | os.PathLike[str]] = ()) -> Call:
    """Open a call for the rest of the process (a workflow job's script): as
    :func:`output_call`, without a ``with`` block."""
    call = Call()
    _CALL.set(call)
    for p in inputs:
        note_input(p)
    return call


def current_call() -> Call | None:
    """The open call, or None outside one (a plain Python session)."""
    return _CALL.get()


def note_input(path: str | os.PathLike[str]) -> None:
    """Record ``path`` as an input of the open call (nothing outside a call; names that
    are not files are skipped when compared)."""
    call = _CALL.get()
    if call is not None:
        text = os.fspath(path)
        if isinstance(text, str) and text not in call.inputs:
            call.inputs.append(text)


def allow_rewrite(path: str | os.PathLike[str]) -> None:
    """Let the open call replace ``path`` although it read it: a command whose purpose is
    to regenerate a data file from what it computes (``pencore fit-table3 --write`` onto
    the shipped Table-3 geometry, which every run reads). Nothing outside a call."""
    call = _CALL.get()
    if call is not None:
        call.rewrites.append(os.fspath(path))  # type: ignore[arg-type]


def note_written(path: str | os.PathLike[str]) -> None:
    """Record ``path`` as written completely by the open call."""
    call = _CALL.get()
    if call is not None:
        call.written.append(os.fspath(path))  # type: ignore[arg-type]


def written_files() -> list[str]:
    """The files the open call has written completely (empty outside a call)."""
    call = _CALL.get()
    return [] if call is None else list(call.written)


def interrupted_message(what: str = "interrupted (Ctrl-C)") -> str:
    """What an interrupted call says: ``what`` and exactly which files are on disk."""
    done = written_files()
    if not done:
        return INTERRUPTED if what == "interrupted (Ctrl-C)" else f"{what}; nothing was written"
    names = ", ".join(_quote(p) for p in done)
    return f"{what}; written completely before it: {names}; nothing else was written"


def check_replaceable(
    path: str | os.PathLike[str], protect: Iterable[str | os.PathLike[str]] = ()
) -> None:
    """Refuse a destination that is not a regular file, is read-only, or is one of
    ``protect`` or an input of the open call.

    Parameters
    ----------
    path : path-like
        The destination (it may not exist yet).
    protect : iterable of path-like
        Files the destination must not be (a run's own inputs); compared as files
        (device and inode), so another spelling or a hard link of an input is refused
        too. The inputs of the open call (:func:`note_input`) are added.

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
    call = _CALL.get()
    rewrites = set()
    for r in call.rewrites if call is not None else ():
        with contextlib.suppress(OSError, ValueError):
            rewrites.add((os.stat(r).st_dev, os.stat(r).st_ino))
    for other in [*protect, *(call.inputs if call is not None else ())]:
        try:
            o = os.stat(other)
        except (OSError, ValueError):
            continue
        same = (o.st_dev, o.st_ino) == (st.st_dev, st.st_ino)
        if same and not (other not in protect and (o.st_dev, o.st_ino) in rewrites):
            raise WriteError(
                f"cannot write {_quote(path)}: it is an input of this run "
                f"({_quote(other)}); choose another output name",
                errno.EEXIST,
            )
    if not st.st_mode & 0o222:
        # renaming a new file onto it would replace it (the directory is writable), and
        # root may write it anyway: a file made read-only is one its owner wants kept
        raise WriteError(
            f"cannot write {_quote(path)}: it is read-only (mode "
            f"{stat.S_IMODE(st.st_mode):04o}); make it writable to replace it, or give "
            "another name",
            errno.EACCES,
        )


def check_destination(
    path: str | os.PathLike[str],
    suffixes: Iterable[str] | None = None,
    protect: Iterable[str | os.PathLike[str]] = (),
) -> Path:
    """Check a destination against the output rules (see the module), before writing.

    Parameters
    ----------
    path : path-like
        The file to write (it may not exist yet).
    suffixes : iterable of str, optional
        The suffixes the writer knows (``.png``, ...; compared without case); None: any.
    protect : iterable of path-like
        Files the destination must not be (the call's own inputs).

    Returns
    -------
    pathlib.Path
        ``path`` as a path.

    Raises
    ------
    WriteError
        One line naming the path and the rule it breaks; nothing is written.
    """
    text = os.fsdecode(path) if isinstance(path, bytes) else os.fspath(path)
    if not str(text).strip():
        raise WriteError(f"cannot write {_quote(text)}: a file name is needed", errno.ENOENT)
    if "\0" in text:
        raise WriteError(f"cannot write {_quote(text)}: the name holds a NUL character")
    if text.endswith(("/", os.sep)):  # Path() would drop the slash and write the file
        raise WriteError(
            f"cannot write {_quote(text)}: it ends in {text[-1]!r}, which names a directory; "
            "give a file name",
            errno.EISDIR,
        )
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        # bytes the locale cannot decode: libraries taking names as UTF-8 would fail late
        raise WriteError(
            f"cannot write {_quote(text)}: the name is not text in this locale's encoding "
            f"({sys.getfilesystemencoding()}); use a UTF-8 locale or an ASCII name"
        ) from None
    p = Path(text)
    try:
        st = os.lstat(p)
    except (OSError, ValueError):
        st = None
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise WriteError(
            f"cannot write {_quote(text)}: it is a directory, not a regular file; "
            "only a regular file is replaced",
            errno.EISDIR,
        )
    check_replaceable(p, protect)  # what is there, before what the name asks for
    if suffixes is not None:
        allowed = tuple(suffixes)
        if p.suffix.lower() not in allowed:
            raise WriteError(
                f"cannot write {_quote(text)}: unknown suffix "
                f"{p.suffix or '(none)'!r}; the file must end in one of {', '.join(allowed)}",
                errno.EINVAL,
            )
    return p
