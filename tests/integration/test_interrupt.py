"""Interrupting a run: Ctrl-C stops the compiled integrator within a second, with one
line and exit status 130, and leaves no file behind."""

import os
import signal
import subprocess
import sys
import time

# A run of ~6e5 steps (~20 s): long enough to be interrupted mid-integration.
LONG = [
    "simulate", "--projectile", "p2", "--target", "soil", "--velocity", "1000",
    "--obliquity", "45", "--numerics", "rtol=1e-10", "--numerics", "max_travel=2e-5",
    "--numerics", "max_steps=1000000",
]  # fmt: skip


def _default_sigint() -> None:
    # a shell that starts the test run in the background (`cmd &`) ignores SIGINT, and
    # children inherit that: the run under test gets the default a terminal gives it
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _start(args, tmp_path):
    return subprocess.Popen(
        [sys.executable, "-m", "pencore", *args],
        cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        preexec_fn=_default_sigint,
    )  # fmt: skip


def test_ctrl_c_stops_a_running_trajectory_within_a_second(tmp_path):
    out = tmp_path / "run.nc"
    proc = _start([*LONG, "--out", str(out)], tmp_path)
    time.sleep(4.0)  # past start-up (imports, cached kernels) into the integration
    assert proc.poll() is None, proc.communicate()
    t0 = time.monotonic()
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=30)
    elapsed = time.monotonic() - t0
    assert proc.returncode == 130
    assert stderr.strip().splitlines() == [
        "pencore: error: interrupted (Ctrl-C); nothing was written"
    ]
    assert "Traceback" not in stderr
    assert os.listdir(tmp_path) == []  # neither the file nor a temporary one
    # a chunk of 500 steps takes ~0.1 s here; 1 s is the promise, 5 s a hang guard that
    # holds on a loaded machine
    assert elapsed < 5.0, elapsed


# Ctrl-C while the command line's modules load: an import hook sends SIGINT to the
# process as pencore.cli.options is looked up, so the interrupt lands inside the import
_DURING_IMPORT = """
import os, signal, sys

class Hook:
    def find_spec(self, name, path=None, target=None):
        if name == "pencore.cli.options":
            os.kill(os.getpid(), signal.SIGINT)
        return None

sys.meta_path.insert(0, Hook())
from pencore.__main__ import run
sys.exit(run())
"""

# Ctrl-C after the command returned, as the interpreter shuts down
_AFTER_RETURN = """
import os, signal, sys
from pencore.__main__ import run
status = run()
os.kill(os.getpid(), signal.SIGINT)
sys.exit(status)
"""


def _entry(code: str, tmp_path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", code, *args], cwd=tmp_path, capture_output=True, text=True,
        preexec_fn=_default_sigint, timeout=60,
    )  # fmt: skip


def test_ctrl_c_while_the_command_line_loads_is_one_line_and_130(tmp_path):
    proc = _entry(_DURING_IMPORT, tmp_path, "list")
    assert proc.returncode == 130, proc.stderr
    assert proc.stderr.strip().splitlines() == [
        "pencore: error: interrupted (Ctrl-C); nothing was written"
    ]
    assert os.listdir(tmp_path) == []


def test_ctrl_c_after_the_command_returned_keeps_its_status(tmp_path):
    proc = _entry(_AFTER_RETURN, tmp_path, "--version")
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == "" and proc.stdout.startswith("pencore ")


def test_python_dash_m_pencore_is_the_command_line(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "pencore", "--version"], cwd=tmp_path, capture_output=True,
        text=True, timeout=60,
    )  # fmt: skip
    assert proc.returncode == 0 and proc.stdout.startswith("pencore ")
