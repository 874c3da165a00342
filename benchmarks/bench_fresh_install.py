"""First result on a fresh install: the wheel's shipped kernels against a first compile.

From a clean clone of the committed tree: build the wheel with the project's own build
step (``python -m build --wheel``, whose ``setup.py`` compiles the kernels for the
portable target; with an empty build cache of its own, so that it compiles), install it
in a fresh virtual environment (``--system-site-packages`` for numpy, numba and the
rest; pencore itself comes from the wheel, checked), and time
the first ``pencore simulate --projectile p2 --target soil --velocity 280`` from an
empty directory, then a second one. A fresh environment has an empty local kernel cache,
so the first run either loads the shipped kernels or compiles (it then says so on
stderr: recorded as ``compile_notice``).

Writes benchmarks/results/fresh_install.csv (with the machine and its load). Run from the
repository root, under the heavy-job lock on a shared machine:
python benchmarks/bench_fresh_install.py [--keep DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

import pandas as pd

HERE = Path(__file__).parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

SIMULATE = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "280"]
NOTICE = "pencore: compiling the numba kernels"


def _env() -> dict[str, str]:
    """The caller's environment without anything that would point pencore or numba
    elsewhere (a fresh install sees none of them)."""
    drop = ("PYTHONPATH", "NUMBA_CACHE_DIR", "NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES")
    return {k: v for k, v in os.environ.items() if k not in drop and not k.startswith("PENCORE")}


def _run(cmd: list[str], **kw) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, env=kw.pop("env", _env()), **kw)
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--keep", help="build in this folder and keep it (default: a temporary one)")
    args = ap.parse_args()
    tmp = Path(args.keep or tempfile.mkdtemp(prefix="pencore-fresh-"))
    tmp.mkdir(parents=True, exist_ok=True)
    clone, dist, venv, empty = tmp / "clone", tmp / "dist", tmp / "venv", tmp / "empty"
    for d in (clone, dist, venv, empty):
        shutil.rmtree(d, ignore_errors=True)
    empty.mkdir()
    _run(["git", "clone", "--quiet", str(REPO), str(clone)])
    # an empty build cache of its own: the build compiles, as on a first install
    # (the user's build cache would let it copy kernels an earlier build compiled)
    cache = tmp / "build-cache"
    shutil.rmtree(cache, ignore_errors=True)
    build_env = {**_env(), "PENCORE_BUILD_CACHE": str(cache)}
    build = [sys.executable, "-m", "build", "--wheel", "--outdir", str(dist), str(clone)]
    build_s = _run(build, env=build_env)
    (wheel,) = dist.glob("pencore-*.whl")
    with zipfile.ZipFile(wheel) as zf:
        names = zf.namelist()
        info = json.loads(zf.read("pencore/kernels/compiled/BUILD.json"))
    shipped = sum(n.endswith(".nbc") for n in names)
    _run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)])
    py = venv / "bin" / "python"
    pip = [str(py), "-m", "pip", "install", "--quiet", "--no-deps", "--ignore-installed"]
    install_s = _run([*pip, str(wheel)])
    where = subprocess.run(
        [str(py), "-c", "import pencore; print(pencore.__file__)"],
        cwd=empty, env=_env(), capture_output=True, text=True, check=True,
    ).stdout.strip()  # fmt: skip
    if not where.startswith(str(venv)):
        raise SystemExit(f"bench_fresh_install: pencore came from {where}, not the wheel")
    rows = []
    for case in ("first_result_fresh_install", "second_result"):
        t0 = time.perf_counter()
        done = subprocess.run(
            [str(venv / "bin" / "pencore"), *SIMULATE],
            cwd=empty, env=_env(), capture_output=True, text=True, check=True,
        )  # fmt: skip
        wall = time.perf_counter() - t0
        rows.append((case, wall, NOTICE in done.stderr))
    rows.append(("build_wheel", build_s, False))
    rows.append(("install_wheel", install_s, False))
    m = machine()
    note = {
        "first_result_fresh_install": "pencore simulate p2 soil 280 m/s, first run after "
        "installing the wheel in a fresh venv, from an empty directory",
        "second_result": "the same command again",
        "build_wheel": f"python -m build --wheel from a clean clone (kernels compiled in "
        f"{info['compile_s']} s: {info['target']}; {shipped} compiled files)",
        "install_wheel": "pip install of the wheel into the fresh venv",
    }
    df = pd.DataFrame(
        [
            {
                "case": c,
                "wall_s": s,
                "compile_notice": n,
                "note": note[c],
                "numba": info["numba"],
                "python": info["python"],
                **m,
            }
            for c, s, n in rows
        ]
    )
    (HERE / "results").mkdir(exist_ok=True)
    df.to_csv(HERE / "results" / "fresh_install.csv", index=False, float_format="%.3g")
    print(df[["case", "wall_s", "compile_notice"]].to_string(index=False))
    print(m)
    if not args.keep:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
