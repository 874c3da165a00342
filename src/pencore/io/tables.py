"""Reading pencore's CSV tables: the shipped ones (``config/*.csv``, the measured shots
and the paper's claims; ``results/archive/**/*.csv``; ``benchmarks/results/*.csv``) and
those a command's ``--out FILE.csv`` writes.

A table may open with ``#`` lines that say where its numbers come from (source, table,
page, units, the command that wrote it); the rows follow. :func:`read_table` keeps those
lines apart in ``frame.attrs["provenance"]`` and reads the rows as they are: a ``#`` in a
row (projectile ``#2`` in the paper's claims and the comparison table) is text.
``pandas.read_csv(path, comment="#")`` reads the header the same way but cuts every row
at a ``#``, so on those two tables it returns empty cells without a word.
"""

from __future__ import annotations

import io
import os
from typing import TYPE_CHECKING

from pencore.errors import InputError, hint_keywords

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["read_table"]


def read_table(path: str | os.PathLike[str]) -> pd.DataFrame:
    """A CSV table of pencore as a ``pandas.DataFrame``, its ``#`` header apart.

    Parameters
    ----------
    path : path-like
        A CSV file: optional leading lines that start with ``#`` (the provenance), then a
        header row and the rows.

    Returns
    -------
    pandas.DataFrame
        The rows, read by ``pandas.read_csv`` with its defaults (columns and values as in
        the file; units are in the column names or the provenance). ``attrs["provenance"]``
        holds the leading ``#`` lines without the ``#`` (a list of str, empty when there
        are none) and ``attrs["path"]`` the file read.

    Raises
    ------
    InputError
        One line naming the file: missing, not UTF-8 text, or without a table after its
        header.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import pencore
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = Path(tmp) / "shots.csv"
    ...     _ = path.write_text("# source: a paper, Table 1\\nshot,v_m_s,note\\n1,800,#2 rod\\n")
    ...     frame = pencore.read_table(path)
    >>> frame.attrs["provenance"], frame["v_m_s"].tolist(), frame["note"].tolist()
    (['source: a paper, Table 1'], [800], ['#2 rod'])
    """
    import pandas as pd

    name = os.fspath(path)
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines(keepends=True)
    except FileNotFoundError:
        raise InputError(f"table {name} does not exist") from None
    except IsADirectoryError:
        raise InputError(f"table {name} is a directory, not a CSV file") from None
    except UnicodeDecodeError:
        raise InputError(f"table {name} is not UTF-8 text (a CSV file is)") from None
    n = 0
    while n < len(lines) and lines[n].lstrip().startswith("#"):
        n += 1
    try:
        frame = pd.read_csv(io.StringIO("".join(lines[n:])))
    except pd.errors.EmptyDataError:
        raise InputError(f"table {name} holds no table after its # lines") from None
    except (pd.errors.ParserError, ValueError) as exc:
        cause = " ".join(str(exc).split())[:160]
        raise InputError(f"table {name} cannot be read as CSV: {cause}") from None
    frame.attrs["provenance"] = [ln.strip()[1:].strip() for ln in lines[:n]]
    frame.attrs["path"] = name
    return frame


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
