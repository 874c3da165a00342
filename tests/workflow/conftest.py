"""One end-to-end run of the CI configuration, shared by the workflow test files.

``.test/config.yaml`` runs every rule of the workflow in a copy of it (a few minutes on 2
idle cores). Its tests only read the results or dry-run against them, so one run serves
them all: under ``pytest -n 2`` the first test process to ask makes it and the other waits
on a file lock and reuses it (the pattern of pytest-xdist's documentation, "Making
session-scoped fixtures execute only once"; :func:`helpers.shared_once`: a folder left
half made by a failed or killed attempt is made again, a failure is recorded for every
process). The run's hang guard scales with the machine's load
(:func:`helpers.run_guarded`), says "too slow" with the load it saw when it stops a run,
and the run prints its progress to the terminal while the tests wait. With
``PENCORE_E2E_DIR`` set (``.ci/run`` sets it) the run is kept there, and the docs step
builds the workflow report from it instead of running the configuration a second time.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from helpers import SharedRunFailed, copy_workflow, run_snakemake, shared_once

#: Seconds the end-to-end run may take on an idle 2-core machine before its guard stops
#: it, several times what it needs there; the guard multiplies it by load/cores.
E2E_IDLE_S = 600


@pytest.fixture(scope="session")
def e2e(tmp_path_factory, worker_id, request) -> Path:
    """A copy of the workflow in which ``.test/config.yaml`` has run to the end."""
    if os.environ.get("PENCORE_E2E_DIR"):  # kept for the docs step (.ci/run)
        root = Path(os.environ["PENCORE_E2E_DIR"])
    elif worker_id == "master":  # not under xdist
        root = tmp_path_factory.mktemp("e2e_shared")
    else:  # the base temp shared by every test process of this session
        root = tmp_path_factory.getbasetemp().parent / "e2e_shared"
    capture = request.config.pluginmanager.getplugin("capturemanager")

    def say(line: str) -> None:
        """A line on the terminal past pytest's capture (a test process's stderr is the
        terminal's under xdist too)."""
        if capture is None:  # pytest -p no:capture
            print(f"\n[{worker_id}] {line}", file=sys.stderr, flush=True)
            return
        with capture.global_and_fixture_disabled():
            print(f"\n[{worker_id}] {line}", file=sys.stderr, flush=True)

    def make(wd: Path) -> None:
        copy_workflow(wd)
        say(
            "the end-to-end workflow run (.test/config.yaml) starts; the workflow tests "
            "wait for it (a few minutes on 2 idle cores, longer on a busy machine)"
        )
        r = run_snakemake(
            wd, "--cores", "2", "--configfile", ".test/config.yaml",
            timeout=E2E_IDLE_S, log=wd.parent / "snakemake.log", progress=say,
            label="end-to-end workflow run",
        )  # fmt: skip
        if r.returncode != 0:
            raise RuntimeError(
                f"snakemake exited with {r.returncode} ({wd.parent / 'snakemake.log'}):\n"
                + r.stderr[-4000:]
            )
        say("the end-to-end workflow run finished")

    try:
        return shared_once(root, make)
    except SharedRunFailed as exc:
        pytest.fail(f"the end-to-end workflow run: {exc}", pytrace=False)
