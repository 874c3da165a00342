"""The numba cache of pencore's compiled kernels: where compiled code is kept, shipped,
found and checked, and the notice of a process that is about to compile.

Every compiled (``cache=True``) function of the compiled folders (:data:`COMPILED_FOLDERS`)
keeps its cache in a :class:`KernelCache` (each compiled module ends with
:func:`use_kernel_cache`), which looks in two places:

* the **local cache** (:func:`cache_dir_of`): ``NUMBA_CACHE_DIR`` when set, else
  ``__pycache__`` next to the sources when writable, else numba's user-wide cache; with
  none writable (a read-only install with a read-only home) the kernels are compiled in
  memory, every process. What this process compiles is saved here, tuned for this CPU;
* the **shipped kernels** (:data:`SHIPPED`, ``pencore/kernels/compiled/``): object code
  the project's build step (``setup.py``: ``python -m pencore.warmup`` with
  ``NUMBA_CPU_NAME=generic``) compiled for any CPU of the architecture and put in the
  wheel (or, for an editable install, next to the sources), so that a fresh install
  loads its kernels instead of compiling them (read only: never written at run time).

Each entry is keyed, as numba keys its own cache, on the call signature, the code
generator (architecture triple, CPU name, CPU features: this CPU's for the local cache,
``generic`` for the shipped kernels), the function's bytecode and numba's version; the
source stamp is the **kernel stamp** :func:`kernel_hash` (a SHA-256 of every source file
of the compiled folders, not of the function's own file: the integrators inline the
force kernels of other modules, so a cached integrator must not outlive any of them).
The stamp survives installation (file times do not), so the wheel's shipped kernels
match its own sources, and a changed source in any compiled module invalidates all.

A cache that does not fit (another CPU family, numba or Python, an older source) is not
used; one that is damaged (a truncated or garbage data file, an emptied index: a disk
that filled, an interrupted copy) is discarded. Either way the kernels are compiled as on
a first use, with :data:`COMPILE_NOTICE`, never an error.

The local cache is looked in first, so kernels tuned for this CPU, once compiled
(``PENCORE_NO_SHIPPED_KERNELS=1 python -m pencore.warmup``), take the place of the
shipped ones; the twelve reference runs give the same bits with either
(``benchmarks/reference_runs.py``).
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import os
import sys
import tempfile
from pathlib import Path
from typing import Any

from pencore.errors import InputError
from pencore.kernels.buildcache import FOLDERS

__all__ = [
    "BUILD_ENV",
    "COMPILED_FOLDERS",
    "COMPILE_NOTICE",
    "PACKAGE",
    "PORTABLE_CPU",
    "SHIPPED",
    "NO_SHIPPED_ENV",
    "KernelCache",
    "build_info",
    "cache_dir_of",
    "compile_notice",
    "compiled_in_cache",
    "compiled_sources",
    "import_numba",
    "invalidate_stale_caches",
    "kernel_hash",
    "use_kernel_cache",
]

#: The package folders that hold compiled (numba) code; their caches go stale together
#: (:data:`pencore.kernels.buildcache.FOLDERS`, which the build step reads without numba).
COMPILED_FOLDERS = FOLDERS

#: ``src/pencore`` (or ``site-packages/pencore``).
PACKAGE = Path(__file__).resolve().parent.parent

#: Where the build step puts the shipped kernels: one folder per compiled folder.
SHIPPED = PACKAGE / "kernels" / "compiled"

#: The CPU name the shipped kernels are compiled for (any CPU of the architecture).
PORTABLE_CPU = "generic"

#: Environment variable of the build step: the folder the kernels compiled by this
#: process are saved into (the shipped kernels of a wheel); the local cache and the
#: shipped kernels are then neither read nor written.
BUILD_ENV = "PENCORE_KERNEL_BUILD"

#: Environment variable that, set to ``1``, leaves the shipped kernels unused (the
#: compile benchmarks and tests measure and check a first compile with it).
NO_SHIPPED_ENV = "PENCORE_NO_SHIPPED_KERNELS"

#: What a process that is about to compile the kernels says on stderr (once).
COMPILE_NOTICE = (
    "pencore: compiling the numba kernels on first use (about a minute, once; "
    "`python -m pencore.warmup` does it at install time)"
)


def import_numba() -> Any:
    """Import numba, turning its refusal of the environment into one line.

    numba reads its ``NUMBA_*`` environment variables when first imported and stops
    with a traceback on some (``NUMBA_NUM_THREADS=0``: "Number of threads specified must
    be > 0"); the values it cannot read it ignores with a warning.

    Raises
    ------
    InputError
        naming the ``NUMBA_*`` variables set and numba's reason.
    """
    try:
        import numba
    except (ValueError, TypeError, RuntimeError) as exc:
        for name in [m for m in sys.modules if m == "numba" or m.startswith("numba.")]:
            del sys.modules[name]  # the next import tries again instead of half a module
        names = ", ".join(
            f"{k}={v[:40]!r}" for k, v in sorted(os.environ.items()) if k.startswith("NUMBA_")
        )
        raise InputError(
            f"numba refused its environment settings ({names or 'no NUMBA_* variable set'}): "
            f"{str(exc)[:200]}; correct or unset the NUMBA_* variable"
        ) from None
    return numba


def compiled_sources(package: Path = PACKAGE) -> list[Path]:
    """Every ``.py`` file of the compiled folders, sorted."""
    return sorted(f for d in COMPILED_FOLDERS for f in (package / d).glob("*.py"))


@functools.cache
def _kernel_hash(package: Path) -> str:
    h = hashlib.sha256()
    for f in compiled_sources(package):
        h.update(f.relative_to(package).as_posix().encode())
        h.update(f.read_bytes())
    return h.hexdigest()


def kernel_hash(package: Path = PACKAGE) -> str:
    """The kernel stamp: SHA-256 (hex) of the path and bytes of every compiled source
    file; computed once per process."""
    return _kernel_hash(package)


@functools.cache
def cache_dir_of(folder: Path) -> Path | None:
    """The local cache directory of the compiled functions of ``folder``.

    The first that applies of: the build step's folder (``PENCORE_KERNEL_BUILD``), then,
    as numba chooses for its own caches, ``NUMBA_CACHE_DIR``, ``__pycache__`` when
    writable, the user-wide cache when writable; None when none is writable (the kernels
    are then compiled in memory). Looked up once per folder and process.
    """
    folder = Path(folder)
    build = os.environ.get(BUILD_ENV)
    if build:
        return Path(build) / folder.name
    from numba.core import caching

    source = str(next(iter(sorted(folder.glob("*.py"))), folder / "__init__.py"))
    for cls in (
        caching.UserProvidedCacheLocator,
        caching.InTreeCacheLocator,
        caching.UserWideCacheLocator,
    ):
        try:
            locator = cls.from_function(compiled_sources, source)
        except Exception:  # a locator that does not apply to a plain source file
            continue
        if locator is not None:
            return Path(locator.get_cache_path())
    return None


def invalidate_stale_caches(package: Path = PACKAGE) -> None:
    """Delete the local cache files of every compiled folder when any compiled source
    changed (their stamp would refuse them anyway: this keeps the disk clean)."""
    digest = kernel_hash(package)
    for name in COMPILED_FOLDERS:
        cache_dir = cache_dir_of(package / name)
        if cache_dir is None or os.environ.get(BUILD_ENV):
            continue
        stamp = cache_dir / "kernels.kernel-hash"
        try:
            if stamp.exists() and stamp.read_text() == digest:
                continue
            for f in cache_dir.glob("*.nb[ic]"):
                f.unlink()
            cache_dir.mkdir(parents=True, exist_ok=True)
            stamp.write_text(digest)
        except OSError:  # read-only: the stamps inside the index files still refuse them
            pass


def build_info() -> dict[str, str]:
    """What the shipped kernels of this process's build fit: numba and Python versions
    (with the ABI flags, ``py313t`` for a free-threaded 3.13), the code generator key
    (``target``: triple, CPU name, features) and the kernel stamp (written to
    ``BUILD.json`` beside them by the build step; the key of the build cache,
    :mod:`pencore.kernels.buildcache`)."""
    import numba

    triple, cpu, features = _host_magic()
    return {
        "numba": numba.__version__,
        "python": f"py{sys.version_info[0]}{sys.version_info[1]}{getattr(sys, 'abiflags', '')}",
        "target": f"{triple}, cpu {cpu!r}, features {features!r}",
        "kernel_hash": kernel_hash(),
    }


# --- the cache of one compiled function ----------------------------------------------


class _Locator:
    """A numba cache locator for the compiled folders: lets numba set up its own cache of
    a pencore function at decoration time even where no directory is writable (numba's
    own locators then fail with "no locator available"). That cache is replaced by a
    :class:`KernelCache` before use (:func:`use_kernel_cache`)."""

    def __init__(self, py_file: str):
        self._py_file = py_file

    def ensure_cache_path(self) -> None:
        pass

    def get_cache_path(self) -> str:
        d = cache_dir_of(Path(self._py_file).parent)
        return str(d if d is not None else Path(tempfile.gettempdir()))

    def get_source_stamp(self) -> str:
        return kernel_hash()

    def get_disambiguator(self) -> str:
        return "pencore"

    @classmethod
    def from_function(cls, py_func: Any, py_file: str) -> _Locator | None:
        path = Path(py_file).resolve()
        if path.parent.parent != PACKAGE or path.parent.name not in COMPILED_FOLDERS:
            return None
        return cls(py_file)


def _register_locator() -> None:
    """Put :class:`_Locator` first in numba's locator list (it applies to pencore's
    compiled folders only)."""
    from numba.core import caching

    impl = getattr(caching, "CacheImpl", None) or caching._CacheImpl
    abstract = caching._CacheLocator
    if not any(getattr(c, "__name__", "") == "KernelLocator" for c in impl._locator_classes):
        locator = type("KernelLocator", (_Locator, abstract), {})
        impl._locator_classes.insert(0, locator)


def _host_magic() -> tuple:
    """This process's code generator key (triple, CPU name, CPU features)."""
    from numba.core.registry import cpu_target

    return cpu_target.target_context.codegen().magic_tuple()


