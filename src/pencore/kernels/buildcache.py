"""The build cache: kernels the build step compiled once, reused by every later build
with the same kernel stamp, numba, Python and target.

The build step (``setup.py``) compiles the numba kernels into the package it builds
(:mod:`pencore.kernels.cache`, ``pencore/kernels/compiled/``). Without a cache every build
compiles them again (about a minute of CPU): an editable install, an extra added to it
later (pip reinstalls pencore), the packaging build of the sdist and the wheel. With it,
the first build keeps a copy of what it compiled in an entry of the build cache, outside
the source tree, and a later build whose **key** matches copies the entry instead of
compiling. The key is what makes the kernels fit (:func:`pencore.kernels.cache.build_info`,
``BUILD.json``): the numba version, the Python version and ABI, the code generator target
(triple, CPU name ``generic``, features) and the kernel stamp (SHA-256 of every compiled
source file).

Where: ``PENCORE_BUILD_CACHE`` when set (``off`` disables the cache), else the user's cache
folder (``$XDG_CACHE_HOME`` or ``~/.cache`` on Linux, ``~/Library/Caches`` on macOS,
``%LOCALAPPDATA%`` on Windows) ``/pencore/build-kernels/``, one folder per key
(:func:`entry_name`).

An entry is used only when it passes the damage checks of the runtime cache, made
stricter by a manifest: it is complete (written to a ``.partial-*`` folder and renamed
into place as a whole; a partial folder is never read), its ``BUILD.json`` equals the key
asked for (stamp, numba, Python, target), every file of its ``MANIFEST.json`` is there
with the SHA-256 recorded when it was stored (a truncated, emptied or garbage file fails),
and every numba index file starts with this numba's version, compared as bytes: nothing
in the cache is unpickled by the build (:func:`index_version` reads the version's few
leading bytes without executing anything). An entry that fails is deleted (it could only
fail again) and the kernels are compiled, as without a cache. Any failure to use the
cache (a ``PENCORE_BUILD_CACHE`` that cannot be expanded or is too long, a leftover
``compiled.partial`` file, an entry that cannot be read) means compile, said in one line;
a cache that cannot be written (a read-only home) only costs the copy for next time. The
cache keeps the :data:`KEEP` entries used last (about 7 MB each) and the partial folders
of builds that are still running (younger than :data:`PARTIAL_AGE_S`).

This module uses the standard library only: ``setup.py`` loads it by its path, before
numba or the package can be imported.
"""

from __future__ import annotations

import hashlib
import json
import os
import pickle  # dumps only: the expected bytes of a version; nothing is loaded
import shutil
import sys
import time
import uuid
from collections.abc import Callable
from pathlib import Path

__all__ = [
    "CACHE_ENV",
    "FOLDERS",
    "warmup_command",
    "KEEP",
    "KEY_FIELDS",
    "PARTIAL_AGE_S",
    "cache_root",
    "resolve_root",
    "clear_partial",
    "index_version",
    "entry_name",
    "find_entry",
    "provide_kernels",
    "prune",
    "store_entry",
    "verify_entry",
]

#: Environment variable: the build cache's folder; ``off`` disables it.
CACHE_ENV = "PENCORE_BUILD_CACHE"

#: What the kernels fit, as the build step records it in ``BUILD.json``: all must match.
KEY_FIELDS = ("kernel_hash", "numba", "python", "target")

#: The compiled folders of a kernel build (``pencore.kernels.cache.COMPILED_FOLDERS`` is
#: this tuple: this module is the one the build step can load without numba).
FOLDERS = ("kernels", "integrators")

#: How many entries the cache keeps (the ones used last).
KEEP = 4

#: A partial folder older than this (seconds) is of a build that was stopped: deleted.
PARTIAL_AGE_S = 3600.0

#: The record of the build beside the kernels, and the manifest of a cache entry.
BUILD_FILE = "BUILD.json"
MANIFEST_FILE = "MANIFEST.json"


