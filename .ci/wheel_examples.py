#!/usr/bin/env python
"""The examples of a Markdown page, taken from its fenced blocks and run as written.

    python .ci/wheel_examples.py PAGE.md [PAGE.md ...]

run from an empty directory with an installed pencore (``.ci/wheel.sh``), writes the files
the page shows (a ``yaml`` block whose first line is ``# NAME.yaml``), runs every
``pencore`` command of its ``bash`` blocks and every ``python`` block there, and then reads
the paper's claims and builds the paper comparison from the installed package. Exit 0 when
every command exits 0 without compiling the kernels the wheel ships, 1 with one line per
failure otherwise.

``tests/docs/test_examples.py`` imports the same functions (:func:`blocks`,
:func:`commands`, :func:`shown_files`) to run the README's and the guide pages' blocks
from the repository.
"""

from __future__ import annotations

import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

#: A fence: three backticks, the info string (language or ``{directive}``), the body.
FENCE = re.compile(r"^```([^\n`]*)\n(.*?)^```[ \t]*$", re.M | re.S)
#: First line of a ``yaml`` block that is a whole file the page's commands name.
SHOWN_FILE = re.compile(r"^# (\S+\.ya?ml)\b")


@dataclass(frozen=True)
class Block:
    """One fenced block of a page: its info string, its text and its first line."""

    page: str
    info: str
    text: str
    line: int

    @property
    def lang(self) -> str:
        return self.info.split()[0] if self.info.split() else ""

    def __str__(self) -> str:
        return f"{self.page}:{self.line} ({self.info or 'no language'})"


def blocks(page: Path) -> list[Block]:
    """Every fenced block of ``page``, in order."""
    text = page.read_text()
    return [
        Block(page.name, m.group(1).strip(), m.group(2), text.count("\n", 0, m.start()) + 1)
        for m in FENCE.finditer(text)
    ]


def commands(block: Block) -> list[str]:
    """The shell commands of a ``bash`` block: comments dropped, ``\\`` continuations
    joined, ``a && b`` split into ``a`` and ``b``."""
    joined = re.sub(r"\\\n\s*", " ", block.text)
    out: list[str] = []
    for line in joined.splitlines():
        line = re.sub(r"(^|\s)#.*$", "", line).strip()
        if line:
            out += [c.strip() for c in line.split("&&")]
    return out


def shown_files(page_blocks: list[Block]) -> dict[str, str]:
    """The files a page shows whole: ``{name: text}`` of each ``yaml`` block whose first
    line is ``# NAME.yaml``."""
    out = {}
    for b in page_blocks:
        m = SHOWN_FILE.match(b.text) if b.lang == "yaml" else None
        if m:
            out[m.group(1)] = b.text
    return out


def run_page(page: Path, cwd: Path) -> list[str]:
    """Run the ``pencore`` commands and ``python`` blocks of ``page`` in ``cwd``; the
    failures, one line each."""
    found = blocks(page)
    for name, text in shown_files(found).items():
        (cwd / name).write_text(text)
    failures = []
    for b in found:
        if b.lang == "bash":
            todo = [c for c in commands(b) if c.startswith("pencore ")]
            jobs = [(c, ["bash", "-c", c]) for c in todo]
        elif b.lang == "python":
            jobs = [(f"python block at {b}", [sys.executable, "-c", b.text])]
        else:
            continue
        for what, argv in jobs:
            t0 = time.perf_counter()
            done = subprocess.run(argv, cwd=cwd, capture_output=True, text=True)
            dt = time.perf_counter() - t0
            print(f"[{dt:5.1f} s] exit {done.returncode}: {what}")
            if done.returncode != 0:
                failures.append(f"{page.name}: {what} exited {done.returncode}: {done.stderr}")
            if "compiling the numba kernels" in done.stderr:
                # the wheel ships kernels compiled at build time: they must load here
                failures.append(f"{page.name}: {what} compiled the kernels the wheel ships")
    return failures


PAPER = """
import sys
import pandas as pd
import pencore
from pencore.paper.claims import CLAIMS_FILE, TABLE2_FILE, disputed_values, load_claims
from pencore.studies.comparison import paper_comparison

repo = sys.argv[1]
assert "site-packages" in str(CLAIMS_FILE), CLAIMS_FILE
# the installed data is the repository's: claims and Table 2, row for row
claims = load_claims()
shipped = pd.read_csv(f"{repo}/config/paper_claims.csv", comment="#", dtype=str,
                      keep_default_na=False)
pd.testing.assert_frame_equal(claims.reset_index(drop=True), shipped)
pd.testing.assert_frame_equal(pd.read_csv(TABLE2_FILE, comment="#"),
                              pd.read_csv(f"{repo}/config/table2.csv", comment="#"))
table = paper_comparison(claims=claims)  # no study datasets: the Table 3 rows
assert len(table) > 0 and set(table["claim"]) <= set(claims["id"])
ds = pencore.simulate("p2", "soil", 280.0)
print(f"paper claims: {len(claims)}; comparison rows without results: {len(table)}; "
      f"depth of #2 at 280 m/s: {ds.penetration_depth.item():.4g} m "
      f"(paper's Table 2: {disputed_values()['depth_280']} m)")
"""


def main(pages: list[Path]) -> int:
    cwd = Path.cwd()
    if any(cwd.iterdir()):
        print(f"wheel_examples: run from an empty directory, not {cwd}")
        return 1
    failures = []
    for page in pages:
        failures += run_page(page, cwd)
    repo = str(Path(__file__).resolve().parents[1])
    done = subprocess.run([sys.executable, "-c", PAPER, repo], capture_output=True, text=True)
    print(done.stdout, end="")
    if done.returncode != 0:
        failures.append(f"paper claims and comparison: {done.stderr}")
    for f in failures:
        print(f"wheel_examples: {f}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main([Path(p).resolve() for p in sys.argv[1:]]))
