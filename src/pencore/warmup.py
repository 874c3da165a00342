"""Compile and cache every numba kernel once, as an install step.

pencore's kernels are compiled on first use and cached on disk (``cache=True``; in
``__pycache__`` next to the sources, or under ``NUMBA_CACHE_DIR``). A fresh clone, a CI
run or the first jobs of a reproduction would otherwise each pay ~55 s of compilation
before their first result (on the 2-core benchmark machine; the default path compiles
nearly every kernel, ``benchmarks/bench_compile.py``), and say so once on stderr
(:func:`pencore.run.impact._compile_notice`). ``python -m pencore.warmup`` runs one short
trajectory of every kernel variant (the default DAFL on rings with the Rosenbrock
integrator, the cavity and factor shank models, the panel surface and the explicit
integrator), so that afterwards a fresh process loads the kernels from the cache
(``benchmarks/bench_startup.py`` measures both). On a cold cache it says so once too,
at its first variant: the variants share one process, and the notice is once per process.

Run: ``python -m pencore.warmup`` (the README's two set-up commands and ``.ci/run`` do).
"""

from __future__ import annotations

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
    kernel is compiled with the argument types the studies use, and cached.
    """
    start = time.perf_counter()
    from pencore.run.impact import simulate

    for label, kw in VARIANTS:
        t = time.perf_counter()
        simulate("p2", "soil", 300.0, obliquity=30.0, **kw)
        if verbose:
            print(f"pencore warmup: {label:28s} {time.perf_counter() - t:6.2f} s", flush=True)
    return time.perf_counter() - start


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m pencore.warmup``; returns the exit status."""
    if list(argv if argv is not None else sys.argv[1:]):
        print("usage: python -m pencore.warmup (takes no options)", file=sys.stderr)
        return 2
    total = warmup()
    print(f"pencore warmup: kernels compiled and cached in {total:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
