"""Data tables (CSV with ``#`` comments: the paper's claims and tables, measured shot
tables) read through the input gate: a regular UTF-8 text file of bounded size
(:func:`pencore.inputs.gate.read_text`) that holds a table, else one
:class:`~pencore.InputError` line naming the file; never pandas' traceback.
"""

from __future__ import annotations

import io
import os
from typing import Any

import pandas as pd

from pencore.errors import InputError
from pencore.inputs.gate import brief_path, read_text

__all__ = ["read_csv"]


def read_csv(
    path: str | os.PathLike[str], what: str, *, label: str | None = None, **kwargs: Any
) -> pd.DataFrame:
    """The table in the CSV file ``path`` (``kwargs`` go to ``pandas.read_csv``).

    Parameters
    ----------
    path : path-like
        The file.
    what : str
        What the file is, for messages (``"paper claims"``).
    label : str, optional
        The start of the message instead of ``"<what> file <path>"``.

    Raises
    ------
    InputError
        One line naming the file: missing, not a regular file, too large, not UTF-8 text
        (a Latin-1 or binary file), empty or comments only, rows pandas cannot split.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     empty = Path(tmp) / "shots.csv"
    ...     _ = empty.write_text("# a header only")
    ...     try:
    ...         read_csv(empty, "shot table", label="shot table", comment="#")
    ...     except InputError as exc:
    ...         print(exc)
    shot table holds no table (it is empty or only comments)
    """
    name = label or f"{what} file {brief_path(path)}"
    text = read_text(path, name, "CSV")
    if "\x00" in text:
        raise InputError(f"{name} is a binary file, not a CSV text file")
    try:
        return pd.read_csv(io.StringIO(text), **kwargs)
    except pd.errors.EmptyDataError:
        raise InputError(f"{name} holds no table (it is empty or only comments)") from None
    except (pd.errors.ParserError, ValueError) as exc:
        cause = " ".join(str(exc).split())[:160]
        raise InputError(f"{name} cannot be read as CSV: {cause}") from None
