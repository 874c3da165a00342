"""The test suite's own guards (tests/helpers.py): a hang guard that scales with the
machine's load and says "too slow" when it stops a command, and a shared run that is made
once, survives a half-made folder and records a failure for every test process."""

from __future__ import annotations

import json
import multiprocessing
import sys
import time
from pathlib import Path

import pytest
from helpers import SharedRunFailed, TooSlow, guard_scale, run_guarded, shared_once


def _sleep(seconds: float, started: Path | None = None) -> list[str]:
    """A command that prints a Snakemake-like progress line, then (when ``started`` is
    given) creates that file, then sleeps."""
    touch = f"open({str(started)!r}, 'w').close(); " if started else ""
    code = (
        "import sys, time; print('1 of 3 steps (33%) done', file=sys.stderr, flush=True); "
        f"{touch}time.sleep({seconds})"
    )
    return [sys.executable, "-c", code]


def _load_once(path: Path, load: tuple[float, int]):
    """A load reading that first waits for ``path`` to exist: the guard cannot stop the
    command before it has started, however slowly a busy machine starts Python."""

    def read() -> tuple[float, int]:
        deadline = time.monotonic() + 300
        while not path.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        return load

    return read


def test_guard_scale_is_load_per_core_at_least_one(monkeypatch):
    monkeypatch.delenv("PENCORE_TEST_GUARD_SCALE", raising=False)
    assert guard_scale(0.3, 2) == 1.0
    assert guard_scale(2.0, 2) == 1.0
    assert guard_scale(6.0, 2) == 3.0
    assert guard_scale(10.0, 2) == 5.0
    monkeypatch.setenv("PENCORE_TEST_GUARD_SCALE", "2")
    assert guard_scale(6.0, 2) == 6.0


def test_guard_stops_a_hang_on_an_idle_machine_saying_too_slow(tmp_path):
    started = tmp_path / "started"
    t0 = time.monotonic()
    with pytest.raises(TooSlow) as err:
        run_guarded(
            _sleep(900, started), tmp_path, idle_s=1.0, label="sleeper",
            load=_load_once(started, (0.5, 2)), poll_s=0.2,
        )  # fmt: skip
    assert time.monotonic() - t0 < 600  # stopped by the guard, not by the command's end
    msg = str(err.value)
    assert msg.startswith("sleeper: too slow, stopped after ")
    assert "1 of 3 steps done" in msg  # the last progress line it saw
    assert "load averaged 0.5 on 2 cores" in msg and "PENCORE_TEST_GUARD_SCALE" in msg
    assert "a hang" in msg  # idle: not blamed on the load


def test_guard_on_a_busy_machine_says_so(tmp_path):
    started = tmp_path / "started"
    with pytest.raises(TooSlow) as err:
        run_guarded(
            _sleep(900, started), tmp_path, idle_s=0.5, label="busy",
            load=_load_once(started, (7.0, 2)), poll_s=0.2,
        )  # fmt: skip
    msg = str(err.value)
    assert msg.startswith("busy: too slow, stopped after ")
    assert "load averaged 7.0 on 2 cores" in msg and "a busy machine" in msg


def test_guard_gives_a_busy_machine_proportionally_longer(tmp_path):
    """At load 20 on 2 cores a command of 2 s passes a 1 s idle guard (10 s allowed)
    and reports its progress; at load 1 the same command is stopped."""
    lines: list[str] = []
    r = run_guarded(
        _sleep(2), tmp_path, idle_s=1.0, label="busy", load=lambda: (20.0, 2),
        poll_s=0.2, progress=lines.append, gap_s=0,
    )  # fmt: skip
    assert r.returncode == 0
    assert "1 of 3 steps (33%) done" in r.stderr
    assert lines and lines[0].startswith("busy: 1 of 3 steps done after ")
    assert "load 20.0 on 2 cores; guard 10 s" in lines[0]
    with pytest.raises(TooSlow):
        run_guarded(_sleep(2), tmp_path, idle_s=1.0, label="idle", load=lambda: (1.0, 2),
                    poll_s=0.2)  # fmt: skip


