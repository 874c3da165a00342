"""``benchmarks/bench_compile.py`` counts what it says: index files (one per compiled
function) and compiled files (one per specialisation) wherever numba put them under the
cache directory, the child's CPU (not ours), and each case starts on an empty temporary
cache that is gone afterwards. No compile is timed here."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest


@pytest.fixture(scope="module")
def bench(load_benchmark):
    return load_benchmark("bench_compile")


def _touch(folder: Path, *names: str) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        (folder / name).write_bytes(b"")


def test_counts_index_and_compiled_files_in_every_folder(bench, tmp_path):
    # NUMBA_CACHE_DIR holds one folder per source folder, as numba lays it out
    _touch(
        tmp_path / "kernels_0123abcd",
        "contact_points.point_loads-160.py311.nbi",
        *(f"contact_points.point_loads-160.py311.{n}.nbc" for n in (1, 2, 3, 4)),
        "state.lu_solve-74.py311.nbi",
        "state.lu_solve-74.py311.1.nbc",
        "kernels.kernel-hash",  # the stale-cache guard's stamp: not a function
    )
    _touch(
        tmp_path / "integrators_4567ef01",
        "rosenbrock.integrate_chunk-223.py311.nbi",
        "rosenbrock.integrate_chunk-223.py311.1.nbc",
        "rosenbrock.integrate_chunk-223.py311.2.nbc",
    )
    counts = bench.cache_counts(tmp_path)
    assert counts["index_files"] == 3
    assert counts["compiled_files"] == 7
    # the functions compiled more than once, most specialisations first
    assert counts["specialised_functions"] == (
        "contact_points.point_loads-160:4 rosenbrock.integrate_chunk-223:2"
    )
    assert bench.cache_counts(tmp_path / "kernels_0123abcd")["index_files"] == 2


def test_an_empty_cache_counts_nothing(bench, tmp_path):
    assert bench.cache_counts(tmp_path) == {
        "index_files": 0,
        "compiled_files": 0,
        "specialised_functions": "",
    }


# a child that burns 0.3 s of its own CPU
BURN = "import time; t = time.process_time()\nwhile time.process_time() - t < 0.3: pass"


def test_cpu_is_the_childs(bench):
    wall, cpu = bench.timed_run(["-c", BURN], {})
    # the child's own process_time reaches us through its rusage: at least 0.3 s by
    # construction, whatever the machine's speed; and it took at least that long
    assert cpu >= 0.3
    assert wall >= 0.3


def test_a_failing_child_stops_with_its_exit_code(bench):
    with pytest.raises(SystemExit, match="exited 3"):
        bench.timed_run(["-c", "import sys; sys.exit(3)"], {})


# a stand-in for a cold run: checks that its cache starts empty, then writes what numba
# would (two functions, one of them specialised twice) and prints where
FAKE_COLD = """
import os, pathlib
cache = pathlib.Path(os.environ["NUMBA_CACHE_DIR"])
assert cache.is_dir() and not any(cache.iterdir()), "the cache is not empty"
d = cache / "kernels_0123abcd"
d.mkdir()
for name in ("m.f-1.py311.nbi", "m.f-1.py311.1.nbc", "m.f-1.py311.2.nbc",
             "m.g-9.py311.nbi", "m.g-9.py311.1.nbc"):
    (d / name).write_bytes(b"")
print(cache)
"""


def test_cold_runs_on_an_empty_temporary_cache(bench, monkeypatch, tmp_path):
    # a cache of the caller's (not empty) must not be the one the child gets
    mine = tmp_path / "my-cache"
    _touch(mine, "m.f-1.py311.nbi")
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(mine))
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(temporary))
    row = bench.cold(["-c", FAKE_COLD])
    assert row["index_files"] == 2
    assert row["compiled_files"] == 3
    assert row["specialised_functions"] == "m.f-1:2"
    assert row["cpu_s"] > 0.0 and row["wall_s"] > 0.0
    assert not any(temporary.iterdir())  # the temporary cache is gone
    assert sorted(f.name for f in mine.iterdir()) == ["m.f-1.py311.nbi"]  # untouched


def test_the_cases_are_the_default_path_and_the_install_step(bench):
    assert set(bench.CASES) == {"first_result", "warmup"}
    assert bench.CASES["warmup"] == ["-m", "pencore.warmup"]
    assert "simulate('p2', 'soil', 1000.0, obliquity=45.0)" in bench.CASES["first_result"][1]
