"""The editable install of README command 1, timed in fresh virtual environments.

For each commit and installer asked for (default HEAD with uv): a clean clone, a fresh
venv (``python -m venv``), and the install of README command 1 without its constraints,
with an empty build cache (``PENCORE_BUILD_CACHE`` a new directory: the kernels are
compiled, as on a fresh machine), then the same install in a second fresh venv with that
build cache kept (the kernels copied, not compiled), in the environment a fresh install
sees (no PYTHONPATH, NUMBA_* or PENCORE_* settings of this shell). The installers
(:data:`INSTALLERS`): ``pip``, ``python -m pip install -e '.[workflow]'``; ``uv``,
``python -m pip install uv`` and then ``python -m uv pip install -e '.[workflow]'``, both
timed, as the README runs them. The download caches of pip and uv are left as they are
(the machine's package registry is local; a fresh machine downloads on top). Wall and CPU
seconds from the first command's start to the last one's exit
(``bench_reproduction.timed_run``). Run several in one call to measure them back to back,
e.g. ``python benchmarks/bench_install.py 1704ae2:pip HEAD:pip HEAD:uv``.

Writes benchmarks/results/install.csv (with the machine and its load). Run from the
repository root, under the heavy-job lock on a shared machine.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import pandas as pd

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from bench_fresh_install import _env  # noqa: E402
from bench_reproduction import timed_run  # noqa: E402
from machine import machine  # noqa: E402

#: the commands of each installer, after ``python -m`` of the new venv's Python
INSTALLERS = {
    "pip": (["pip", "install", "-q", "-e", ".[workflow]"],),
    "uv": (["pip", "install", "-q", "uv"], ["uv", "pip", "install", "-q", "-e", ".[workflow]"]),
}


#: what the second install of each installer reuses (the kernels are not compiled)
SECOND = {
    "pip": "build cache of the first: the kernels are copied",
    "uv": "uv's build of the first (its cache), else the build cache: nothing is compiled",
}


def timed_install(
    clone: Path, venv: Path, build_cache: Path, installer: str = "uv"
) -> tuple[float, float]:
    """Wall and CPU seconds of the ``installer``'s commands (:data:`INSTALLERS`) installing
    ``clone`` into a new ``venv``, in the environment a fresh install sees
    (``bench_fresh_install._env``)."""
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    env = {**_env(), "PENCORE_BUILD_CACHE": str(build_cache)}
    wall = cpu = 0.0
    for command in INSTALLERS[installer]:
        w, c = timed_run([str(venv / "bin" / "python"), "-m", *command], clone, env)
        wall, cpu = wall + w, cpu + c
    return wall, cpu


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="*", default=["HEAD:uv"], help="COMMIT[:INSTALLER] (uv)")
    ap.add_argument("--csv", default=str(HERE / "results" / "install.csv"))
    args = ap.parse_args()
    repo = HERE.parent
    rows = []
    for run in args.runs:
        commit, _, installer = run.partition(":")
        installer = installer or "uv"  # README command 1's
        if installer not in INSTALLERS:
            raise SystemExit(f"bench_install: {run!r}: the installer is one of {list(INSTALLERS)}")
        sha = subprocess.run(["git", "rev-parse", "--short", commit], cwd=repo,
                             capture_output=True, text=True, check=True).stdout.strip()  # fmt: skip
        with tempfile.TemporaryDirectory(prefix="pencore-install-") as tmp:
            clone, cache = Path(tmp) / "clone", Path(tmp) / "build-cache"
            subprocess.run(["git", "clone", "-q", str(repo), str(clone)], check=True)
            subprocess.run(["git", "checkout", "-q", sha], cwd=clone, check=True)
            before = machine()
            cold = timed_install(clone, Path(tmp) / "venv1", cache, installer)
            warm = timed_install(clone, Path(tmp) / "venv2", cache, installer)
        second = SECOND[installer]
        for case, (wall, cpu), note in (
            ("fresh_editable_install", cold, "empty build cache: the kernels are compiled"),
            ("second_editable_install", warm, second),
        ):
            print(f"{sha} {installer} {case}: {wall:.1f} s ({cpu:.1f} s CPU)", flush=True)
            rows.append({"case": case, "installer": installer, "wall_s": round(wall, 1),
                         "cpu_s": round(cpu, 1), "note": note,
                         **{**before, "commit": sha}})  # fmt: skip
    Path(args.csv).parent.mkdir(parents=True, exist_ok=True)
    pd.DataFrame(rows).to_csv(args.csv, index=False)


if __name__ == "__main__":
    main()
