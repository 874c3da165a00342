"""The folder tree is the architecture: layers import downward only (import-linter's
contracts in pyproject.toml), no module imports another in a cycle, no private name
crosses a subpackage, and no history narrative lives in the code, config or README."""

from __future__ import annotations

import ast
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "src" / "pencore"


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path) -> list[tuple[str, str]]:
    """(module, name) of every ``from pencore... import name`` in ``path``, and
    (module, "") of every ``import pencore...``."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("pencore"):
            out += [(node.module, a.name) for a in node.names]
        elif isinstance(node, ast.Import):
            out += [(a.name, "") for a in node.names if a.name.startswith("pencore")]
    return out


def _subpackage(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def _graph() -> dict[str, set[str]]:
    modules = {_module_name(p): p for p in PACKAGE.rglob("*.py")}
    graph: dict[str, set[str]] = {m: set() for m in modules}
    for m, path in modules.items():
        for target, name in _imports(path):
            if f"{target}.{name}" in modules:  # from package import submodule
                graph[m].add(f"{target}.{name}")
            elif target in modules and target != "pencore":
                graph[m].add(target)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    sys.setrecursionlimit(10_000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_import_cycle_between_modules():
    # imports inside functions count too: a lazy import is still a dependency
    assert _cycles(_graph()) == []


def test_the_cycle_finder_finds_a_cycle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_no_private_name_crosses_a_subpackage():
    crossing = []
    for path in PACKAGE.rglob("*.py"):
        here = _subpackage(_module_name(path))
        for target, name in _imports(path):
            if name.startswith("_") and not name.startswith("__") and _subpackage(target) != here:
                crossing.append(f"{_module_name(path)}: from {target} import {name}")
    assert crossing == []


def test_at_most_about_a_dozen_top_level_modules():
    top = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert len(top) <= 12, top


#: History narratives: issue numbers and benchmark "rounds" belong in git and the CHANGELOG.
HISTORY = re.compile(r"\bissues? ?#?\d+\b|\b(this|last|next|first|second|third|fourth|fifth|"
                     r"sixth|seventh|earlier|previous) round\b", re.IGNORECASE)  # fmt: skip


def _history_files() -> list[Path]:
    roots = [PACKAGE, REPO / "config", REPO / "workflow", REPO / "benchmarks", REPO / "docs"]
    files = [
        REPO / "Snakefile",
        REPO / "README.md",
        *(f for f in (REPO / ".ci").iterdir() if f.is_file()),
    ]
    for root in roots:
        files += [
            p
            for p in root.rglob("*")
            if p.is_file() and p.suffix in {".py", ".smk", ".yaml", ".csv", ".rst", ".sh", ".md"}
        ]
    return files


def test_no_history_markers_in_code_config_or_workflow():
    hits = [
        f"{p.relative_to(REPO)}:{n}: {line.strip()[:80]}"
        for p in _history_files()
        for n, line in enumerate(p.read_text(errors="replace").splitlines(), 1)
        if HISTORY.search(line)
    ]
    assert hits == []


def test_history_pattern_catches_the_usual_phrasings():
    for text in ("Beyond the paper (issue 11)", "issue #12", "the sixth round", "this round"):
        assert HISTORY.search(text), text
    for text in ("round(x, 3)", "around the nose", "rounded to 0.1 m/s", "background"):
        assert not HISTORY.search(text), text


def test_import_linter_contracts_hold():
    # import-linter is in the test extra; its command sits beside this interpreter
    exe = shutil.which("lint-imports", path=str(Path(sys.executable).parent)) or "lint-imports"
    out = subprocess.run([exe], cwd=REPO, capture_output=True, text=True)
    assert out.returncode == 0, out.stdout[-3000:]
    assert " 0 broken" in out.stdout


def test_the_snakefile_imports_only_what_the_light_contract_covers():
    """The Snakefile and its rule files run at every Snakemake start (each dry run, targeted
    rerun, cluster job): each pencore module they import is a source of the contract that
    forbids the solver, numba and the data stack there."""
    config = tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["importlinter"]
    (light,) = [c for c in config["contracts"] if c["name"].startswith("what the Snakefile")]
    sources = [REPO / "Snakefile", *sorted((REPO / "workflow" / "rules").glob("*.smk"))]
    imported = {
        line.split()[1]
        for src in sources
        for line in src.read_text().splitlines()
        if line.startswith(("from pencore", "import pencore"))
    }
    assert imported, "found no pencore import in the workflow (the test reads nothing)"
    covered = tuple(light["source_modules"])
    outside = sorted(m for m in imported if not m.startswith(covered))
    assert outside == [], f"the Snakefile imports {outside}, which no light contract covers"