def _portable(magic: tuple) -> tuple:
    """The code generator key of the shipped kernels on this architecture."""
    return (magic[0], PORTABLE_CPU, "")


class KernelCache:
    """numba's on-disk cache of one compiled function of pencore (a ``_Cache``): loads
    from the local cache (this CPU's key), then from the shipped kernels (the portable
    key); saves to the local cache; a damaged file is discarded, never raised."""

    def __init__(self, py_func: Any):
        from numba.core import caching

        self._caching = caching
        self._py_func = py_func
        source = Path(inspect.getfile(py_func))
        qualname = py_func.__qualname__.replace("<", "").replace(">", "")
        abiflags = getattr(sys, "abiflags", "")
        self._base = (
            f"{source.stem}.{qualname}-{py_func.__code__.co_firstlineno}"
            f".py{sys.version_info[0]}{sys.version_info[1]}{abiflags}"
        )
        self._local = cache_dir_of(source.parent)
        shipped = SHIPPED / source.parent.name
        unused = os.environ.get(BUILD_ENV) or os.environ.get(NO_SHIPPED_ENV) == "1"
        self._shipped = None if unused else shipped
        self._enabled = True

    def __repr__(self) -> str:
        return f"<KernelCache {self._base} local={self._local} shipped={self._shipped}>"

    @property
    def cache_path(self) -> str | None:
        """The local cache directory (None: compiled in memory)."""
        return None if self._local is None else str(self._local)

    def enable(self) -> None:
        self._enabled = True

    def disable(self) -> None:
        self._enabled = False

    def flush(self) -> None:
        if self._local is not None:
            try:
                self._file(self._local).flush()
            except OSError:
                pass

    def _file(self, directory: Path) -> Any:
        return self._caching.IndexDataCacheFile(str(directory), self._base, kernel_hash())

    def _key(self, sig: Any, magic: tuple) -> tuple:
        """numba's index key (``Cache._index_key``) with the code generator key given."""
        code = self._py_func.__code__.co_code
        closure = self._py_func.__closure__
        if closure is not None:
            from numba.core.serialize import dumps

            cvars = dumps(tuple(c.cell_contents for c in closure))
        else:
            cvars = b""
        return (
            sig,
            magic,
            (hashlib.sha256(code).hexdigest(), hashlib.sha256(cvars).hexdigest()),
        )

    def _places(self, magic: tuple) -> list[tuple[Path, tuple]]:
        """(directory, code generator key) to look in, in order."""
        places = []
        if self._local is not None:
            places.append((self._local, magic))
        if self._shipped is not None and self._shipped.is_dir():
            places.append((self._shipped, _portable(magic)))
        return places

    def load_overload(self, sig: Any, target_context: Any) -> Any:
        """The compiled function for ``sig`` from the first place that holds it, else
        None (numba then compiles). A file that cannot be read is discarded."""
        target_context.refresh()
        if not self._enabled:
            return None
        from numba.core import compiler

        magic = target_context.codegen().magic_tuple()
        damaged = False
        for directory, key_magic in self._places(magic):
            try:
                data = self._file(directory).load(self._key(sig, key_magic))
                if data is not None:
                    return compiler.CompileResult._rebuild(target_context, *data)
            except Exception:  # truncated, garbage, unreadable: the next place, or compile
                self._discard(directory)
                damaged = True
        if damaged:  # only now is a compile certain (the shipped kernels may have served)
            announce_compile()
        return None

    def save_overload(self, sig: Any, data: Any) -> None:
        """Save the compiled function to the local cache; a full disk, a read-only
        folder or a damaged index leaves it compiled in memory only."""
        if not self._enabled or self._local is None or not _cachable(data):
            return
        key = self._key(sig, data.codegen.magic_tuple())
        reduced = data._reduce()
        for _ in range(2):
            try:
                self._local.mkdir(parents=True, exist_ok=True)
                self._file(self._local).save(key, reduced)
                return
            except Exception:  # a damaged index: start it afresh, once
                self._discard(self._local)

    def _discard(self, directory: Path) -> None:
        """Forget this function's files in ``directory``: deleted from the local cache,
        not read again from the shipped kernels."""
        if directory == self._shipped:
            self._shipped = None
            return
        for f in directory.glob(f"{self._base}.*"):
            if f.name == f"{self._base}.nbi" or f.suffix == ".nbc":
                try:
                    f.unlink()
                except OSError:
                    pass

    def holds_compiled_code(self) -> bool:
        """Whether a place holds compiled code of this function that this process can
        load: a readable index of this numba version and kernel stamp with an entry for
        its code generator key whose data file is not empty."""
        magic = _host_magic()
        for directory, key_magic in self._places(magic):
            try:
                overloads = self._file(directory)._load_index()
                for key, name in overloads.items():
                    if key[1] == key_magic and (directory / name).stat().st_size > 0:
                        return True
            except Exception:  # damaged or unreadable: not usable
                continue
        return False


