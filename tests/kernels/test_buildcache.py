"""The build cache: a build whose key (kernel stamp, numba, Python, target) matches an
earlier one copies its kernels instead of compiling; a damaged or partial entry is refused
and the kernels compiled; any changed key field misses. The compile is a stand-in that
writes numba-format index and data files and counts its calls (``BUILD.json`` says which
way each build went)."""

from __future__ import annotations

import json
import os
import pickle
from pathlib import Path

import numba
import pytest
from numba.core import caching

from pencore.kernels import buildcache

RECORD = {
    "numba": numba.__version__,
    "python": "py311",
    "target": "x86_64-unknown-linux-gnu, cpu 'generic', features ''",
    "kernel_hash": "0123456789abcdef" * 4,
}


class FakeCompile:
    """Writes what a kernel build holds (an index and data file per compiled folder, in
    numba's own format) and counts its calls; ``fail`` makes it fail as a broken
    environment does."""

    def __init__(self, fail: bool = False):
        self.calls = 0
        self.fail = fail

    def __call__(self, folder: Path) -> float | None:
        self.calls += 1
        if self.fail:
            return None
        for name in buildcache.FOLDERS:
            (folder / name).mkdir(parents=True)
            index = caching.IndexDataCacheFile(str(folder / name), f"{name}.f-1.py311", "stamp")
            index.save(("sig", ("triple", "generic", ""), ("a", "b")), {"code": name * 100})
        return 12.5


def build(tmp_path: Path, record=RECORD, compile_=None, root=None) -> tuple[dict, FakeCompile]:
    compile_ = compile_ or FakeCompile()
    out = tmp_path / "package" / "compiled"
    root = tmp_path / "cache" if root is None else root
    said = []
    done = buildcache.provide_kernels(out, record, compile_, root, say=said.append)
    if done is not None:
        assert json.loads((out / "BUILD.json").read_text()) == done
    return done, compile_


def entry_of(tmp_path: Path, record=RECORD) -> Path:
    return tmp_path / "cache" / buildcache.entry_name(record)


def test_second_build_with_the_same_key_copies_instead_of_compiling(tmp_path):
    first, c1 = build(tmp_path)
    assert (c1.calls, first["build"], first["compile_s"]) == (1, "compiled", 12.5)
    assert first["build_cache"] == str(entry_of(tmp_path))
    compiled = {
        p.relative_to(tmp_path / "package").as_posix(): p.read_bytes()
        for p in sorted((tmp_path / "package").rglob("*.nb[ic]"))
    }
    second, c2 = build(tmp_path)
    assert (c2.calls, second["build"], second["compile_s"]) == (0, "copied", 0.0)
    assert {k: second[k] for k in buildcache.KEY_FIELDS} == RECORD
    copied = {
        p.relative_to(tmp_path / "package").as_posix(): p.read_bytes()
        for p in sorted((tmp_path / "package").rglob("*.nb[ic]"))
    }
    assert copied == compiled and len(copied) == 4
    assert not (tmp_path / "package" / "compiled.partial").exists()


@pytest.mark.parametrize("field", buildcache.KEY_FIELDS)
def test_a_changed_key_field_misses(tmp_path, field):
    build(tmp_path)
    changed = {**RECORD, field: RECORD[field] + "-other"}
    done, c = build(tmp_path, record=changed)
    assert (c.calls, done["build"]) == (1, "compiled")
    assert entry_of(tmp_path, changed) != entry_of(tmp_path)  # the old entry stays
    assert buildcache.verify_entry(entry_of(tmp_path), RECORD) is None


def truncate(f: Path) -> None:
    f.write_bytes(f.read_bytes()[:10])


def garbage(f: Path) -> None:
    f.write_bytes(b"\x00garbage" * 8)


def empty(f: Path) -> None:
    f.write_bytes(b"")


def delete(f: Path) -> None:
    f.unlink()


