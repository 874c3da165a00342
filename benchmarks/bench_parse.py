"""The worst inputs the input gate admits or refuses, timed: every parse is decided in seconds.

Each case is a YAML text at a bound of :mod:`pencore.inputs.gate` or of the count limits
of :data:`pencore.inputs.limits.LIMITS`, read the way a user's file is read:

* ``values_at_cap``: a flow list of ``MAX_YAML_NODES - 2`` numbers (the most values a
  document may hold), parsed;
* ``values_over_cap``: a 16 MiB flow list (~5.6 million numbers), refused when the count
  passes the cap;
* ``block_over_cap``: 10^5 target layers in block style (3.5 MB), refused at the cap;
* ``alias_expansion``: aliases that expand to just over the cap, refused;
* ``deep_nesting``: 16 MiB of ``[``, refused at depth ``MAX_YAML_DEPTH``;
* ``long_scalar``, ``long_comment``: one 16 MiB string, 16 MiB of comment lines;
* ``friction_table_longest``: a target file with a friction table of
  ``LIMITS["friction_rows"]`` rows, read into a :class:`~pencore.inputs.target.Target`;
* ``layers_most``: a target file of ``LIMITS["layers"]`` plates, read into a Target;
* ``friction_table_over``, ``layers_over``: one more row or layer than allowed, refused.

``fast_yaml`` says whether PyYAML's libyaml scanner was used (``yaml.__with_libyaml__``).
Writes benchmarks/results/parse.csv (with the machine and its load).
Run: python benchmarks/bench_parse.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).parent))
from machine import machine  # noqa: E402

from pencore.errors import InputError  # noqa: E402
from pencore.inputs import gate  # noqa: E402
from pencore.inputs.library import get_target  # noqa: E402
from pencore.inputs.limits import LIMITS  # noqa: E402

MIB16 = gate.MAX_YAML_BYTES


def _alias_text() -> str:
    # a list of 100 numbers, listed by 2001 aliases: 200 100 values once expanded
    return "a: &a [" + ", ".join(["1"] * 100) + "]\nb: [" + ", ".join(["*a"] * 2001) + "]\n"


def _friction(rows: int) -> str:
    body = "".join(f"  - [{i}, 0.1]\n" for i in range(rows))
    return f"name: rough\ncoefficients: [1.0e7, 0.0, 100.0]\nfriction:\n{body}"


def _layers(n: int) -> str:
    return "name: stack\nlayers:\n" + "  - {medium: aluminium, thickness: 0.001}\n" * n


def cases() -> dict[str, tuple[str, str, bool]]:
    """Case name -> (YAML text, read by ``"gate"`` or as a ``"target"``, refused?)."""
    cap = gate.MAX_YAML_NODES
    items_16 = (MIB16 - 16) // 3
    rows = int(LIMITS["friction_rows"].hi)
    layers = int(LIMITS["layers"].hi)
    return {
        "values_at_cap": ("[" + "1, " * (cap - 2) + "1]", "gate", False),
        "values_over_cap": ("[" + "1, " * items_16 + "1]", "gate", True),
        "block_over_cap": (_layers(10**5), "target", True),
        "alias_expansion": (_alias_text(), "gate", True),
        "deep_nesting": ("[" * (MIB16 - 1), "gate", True),
        "long_scalar": ("x: " + "a" * (MIB16 - 8) + "\n", "gate", False),
        "long_comment": (("# " + "c" * 78 + "\n") * (MIB16 // 81) + "x: 1\n", "gate", False),
        "friction_table_longest": (_friction(rows), "target", False),
        "friction_table_over": (_friction(rows + 1), "target", True),
        "layers_most": (_layers(layers), "target", False),
        "layers_over": (_layers(layers + 1), "target", True),
    }


def timed(call: Callable[[], object]) -> tuple[float, str]:
    """Wall seconds of ``call`` and how it ended (``ok`` or the refusal, cut short)."""
    t = time.perf_counter()
    try:
        call()
        outcome = "ok"
    except InputError as exc:
        outcome = "refused: " + str(exc).rsplit(".yaml'", 1)[-1].lstrip(": ")[:90]
    return time.perf_counter() - t, outcome


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, (text, reader, refused) in cases().items():
            path = Path(tmp) / f"{name}.yaml"
            path.write_text(text)
            if reader == "target":
                call: Callable[[], object] = lambda p=path: get_target(str(p))  # noqa: E731
            else:
                call = lambda p=path: gate.read_yaml(p, "file")  # noqa: E731
            runs = [timed(call) for _ in range(args.repeats)]
            outcome = runs[0][1]
            if outcome.startswith("refused") != refused:
                raise SystemExit(f"bench_parse: {name} ended {outcome!r}")
            rows.append(
                {
                    "case": name,
                    "bytes": len(text.encode()),
                    "wall_s": statistics.median(r[0] for r in runs),
                    "max_wall_s": max(r[0] for r in runs),
                    "reader": reader,
                    "outcome": outcome,
                    "fast_yaml": gate.FAST_YAML,
                }
            )
            print(f"{name:24s} {rows[-1]['wall_s']:.3f} s  {outcome}", flush=True)
    m = machine()
    df = pd.DataFrame([{**r, **m} for r in rows])
    out = Path(__file__).parent / "results"
    out.mkdir(exist_ok=True)
    df.to_csv(out / "parse.csv", index=False, float_format="%.3g")
    print(df[["case", "bytes", "wall_s", "max_wall_s", "fast_yaml"]].to_string(index=False))


if __name__ == "__main__":
    main()
