"""A cold first use says once on stderr that it is compiling the kernels; a warm one says
nothing (:func:`pencore.kernels.cache.compile_notice`, called by each run).

A cold run compiles for about a minute, too long for a test: the cache test is checked
in fresh interpreters on made-up cache directories (``NUMBA_CACHE_DIR``), against a
small real kernel that numba caches there, and the choice of entry point per integrator
and the once-per-process promise with the compiled code replaced."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

import pencore.integrators.explicit as explicit
import pencore.kernels.cache as cache
import pencore.run.impact as impact
from pencore.run.impact import COMPILE_NOTICE

# fresh interpreters that load or compile the kernels (~12 s in all)
pytestmark = pytest.mark.slow


def _child(code: str, cache) -> subprocess.CompletedProcess:
    """Run ``code`` in a fresh interpreter whose numba cache is ``cache``."""
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_DISABLE_JIT"}
    env["NUMBA_CACHE_DIR"] = str(cache)
    env["PENCORE_NO_SHIPPED_KERNELS"] = "1"  # a cold cache, whatever the package ships
    done = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    return done


NOTICE_TWICE = """
from pencore.run import impact
print(impact.compiled_in_cache(impact.integrate_chunk))
impact._compile_notice(impact.integrate_chunk)
impact._compile_notice(impact.integrate_chunk)
impact._compile_notice(impact.rhs_model)  # another cold entry point: still once
"""


def test_an_empty_cache_gets_the_notice_once(tmp_path):
    done = _child(NOTICE_TWICE, tmp_path)
    assert done.stdout.split() == ["False"]
    assert done.stderr.splitlines() == [COMPILE_NOTICE]


# an index for the integrator as numba writes it (<module>.<function>-<first line>.py<XY>.nbi
# in the folder's cache directory: numba's version, then the source stamp and the entries),
# with one entry for this CPU whose data file is not empty
MAKE_INDEX = """
import pickle, sys
import numba
from numba.core.registry import cpu_target
from numba.core.serialize import dumps
from pencore.kernels.cache import PACKAGE, cache_dir_of, kernel_hash
from pencore.integrators.rosenbrock import integrate_chunk
line = integrate_chunk.py_func.__code__.co_firstlineno
tag = "py%d%d" % sys.version_info[:2]
folder = cache_dir_of(PACKAGE / "integrators")
base = f"rosenbrock.integrate_chunk-{line}.{tag}"
magic = cpu_target.target_context.codegen().magic_tuple()
entries = {(("sig",), magic, ("code", "closure")): base + ".1.nbc"}
with open(folder / (base + ".nbi"), "wb") as f:
    pickle.dump(numba.__version__, f, protocol=-1)
    f.write(dumps((kernel_hash(), entries)))
