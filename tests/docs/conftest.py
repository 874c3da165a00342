"""The docs' generator module (``docs/_ext/pencore_docs.py``) as a fixture."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def gen() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "pencore_docs", REPO / "docs" / "_ext" / "pencore_docs.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod
