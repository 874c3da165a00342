#!/usr/bin/env python
"""Check a built wheel and sdist: every module of src/pencore, the shipped data and the
compiled kernels of the build step (setup.py) are in the wheel, and the sdist holds the
sources, README, LICENSE and pyproject.toml (and no compiled kernels).

    python .ci/check_dist.py DIST_DIR

Exit 0 when both hold, 1 with one line per missing file otherwise.
"""

from __future__ import annotations

import sys
import tarfile
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def main(dist: Path) -> int:
    wheels, sdists = sorted(dist.glob("*.whl")), sorted(dist.glob("*.tar.gz"))
    if len(wheels) != 1 or len(sdists) != 1:
        print(f"check_dist: expected one wheel and one sdist in {dist}")
        return 1
    src = REPO / "src"
    wanted = {p.relative_to(src).as_posix() for p in (src / "pencore").rglob("*.py")}
    for pattern in ("data/*.yaml", "data/*.csv"):
        wanted |= {p.relative_to(src).as_posix() for p in (src / "pencore").rglob(pattern)}
    in_wheel = set(zipfile.ZipFile(wheels[0]).namelist())
    missing = sorted(wanted - in_wheel)
    compiled = "pencore/kernels/compiled/"
    if not any(n.startswith(compiled) and n.endswith(".nbc") for n in in_wheel):
        missing.append(f"{compiled}*.nbc (the kernels compiled by setup.py's build step)")
    with tarfile.open(sdists[0]) as tar:
        names = {n.split("/", 1)[1] for n in tar.getnames() if "/" in n}
    missing += [
        f"sdist: {n}"
        for n in ("README.md", "LICENSE", "pyproject.toml", "src/pencore/__init__.py")
        if n not in names
    ]
    missing += [f"sdist: no compiled kernels, but {n}" for n in names if "/compiled/" in n]
    for m in missing:
        print(f"check_dist: missing {m}")
    if not missing:
        print(f"check_dist: {wheels[0].name} ({len(wanted)} files) and {sdists[0].name} complete")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