(folder / (base + ".1.nbc")).write_bytes(b"object code")
"""


def test_a_cached_integrator_gets_no_notice(tmp_path):
    _child(MAKE_INDEX, tmp_path)
    done = _child(NOTICE_TWICE.replace("impact.rhs_model", "impact.integrate_chunk"), tmp_path)
    assert done.stdout.split() == ["True"]
    assert done.stderr == ""


def test_an_emptied_index_is_no_cache(tmp_path):
    # a disk that filled during the warm-up leaves an empty index: it holds nothing
    _child(MAKE_INDEX + "(folder / (base + '.nbi')).write_bytes(b'')", tmp_path)
    done = _child(NOTICE_TWICE, tmp_path)
    assert done.stdout.split() == ["False"]
    assert done.stderr.splitlines() == [COMPILE_NOTICE]


# a small real kernel: not cached on an empty cache, cached once numba compiled it
REAL_KERNEL = """
import numpy as np
from pencore.kernels.state import speed_of
from pencore.run.impact import compiled_in_cache
before = compiled_in_cache(speed_of)
speed_of(np.zeros(14))
print(before, compiled_in_cache(speed_of))
"""


def test_the_check_looks_where_numba_writes(tmp_path):
    assert _child(REAL_KERNEL, tmp_path).stdout.split() == ["False", "True"]
    # a new process finds it in the cache, as a warm run finds the integrator
    assert _child(REAL_KERNEL, tmp_path).stdout.split() == ["True", "True"]


def test_no_compiled_code_means_nothing_to_announce():
    def plain(x):  # what numba's decorator returns under NUMBA_DISABLE_JIT
        return x

    assert impact.compiled_in_cache(plain)


@pytest.fixture
def fresh_notice(monkeypatch):
    """A process that has not looked at the cache yet; the integrators replaced by stubs
    (a run is not wanted, only the entry point the notice is given for)."""
    monkeypatch.setattr(cache, "_notice_printed", False)
    monkeypatch.setattr(cache, "_notice_checked", set())
    ran = []

    def stub(pr, y0, velocity, *, stop_at_reversal, keep_derivatives=False):
        ran.append(pr)

    monkeypatch.setattr(impact, "integrate", stub)
    monkeypatch.setattr(explicit, "integrate_explicit", stub)
    return ran


def _run_variants(prepared_kw):
    for kw in prepared_kw:
        impact._run(impact.prepare("p2", "soil", **kw), None, 300.0, False)


def test_each_integrator_is_looked_up_once(fresh_notice, monkeypatch, capsys):
    checked = []
    monkeypatch.setattr(cache, "compiled_in_cache", lambda d: checked.append(d) or True)
    explicit_kw = {"emulation": {"integrator": "explicit", "dt": 2e-5}}
    _run_variants([{}, {}, explicit_kw, explicit_kw, {"shank": "factor"}])
    assert checked == [impact.integrate_chunk, explicit.explicit_chunk]
    assert len(fresh_notice) == 5
    assert capsys.readouterr().err == ""  # warm: nothing said


def test_warmup_says_it_once(fresh_notice, monkeypatch, capsys):
    """``python -m pencore.warmup`` on a cold cache: every variant, two integrators, one
    notice."""
    from pencore import warmup

    monkeypatch.setattr(cache, "compiled_in_cache", lambda d: False)
    monkeypatch.setattr(warmup, "_cores", lambda: 1)  # the variants in this process

    def simulate(projectile, target, velocity, obliquity=0.0, **kw):
        _run_variants([kw])

    monkeypatch.setattr(impact, "simulate", simulate)
    monkeypatch.setattr(impact, "run_impact", simulate)  # the search run's variant
    assert warmup.main([]) == 0
    err = capsys.readouterr().err
    assert err.count(COMPILE_NOTICE) == 1
    assert len(fresh_notice) == len(warmup.VARIANTS)


# python -m pencore.warmup --host, with the compile itself left out: the kernels defined
# after it leave the shipped (portable) kernels unused, so the warm-up compiles for this CPU
HOST = """
import sys
from pencore import warmup
warmup.warmup = lambda verbose=True: 0.0
status = warmup.main(["--host"])
from pencore.kernels.state import speed_of
print(status, speed_of._cache._shipped)
"""


def test_warmup_host_leaves_the_shipped_kernels_unused(tmp_path):
    env = {k: v for k, v in os.environ.items() if not k.startswith("PENCORE_")}
    env["NUMBA_CACHE_DIR"] = str(tmp_path)
    done = subprocess.run(
        [sys.executable, "-c", HOST], env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[-2:] == ["0", "None"]


@pytest.mark.parametrize("argv", [["--hots"], ["--host", "x"], ["-h"]])
def test_warmup_refuses_other_options(argv, capsys):
    from pencore import warmup

    assert warmup.main(argv) == 2
    assert capsys.readouterr().err.startswith("usage: python -m pencore.warmup [--host]")


def test_warmup_host_needs_a_fresh_process(capsys):
    from pencore import warmup

    assert warmup.main(["--host"]) == 2  # this process has defined its kernels already
    assert "needs a fresh process" in capsys.readouterr().err
