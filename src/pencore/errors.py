"""Every exception pencore raises on purpose, in one place.

The command line turns :class:`InputError` and :class:`ConfigError` into exit status 2,
:class:`SolverError` and :class:`WriteError` into exit status 1, each with a one-line
message; a Python caller can catch them by these classes.

=================  ==========================================================
class              raised when
=================  ==========================================================
InputError         a name, file or value given by the user is not valid
GeometryError      a projectile definition does not describe a valid body
TargetError        a target definition cannot be used
ConfigError        a workflow configuration cannot be run
SolverError        an integration could not finish
WriteError         a file could not be written (nothing was left behind)
ResultError        a result file cannot be read (corrupt or truncated)
=================  ==========================================================
"""

from __future__ import annotations

__all__ = [
    "INTERRUPTED",
    "InputError",
    "GeometryError",
    "TargetError",
    "ConfigError",
    "SolverError",
    "WriteError",
    "ResultError",
]

#: What the command line says when Ctrl-C ends it (exit status 130).
INTERRUPTED = "interrupted (Ctrl-C); nothing was written"


class InputError(ValueError):
    """Bad user input (name, file or value); the message names the value and what is allowed."""


class GeometryError(InputError):
    """A projectile definition that does not describe a valid body."""


class TargetError(InputError):
    """A target definition that cannot be used."""


class ConfigError(ValueError):
    """A workflow configuration that cannot be run; the message is one line naming the
    key path and the value."""


class SolverError(RuntimeError):
    """The integration could not finish; the message names the cause and the state."""


class WriteError(OSError):
    """A file could not be written; nothing was left behind. The message is one line."""

    def __init__(self, message: str, code: int | None = None) -> None:
        super().__init__(message)
        self.errno = code


class ResultError(RuntimeError):
    """A result file that cannot be read (corrupt or truncated); the message is one line
    naming the file and how to make it again."""
