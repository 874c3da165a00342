"""Compile and cache every numba kernel once, ahead of the first run.

An installed pencore loads its kernels compiled: the build step (``setup.py``) runs this
module with ``NUMBA_CPU_NAME=generic`` and ships the result with the package
(:mod:`pencore.kernels.cache`). Where those do not fit (another numba, Python or
architecture, a changed kernel source, a damaged file) the kernels are compiled on first
use and cached on disk (``__pycache__`` next to the sources, ``NUMBA_CACHE_DIR``, or the
user-wide cache), which costs ~45 s of CPU on the 2-core benchmark machine
(``benchmarks/bench_compile.py``) and is said once on stderr
(:func:`pencore.kernels.cache.compile_notice`). ``python -m pencore.warmup`` pays that ahead:
it runs one short trajectory of every kernel variant (the default DAFL on rings with the
Rosenbrock integrator, the cavity and factor shank models, the panel surface and the
explicit integrator), so that afterwards a fresh process loads the kernels from a cache
(``benchmarks/bench_startup.py`` measures both); with fitting shipped kernels it only
loads them. On a cold cache it says so once too, at its first variant: the variants share
one process, and the notice is once per process.

``python -m pencore.warmup --host`` compiles them tuned for this CPU instead, leaving the
shipped kernels unused (``PENCORE_NO_SHIPPED_KERNELS=1``): later processes load those
first. Tuned kernels ran the benchmark trajectory about 2-3 % faster than the portable
ones, at the edge of the noise of the 2-core benchmark machine (``docs/performance.md``),
for one compile (~45 s of CPU).

On a cold cache with two or more cores, the two largest independent parts of the
integrator are compiled side by side first (:data:`PARTS`: the force kernel and the
closed-form velocity Jacobian, in two processes, each saving its compiled code to the
cache); then the integrator's two specialisations (with and without the derivatives the
loads are read from) compile side by side, loading the parts from the cache
(:data:`SECOND_PARTS`). ``benchmarks/bench_compile.py`` measures the wall it saves.

Run: ``python -m pencore.warmup [--host]`` (``setup.py``'s build step runs it, for the
shipped kernels).
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

#: (label, keyword arguments of pencore.simulate) of the variants compiled.
VARIANTS: tuple[tuple[str, dict], ...] = (
    ("dafl, rings, rosenbrock", {}),
    ("cavity shank", {"shank": "cavity"}),
    ("factor shank", {"shank": "factor"}),
    ("panels", {"emulation": {"surface": "panels"}}),
    ("explicit integrator", {"emulation": {"integrator": "explicit", "dt": 2e-5}}),
    # a search's run keeps no derivatives for loads: the integrator's other specialisation
    ("search run", {"raw": True}),
)


#: Independent parts of the integrator's compile, compiled side by side on a cold cache
#: (:func:`compile_part`): the force kernel (about 17 s of a 45-s compile on the benchmark
#: machine) and the closed-form velocity Jacobian (about 15 s), which the integrator calls.
PARTS = ("rhs", "jacobian")
#: Compiled beside the integrator once :data:`PARTS` are cached: the last two variants,
#: the explicit integrator (about 3 s) and the search run (the Rosenbrock integrator's
#: specialisation without derivatives, about 10 s), which load the parts from the cache.
SECOND_PARTS = ("beside",)
#: How many of the last :data:`VARIANTS` the :data:`SECOND_PARTS` compile.
BESIDE = 2


def run_variant(kw: dict) -> None:
    """The warm-up's run of one variant (``kw`` of :data:`VARIANTS`): p2 into soil at 30 deg
    and 300 m/s, a Dataset with its loads, or with ``raw`` a search's raw run."""
    from pencore.run import impact

    kw = dict(kw)
    run = impact.run_impact if kw.pop("raw", False) else impact.simulate
    run("p2", "soil", 300.0, obliquity=30.0, **kw)


def part_call(part: str) -> tuple[Any, tuple]:
    """The compiled function of one of :data:`PARTS` and the arguments the part calls it
    with: of the types the integrator passes it (the values are a body above the surface:
    nothing is integrated)."""
    import numpy as np

    from pencore.integrators.driver import start_path
    from pencore.run import impact

    pr = impact.prepare("p2", "soil")
    mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss, model = pr.load_args()
    y = np.zeros(14)
    y[1], y[3], y[8] = 1.0, 1.0, -300.0  # 1 m above the surface, falling
    model = start_path(model, y)
    if part == "rhs":
        from pencore.kernels.forces import rhs_model

        return rhs_model, (y, mass, inertia, gravity, rings, bounds, coef, fric, eps, n_gauss,
                           model)  # fmt: skip
    if part == "jacobian":
        from pencore.kernels.jacobian import velocity_jacobian

        jac, f0 = np.zeros((14, 14)), np.zeros(14)
        return velocity_jacobian, (jac, y, f0, mass, inertia, gravity, rings, bounds, coef,
                                   fric, eps, model)  # fmt: skip
    raise ValueError(f"unknown part {part!r}; use one of {PARTS}")


