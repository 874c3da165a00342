"""The numba cache guard (pencore.kernels.cache): a compiled function's cache never
outlives the sources of the compiled folders.

numba keys a cached function on its own source file only, while the integrators inline
the force kernels of other modules; the guard drops every cache of the compiled folders
when any of their sources changes, wherever numba keeps them.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from pencore.kernels import cache

# every test compiles or loads the kernels in a fresh interpreter (~6 s each, ~80 s in all)
pytestmark = pytest.mark.slow

PACKAGE = Path(cache.__file__).resolve().parents[1]


def test_every_compiled_module_is_in_a_guarded_folder():
    # a module with compiled functions outside the guarded folders would leave stale
    # code inlined into its callers (a hand-kept list of modules once missed one)
    compiled = {
        f.relative_to(PACKAGE).as_posix()
        for f in PACKAGE.rglob("*.py")
        if re.search(r"@nb\.njit|numba\.njit|@njit", f.read_text())
    }
    guarded = {f.relative_to(PACKAGE).as_posix() for f in cache.compiled_sources()}
    assert compiled, "no compiled module found: the pattern is out of date"
    assert compiled <= guarded, compiled - guarded


def test_every_cached_compiled_function_has_the_kernel_cache():
    # a compiled module that forgot use_kernel_cache(globals()) would keep numba's own
    # cache: no shipped kernels, and a damaged file would raise again
    import importlib

    from numba.core.dispatcher import Dispatcher

    found = []
    for f in cache.compiled_sources():
        module = importlib.import_module(f"pencore.{f.parent.name}.{f.stem}")
        for value in vars(module).values():
            if isinstance(value, Dispatcher) and value.py_func.__module__ == module.__name__:
                found.append(value)
                assert isinstance(value._cache, cache.KernelCache), value
    assert len(found) > 50  # the pattern still finds the compiled functions


def test_guard_clears_a_stale_numba_cache_dir(tmp_path):
    # with NUMBA_CACHE_DIR (clusters, read-only installs) the caches live there, not in
    # __pycache__: a planted cache file under an out-of-date stamp must be dropped on
    # import, and the stamp brought up to date; a current stamp keeps the files
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    where = (
        "from pencore.kernels import cache as c; print(c.cache_dir_of(c.PACKAGE / 'integrators'))"
    )
    out = subprocess.run(
        [sys.executable, "-c", where], env=env, capture_output=True, text=True, check=True
    )
    cache_dir = Path(out.stdout.strip())
    assert tmp_path in cache_dir.parents
    stamp = cache_dir / "kernels.kernel-hash"
    current = stamp.read_text()
    planted = cache_dir / "rosenbrock.integrate_chunk-1.py311.nbi"
    planted.write_bytes(b"stale")
    stamp.write_text("out of date")
    subprocess.run([sys.executable, "-c", "import pencore.kernels"], env=env, check=True)
    assert not planted.exists()
    assert stamp.read_text() == current
    planted.write_bytes(b"current")
    subprocess.run([sys.executable, "-c", "import pencore.kernels"], env=env, check=True)
    assert planted.exists()


# --- damaged, shipped and unwritable caches, on a small real kernel -------------------
#
# Each case runs in fresh interpreters on a made-up local cache (NUMBA_CACHE_DIR) and,
# where it matters, made-up shipped kernels, with state.speed_of (a small real kernel
# that compiles in a fraction of a second) standing for the whole set.

NOTICE = cache.COMPILE_NOTICE

# compiles or loads speed_of, says whether it was loaded (cache hits), its local
# cache directory, and the speed it computes; SHIPPED set before the kernels are defined
USE_KERNEL = """
import sys
from pathlib import Path
import numpy as np
import pencore.kernels.cache as c
c.SHIPPED = Path(sys.argv[1])
from pencore.kernels.state import speed_of
c.compile_notice(speed_of)
y = np.zeros(14)
y[7:10] = (3.0, 4.0, 12.0)
v = speed_of(y)
print(sum(speed_of._cache_hits.values()), v)
"""


def _kernel(tmp_path: Path, env_extra: dict | None = None) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "PENCORE_"))}
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "local")
    env.update(env_extra or {})
    done = subprocess.run(
        [sys.executable, "-c", USE_KERNEL, str(tmp_path / "shipped")],
        env=env, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return done


def _ship(tmp_path: Path) -> Path:
    """Build shipped kernels as the build step does (generic CPU, PENCORE_KERNEL_BUILD)."""
    _kernel(tmp_path, {"NUMBA_CPU_NAME": "generic", cache.BUILD_ENV: str(tmp_path / "shipped")})
    return tmp_path / "shipped" / "kernels"


def _files(folder: Path, suffix: str) -> list[Path]:
    return sorted(folder.rglob(f"state.speed_of-*{suffix}"))


def test_shipped_kernels_load_without_compiling(tmp_path):
    shipped = _ship(tmp_path)
    assert _files(shipped, ".nbi") and _files(shipped, ".nbc")
    done = _kernel(tmp_path)
    assert done.stdout.split() == ["1", "13.0"]  # loaded from the shipped kernels
    assert done.stderr == ""
    assert not _files(tmp_path / "local", ".nbc")  # nothing compiled, nothing saved


def _rewrite_index(index: Path, version=None, triple=None) -> None:
    """Rewrite a numba index as another numba version or another CPU family wrote it."""
    import pickle

    from numba.core.serialize import dumps

    with open(index, "rb") as f:
        old_version = pickle.load(f)
        stamp, entries = pickle.loads(f.read())
    if triple is not None:
        entries = {(k[0], (triple, *k[1][1:]), k[2]): v for k, v in entries.items()}
    with open(index, "wb") as f:
        pickle.dump(version or old_version, f, protocol=-1)
        f.write(dumps((stamp, entries)))


SHIPPED_CASES = {
    "another CPU family": lambda s: _rewrite_index(_files(s, ".nbi")[0], triple="aarch64-x"),
    "another numba": lambda s: _rewrite_index(_files(s, ".nbi")[0], version="0.0.1"),
    "another Python": lambda s: _retag_python(s),
    "an older source": lambda s: _restamp(s),
    "a truncated data file": lambda s: _truncate(_files(s, ".nbc")[0]),
    "a garbage data file": lambda s: _files(s, ".nbc")[0].write_bytes(b"\x80\x05garbage" * 9),
    "an emptied index": lambda s: _files(s, ".nbi")[0].write_bytes(b""),
    "a missing data file": lambda s: _files(s, ".nbc")[0].unlink(),
}


def _retag_python(folder: Path) -> None:
    """Rename the kernel's cache files as another Python version's build names them (a
    wheel of another interpreter's kernels)."""
    tag = f".py{sys.version_info[0]}{sys.version_info[1]}"
    for f in _files(folder, ""):
        assert tag in f.name
        f.rename(f.with_name(f.name.replace(tag, ".py30")))


def _truncate(f: Path) -> None:
    f.write_bytes(f.read_bytes()[: f.stat().st_size // 2])


def _restamp(folder: Path) -> None:
    import pickle

    from numba.core.serialize import dumps

    index = _files(folder, ".nbi")[0]
    with open(index, "rb") as f:
        version = pickle.load(f)
        _, entries = pickle.loads(f.read())
    with open(index, "wb") as f:
        pickle.dump(version, f, protocol=-1)
        f.write(dumps(("an older kernel stamp", entries)))


def _recompiles_with_the_notice_then_loads(tmp_path) -> None:
    """The kernel compiles (0), says so once, gives the same value, and the next process
    loads it from the cache (1) in silence."""
    done = _kernel(tmp_path)
    assert done.stdout.split() == ["0", "13.0"]
    assert done.stderr.splitlines() == [NOTICE]
    again = _kernel(tmp_path)
    assert again.stdout.split() == ["1", "13.0"]
    assert again.stderr == ""


@pytest.mark.parametrize("case", sorted(SHIPPED_CASES))
def test_shipped_kernels_that_do_not_fit_are_compiled_with_the_notice(case, tmp_path):
    # never worse than without them: the kernel compiles, says so once, gives the same
    # speed and is saved to the local cache, from where the next process loads it
    shipped = _ship(tmp_path)
    SHIPPED_CASES[case](shipped)
    _recompiles_with_the_notice_then_loads(tmp_path)


LOCAL_CASES = {k: v for k, v in SHIPPED_CASES.items() if k not in ("another CPU family",)}


@pytest.mark.parametrize("case", sorted(LOCAL_CASES))
def test_a_damaged_local_cache_is_discarded_and_recompiled(case, tmp_path):
    # a disk that filled during the warm-up or an interrupted copy: no traceback on
    # every later run, but one recompile with the notice, and a healthy cache after it
    first = _kernel(tmp_path)
    assert first.stdout.split() == ["0", "13.0"]
    LOCAL_CASES[case](tmp_path / "local")
    _recompiles_with_the_notice_then_loads(tmp_path)


# every place numba could write its cache refuses (a read-only install with a read-only
# home; the tests run as any user, root included, so the refusal is made where numba and
# pencore probe a folder for writing: tempfile.TemporaryFile)
READ_ONLY = """
import tempfile
def refuse(*args, **kwargs):
    raise PermissionError(13, "Read-only file system")
tempfile.TemporaryFile = refuse
"""


def test_no_writable_cache_compiles_in_memory(tmp_path):
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "PENCORE_"))}
    code = READ_ONLY + USE_KERNEL + "print(speed_of._cache.cache_path)"
    done = subprocess.run(
        [sys.executable, "-c", code, str(tmp_path / "shipped")],
        env=env, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["0", "13.0", "None"]
    assert done.stderr.splitlines() == [NOTICE]


def test_the_kernel_stamp_is_of_every_compiled_source(tmp_path):
    # two copies of the compiled folders, one with a source changed by a byte: the
    # unchanged copy has the package's stamp, the changed one another
    for copy in ("same", "changed"):
        for d in cache.COMPILED_FOLDERS:
            (tmp_path / copy / d).mkdir(parents=True)
            for f in (PACKAGE / d).glob("*.py"):
                (tmp_path / copy / d / f.name).write_bytes(f.read_bytes())
    target = tmp_path / "changed" / "integrators" / "rosenbrock.py"
    target.write_bytes(target.read_bytes() + b"\n")
    assert cache.kernel_hash(tmp_path / "same") == cache.kernel_hash(PACKAGE)
    assert cache.kernel_hash(tmp_path / "changed") != cache.kernel_hash(PACKAGE)
