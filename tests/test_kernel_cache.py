"""The numba cache guard of pencore.stepping: a kernel cache never outlives its sources.

numba keys a cached function on its own source file only, while the integrators inline
the force kernels of other modules; the guard drops every kernel cache when any kernel
source changes, wherever numba keeps them.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from pencore import stepping

SRC = Path(stepping.__file__).parent


def test_every_compiled_module_is_a_kernel_module():
    # a module with compiled functions missing from the list would leave stale code
    # inlined into its callers (bands.py once was)
    compiled = {
        f.stem for f in SRC.glob("*.py") if re.search(r"@nb\.njit|numba\.njit", f.read_text())
    }
    assert compiled <= set(stepping.KERNEL_MODULES), compiled - set(stepping.KERNEL_MODULES)


def test_guard_clears_a_stale_numba_cache_dir(tmp_path):
    # with NUMBA_CACHE_DIR (clusters, read-only installs) the caches live there, not in
    # __pycache__: a planted cache file under an out-of-date stamp must be dropped on
    # import, and the stamp brought up to date; a current stamp keeps the files
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    where = (
        "from pencore import stepping as s; print(s._kernel_cache_dir(s.Path(s.__file__).parent))"
    )
    out = subprocess.run(
        [sys.executable, "-c", where], env=env, capture_output=True, text=True, check=True
    )
    cache_dir = Path(out.stdout.strip())
    assert tmp_path in cache_dir.parents
    stamp = cache_dir / "kernels.kernel-hash"
    current = stamp.read_text()
    planted = cache_dir / "dynamics.contact_loads-1.py311.nbi"
    planted.write_bytes(b"stale")
    stamp.write_text("out of date")
    subprocess.run([sys.executable, "-c", "import pencore.stepping"], env=env, check=True)
    assert not planted.exists()
    assert stamp.read_text() == current
    planted.write_bytes(b"current")
    subprocess.run([sys.executable, "-c", "import pencore.stepping"], env=env, check=True)
    assert planted.exists()