def compile_part(part: str) -> None:
    """Compile one of :data:`PARTS` (:func:`part_call`), or run the variant of
    :data:`SECOND_PARTS`, saving what is compiled to the kernel cache."""
    if part in SECOND_PARTS:
        for _, kw in VARIANTS[-BESIDE:]:
            run_variant(kw)
        return
    function, args = part_call(part)
    function(*args)


def _cores() -> int:
    """Cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _start_parts(parts: Sequence[str]) -> list[subprocess.Popen]:
    """``python -m pencore.warmup --part NAME`` for each part, started (not waited for)."""
    from pencore.kernels.buildcache import warmup_command

    here = Path(__file__).resolve().parent.parent  # this process's pencore
    # stderr kept: the compile notice is this process's to say, once
    return [
        subprocess.Popen(warmup_command(here, "--part", part), stderr=subprocess.PIPE)
        for part in parts
    ]


def _finish(procs: Sequence[subprocess.Popen]) -> None:
    """Wait for the part processes; a failed one is said with its last lines (what it
    should have compiled is compiled by the variants instead)."""
    for proc in procs:
        _, err = proc.communicate()
        if proc.returncode != 0:
            tail = "\n".join(err.decode(errors="replace").strip().splitlines()[-5:])
            print(
                f"pencore warmup: part {proc.args[-1]!r} exited "
                f"{proc.returncode}; the variants compile it instead\n{tail}",
                file=sys.stderr,
            )


def compile_parts_side_by_side(verbose: bool = True) -> list[subprocess.Popen]:
    """On a cold cache with two or more cores, compile :data:`PARTS` in parallel processes
    (``python -m pencore.warmup --part NAME``), then start :data:`SECOND_PARTS` (returned,
    for the caller to wait for while it compiles the integrator). Nothing is done (an empty
    list) with one core or when the integrator is already in a cache. A failed part only
    costs its time: the variants compile whatever is missing."""
    from pencore.integrators.rosenbrock import integrate_chunk
    from pencore.kernels.cache import compiled_in_cache

    if _cores() < 2 or compiled_in_cache(integrate_chunk):
        return []
    if verbose:
        print(f"pencore warmup: compiling {', '.join(PARTS)} side by side ...", flush=True)
    t = time.perf_counter()
    _finish(_start_parts(PARTS))
    if verbose:
        print(f"pencore warmup: parts compiled in {time.perf_counter() - t:.1f} s", flush=True)
    return _start_parts(SECOND_PARTS)


def warmup(verbose: bool = True) -> float:
    """Run one short oblique trajectory per kernel variant; returns the seconds taken.

    The runs are p2 into soil at 30 deg and 300 m/s (a few hundred steps each): every
    kernel is compiled with the argument types the studies use, and cached. With
    ``verbose``, each variant is announced before it runs (``kernel i of n``), and its
    time said after it: the first one, which compiles the shared kernels, takes most of
    a cold warm-up.
    """
    start = time.perf_counter()
    beside = compile_parts_side_by_side(verbose)
    n = len(VARIANTS)
    for i, (label, kw) in enumerate(VARIANTS, 1):
        if i == n - BESIDE + 1:  # the last variants are compiled beside the others
            _finish(beside)
        if verbose:  # said before the variant: a compile is the long part
            print(f"pencore warmup: kernel {i} of {n} ({label}) ...", flush=True)
        t = time.perf_counter()
        run_variant(kw)
        if verbose:
            print(f"pencore warmup: kernel {i} of {n} ready in {time.perf_counter() - t:.1f} s")
    return time.perf_counter() - start


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m pencore.warmup [--host]``; returns the exit status."""
    args = list(argv if argv is not None else sys.argv[1:])
    if len(args) == 2 and args[0] == "--part" and args[1] in PARTS + SECOND_PARTS:
        compile_part(args[1])  # one process of compile_parts_side_by_side
        return 0
    if args not in ([], ["--host"]):
        print("usage: python -m pencore.warmup [--host]", file=sys.stderr)
        return 2
    if args:
        if "pencore.kernels" in sys.modules:  # its compiled functions have chosen already
            print(
                "pencore warmup: --host needs a fresh process (python -m pencore.warmup --host)",
                file=sys.stderr,
            )
            return 2
        os.environ["PENCORE_NO_SHIPPED_KERNELS"] = "1"  # read when the kernels are defined
    total = warmup()
    print(f"pencore warmup: kernels compiled and cached in {total:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
