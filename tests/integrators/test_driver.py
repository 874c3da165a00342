"""The run guard of the integrators: Ctrl-C and the wall budget on a time basis."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time

import pytest

from pencore.integrators import driver
from pencore.integrators.driver import STOP_INTERRUPT, STOP_WALL, WATCH_INTERVAL, RunGuard


def test_wall_budget_is_raised_by_the_watcher_within_its_interval():
    with RunGuard(0.1) as guard:
        t0 = time.monotonic()
        while guard.stop[0] == 0 and time.monotonic() - t0 < 5.0:
            time.sleep(0.005)  # stands for compiled code, which only reads the flag
        waited = time.monotonic() - t0
    assert guard.stop[0] == STOP_WALL and guard.out_of_time
    # the budget plus at most a few watcher intervals (a loaded machine adds some)
    assert 0.1 <= waited < 0.1 + 20 * WATCH_INTERVAL, waited


def test_no_budget_never_stops():
    with RunGuard(math.inf) as guard:
        time.sleep(3 * WATCH_INTERVAL)
    assert guard.stop[0] == 0 and not guard.out_of_time


@pytest.fixture
def python_sigint_handler():
    """Python's own SIGINT handler for the test: a test run started in the background by
    a shell without job control inherits SIGINT ignored, and a run then keeps ignoring
    it (see the next test), which is not what this test is about."""
    saved = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, saved)


def test_ctrl_c_during_a_run_raises_the_flag_then_keyboard_interrupt(python_sigint_handler):
    guard = RunGuard(math.inf)
    with pytest.raises(KeyboardInterrupt):
        with guard:
            os.kill(os.getpid(), signal.SIGINT)
            t0 = time.monotonic()
            while guard.stop[0] == 0 and time.monotonic() - t0 < 5.0:
                time.sleep(0.001)
            assert guard.stop[0] == STOP_INTERRUPT  # recorded, not raised, inside the run
    # outside runs the handler is Python's behaviour: KeyboardInterrupt
    assert signal.getsignal(signal.SIGINT) is driver._on_sigint
    with pytest.raises(KeyboardInterrupt):
        driver._on_sigint(signal.SIGINT, None)


def test_a_process_that_ignores_sigint_keeps_ignoring_it():
    code = (
        "import os, signal, time\n"
        "signal.signal(signal.SIGINT, signal.SIG_IGN)\n"
        "from pencore.integrators.driver import RunGuard\n"
        "with RunGuard(float('inf')) as g:\n"
        "    os.kill(os.getpid(), signal.SIGINT); time.sleep(0.3)\n"
        "print(int(g.stop[0]), signal.getsignal(signal.SIGINT) is signal.SIG_IGN)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["0", "True"]
