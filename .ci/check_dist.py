#!/usr/bin/env python
"""Check a built wheel and sdist: every module of src/pencore, the shipped data and the
compiled kernels of the build step (setup.py) are in the wheel, its tag says what the
kernels fit (the interpreter, ABI and platform of BUILD.json's python and target, not
``py3-none-any``; :func:`tag_problems`), and the sdist holds the sources, README, LICENSE
and pyproject.toml (and no compiled kernels).

    python .ci/check_dist.py DIST_DIR

Exit 0 when both hold, 1 with one line per missing file otherwise.
"""

from __future__ import annotations

import json
import sys
import tarfile
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: The platform tags of an operating system, by the word its target triple holds.
OS_PLATFORMS = {
    "linux": ("linux_", "manylinux", "musllinux"),
    "darwin": ("macosx_",),
    "windows": ("win",),
}
#: An architecture as the platform tag spells it, where it differs from the triple.
ARCH_IN_TAG = {
    ("windows", "x86_64"): "amd64",
    ("windows", "i386"): "32",
    ("darwin", "aarch64"): "arm64",
}


def tag_problems(wheel_name: str, build: dict[str, str], root_is_purelib: bool) -> list[str]:
    """What is wrong with the tag of a wheel that ships the kernels of ``build`` (its
    BUILD.json): the interpreter and ABI must be CPython of ``build["python"]`` (numba's
    cache files are per Python version), the platform that of ``build["target"]``'s
    triple, and the wheel not pure (its files go to platlib)."""
    python, abi, platform = wheel_name.removesuffix(".whl").split("-")[-3:]
    digits = build["python"].removeprefix("py")
    version = digits.rstrip("abcdefghijklmnopqrstuvwxyz")
    problems = []
    if python != f"cp{version}" or abi != f"cp{digits}":
        problems.append(f"tag {python}-{abi} is not cp{version}-cp{digits} ({build['python']})")
    triple = build["target"].split(",")[0].strip()
    arch = triple.split("-")[0]
    system = next(
        (s for s in OS_PLATFORMS if s in triple or (s == "darwin" and "apple" in triple)), None
    )
    if system is None:
        problems.append(f"target {triple} is of no platform this check knows")
    else:
        arch = ARCH_IN_TAG.get((system, arch), arch)
        ok = any(
            p.startswith(OS_PLATFORMS[system]) and p.endswith(arch) for p in platform.split(".")
        )
        if not ok:
            problems.append(f"platform tag {platform} is not {system} {arch} ({triple})")
    if root_is_purelib:
        problems.append("WHEEL says Root-Is-Purelib: true for compiled kernels")
    return problems


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
    if f"{compiled}BUILD.json" in in_wheel:
        with zipfile.ZipFile(wheels[0]) as zf:
            build = json.loads(zf.read(f"{compiled}BUILD.json"))
            wheel_file = next(n for n in in_wheel if n.endswith(".dist-info/WHEEL"))
            purelib = "Root-Is-Purelib: true" in zf.read(wheel_file).decode()
        missing += [f"a matching tag: {p}" for p in tag_problems(wheels[0].name, build, purelib)]
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
