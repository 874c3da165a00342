"""Interrupting a run: Ctrl-C stops the compiled integrator within a second, with one
line and exit status 130, and leaves no file behind."""

import os
import select
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


# The command line's entry point, saying "ready" once the command line and the solver are
# imported: a Ctrl-C from then on is the command's to answer. (Before that, the
# interpreter's own start is outside pencore, and on a loaded machine it can take seconds.)
_READY_THEN_RUN = """
import sys
from pencore.__main__ import run
import pencore.cli.main, pencore.run.impact
print("ready", flush=True)
sys.exit(run())
"""


def test_ctrl_c_stops_a_running_trajectory_within_a_second(tmp_path):
    out = tmp_path / "run.nc"
    proc = subprocess.Popen(
        [sys.executable, "-c", _READY_THEN_RUN, *LONG, "--out", str(out)],
        cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        preexec_fn=_default_sigint,
    )  # fmt: skip
    ready, _, _ = select.select([proc.stdout], [], [], 120)
    assert ready and proc.stdout.readline() == "ready\n", proc.communicate()
    time.sleep(3.0)  # past the kernels' first load into the integration (~20 s long)
    assert proc.poll() is None, proc.communicate()
    t0 = time.monotonic()
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=30)
    elapsed = time.monotonic() - t0
    assert proc.returncode == 130, stderr
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


# Ctrl-C while scipy's extension modules initialise: pybind11 reports it as
# ImportError("initialization failed") raised from the KeyboardInterrupt. An import hook
# raises just that as the run loads scipy's integrators (Radau) in its first step.
_SCIPY_INTERRUPTED = """
import sys

class Hook:
    def find_spec(self, name, path=None, target=None):
        if name == "pencore.integrators.scipy_ivp":
            try:
                raise KeyboardInterrupt
            except KeyboardInterrupt as exc:
                raise ImportError("initialization failed") from exc
        return None

sys.meta_path.insert(0, Hook())
"""


def test_ctrl_c_while_scipy_loads_is_ctrl_c_from_the_api(tmp_path):
    code = _SCIPY_INTERRUPTED + (
        "import pencore\n"
        "try:\n"
        "    pencore.simulate('p2', 'soil', 300.0, numerics={'method': 'Radau'})\n"
        "except KeyboardInterrupt as exc:\n"
        "    print('KeyboardInterrupt', type(exc.__cause__).__name__, file=sys.stderr)\n"
        "    sys.exit(130)\n"
    )
    proc = _entry(code, tmp_path)
    assert proc.returncode == 130, proc.stderr
    # the caller sees the interrupt, with the import that it stopped as its cause
    assert proc.stderr.strip().splitlines() == ["KeyboardInterrupt ImportError"]


def test_ctrl_c_while_scipy_loads_is_one_line_and_130_on_the_command_line(tmp_path):
    code = _SCIPY_INTERRUPTED + "from pencore.__main__ import run\nsys.exit(run())\n"
    args = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "300",
            "--numerics", "method=Radau", "--out", str(tmp_path / "run.nc")]  # fmt: skip
    proc = _entry(code, tmp_path, *args)
    assert proc.returncode == 130, proc.stderr
    assert proc.stderr.strip().splitlines() == [
        "pencore: error: interrupted (Ctrl-C); nothing was written"
    ]
    assert os.listdir(tmp_path) == []


def test_an_import_error_of_another_cause_is_not_taken_for_ctrl_c(tmp_path):
    code = _SCIPY_INTERRUPTED.replace("raise KeyboardInterrupt", "raise OSError('gone')")
    code = code.replace("except KeyboardInterrupt", "except OSError")
    code += "from pencore.__main__ import run\nsys.exit(run())\n"
    args = ["simulate", "--projectile", "p2", "--target", "soil", "--velocity", "300",
            "--numerics", "method=Radau"]  # fmt: skip
    proc = _entry(code, tmp_path, *args)
    assert proc.returncode == 1
    assert "interrupted" not in proc.stderr
    assert "ImportError: initialization failed" in proc.stderr
