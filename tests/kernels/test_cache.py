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

from pencore.kernels import cache

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