def _cachable(cres: Any) -> bool:
    """What numba's ``CompileResultCacheImpl.check_cachable`` allows."""
    return not any(not x.can_cache for x in cres.lifted) and not cres.library.has_dynamic_globals


def use_kernel_cache(namespace: dict[str, Any]) -> None:
    """Give every cached compiled function of a module (its ``globals()``) a
    :class:`KernelCache`; each compiled module calls this at its end."""
    for value in list(namespace.values()):
        cache = getattr(value, "_cache", None)
        py_func = getattr(value, "py_func", None)
        if py_func is None or cache is None or isinstance(cache, KernelCache):
            continue
        if type(cache).__name__ == "NullCache":  # not a cache=True function
            continue
        if py_func.__module__ != namespace.get("__name__"):
            continue  # imported from another module: that one sets it
        value._cache = KernelCache(py_func)


# --- the compile notice --------------------------------------------------------------

_notice_printed = False
_notice_checked: set[Any] = set()  # the compiled entry points looked up in the cache


def announce_compile() -> None:
    """Print :data:`COMPILE_NOTICE` to stderr, at most once per process."""
    global _notice_printed
    if not _notice_printed:
        _notice_printed = True
        print(COMPILE_NOTICE, file=sys.stderr, flush=True)


def compile_notice(dispatcher: Any) -> None:
    """Print :data:`COMPILE_NOTICE` to stderr, at most once per process, when the compiled
    entry point of a run (``dispatcher``: the integrator's chunk, or the right-hand side
    for scipy) is not in a cache this process can load, i.e. the run is about to compile
    the kernels. Each entry point is looked up once per process."""
    if _notice_printed or dispatcher in _notice_checked:
        return
    _notice_checked.add(dispatcher)
    if not compiled_in_cache(dispatcher):
        announce_compile()


def compiled_in_cache(dispatcher: Any) -> bool:
    """Whether a cache holds compiled code of ``dispatcher`` (a ``cache=True`` function)
    that this process can load (:meth:`KernelCache.holds_compiled_code`: the local cache
    for this CPU, or the shipped kernels). True when numba will not compile or cannot
    cache the function (``NUMBA_DISABLE_JIT``, no cache): there is nothing to announce."""
    cache = getattr(dispatcher, "_cache", None)
    if isinstance(cache, KernelCache):
        return cache.holds_compiled_code()
    index = getattr(getattr(cache, "_cache_file", None), "_index_path", None)
    if index is not None:  # another function with numba's own cache
        return os.path.exists(index)
    return True  # not compiled, or compiled without a cache (nothing to look up)