@pytest.mark.parametrize("damage", [truncate, garbage, empty, delete])
@pytest.mark.parametrize("suffix", [".nbi", ".nbc"])
def test_a_damaged_entry_is_refused_deleted_and_recompiled(tmp_path, damage, suffix):
    build(tmp_path)
    entry = entry_of(tmp_path)
    damage(next(entry.rglob(f"*{suffix}")))
    why = buildcache.verify_entry(entry, RECORD)
    assert why is not None and suffix in why
    done, c = build(tmp_path)
    assert (c.calls, done["build"]) == (1, "compiled")
    assert buildcache.verify_entry(entry, RECORD) is None  # stored afresh
    assert build(tmp_path)[0]["build"] == "copied"


@pytest.mark.parametrize("name", ["BUILD.json", "MANIFEST.json"])
def test_an_entry_without_its_record_or_manifest_is_refused(tmp_path, name):
    build(tmp_path)
    (entry_of(tmp_path) / name).unlink()
    assert name in buildcache.verify_entry(entry_of(tmp_path), RECORD)
    assert build(tmp_path)[0]["build"] == "compiled"


def test_a_kernel_file_not_in_the_manifest_is_refused(tmp_path):
    build(tmp_path)
    extra = entry_of(tmp_path) / "kernels" / "other.g-1.py311.1.nbc"
    extra.write_bytes(b"x")
    assert "other.g-1.py311.1.nbc is not in MANIFEST.json" in buildcache.verify_entry(
        entry_of(tmp_path), RECORD
    )


def test_an_entry_whose_record_differs_from_its_name_is_refused(tmp_path):
    build(tmp_path)
    entry = entry_of(tmp_path)
    built = json.loads((entry / "BUILD.json").read_text())
    (entry / "BUILD.json").write_text(json.dumps({**built, "numba": "0.1.0"}))
    assert buildcache.verify_entry(entry, RECORD) == f"numba '0.1.0' is not {numba.__version__!r}"


def test_an_index_of_another_numba_is_refused(tmp_path):
    """numba writes its version first in an index; an entry whose record claims this
    numba but whose index is another's (with a manifest that matches) is not used."""
    other = {**RECORD, "numba": "0.1.0"}
    build(tmp_path, record=other)  # the fake index carries this numba's version
    entry = entry_of(tmp_path, other)
    assert "index of numba" in buildcache.verify_entry(entry, other)


def test_a_real_numba_index_passes(tmp_path):
    build(tmp_path)
    index = next(entry_of(tmp_path).rglob("*.nbi"))
    with open(index, "rb") as f:
        assert pickle.load(f) == numba.__version__
    assert buildcache.verify_entry(entry_of(tmp_path), RECORD) is None


def test_a_partial_entry_is_never_read(tmp_path):
    """An interrupted store leaves ``<entry>.partial-*``: not an entry."""
    build(tmp_path)
    entry = entry_of(tmp_path)
    entry.rename(entry.with_name(entry.name + ".partial-1-abc"))
    done, c = build(tmp_path)
    assert (c.calls, done["build"]) == (1, "compiled")


def test_a_failed_compile_leaves_no_kernels_and_no_entry(tmp_path):
    done, c = build(tmp_path, compile_=FakeCompile(fail=True))
    assert done is None and c.calls == 1
    assert not (tmp_path / "package").exists() or not any((tmp_path / "package").iterdir())
    assert not (tmp_path / "cache").exists() or not any((tmp_path / "cache").iterdir())