def cache_root(environ: dict[str, str] | None = None) -> Path | None:
    """The folder of the build cache (None: disabled by ``PENCORE_BUILD_CACHE=off``).

    Examples
    --------
    >>> cache_root({"PENCORE_BUILD_CACHE": "/tmp/kernels"}).as_posix()
    '/tmp/kernels'
    >>> cache_root({"PENCORE_BUILD_CACHE": "off"}) is None
    True
    """
    env = os.environ if environ is None else environ
    given = env.get(CACHE_ENV, "").strip()
    if given.lower() == "off":
        return None
    if given:
        return Path(given).expanduser()
    if sys.platform == "win32":
        base = Path(env.get("LOCALAPPDATA") or Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = Path.home() / "Library" / "Caches"
    else:
        base = Path(env.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return base / "pencore" / "build-kernels"


def resolve_root(environ: dict[str, str] | None = None) -> tuple[Path | None, str]:
    """:func:`cache_root` and, when there is none, why in words: ``(root, "")``,
    ``(None, "disabled")``, or ``(None, why)`` when the setting cannot be used (a ``~user``
    that does not exist, no home folder).

    Examples
    --------
    >>> resolve_root({"PENCORE_BUILD_CACHE": "~no_such_user_here/x"})[1][:38]
    'PENCORE_BUILD_CACHE cannot be expanded'
    """
    try:
        root = cache_root(environ)
    except (RuntimeError, KeyError, ValueError, OSError) as exc:
        return None, f"{CACHE_ENV} cannot be expanded ({_brief(exc)})"
    return (root, "") if root is not None else (None, "disabled")


def _brief(exc: BaseException) -> str:
    """An exception in one short line."""
    text = " ".join(f"{type(exc).__name__}: {exc}".split())
    return text if len(text) <= 160 else text[:157] + "..."


def clear_partial(path: Path) -> None:
    """Remove what is at ``path`` (a leftover ``compiled.partial`` of a stopped build: a
    folder, a file or a link); nothing when there is nothing."""
    path = Path(path)
    try:
        if path.is_symlink() or (path.exists() and not path.is_dir()):
            path.unlink()
        else:
            shutil.rmtree(path, ignore_errors=True)
    except OSError:
        pass


def index_version(head: bytes) -> str | None:
    """The numba version at the start of a numba index file, read from its bytes without
    unpickling: numba writes it first as a pickled ``str`` (``pickle.dump(version, f,
    protocol=-1)``: the PROTO opcode, a FRAME on protocol 4 and above, then
    SHORT_BINUNICODE or BINUNICODE, its memo and STOP); None when the bytes are not that.

    Examples
    --------
    >>> import pickle
    >>> index_version(pickle.dumps("0.61.0", protocol=-1) + b"rest of the index")
    '0.61.0'
    >>> index_version(b"cos\\nsystem\\n...") is None
    True
    """
    try:
        if head[0] != 0x80:  # PROTO
            return None
        i = 2
        if head[1] >= 4:
            if head[i] != 0x95:  # FRAME
                return None
            i += 9
        if head[i] == 0x8C:  # SHORT_BINUNICODE
            n, i = head[i + 1], i + 2
        elif head[i] == 0x58:  # BINUNICODE
            n, i = int.from_bytes(head[i + 1 : i + 5], "little"), i + 5
        else:
            return None
        text, j = head[i : i + n], i + n
        if len(text) != n or n > 64:
            return None
        if head[j] == 0x94:  # MEMOIZE (protocol 4 and above)
            j += 1
        elif head[j] == 0x71:  # BINPUT (protocols 1-3)
            j += 2
        if head[j] != 0x2E:  # STOP: the string is the whole first pickle
            return None
        return text.decode("utf-8")
    except (IndexError, UnicodeDecodeError):
        return None


def _expected_index_head(version: str) -> bytes:
    """The leading bytes numba writes for ``version`` in an index (the pickled string,
    as this interpreter's highest protocol writes it, as numba does)."""
    return pickle.dumps(version, protocol=-1)


def entry_name(record: dict[str, str]) -> str:
    """The folder name of the entry for a key: the stamp's start, numba and Python
    readable, and a digest of the whole key (the target string holds spaces and quotes).

    Examples
    --------
    >>> key = {"kernel_hash": "ab" * 32, "numba": "0.61.0", "python": "py311",
    ...        "target": "x86_64-unknown-linux-gnu, cpu 'generic', features ''"}
    >>> entry_name(key)[:34]
    'abababababababab-numba0.61.0-py311'
    """
    key = json.dumps({k: record[k] for k in KEY_FIELDS}, sort_keys=True)
    digest = hashlib.sha256(key.encode()).hexdigest()[:12]
    return f"{record['kernel_hash'][:16]}-numba{record['numba']}-{record['python']}-{digest}"


def _sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _kernel_files(folder: Path) -> list[Path]:
    """The numba cache files (index and data) of a kernel build, sorted."""
    return sorted(p for d in FOLDERS for p in (folder / d).glob("*.nb[ic]"))


def verify_entry(entry: Path, record: dict[str, str]) -> str | None:
    """Why the cache entry ``entry`` cannot serve the key ``record`` (None: it can).

    The checks: ``BUILD.json`` matches every key field, ``MANIFEST.json`` lists at least
    one index and one data file, each listed file exists with its recorded SHA-256 and
    no kernel file is there unlisted, and every index file begins with ``record``'s numba
    version (numba's own check before it reads an index).
    """
    try:
        built = json.loads((entry / BUILD_FILE).read_text())
        manifest = json.loads((entry / MANIFEST_FILE).read_text())
    except (OSError, ValueError) as exc:
        return f"no readable {BUILD_FILE} and {MANIFEST_FILE} ({type(exc).__name__})"
    if not isinstance(built, dict) or not isinstance(manifest, dict):
        return f"{BUILD_FILE} or {MANIFEST_FILE} is not a JSON object"
    for field in KEY_FIELDS:
        if built.get(field) != record[field]:
            return f"{field} {built.get(field)!r} is not {record[field]!r}"
    names = sorted(manifest)
    if not any(n.endswith(".nbi") for n in names) or not any(n.endswith(".nbc") for n in names):
        return f"{MANIFEST_FILE} lists no kernels"
    present = {p.relative_to(entry).as_posix() for p in _kernel_files(entry)}
    if present - set(names):
        return f"{sorted(present - set(names))[0]} is not in {MANIFEST_FILE}"
    for name in names:
        path = entry / name
        try:
            if _sha256(path) != manifest[name]:
                return f"{name} does not match its SHA-256 (damaged)"
            if name.endswith(".nbi"):
                expected = _expected_index_head(record["numba"])
                with open(path, "rb") as f:
                    head = f.read(max(len(expected), 128))
                if head[: len(expected)] != expected:
                    version = index_version(head)
                    if version is None:
                        return f"{name} does not start as a numba index (not unpickled)"
                    return f"{name} is an index of numba {version!r}"
        except OSError as exc:
            return f"{name} cannot be read ({type(exc).__name__})"
    return None


def find_entry(root: Path, record: dict[str, str]) -> tuple[Path | None, str]:
    """The verified entry for ``record`` under ``root`` and a one-line account: (entry,
    "") on a hit, (None, why) on a miss. A damaged entry is deleted (it would fail again)."""
    entry = root / entry_name(record)
    if not entry.is_dir():
        return None, f"no entry {entry.name} in {root}"
    why = verify_entry(entry, record)
    if why is None:
        try:
            os.utime(entry)  # used now: the last to be pruned
        except OSError:
            pass
        return entry, ""
    shutil.rmtree(entry, ignore_errors=True)
    return None, f"entry {entry} refused and deleted: {why}"


def store_entry(root: Path, built: Path, record: dict[str, str]) -> Path:
    """Copy the kernel build ``built`` (its compiled folders and ``BUILD.json``) into the
    cache as the entry of ``record``, with its manifest; returns the entry.

    Written to ``<entry>.partial-<id>`` and renamed into place, so a reader sees a whole
    entry or none; when another build stored the same entry first, theirs is kept.

    Raises
    ------
    OSError
        when the cache cannot be written (the caller goes on without it).
    """
    entry = root / entry_name(record)
    tmp = root / f"{entry.name}.partial-{os.getpid()}-{uuid.uuid4().hex[:8]}"
    try:
        tmp.mkdir(parents=True)
        for d in FOLDERS:
            if (built / d).is_dir():
                shutil.copytree(built / d, tmp / d)
        shutil.copy2(built / BUILD_FILE, tmp / BUILD_FILE)
        manifest = {p.relative_to(tmp).as_posix(): _sha256(p) for p in _kernel_files(tmp)}
        (tmp / MANIFEST_FILE).write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
        if entry.is_dir() and verify_entry(entry, record) is not None:
            shutil.rmtree(entry, ignore_errors=True)  # a damaged one: replaced
        try:
            os.rename(tmp, entry)
        except OSError:
            if not entry.is_dir():  # not a concurrent store of the same entry
                raise
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return entry


def prune(root: Path, keep: int = KEEP, now: float | None = None) -> list[Path]:
    """Delete all but the ``keep`` entries of ``root`` used last (by their folder's time,
    renewed on each use) and the partial folders older than :data:`PARTIAL_AGE_S`;
    returns what was deleted."""
    now = time.time() if now is None else now
    entries, gone = [], []
    for d in sorted(root.iterdir()) if root.is_dir() else []:
        if not d.is_dir():
            continue
        if ".partial-" in d.name:
            if now - d.stat().st_mtime > PARTIAL_AGE_S:
                gone.append(d)
        else:
            entries.append(d)
    entries.sort(key=lambda d: d.stat().st_mtime, reverse=True)
    gone += entries[keep:]
    for d in gone:
        shutil.rmtree(d, ignore_errors=True)
    return gone


def _copy_entry(entry: Path, dest: Path) -> str:
    """Copy the kernels of a verified entry into ``dest`` and check the copies against its
    manifest; returns why that failed ("" when done): an entry deleted or changed while
    it was copied (another build pruning the cache), a full disk."""
    try:
        manifest = json.loads((entry / MANIFEST_FILE).read_text())
        dest.mkdir(parents=True)
        for d in FOLDERS:
            if (entry / d).is_dir():
                shutil.copytree(entry / d, dest / d)
        copied = {p.relative_to(dest).as_posix(): _sha256(p) for p in _kernel_files(dest)}
    except Exception as exc:
        return f"copy from {entry} failed ({_brief(exc)})"
    return "" if copied == manifest else f"copy from {entry} differs from its manifest"


def provide_kernels(
    out: Path,
    record: dict[str, str],
    compile_into: Callable[[Path], float | None],
    root: Path | None,
    say: Callable[[str], None] = print,
    no_root: str = "disabled",
) -> dict | None:
    """Put the kernels of key ``record`` into ``out``: copied from the build cache under
    ``root`` when it holds a verified entry, else compiled by ``compile_into(folder)``
    (returns the seconds it took, None on failure) and stored in the cache.

    ``out`` is written through ``out.partial`` and replaced as a whole. Its
    ``BUILD.json`` is ``record`` plus ``build`` (``compiled`` or ``copied``),
    ``compile_s`` (the seconds this build compiled: 0 when copied) and ``build_cache``
    (the entry, or None). Returns that record, or None when the compile failed (``out``
    is then left absent). ``say`` reports each step in one line; ``no_root`` is why
    there is no cache when ``root`` is None (:func:`resolve_root`). Any failure to use
    the cache is a compile, and one that keeps it from storing the result only a line.
    """
    out = Path(out)
    tmp = out.with_name(out.name + ".partial")
    clear_partial(tmp)  # a stopped build's leftover: a folder, or a file
    entry, why = None, no_root
    if root is not None:
        try:
            entry, why = find_entry(root, record)
            if entry is not None:
                why = _copy_entry(entry, tmp)
                if why:
                    entry = None
        except Exception as exc:  # any failure to use the cache means compile
            entry, why = None, f"the build cache {str(root)[:80]!r} cannot be used ({_brief(exc)})"
    if entry is None:
        clear_partial(tmp)
    if entry is not None:
        say(f"pencore build: numba kernels copied from the build cache {entry} (no compile)")
        done = {**record, "build": "copied", "compile_s": 0.0, "build_cache": str(entry)}
    else:
        say(
            f"pencore build: compiling the numba kernels (about a minute of CPU; build cache: "
            f"{why})"
        )
        seconds = compile_into(tmp)
        if seconds is None:
            shutil.rmtree(tmp, ignore_errors=True)
            return None
        done = {**record, "build": "compiled", "compile_s": round(seconds, 1)}
        done["build_cache"] = None
        (tmp / BUILD_FILE).write_text(json.dumps(done, indent=1) + "\n")
        if root is not None:
            try:
                done["build_cache"] = str(store_entry(root, tmp, done))
                say(f"pencore build: kept in the build cache {done['build_cache']}")
                prune(root)
            except Exception as exc:  # the kernels are built; only the copy is lost
                say(
                    f"pencore build: the build cache {str(root)[:80]!r} cannot be written "
                    f"({_brief(exc)}): not kept"
                )
    (tmp / BUILD_FILE).write_text(json.dumps(done, indent=1) + "\n")
    clear_partial(out)
    os.replace(tmp, out)
    return done


def warmup_command(src: str | Path, *args: str) -> list[str]:
    """``python -m pencore.warmup ARGS`` with the pencore package of ``src`` (the folder
    holding ``pencore/``) first on ``sys.path``, explicitly: pip's isolated build
    environment rewrites the path of its interpreter at start-up, and PYTHONPATH alone
    does not reach it (the build step, and the warm-up's parts compiled side by side)."""
    code = (
        f"import sys, runpy; sys.path.insert(0, {str(src)!r}); "
        "runpy.run_module('pencore.warmup', run_name='__main__')"
    )
    return [sys.executable, "-c", code, *args]