def test_guard_kills_the_command_s_children(tmp_path):
    """The whole process group goes: a Snakemake job started by the guarded command does
    not outlive it."""
    pid_file = tmp_path / "child.pid"
    code = (
        "import subprocess, sys, time; "
        "p = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(60)']); "
        f"open({str(pid_file)!r} + '.tmp', 'w').write(str(p.pid)); "
        f"import os; os.replace({str(pid_file)!r} + '.tmp', {str(pid_file)!r}); time.sleep(60)"
    )
    with pytest.raises(TooSlow):
        run_guarded([sys.executable, "-c", code], tmp_path, idle_s=1.0, label="parent",
                    load=_load_once(pid_file, (0.0, 2)), poll_s=0.2)  # fmt: skip
    child = int(pid_file.read_text())
    time.sleep(0.5)
    assert not Path(f"/proc/{child}").exists() or "Z" in _state(child)


def _state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(")")[1].split()[0]
    except OSError:
        return "Z"


def _counting_make(counter: Path):
    def make(wd: Path) -> None:
        with open(counter, "a") as f:
            f.write("x")
        (wd / "workflow").mkdir()
        time.sleep(0.5)
        (wd / "out.txt").write_text("done")

    return make


def test_shared_run_is_made_once_and_reused(tmp_path):
    counter = tmp_path / "count"
    wd = shared_once(tmp_path / "root", _counting_make(counter))
    assert (wd / "out.txt").read_text() == "done"
    assert shared_once(tmp_path / "root", _counting_make(counter)) == wd
    assert counter.read_text() == "x"
    assert json.loads((tmp_path / "root" / "done.json").read_text())["ok"] is True


def _worker(root: str, counter: str, out: str) -> None:
    wd = shared_once(Path(root), _counting_make(Path(counter)))
    Path(out).write_text(str(wd))


def test_two_processes_asking_at_once_make_it_once(tmp_path):
    ctx = multiprocessing.get_context("spawn")
    procs = [
        ctx.Process(target=_worker, args=(str(tmp_path / "root"), str(tmp_path / "n"),
                                          str(tmp_path / f"o{i}")))
        for i in range(2)
    ]  # fmt: skip
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
        assert p.exitcode == 0
    assert (tmp_path / "n").read_text() == "x"
    assert (tmp_path / "o0").read_text() == (tmp_path / "o1").read_text()


def test_a_half_made_folder_is_made_again(tmp_path):
    """A first process killed in the middle left ``wd/workflow`` and no record: the next
    one removes it and makes it anew (no FileExistsError)."""
    root = tmp_path / "root"
    (root / "wd" / "workflow").mkdir(parents=True)
    (root / "wd" / "stale.txt").write_text("half")
    wd = shared_once(root, _counting_make(tmp_path / "n"))
    assert (wd / "out.txt").read_text() == "done"
    assert not (wd / "stale.txt").exists()


def test_a_failed_attempt_is_cleaned_and_retried_once(tmp_path):
    calls: list[int] = []

    def flaky(wd: Path) -> None:
        calls.append(1)
        (wd / "workflow").mkdir()  # fails with FileExistsError if not cleaned
        if len(calls) == 1:
            raise RuntimeError("the first attempt broke")
        (wd / "out.txt").write_text("done")

    wd = shared_once(tmp_path / "root", flaky)
    assert len(calls) == 2 and (wd / "out.txt").is_file()


def test_a_failure_is_recorded_for_every_caller_without_a_third_run(tmp_path):
    calls: list[int] = []

    def broken(wd: Path) -> None:
        calls.append(1)
        raise RuntimeError("snakemake exited with 1")

    for _ in range(3):
        with pytest.raises(SharedRunFailed, match="attempt 2 of 2 failed: snakemake exited"):
            shared_once(tmp_path / "root", broken)
    assert len(calls) == 2


def test_too_slow_is_recorded_not_retried(tmp_path):
    """On a machine too busy for the guard a second attempt would double the wait: the
    first one's "too slow" message goes to every caller."""
    calls: list[int] = []

    def slow(wd: Path) -> None:
        calls.append(1)
        raise TooSlow("e2e: too slow, stopped after 1800 s: load averaged 9.5 on 2 cores")

    for _ in range(2):
        with pytest.raises(SharedRunFailed, match="too slow.*load averaged 9.5"):
            shared_once(tmp_path / "root", slow)
    assert len(calls) == 1
