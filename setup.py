"""The project's build step: compile the numba kernels into the package.

Everything else about the build is in ``pyproject.toml``. ``build_py`` here also runs
``python -m pencore.warmup`` on the sources being packaged, with ``NUMBA_CPU_NAME=generic``
(object code for any CPU of this architecture) and ``PENCORE_KERNEL_BUILD`` pointing at
``pencore/kernels/compiled/`` of the build (of the source tree for an editable install),
so that an installed pencore loads its kernels at first use instead of compiling them
for about a minute (:mod:`pencore.kernels.cache` finds them by the kernel stamp).

The kernels fit the numba, Python and architecture of the build environment; anywhere
else they are not used and the kernels compile on first use, as without them. A build
environment that cannot run the solver (numba or a dependency missing) or
``PENCORE_SKIP_KERNELS=1`` builds the package without them, saying so.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
SRC = ROOT / "src"

#: numba settings the build must not inherit: they would change what is compiled or where.
_UNSET = ("NUMBA_CPU_FEATURES", "NUMBA_CACHE_DIR", "NUMBA_DISABLE_JIT", "NUMBA_OPT")

BUILD_INFO = """
import json, sys
sys.path.insert(0, {src!r})
from pencore.kernels.cache import build_info
print(json.dumps(build_info()))
"""


def compile_kernels(out: Path) -> bool:
    """Compile every kernel variant for the portable target into ``out``; True when done."""
    out = out.resolve()
    tmp = out.with_name(out.name + ".partial")
    shutil.rmtree(tmp, ignore_errors=True)
    env = {k: v for k, v in os.environ.items() if k not in _UNSET}
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(SRC), env.get("PYTHONPATH")]))
    env["NUMBA_CPU_NAME"] = "generic"
    env["PENCORE_KERNEL_BUILD"] = str(tmp)
    t0 = time.perf_counter()
    # the sources on sys.path explicitly: pip's isolated build environment rewrites the
    # path of its interpreter at start-up, and PYTHONPATH alone did not reach it
    run = (
        f"import sys, runpy; sys.path.insert(0, {str(SRC)!r}); "
        "runpy.run_module('pencore.warmup', run_name='__main__')"
    )
    done = subprocess.run([sys.executable, "-c", run], env=env, cwd=str(tmp.parent))
    seconds = time.perf_counter() - t0
    info = subprocess.run(
        [sys.executable, "-c", BUILD_INFO.format(src=str(SRC))],
        env=env,
        capture_output=True,
        text=True,
    )
    if done.returncode != 0 or info.returncode != 0:
        shutil.rmtree(tmp, ignore_errors=True)
        print(
            "pencore build: the numba kernels could not be compiled here (see above); "
            "the package is built without them and compiles them on first use",
            file=sys.stderr,
        )
        return False
    record = json.loads(info.stdout)
    record["compile_s"] = round(seconds, 1)
    (tmp / "BUILD.json").write_text(json.dumps(record, indent=1) + "\n")
    shutil.rmtree(out, ignore_errors=True)
    os.replace(tmp, out)
    print(f"pencore build: numba kernels compiled for {record['target']} in {seconds:.0f} s")
    return True


class build_py_with_kernels(build_py):
    """``build_py`` that also compiles the kernels into the package."""

    def run(self) -> None:
        super().run()
        if os.environ.get("PENCORE_SKIP_KERNELS") == "1":
            print("pencore build: PENCORE_SKIP_KERNELS=1: built without compiled kernels")
            return
        if getattr(self, "editable_mode", False):
            package = SRC / "pencore"
        else:
            package = Path(self.build_lib) / "pencore"
        compile_kernels(package / "kernels" / "compiled")


setup(cmdclass={"build_py": build_py_with_kernels})
