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

Run: ``python -m pencore.warmup [--host]`` (``setup.py``'s build step runs it, for the
shipped kernels).
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Sequence

#: (label, keyword arguments of pencore.simulate) of the variants compiled.
VARIANTS: tuple[tuple[str, dict], ...] = (
    ("dafl, rings, rosenbrock", {}),
    ("cavity shank", {"shank": "cavity"}),
    ("factor shank", {"shank": "factor"}),
    ("panels", {"emulation": {"surface": "panels"}}),
    ("explicit integrator", {"emulation": {"integrator": "explicit", "dt": 2e-5}}),
)


def warmup(verbose: bool = True) -> float:
    """Run one short oblique trajectory per kernel variant; returns the seconds taken.

    The runs are p2 into soil at 30 deg and 300 m/s (a few hundred steps each): every
    kernel is compiled with the argument types the studies use, and cached. With
    ``verbose``, each variant is announced before it runs (``kernel i of n``), and its
    time said after it: the first one, which compiles the shared kernels, takes most of
    a cold warm-up.
    """
    start = time.perf_counter()
    from pencore.run import impact

    n = len(VARIANTS)
    for i, (label, kw) in enumerate(VARIANTS, 1):
        if verbose:  # said before the variant: a compile is the long part
            print(f"pencore warmup: kernel {i} of {n} ({label}) ...", flush=True)
        t = time.perf_counter()
        impact.simulate("p2", "soil", 300.0, obliquity=30.0, **kw)
        if verbose:
            print(f"pencore warmup: kernel {i} of {n} ready in {time.perf_counter() - t:.1f} s")
    return time.perf_counter() - start


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m pencore.warmup [--host]``; returns the exit status."""
    args = list(argv if argv is not None else sys.argv[1:])
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