def test_an_unwritable_cache_still_builds(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("a file where the cache folder would be")
    done, c = build(tmp_path, root=blocker / "cache")
    assert (c.calls, done["build"], done["build_cache"]) == (1, "compiled", None)
    assert sorted(p.name for p in (tmp_path / "package" / "compiled").iterdir()) == [
        "BUILD.json",
        "integrators",
        "kernels",
    ]


def test_a_disabled_cache_compiles_every_time(tmp_path, monkeypatch):
    monkeypatch.setenv(buildcache.CACHE_ENV, "off")
    assert buildcache.cache_root() is None
    out = tmp_path / "compiled"
    for _ in range(2):
        c = FakeCompile()
        done = buildcache.provide_kernels(out, RECORD, c, None, say=lambda line: None)
        assert (c.calls, done["build"], done["build_cache"]) == (1, "compiled", None)


def test_the_cache_is_in_the_user_cache_folder_unless_set(monkeypatch, tmp_path):
    monkeypatch.delenv(buildcache.CACHE_ENV, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    root = buildcache.cache_root()
    if root.is_relative_to(tmp_path):  # Linux and the other XDG systems
        assert root == tmp_path / "pencore" / "build-kernels"
    monkeypatch.setenv(buildcache.CACHE_ENV, str(tmp_path / "mine"))
    assert buildcache.cache_root() == tmp_path / "mine"


def test_the_build_step_says_what_it_does(tmp_path):
    said = []
    out = tmp_path / "compiled"
    root = tmp_path / "cache"
    buildcache.provide_kernels(out, RECORD, FakeCompile(), root, say=said.append)
    assert said[0].startswith("pencore build: compiling the numba kernels")
    assert "no entry" in said[0] and said[1].startswith("pencore build: kept in the build cache")
    said.clear()
    buildcache.provide_kernels(out, RECORD, FakeCompile(), root, say=said.append)
    assert said == [
        f"pencore build: numba kernels copied from the build cache {root / buildcache.entry_name(RECORD)} (no compile)"  # noqa: E501
    ]


def test_the_cache_keeps_the_entries_used_last(tmp_path):
    records = [{**RECORD, "kernel_hash": f"{i:02d}" * 32} for i in range(buildcache.KEEP + 2)]
    for i, record in enumerate(records[: buildcache.KEEP]):
        build(tmp_path, record=record)
        os.utime(entry_of(tmp_path, record), (1000 + i, 1000 + i))  # stored in this order
    assert build(tmp_path, record=records[0])[0]["build"] == "copied"  # used again: last
    for record in records[buildcache.KEEP :]:
        build(tmp_path, record=record)
    kept = {p.name for p in (tmp_path / "cache").iterdir()}
    expected = [records[0], *records[3 : buildcache.KEEP], *records[buildcache.KEEP :]]
    assert kept == {buildcache.entry_name(r) for r in expected}


def test_a_stopped_build_partial_folder_is_deleted_a_running_one_kept(tmp_path):
    root = tmp_path / "cache"
    old, young = root / "x.partial-1-aa", root / "y.partial-2-bb"
    old.mkdir(parents=True)
    young.mkdir()
    os.utime(old, (1, 1))
    assert buildcache.prune(root) == [old]
    assert young.is_dir()


def test_a_copy_that_differs_from_the_manifest_is_compiled_instead(tmp_path, monkeypatch):
    """An entry changed while it is copied (another build pruning the cache, a full
    disk): the copies are checked against the manifest, and the build compiles."""
    build(tmp_path)
    real_copytree = buildcache.shutil.copytree

    def copy_then_damage(src, dst, **kw):
        real_copytree(src, dst, **kw)
        truncate(next(Path(dst).glob("*.nbc")))

    monkeypatch.setattr(buildcache.shutil, "copytree", copy_then_damage)
    done, c = build(tmp_path)
    assert (c.calls, done["build"]) == (1, "compiled")


def test_the_module_uses_the_standard_library_only():
    """setup.py loads it by its path in the build environment, before numba or pencore
    can be imported: every import is of the standard library."""
    import ast
    import sys

    tree = ast.parse(Path(buildcache.__file__).read_text())
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            names.add((node.module or "").split(".")[0])
    assert names and names <= set(sys.stdlib_module_names) | {"__future__"}


def test_uv_rebuilds_the_editable_install_when_a_compiled_source_changes():
    """uv builds an installed editable pencore again only when a file of its
    ``cache-keys`` changes: they must cover every file the kernel stamp hashes (else an
    install after a pull leaves the changed kernels to the first run), and the build."""
    import tomllib

    from pencore.kernels.cache import PACKAGE, compiled_sources

    repo = Path(__file__).resolve().parents[2]
    keys = tomllib.loads((repo / "pyproject.toml").read_text())["tool"]["uv"]["cache-keys"]
    patterns = [k["file"] for k in keys]
    assert {"pyproject.toml", "setup.py"} <= set(patterns)
    sources = compiled_sources(PACKAGE)
    assert sources
    for f in sources:
        relative = f.resolve().relative_to(repo)
        assert any(relative.match(p) for p in patterns), f"{relative} is not a uv cache key"


# ------------------------------------------------------------ any failure to use it: compile


def said_by(tmp_path: Path, root, record=RECORD, no_root="disabled") -> tuple[dict, list[str]]:
    said: list[str] = []
    out = tmp_path / "package" / "compiled"
    done = buildcache.provide_kernels(out, record, FakeCompile(), root, said.append, no_root)
    return done, said


def test_a_cache_setting_that_cannot_be_expanded_means_compile():
    root, why = buildcache.resolve_root({buildcache.CACHE_ENV: "~no_such_user_pencore/kernels"})
    assert root is None and why.startswith("PENCORE_BUILD_CACHE cannot be expanded")
    assert "\n" not in why


def test_a_cache_setting_that_cannot_be_expanded_builds(tmp_path):
    _, why = buildcache.resolve_root({buildcache.CACHE_ENV: "~no_such_user_pencore/kernels"})
    done, said = said_by(tmp_path, None, no_root=why)
    assert done["build"] == "compiled" and done["build_cache"] is None
    assert any("cannot be expanded" in line for line in said)


def test_a_cache_path_too_long_means_compile_in_one_line(tmp_path):
    root = tmp_path / ("x" * 300) / "cache"
    done, said = said_by(tmp_path, root)
    assert done["build"] == "compiled" and done["build_cache"] is None
    assert all("\n" not in line for line in said)
    assert any("cannot be used" in line or "cannot be written" in line for line in said), said


@pytest.mark.parametrize("kind", ["file", "folder", "link"])
def test_a_leftover_partial_means_nothing(tmp_path, kind):
    out = tmp_path / "package" / "compiled"
    out.parent.mkdir(parents=True)
    partial = out.with_name("compiled.partial")
    if kind == "file":
        partial.write_text("left by a stopped build")
    elif kind == "folder":
        (partial / "kernels").mkdir(parents=True)
        (partial / "kernels" / "junk.nbi").write_bytes(b"junk")
    else:
        partial.symlink_to(tmp_path / "nowhere")
    done, said = said_by(tmp_path, tmp_path / "cache")
    assert done["build"] == "compiled"
    assert not os.path.lexists(partial) and (out / "BUILD.json").is_file()
    done, _ = said_by(tmp_path, tmp_path / "cache")
    assert done["build"] == "copied"


PLANTED = b"cos\nsystem\n(S'touch /tmp/pencore-planted'\ntR."  # runs a command if unpickled


@pytest.mark.parametrize(
    "head, words",
    [
        (PLANTED, "does not start as a numba index (not unpickled)"),
        (pickle.dumps(("not", "a", "version"), protocol=-1), "does not start as a numba index"),
        (pickle.dumps(42, protocol=-1), "does not start as a numba index"),
        (pickle.dumps("0.1.0", protocol=-1), "is an index of numba '0.1.0'"),
        (b"", "does not start as a numba index"),
    ],
    ids=["planted-code", "a-tuple", "a-number", "another-numba", "empty"],
)
def test_an_index_is_read_as_bytes_never_unpickled(tmp_path, head, words, monkeypatch):
    build(tmp_path)
    entry = entry_of(tmp_path)
    index = next(entry.rglob("*.nbi"))
    index.write_bytes(head)
    manifest = json.loads((entry / "MANIFEST.json").read_text())
    manifest[index.relative_to(entry).as_posix()] = buildcache._sha256(index)
    (entry / "MANIFEST.json").write_text(json.dumps(manifest))  # a planted, consistent entry

    def no_unpickling(*args, **kwargs):
        raise AssertionError("the build cache unpickled a file")

    monkeypatch.setattr(pickle, "load", no_unpickling)
    monkeypatch.setattr(pickle, "loads", no_unpickling)
    assert words in buildcache.verify_entry(entry, RECORD)
    done, said = said_by(tmp_path, tmp_path / "cache")
    assert done["build"] == "compiled"
    assert any("refused and deleted" in line for line in said), said
    assert not Path("/tmp/pencore-planted").exists()


def test_the_index_version_is_read_from_a_real_numba_index(tmp_path):
    build(tmp_path)
    index = next(entry_of(tmp_path).rglob("*.nbi"))
    assert buildcache.index_version(index.read_bytes()[:128]) == numba.__version__


def test_an_entry_that_raises_while_it_is_checked_means_compile(tmp_path, monkeypatch):
    build(tmp_path)

    def broken(entry, record):
        raise RuntimeError("something no check foresaw")

    monkeypatch.setattr(buildcache, "verify_entry", broken)
    done, said = said_by(tmp_path, tmp_path / "cache")
    assert done["build"] == "compiled"
    assert any("cannot be used (RuntimeError: something no check foresaw)" in x for x in said)


def _setup_module(monkeypatch):
    """setup.py's functions, without running setup()."""
    import importlib
    import runpy
    import subprocess
    import sys
    import types

    import setuptools

    monkeypatch.setattr(setuptools, "setup", lambda **kwargs: None)
    try:  # setuptools >= 70 (the build environment's); older ones: a stand-in
        importlib.import_module("setuptools.command.bdist_wheel")
    except ImportError:
        stub = types.ModuleType("setuptools.command.bdist_wheel")
        stub.bdist_wheel = type("bdist_wheel", (), {})
        monkeypatch.setitem(sys.modules, "setuptools.command.bdist_wheel", stub)
    ns = runpy.run_path(str(Path(buildcache.__file__).parents[3] / "setup.py"))
    return ns, subprocess


@pytest.mark.parametrize("failure", ["no-solver", "warm-up-fails"])
def test_a_build_that_fails_stops_the_install_in_one_line(failure, tmp_path, monkeypatch):
    # a SystemExit: setuptools' editable install swallows any Exception of build_py and
    # reports success without kernels
    import subprocess

    ns, _ = _setup_module(monkeypatch)
    real_run = subprocess.run

    def run(cmd, *args, **kwargs):
        if failure == "no-solver" and "build_info" in cmd[-1]:
            return subprocess.CompletedProcess(cmd, 1, "", "ModuleNotFoundError: numba\n")
        if failure == "warm-up-fails" and "pencore.warmup" in cmd[-1]:
            return subprocess.CompletedProcess(cmd, 1)
        return real_run(cmd, *args, **kwargs)

    monkeypatch.setattr(subprocess, "run", run)
    monkeypatch.setenv(buildcache.CACHE_ENV, "off")
    with pytest.raises(SystemExit) as info:
        ns["compile_kernels"](tmp_path / "compiled")
    assert not isinstance(info.value, Exception)
    text = str(info.value.code)
    assert text.startswith("error: pencore build: the numba kernels could not be compiled (")
    assert "PENCORE_SKIP_KERNELS=1" in text and "\n" not in text
    word = "the solver does not import: ModuleNotFoundError: numba" if failure == "no-solver" \
        else "the warm-up run failed"  # fmt: skip
    assert word in text
    assert not (tmp_path / "compiled").exists()
