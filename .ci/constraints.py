"""Print constraints.txt: the exact versions of pencore's ``workflow`` dependency tree in
the running environment (``pip freeze`` restricted to what ``pencore[workflow]`` needs).

Run it in the environment whose reproduction made results/archive/ (after
``python -m pip install -e '.[workflow]'`` and ``python -m snakemake --cores 2``):

    python .ci/constraints.py > constraints.txt

The tree is walked from pyproject.toml's dependencies and the ``workflow`` extra through
each installed distribution's own requirements (markers evaluated here, extras
followed); pencore itself is left out (it is installed from the clone).
"""

from __future__ import annotations

import sys
import tomllib
from importlib import metadata
from pathlib import Path

from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

REPO = Path(__file__).resolve().parents[1]
HEADER = """\
# Exact versions of the reproduction's dependency tree (pencore[workflow]), as installed
# where the archived results (results/archive/) were made. The reproduction command of
# the README installs with them, so that a fresh machine runs the same numpy, scipy,
# numba, xarray, netCDF4 and Snakemake and makes the archive bit-identical:
#     uv pip install -e '.[workflow]' -c constraints.txt --build-constraint constraints.txt
# The tests do not use this file: CI installs the newest versions pyproject.toml allows
# in a fresh virtual environment (.ci/run), which is what a fresh install gets.
# Regenerate after a reproduction in an environment with newer versions:
#     python .ci/constraints.py > constraints.txt
"""


def _applies(req: Requirement, extras: frozenset[str] | set[str]) -> bool:
    """Whether ``req`` is needed here when its parent was asked for with ``extras`` (its
    marker evaluated on this platform, once per extra; no extras: the plain install)."""
    return req.marker is None or any(req.marker.evaluate({"extra": e}) for e in (extras or {""}))


def tree(requirements: list[Requirement]) -> dict[str, str]:
    """name -> installed version of every distribution the requirements reach."""
    seen: dict[str, str] = {}
    todo = [r for r in requirements if _applies(r, frozenset())]
    while todo:
        req = todo.pop()
        name = canonicalize_name(req.name)
        try:
            dist = metadata.distribution(req.name)
        except metadata.PackageNotFoundError:
            continue  # not needed on this platform
        first = name not in seen
        seen[name] = dist.version
        if not first and not req.extras:
            continue
        for text in dist.requires or []:
            sub = Requirement(text)
            if _applies(sub, req.extras):
                todo.append(sub)
    return seen


def main() -> int:
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    roots = [Requirement(r) for r in project["dependencies"]]
    roots += [Requirement(r) for r in project["optional-dependencies"]["workflow"]]
    pins = {n: v for n, v in tree(roots).items() if n != "pencore"}
    sys.stdout.write(HEADER)
    sys.stdout.writelines(f"{n}=={v}\n" for n, v in sorted(pins.items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
