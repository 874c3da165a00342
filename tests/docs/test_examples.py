"""Every fenced block of the README and the guide pages, run as written.

Each block is labelled by its fence: ``bash`` (commands), ``python`` (run), ``yaml`` (a
file the page's commands name, ``# NAME.yaml`` on its first line; a projectile or target,
``# projectile`` / ``# target``; otherwise an excerpt of the workflow configuration), or
``text`` (output, shown and not run); ``{directive}`` fences are Sphinx's. A fence without
a label fails.

Commands: ``pencore ...`` runs in a fresh directory holding the files the page shows;
``python -m snakemake ...`` runs as a dry run (``-n``) in the repository, so its targets,
rules, profile and configuration files are checked without the hours of a reproduction
(the workflow's end-to-end tests run it, and build the report, on the small test
configuration); ``python -m pip install ...`` and ``python -m uv pip install ...`` name
extras that exist, or install uv itself, and ``python -m venv .venv && . .venv/bin/activate``
make and enter the environment (not run: they would change the environment under test;
CI's install step and ``.ci/wheel.sh`` install);
``python -m pytest -q`` is the suite this test belongs to. Any other command fails here
until it is given a way to run.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
PAGES = [
    REPO / "README.md",
    REPO / "docs" / "getting-started.md",
    *sorted((REPO / "docs" / "user-guide").glob("*.md")),
]

_spec = importlib.util.spec_from_file_location("wheel_examples", REPO / ".ci/wheel_examples.py")
ex = sys.modules.setdefault("wheel_examples", importlib.util.module_from_spec(_spec))
_spec.loader.exec_module(ex)

#: placeholders a reader fills in, and what the dry run uses
PLACEHOLDERS = {"<partition>": "debug", "<account>": "pencore"}
LABELS = {"bash", "python", "yaml", "text"}


def _blocks(lang: str) -> list:
    return [b for page in PAGES for b in ex.blocks(page) if b.lang == lang]


def _commands(prefix: str) -> list:
    return [
        pytest.param(page, c, id=f"{page.name}:{c[:60]}")
        for page in PAGES
        for b in ex.blocks(page)
        if b.lang == "bash"
        for c in ex.commands(b)
        if c.startswith(prefix)
    ]


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO / "src"), env.get("PYTHONPATH")]))
    return env


def test_every_block_is_labelled():
    bad = [
        str(b)
        for page in PAGES
        for b in ex.blocks(page)
        if b.lang not in LABELS and not b.lang.startswith("{")
    ]
    assert not bad, f"blocks without a known label (bash, python, yaml, text): {bad}"


def test_every_command_has_a_way_to_run():
    known = (
        "python -m venv .venv",  # the set-up commands' virtual environment, and entering it
        ". .venv/bin/activate",
        ". .venv-test/bin/activate",  # the tests' own environment
        "export PENCORE_SLURM_",  # the cluster page's partition and account (dry runs use them)
        "pencore ",
        "python -m snakemake",
        "python -m pip install ",
        "python -m uv pip install ",
        "python -m pytest",
    )
    cmds = [c for b in _blocks("bash") for c in ex.commands(b)]
    assert cmds
    assert [c for c in cmds if not c.startswith(known)] == []


def test_named_files_are_shown():
    """A ``--target``/``--projectile`` file a command names is shown on its page."""
    for page in PAGES:
        found = ex.blocks(page)
        shown = ex.shown_files(found)
        for b in found:
            for c in ex.commands(b) if b.lang == "bash" else []:
                for name in re.findall(r"--(?:target|projectile) (\S+\.ya?ml)", c):
                    assert name in shown, f"{page.name}: {c!r} names {name}, not shown"


@pytest.mark.slow
@pytest.mark.parametrize(("page", "command"), _commands("pencore "))
def test_pencore_command_runs(page, command, tmp_path):
    for name, text in ex.shown_files(ex.blocks(page)).items():
        (tmp_path / name).write_text(text)
    argv = shlex.split(command)
    done = subprocess.run(
        [sys.executable, "-m", "pencore", *argv[1:]],
        cwd=tmp_path,
        env=_env(),
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip()
    if "--out" in argv:
        assert (tmp_path / argv[argv.index("--out") + 1]).stat().st_size > 0


@pytest.mark.slow
@pytest.mark.parametrize("block", [pytest.param(b, id=str(b)) for b in _blocks("python")])
def test_python_block_runs(block, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    page = next(p for p in PAGES if p.name == block.page)
    for name, text in ex.shown_files(ex.blocks(page)).items():
        (tmp_path / name).write_text(text)
    exec(compile(block.text, str(block), "exec"), {"__name__": "__example__"})  # noqa: S102


@pytest.mark.slow
@pytest.mark.parametrize(("page", "command"), _commands("python -m snakemake"))
def test_snakemake_command_dry_runs(page, command):
    env = _env()
    for k, v in PLACEHOLDERS.items():
        command = command.replace(k, v)
    for b in ex.blocks(page):  # the page's `export NAME=value` lines, as a reader runs them
        for c in ex.commands(b) if b.lang == "bash" else []:
            if c.startswith("export "):
                for k, v in PLACEHOLDERS.items():
                    c = c.replace(k, v)
                env.update(item.split("=", 1) for item in shlex.split(c)[1:])
    argv = shlex.split(command)[1:]
    if "--report" in argv:
        # the report is of a finished run: its command is checked for what it names
        # (tests/workflow/test_workflow.py::test_e2e_report builds one)
        assert argv[argv.index("--report") + 1] == "results/report.html"
        return
    done = subprocess.run(
        [sys.executable, *argv, "-n"], cwd=REPO, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr[-2000:]


@pytest.mark.parametrize(
    ("page", "command"),
    _commands("python -m pip install ") + _commands("python -m uv pip install "),
)
def test_pip_install_names_extras_that_exist(page, command):
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    argv = shlex.split(command)
    if argv == ["python", "-m", "pip", "install", "uv"]:
        return  # the installer the README's commands use
    assert "-e" in argv, f"{command!r}: expected an editable install of '.'"
    spec = argv[argv.index("-e") + 1]
    m = re.fullmatch(r"\.(?:\[([\w,-]+)\])?", spec)
    assert m, f"{command!r}: expected an editable install of '.'"
    for option in ("-c", "--build-constraint"):  # a constraints file the clone holds
        if option in argv:
            assert (REPO / argv[argv.index(option) + 1]).is_file(), command
    for extra in (m.group(1) or "").split(",") if m.group(1) else []:
        assert extra in project["optional-dependencies"], f"{command!r}: no extra {extra}"


@pytest.mark.parametrize(("page", "command"), _commands("python -m pytest"))
def test_pytest_command_is_the_suite(page, command):
    """Not run here (it is this suite): it must be the very test command CI runs."""
    ci = (REPO / ".ci" / "run").read_text().splitlines()
    assert command in [line for line in ci if line.startswith("python -m pytest")], command


def _yaml_blocks() -> list:
    return [pytest.param(b, id=str(b)) for b in _blocks("yaml")]


@pytest.mark.parametrize("block", _yaml_blocks())
def test_yaml_block_passes_its_gate(block, tmp_path):
    """A shown file, a projectile or a target is read by pencore's readers; any other
    YAML block is a configuration excerpt, merged over ``config/config.yaml`` and checked
    as the workflow checks its configuration (schema, then pencore's config check)."""
    import yaml

    from pencore.inputs.gate import load_yaml_text
    from pencore.inputs.library import projectile_from_dict, target_from_dict
    from pencore.workflowconfig.config_check import check_config, read_config, strict_schema_error

    data = load_yaml_text(block.text, str(block))
    first = block.text.splitlines()[0]
    if first.startswith("# projectile") or (ex.SHOWN_FILE.match(first) and "nose" in data):
        projectile_from_dict(data)
    elif first.startswith("# target") or ex.SHOWN_FILE.match(first):
        target_from_dict(data)
    else:
        excerpt = tmp_path / "excerpt.yaml"
        excerpt.write_text(block.text)
        config = read_config([REPO / "config" / "config.yaml", excerpt])
        schema = yaml.safe_load((REPO / "workflow/schemas/config.schema.yaml").read_text())
        assert strict_schema_error(config, schema) is None
        check_config(config, root=REPO)


def test_durations_read_as_a_reader_says_them(gen):
    """Times in the prose are said in s, min or h, never in exponent notation."""
    assert gen.duration(46.7) == "47 s"
    assert gen.duration(157.2) == "2.6 min"
    assert gen.duration(7200.0) == "2 h"
    numbers = gen.numbers()
    for page in PAGES:
        used = re.findall(r"<!-- n:(\w+) -->", page.read_text())
        shown = {k: numbers[k] for k in used}
        assert not [k for k, v in shown.items() if re.search(r"\de[+-]\d", v)], page.name
    assert "min" in gen.timing_sentence()
