"""The packaging check's tag rule (.ci/check_dist.py): a wheel that ships compiled kernels
is tagged with the CPython version, ABI and platform its BUILD.json records, never
``py3-none-any`` (pip would install it anywhere and only the runtime check would notice)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("check_dist", REPO / ".ci" / "check_dist.py")
check_dist = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(check_dist)

LINUX = {"python": "py311", "target": "x86_64-unknown-linux-gnu, cpu 'generic', features ''"}


@pytest.mark.parametrize(
    ("wheel", "build"),
    [
        ("pencore-0.2.0-cp311-cp311-linux_x86_64.whl", LINUX),
        ("pencore-0.2.0-cp311-cp311-manylinux_2_28_x86_64.whl", LINUX),
        (
            "pencore-0.2.0-cp313-cp313t-linux_aarch64.whl",
            {"python": "py313t", "target": "aarch64-unknown-linux-gnu, cpu 'generic', features ''"},
        ),
        (
            "pencore-0.2.0-cp312-cp312-win_amd64.whl",
            {"python": "py312", "target": "x86_64-pc-windows-msvc, cpu 'generic', features ''"},
        ),
        (
            "pencore-0.2.0-cp312-cp312-macosx_11_0_arm64.whl",
            {"python": "py312", "target": "arm64-apple-darwin23.1.0, cpu 'generic', features ''"},
        ),
    ],
)
def test_a_tag_that_matches_the_kernels_passes(wheel, build):
    assert check_dist.tag_problems(wheel, build, root_is_purelib=False) == []


@pytest.mark.parametrize(
    ("wheel", "says"),
    [
        ("pencore-0.2.0-py3-none-any.whl", "tag py3-none is not cp311-cp311"),
        ("pencore-0.2.0-cp312-cp312-linux_x86_64.whl", "tag cp312-cp312 is not cp311-cp311"),
        ("pencore-0.2.0-cp311-abi3-linux_x86_64.whl", "tag cp311-abi3 is not cp311-cp311"),
        ("pencore-0.2.0-cp311-cp311-linux_aarch64.whl", "platform tag linux_aarch64 is not"),
        ("pencore-0.2.0-cp311-cp311-macosx_11_0_x86_64.whl", "platform tag macosx_11_0_x86_64"),
    ],
)
def test_a_tag_that_does_not_match_the_kernels_is_named(wheel, says):
    problems = check_dist.tag_problems(wheel, LINUX, root_is_purelib=False)
    assert len(problems) >= 1 and problems[0].startswith(says)


def test_a_pure_wheel_with_kernels_is_refused():
    problems = check_dist.tag_problems(
        "pencore-0.2.0-cp311-cp311-linux_x86_64.whl", LINUX, root_is_purelib=True
    )
    assert problems == ["WHEEL says Root-Is-Purelib: true for compiled kernels"]
