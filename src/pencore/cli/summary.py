"""What a subcommand prints: a summary as aligned text, JSON or CSV (``--format``), and
the exit status of a search that finds no threshold in its range.

A summary is a list of :class:`Field`: a key, a label for the text form, a value (a
number in SI units, a string or None) and its units. ``--format json`` prints one object
``{key: {"value": ..., "units": ...}}``; ``--format csv`` prints ``name,value,units``
rows; ``text`` (default) prints ``label: text`` lines for a reader.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = [
    "FORMATS",
    "NOT_FOUND",
    "Field",
    "add_format_option",
    "print_summary",
    "Progress",
    "check_plot_output",
    "write_plot",
]

#: The ``--format`` choices.
FORMATS = ("text", "json", "csv")

#: Exit status of a search that found no threshold in its range (the verdict did not
#: change between the ends of the range, or the search did not converge); the summary
#: is still printed and files still written.
NOT_FOUND = 3


@dataclass(frozen=True)
class Field:
    """One line of a summary.

    Parameters
    ----------
    key : str
        Machine name (the JSON key and the CSV ``name``).
    label : str
        What the text form prints before the colon.
    value : float, int, str or None
        The value (SI units); None or NaN when not defined.
    units : str
        UDUNITS-style units (``"m"``, ``"m s-1"``, ``"degree"``, ``"1"``, ``""`` for text).
    text : str, optional
        The text form's value; default: the value and its units.
    in_text, in_data : bool, default True
        Whether the text form, and the JSON and CSV forms, show the field (a text line
        may gather several data fields).
    """

    key: str
    label: str
    value: Any
    units: str = ""
    text: str | None = None
    in_text: bool = True
    in_data: bool = True

    def shown(self) -> str:
        """The text form of the value."""
        if self.text is not None:
            return self.text
        if isinstance(self.value, float):
            return f"{self.value:.6g} {self.units}".strip()
        return f"{self.value} {self.units}".strip()


def add_format_option(p: argparse.ArgumentParser) -> None:
    """Add ``--format {text,json,csv}`` to a subcommand."""
    p.add_argument(
        "--format",
        choices=FORMATS,
        default="text",
        help="summary on stdout as aligned text (default), one JSON object "
        '{"key": {"value": ..., "units": ...}} or CSV rows name,value,units; numbers in '
        "SI units",
    )


def _json_value(v: Any) -> Any:
    if isinstance(v, float) and not math.isfinite(v):
        return None if math.isnan(v) else ("inf" if v > 0 else "-inf")
    return v


def print_summary(fields: list[Field], fmt: str = "text") -> None:
    """Print ``fields`` on stdout in ``fmt`` (one of :data:`FORMATS`).

    JSON has no infinities or NaN: NaN is ``null`` and an infinity the string ``"inf"``
    or ``"-inf"``; CSV writes them as Python does (``nan``, ``inf``).
    """
    data = [f for f in fields if f.in_data]
    if fmt == "json":
        out = {f.key: {"value": _json_value(f.value), "units": f.units} for f in data}
        print(json.dumps(out, indent=1))
    elif fmt == "csv":
        w = csv.writer(sys.stdout, lineterminator="\n")
        w.writerow(["name", "value", "units"])
        for f in data:
            w.writerow([f.key, "" if f.value is None else f.value, f.units])
    else:
        shown = [f for f in fields if f.in_text]
        width = max(len(f.label) for f in shown)
        for f in shown:
            print(f"{f.label + ':':<{width + 1}} {f.shown()}")


class Progress:
    """Progress of a sweep on stderr: one line per point, ``[i/n] what``.

    Parameters
    ----------
    total : int
        Number of points.
    quiet : bool
        Print nothing.
    """

    def __init__(self, total: int, quiet: bool = False) -> None:
        self.total = total
        self.done = 0
        self.quiet = quiet

    def __call__(self, what: str) -> None:
        """Count one point done and print ``[i/n] what`` on stderr."""
        self.done += 1
        if not self.quiet:
            print(f"[{self.done}/{self.total}] {what}", file=sys.stderr, flush=True)


#: Image formats ``--plot`` writes (from the file's suffix).
PLOT_SUFFIXES = (".png", ".pdf", ".svg")


def check_plot_output(path: str) -> Path:
    """Check a ``--plot`` path before any computation: a known image suffix and an
    existing directory; raises ``CommandFailure`` (status 2) naming the path."""
    from pencore.cli.options import CommandFailure

    p = Path(path)
    if p.suffix.lower() not in PLOT_SUFFIXES:
        raise CommandFailure(f"plot file {path!r} must end in one of {', '.join(PLOT_SUFFIXES)}", 2)
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise CommandFailure(f"plot file {path!r}: directory {str(parent)!r} does not exist", 2)
    if p.is_dir():
        raise CommandFailure(f"plot file {path!r} is a directory", 2)
    return p


def write_plot(fig: Any, path: Path) -> None:
    """Write ``fig`` to ``path`` atomically (a temporary file beside it, then a rename):
    a failed write leaves nothing; raises ``CommandFailure`` (status 1) naming the path."""
    from pencore.cli.options import CommandFailure
    from pencore.plotting.style import save_figure

    tmp = path.with_name(f".{path.stem}.part{path.suffix}")
    try:
        save_figure(fig, tmp)
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise CommandFailure(f"cannot write plot file {str(path)!r}: {exc.strerror}", 1) from None
