"""One end-to-end run of the CI configuration, shared by the workflow test files.

``.test/config.yaml`` runs every rule of the workflow in a copy of it (a few minutes on 2
cores). Its tests only read the results or dry-run against them, so one run serves them
all: under ``pytest -n 2`` the first test process to ask makes it and the other waits on a
file lock and reuses it (the pattern of pytest-xdist's documentation, "Making
session-scoped fixtures execute only once"). With ``PENCORE_E2E_DIR`` set (``.ci/run``
sets it) the run is kept there, and the docs step builds the workflow report from it
instead of running the configuration a second time.
"""

from __future__ import annotations

import fcntl
import json
import os
from pathlib import Path

import pytest
from helpers import copy_workflow, run_snakemake


@pytest.fixture(scope="session")
def e2e(tmp_path_factory, worker_id) -> Path:
    """A copy of the workflow in which ``.test/config.yaml`` has run to the end."""
    if os.environ.get("PENCORE_E2E_DIR"):  # kept for the docs step (.ci/run)
        root = Path(os.environ["PENCORE_E2E_DIR"])
        root.mkdir(parents=True, exist_ok=True)
    elif worker_id == "master":  # not under xdist
        root = tmp_path_factory.mktemp("e2e_shared")
    else:  # the base temp shared by every test process of this session
        root = tmp_path_factory.getbasetemp().parent / "e2e_shared"
        root.mkdir(exist_ok=True)
    done = root / "done.json"
    with open(root / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.exists():
            wd = root / "wd"
            wd.mkdir(exist_ok=True)
            copy_workflow(wd)
            r = run_snakemake(wd, "--cores", "2", "--configfile", ".test/config.yaml")
            done.write_text(json.dumps({"returncode": r.returncode, "stderr": r.stderr[-4000:]}))
    result = json.loads(done.read_text())
    assert result["returncode"] == 0, result["stderr"]
    return root / "wd"
