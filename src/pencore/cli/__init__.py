"""The ``pencore`` command line (``pencore.cli.main.main()``)."""

from pencore.cli.main import build_parser, main

__all__ = ["main", "build_parser"]
