"""README.md: the two set-up commands first, short, its numbers generated or checked, its
links alive and its Python example working."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
README = (REPO / "README.md").read_text()


def test_opens_with_exactly_the_two_setup_commands():
    first = README.split("```")[1].strip().splitlines()
    assert first[0] == "bash"
    commands = first[1:]
    assert len(commands) == 2

    # each makes and enters a virtual environment of its own (uv installs only into one),
    # installs uv and then installs with it: the pinned reproduction's `.venv` and the
    # tests' `.venv-test`, so the tests' newest versions never move the reproduction's
    def uv(venv: str) -> str:
        return (
            f"python -m venv {venv} && . {venv}/bin/activate && "
            "python -m pip install uv && python -m uv pip install -e "
        )

    # the reproduction installs the pinned versions the archive was made with, and builds
    # the kernels with them (the build's numba is the one the kernels must fit)
    assert commands[0].startswith(
        f"{uv('.venv')}'.[workflow]' -c constraints.txt --build-constraint constraints.txt &&"
    )
    assert "snakemake --cores 2" in commands[0]
    # the tests resolve the newest versions pyproject.toml allows, as CI does
    assert commands[1].startswith(f"{uv('.venv-test')}'.[test]' &&")
    envs = [re.findall(r"python -m venv (\S+) ", c) for c in commands]
    assert envs == [[".venv"], [".venv-test"]], envs
    assert "constraints" not in commands[1]
    assert commands[1].endswith("python -m pytest -q -n 2")
    # CI runs the very test command a user runs, in a fresh virtual environment with a
    # fresh resolve (not the constraints, not whatever the machine has installed)
    test_command = commands[1].split("&&")[-1].strip()
    ci = (Path(__file__).parents[2] / ".ci" / "run").read_text()
    assert test_command in ci.splitlines()
    assert "python -m venv" in ci and "-c constraints.txt" not in ci
    install = [ln for ln in ci.splitlines() if "uv pip install" in ln and "-e '." in ln]
    assert install and all("-c " not in ln for ln in install)
    venv = ci.index("python -m venv")
    assert venv < ci.index(install[0]) and venv < ci.index(test_command)
    # nothing but the title before them
    assert README.split("```")[0].strip() == "# pencore"


def test_is_for_users_not_a_lab_notebook():
    lines = README.splitlines()
    assert len(lines) <= 170, f"README has {len(lines)} lines; details belong in docs/"
    assert not re.search(r"\bround\b", README, re.I)


def test_generated_blocks_are_current(gen):
    assert "<!-- generated: headline" in README
    assert gen.readme_with_blocks(README) == README, (
        "README's generated blocks are stale: run `python docs/_ext/pencore_docs.py --readme`"
    )


def test_timing_line_says_how_busy_the_host_was(gen, tmp_path, monkeypatch):
    """The timing line gives the tests' time once benchmarks/bench_tests.py has measured it,
    and says whether its figures are an idle host's or how busy the host was."""
    import shutil

    for name in ("speed.csv", "compile.csv", "install.csv"):
        shutil.copy(gen.BENCH / name, tmp_path / name)
    monkeypatch.setattr(gen, "BENCH", tmp_path)
    head = "command,wall_s,cpu_s,passed,failed,errors,skipped,load_mean,cpu_model,cores,"
    head += "load_1min,load_5min,load_15min,measured_utc,commit\n"
    row = "python -m pytest -q -n 2,{wall},700,2300,0,0,0,{mean},AMD EPYC,2,{l1},1,1,x,abc\n"
    (tmp_path / "tests.csv").write_text(head + row.format(wall=330, mean=0.9, l1=0.4))
    idle = gen.timing_sentence()
    assert "the tests about 5.5 min" in idle and "`tests.csv`" in idle
    assert "These are idle-host figures" in idle and "a busy host takes longer" in idle
    (tmp_path / "tests.csv").write_text(head + row.format(wall=900, mean=6.3, l1=5.0))
    busy = gen.timing_sentence()
    assert "the tests about 15 min" in busy
    assert "the tests' a busy one's (a mean load of 6.3)" in busy
    assert "idle-host" not in busy
    other = head + row.format(wall=900, mean=6.3, l1=5.0).replace("AMD EPYC", "Other CPU")
    (tmp_path / "tests.csv").write_text(other)
    assert "the tests about 15 min on an Other CPU (" in gen.timing_sentence()


def test_relative_links_resolve():
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README)
    assert links
    missing = [x for x in links if not x.startswith("http") and not (REPO / x).exists()]
    assert not missing, f"README links to missing files: {missing}"


def test_every_number_in_the_prose_is_checked():
    """Numbers outside code and generated blocks: each is the paper's citation, or
    a value checked here against the file that holds it."""
    from pencore.studies.attribution.settings import TOLERANCE

    prose = re.sub(r"```.*?```", "", README, flags=re.S)
    prose = re.sub(r"<!-- generated:.*?<!-- end generated -->", "", prose, flags=re.S)
    prose = re.sub(r"`[^`]*`", "", prose)
    citation = "Impact Engineering 38 (2011) 815-823"
    assert prose.count(citation) >= 1
    prose = prose.replace(citation, "").replace("3-D", "")
    bad = subprocess.run(
        [sys.executable, "-m", "pencore", "simulate", "--projectile", "p2", "--target", "soil"]
        + ["--velocity", "-1"],
        capture_output=True,
        text=True,
    )
    checked = {
        f"{100 * TOLERANCE:g} %",  # the attribution study's agreement band
        str(bad.returncode),  # "exit status 2" for a bad input
    }
    found = re.findall(r"\d+(?:\.\d+)?(?:\s*%)?", prose)
    unchecked = [n for n in found if n not in checked]
    assert not unchecked, f"numbers typed in the README without a check: {unchecked}"


@pytest.mark.slow
def test_python_example_runs():
    code = next(b for b in README.split("```python\n")[1:]).split("```")[0]
    namespace: dict = {}
    exec(compile(code, "README.md", "exec"), namespace)  # noqa: S102
    ds, r = namespace["ds"], namespace["r"]
    assert ds.penetration_depth.units == "m"
    assert r.status == "ok" and r.hi - r.lo <= 5.0


def test_constraints_pin_the_reproduction_within_what_pyproject_allows():
    """constraints.txt pins every dependency of pencore[workflow] to one version that
    pyproject.toml allows, says why, and how to regenerate it."""
    import tomllib

    from packaging.requirements import Requirement
    from packaging.utils import canonicalize_name

    text = (REPO / "constraints.txt").read_text()
    header = "\n".join(ln for ln in text.splitlines() if ln.startswith("#"))
    assert "bit-identical" in header and "python .ci/constraints.py > constraints.txt" in header
    pins = {}
    for line in text.splitlines():
        if line.strip() and not line.startswith("#"):
            name, _, version = line.partition("==")
            assert version, f"not an exact pin: {line!r}"
            pins[canonicalize_name(name)] = version
    assert "pencore" not in pins
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    direct = project["dependencies"] + project["optional-dependencies"]["workflow"]
    for spec in map(Requirement, direct):
        name = canonicalize_name(spec.name)
        assert name in pins, f"{name} is not pinned"
        assert spec.specifier.contains(pins[name], prereleases=True), (name, pins[name])


def test_constraints_tree_follows_markers_and_extras():
    """.ci/constraints.py walks the whole tree: a dependency behind an extra asked for
    (``snakemake[reports]`` -> pygments) and one behind a platform marker that holds here
    are pinned; every requirement that applies here of a pinned distribution is pinned too."""
    import importlib.util
    from importlib import metadata

    from packaging.requirements import Requirement
    from packaging.utils import canonicalize_name

    spec = importlib.util.spec_from_file_location("ci_constraints", REPO / ".ci" / "constraints.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    pins = module.tree([Requirement("snakemake[reports]")])
    assert "pygments" in pins  # Requires-Dist: pygments; extra == "reports"
    for name in pins:
        for text in metadata.distribution(name).requires or []:
            sub = Requirement(text)
            if sub.marker is not None and not sub.marker.evaluate({"extra": ""}):
                continue
            try:
                metadata.distribution(sub.name)
            except metadata.PackageNotFoundError:
                continue
            assert canonicalize_name(sub.name) in pins, (name, text)
