"""The numba cache guard: compiled code is never loaded from an older source.

numba keys a cached function on its own source file only, but the integrators inline
the force kernels of other modules, so a cached integrator could keep a kernel compiled
from an older source. :func:`invalidate_stale_caches` (run when :mod:`pencore.kernels`
is first imported, before any compiled function is loaded) hashes every source file of
the compiled folders (:data:`COMPILED_FOLDERS`: this one and the integrators') and drops
every cached function of those folders when the hash changed, wherever numba keeps them
(``__pycache__`` next to the sources, ``NUMBA_CACHE_DIR``, or the user-wide cache of a
read-only install).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

__all__ = [
    "COMPILED_FOLDERS",
    "PACKAGE",
    "cache_dir_of",
    "compiled_sources",
    "invalidate_stale_caches",
]

#: ``src/pencore``.
#: The package folders that hold compiled (numba) code; their caches go stale together.
COMPILED_FOLDERS = ("kernels", "integrators")

PACKAGE = Path(__file__).resolve().parent.parent


def compiled_sources(package: Path = PACKAGE) -> list[Path]:
    """Every ``.py`` file of the compiled folders, sorted."""
    return sorted(f for d in COMPILED_FOLDERS for f in (package / d).glob("*.py"))


def cache_dir_of(folder: Path) -> Path | None:
    """The directory numba caches the functions of ``folder`` in: the first of its
    cache locators that applies (``NUMBA_CACHE_DIR``, then ``__pycache__`` when
    writable, then the user-wide cache), as :class:`numba.core.caching.CacheImpl`
    chooses."""
    try:
        from numba.core import caching

        impl = getattr(caching, "CacheImpl", None) or caching._CacheImpl
        classes = impl._locator_classes
    except (ImportError, AttributeError):  # another numba layout: the default place
        return folder / "__pycache__"
    source = str(next(iter(sorted(folder.glob("*.py"))), folder / "__init__.py"))
    for cls in classes:
        try:
            locator = cls.from_function(cache_dir_of, source)
        except Exception:  # a locator that does not apply to a plain source file
            continue
        if locator is not None:
            return Path(locator.get_cache_path())
    return None


def invalidate_stale_caches(package: Path = PACKAGE) -> None:
    """Drop the numba caches of every compiled folder when any compiled source changed."""
    h = hashlib.sha256()
    for f in compiled_sources(package):
        h.update(f.relative_to(package).as_posix().encode())
        h.update(f.read_bytes())
    digest = h.hexdigest()
    for name in COMPILED_FOLDERS:
        cache_dir = cache_dir_of(package / name)
        if cache_dir is None:
            continue  # numba will not cache here either
        stamp = cache_dir / "kernels.kernel-hash"
        try:
            if stamp.exists() and stamp.read_text() == digest:
                continue
            for f in cache_dir.glob("*.nb[ic]"):
                f.unlink()
            cache_dir.mkdir(parents=True, exist_ok=True)
            stamp.write_text(digest)
        except OSError:  # read-only install: numba falls back to compiling in memory
            pass
