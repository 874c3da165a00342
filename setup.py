"""The project's build step: compile the numba kernels into the package.

Everything else about the build is in ``pyproject.toml``. ``build_py`` here also runs
``python -m pencore.warmup`` on the sources being packaged, with ``NUMBA_CPU_NAME=generic``
(object code for any CPU of this architecture) and ``PENCORE_KERNEL_BUILD`` pointing at
``pencore/kernels/compiled/`` of the build (of the source tree for an editable install),
so that an installed pencore loads its kernels at first use instead of compiling them
for about a minute (:mod:`pencore.kernels.cache` finds them by the kernel stamp).

It compiles once: what it compiled is kept in the build cache outside the source tree
(``~/.cache/pencore/build-kernels/``, ``PENCORE_BUILD_CACHE``), and a later build with the
same kernel stamp, numba, Python and target copies it instead of compiling
(:mod:`pencore.kernels.buildcache`; ``BUILD.json`` beside the kernels says which). pip
shows the build step's lines only with ``pip install -v``.

The kernels fit the numba, Python and architecture of the build environment; anywhere
else they are not used and the kernels compile on first use, as without them. A build
whose compile fails (a build environment that cannot run the solver, numba or a
dependency missing) stops with one line naming the cause, which pip shows without
``-v``, instead of installing a package without kernels that says it succeeded;
``PENCORE_SKIP_KERNELS=1`` builds the package without them on purpose, saying so. Any
failure to use the build cache only means compiling (one line, with ``-v``).
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from setuptools import setup
from setuptools.command.bdist_wheel import bdist_wheel
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
SRC = ROOT / "src"

#: numba settings the build must not inherit: they would change what is compiled or where.
_UNSET = ("NUMBA_CPU_FEATURES", "NUMBA_CACHE_DIR", "NUMBA_DISABLE_JIT", "NUMBA_OPT")

NOT_COMPILED = (
    "pencore build: the numba kernels could not be compiled ({why}); the build stops. "
    "Fix the build environment, or set PENCORE_SKIP_KERNELS=1 to build the package "
    "without them (it then compiles them on first use)"
)

BUILD_INFO = """
import json, sys
sys.path.insert(0, {src!r})
from pencore.kernels.cache import build_info
print(json.dumps(build_info()))
"""


def _load_buildcache():
    """:mod:`pencore.kernels.buildcache` loaded from its file (standard library only):
    importing it as ``pencore.kernels`` would import numba into this process."""
    path = SRC / "pencore" / "kernels" / "buildcache.py"
    spec = importlib.util.spec_from_file_location("_pencore_buildcache", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _say(line: str) -> None:
    """One line of the build step (pip shows it with ``pip install -v``)."""
    print(line, flush=True)


def _stop(message: str) -> None:
    """Stop the build with ``error: <message>`` on stderr and exit status 1.

    A ``SystemExit``, not an ``Exception``: setuptools' editable install runs
    ``build_py`` through ``editable_wheel._safely_run``, which turns any ``Exception`` into
    a deprecation warning and reports success (a package without kernels, the error seen
    only with ``-v``); a ``SystemExit`` passes through it, and pip and uv show the line."""
    raise SystemExit(f"error: {message}")


def compile_kernels(out: Path) -> None:
    """Put the kernels for the portable target into ``out``: copied from the build cache
    (:mod:`pencore.kernels.buildcache`) when an earlier build compiled them for the same
    kernel stamp, numba, Python and target, else compiled (and kept there).

    Raises
    ------
    SystemExit
        The kernels could not be compiled: ``error: <one line naming the cause>``, and the
        build stops (:func:`_stop`).
    """
    buildcache = _load_buildcache()
    out = out.resolve()
    buildcache.clear_partial(out.with_name(out.name + ".partial"))  # a stopped build's leftover
    env = {k: v for k, v in os.environ.items() if k not in _UNSET}
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(SRC), env.get("PYTHONPATH")]))
    env["NUMBA_CPU_NAME"] = "generic"
    # the build's folder set: the kernel package imported here neither reads nor writes
    # the local numba cache (pencore.kernels.cache)
    env["PENCORE_KERNEL_BUILD"] = str(out.with_name(out.name + ".partial"))
    info = subprocess.run(
        [sys.executable, "-c", BUILD_INFO.format(src=str(SRC))],
        env=env,
        capture_output=True,
        text=True,
    )
    if info.returncode != 0:
        sys.stderr.write(info.stderr)
        last = (info.stderr.strip().splitlines() or ["no message"])[-1][:200]
        _stop(NOT_COMPILED.format(why=f"the solver does not import: {last}"))
    record = json.loads(info.stdout)

    def compile_into(tmp: Path) -> float | None:
        t0 = time.perf_counter()
        done = subprocess.run(
            buildcache.warmup_command(SRC), env={**env, "PENCORE_KERNEL_BUILD": str(tmp)}
        )
        return time.perf_counter() - t0 if done.returncode == 0 else None

    root, no_root = buildcache.resolve_root()
    done = buildcache.provide_kernels(out, record, compile_into, root, say=_say, no_root=no_root)
    if done is None:
        _stop(NOT_COMPILED.format(why="the warm-up run failed, see above"))
    if done["build"] == "compiled":
        _say(
            f"pencore build: numba kernels compiled for {record['target']} "
            f"in {done['compile_s']:.0f} s"
        )


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


class bdist_wheel_tagged(bdist_wheel):
    """A wheel tagged for what it carries: with compiled kernels (numba cache files for one
    CPython version and one architecture) the interpreter, ABI and platform of the build
    (``cp311-cp311-linux_x86_64``), without them ``py3-none-any``. ``--plat-name`` still
    sets the platform (``manylinux_2_28_x86_64`` for an index: docs/getting-started.md)."""

    def run(self) -> None:
        if not self.skip_build:
            self.run_command("build")  # build_py compiles (or copies) the kernels, or not
        build_lib = Path(self.get_finalized_command("build_py").build_lib)
        kernels = (build_lib / "pencore" / "kernels" / "compiled" / "BUILD.json").is_file()
        self.root_is_pure = not kernels
        if kernels:  # the install step then puts the package in platlib, at the wheel's root
            self.distribution.has_ext_modules = lambda: True
        super().run()


setup(cmdclass={"build_py": build_py_with_kernels, "bdist_wheel": bdist_wheel_tagged})
