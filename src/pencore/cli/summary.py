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

from pencore.cli.options import (
    add_mass_options,
    add_window_options,
    each_of,
    number_type,
    numerics_option,
    velocity,
)

__all__ = [
    "FORMATS",
    "NOT_FOUND",
    "Field",
    "add_format_option",
    "print_summary",
    "Progress",
    "check_plot_output",
    "write_plot",
    "check_table_output",
    "write_table",
    "dataset_csv",
    "read_csv",
    "EXIT_NOTE",
    "add_search_outputs",
    "add_run_options",
    "add_start_option",
    "start_of",
    "add_speed_bracket",
    "check_bracket",
    "check_outputs",
    "write_outputs",
    "search_fields",
]

#: The ``--format`` choices.
FORMATS = ("text", "json", "csv")

#: Exit status of a search that found no threshold in its range (the verdict did not
#: change between the ends of the range, or the search did not converge); the summary
#: is still printed and files still written.
NOT_FOUND = 3


#: The exit statuses, for the help texts.
EXIT_NOTE = (
    f"Exit status: 0 threshold found, {NOT_FOUND} no threshold in the range (the verdict "
    "is the same at both ends, the bracket did not narrow to --tol, or a run could not "
    "finish, status solver_error; the summary and files are still written, a table with "
    "every other cell), 2 bad input, 1 solver or write failure."
)


#: Units as the text form shows them.
_READABLE = {"1": "", "m s-1": "m/s", "m s-2": "m/s^2", "rad s-1": "rad/s", "degree": "deg"}


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
        units = _READABLE.get(self.units, self.units)
        if isinstance(self.value, float):
            return f"{self.value:.6g} {units}".strip()
        return f"{self.value} {units}".strip()


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


def check_plot_output(path: str) -> Path:
    """Check a ``--plot`` path before any computation (:func:`pencore.cli.options.check_output`
    with :data:`pencore.io.outputs.FIGURE_SUFFIXES`); ``CommandFailure`` status 2."""
    from pencore.cli.options import check_output
    from pencore.io.outputs import FIGURE_SUFFIXES

    return check_output(path, suffixes=FIGURE_SUFFIXES, what="plot file")


def write_plot(fig: Any, path: Path) -> None:
    """Write ``fig`` to ``path`` atomically through the output gate
    (:func:`pencore.plotting.style.save_figure`): a failed write leaves nothing; raises
    ``CommandFailure`` (status 1) naming the path."""
    from pencore.cli.options import CommandFailure, refresh_interrupt_line
    from pencore.errors import WriteError
    from pencore.plotting.style import save_figure

    try:
        save_figure(fig, path)
    except WriteError as exc:
        raise CommandFailure(str(exc), 1) from None
    refresh_interrupt_line()


def check_table_output(path: str) -> Path:
    """Check an ``--out`` path of a search or sweep before any computation
    (:func:`pencore.cli.options.check_output` with
    :data:`pencore.io.outputs.TABLE_SUFFIXES`, ``.nc`` or ``.csv``); ``CommandFailure``
    status 2."""
    from pencore.cli.options import check_output
    from pencore.io.outputs import TABLE_SUFFIXES

    return check_output(path, suffixes=TABLE_SUFFIXES)


def dataset_csv(ds: Any) -> str:
    """A Dataset as CSV text: ``# key: value`` lines for the attributes and the scalars
    (with their units), then one row per point of the data variables on the Dataset's
    dimensions, each column headed ``name [units]``, numbers to 17 significant digits
    (they read back to the bit). :func:`read_csv` reads it back."""

    lines = [f"# {k}: {one_line_attr(v)}" for k, v in ds.attrs.items() if k != "inputs_json"]
    scalars = [k for k in ds.data_vars if ds[k].ndim == 0]
    for k in scalars:
        lines.append(f"# {k} [{ds[k].attrs.get('units', '')}]: {ds[k].item()!r}")
    table = ds.drop_vars(scalars)
    frame = table.to_dataframe().reset_index()
    frame.columns = [f"{c} [{table[c].attrs.get('units', '')}]" for c in frame.columns]
    return (
        "\n".join(lines)
        + "\n"
        + frame.to_csv(index=False, lineterminator="\n", float_format="%.17g")
    )


def one_line_attr(v: Any) -> str:
    """An attribute value on one line."""
    return " ".join(str(v).split())


def read_csv(path: str | os.PathLike[str]) -> Any:
    """Read a CSV written by :func:`dataset_csv`: a ``pandas.DataFrame`` whose
    columns are the variable names, with ``frame.attrs["units"]`` mapping each to its
    units."""
    import pandas as pd

    frame = pd.read_csv(path, comment="#", float_precision="round_trip")
    units = {}
    names = []
    for c in frame.columns:
        name, _, rest = c.partition(" [")
        names.append(name)
        units[name] = rest[:-1] if rest.endswith("]") else ""
    frame.columns = names
    frame.attrs["units"] = units
    return frame


def write_table(ds: Any, path: Path, args: argparse.Namespace, study: str) -> None:
    """Write a search's or sweep's Dataset to ``path`` (``.nc``: netCDF with provenance;
    ``.csv``: :func:`dataset_csv`), atomically; ``CommandFailure`` status 1 on failure."""
    from pencore.cli.options import CommandFailure, cli_inputs, refresh_interrupt_line
    from pencore.errors import WriteError
    from pencore.io.atomic import atomic_write_text
    from pencore.io.netcdf import write_netcdf

    try:
        if path.suffix.lower() == ".nc":
            write_netcdf(ds, path, config_slice={"cli": cli_inputs(args)}, study=study)
        else:
            atomic_write_text(path, dataset_csv(ds), suffixes=(".csv",))
    except WriteError as exc:
        raise CommandFailure(str(exc), 1) from None
    refresh_interrupt_line()


def add_run_options(p: argparse.ArgumentParser, numerics_help: str) -> None:
    """The mass, window and ``--numerics`` options of a search or sweep command
    (``numerics_help``: the help text of ``--numerics``)."""
    add_mass_options(p)
    add_window_options(p)
    p.add_argument(
        "--numerics",
        type=numerics_option,
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help=numerics_help,
    )


#: Help of ``--start`` where the subcommand does not give its own.
START_HELP = (
    "initial nose-tip position of every run in m, e.g. -1 1 0 (the paper starts its Vcr "
    "runs there); y >= 0 (default: tip at x = z = 0, body just touching the surface y = 0 m)"
)


def add_start_option(p: argparse.ArgumentParser, help_text: str = START_HELP) -> None:
    """``--start X Y Z`` (m): the initial nose-tip position of every run of the command,
    each coordinate checked against ``LIMITS["start"]`` as it is read; ``y >= 0`` and a
    start from which the body reaches the target within ``t_max`` are checked by the run
    (:func:`pencore.simulate`), before it integrates. Default ``None``: the body just
    touching the surface."""
    p.add_argument(
        "--start",
        action=each_of(*[number_type("start")] * 3),
        nargs=3,
        default=None,
        metavar=("X", "Y", "Z"),
        help=help_text,
    )


def start_of(args: argparse.Namespace) -> tuple[float, float, float] | None:
    """The ``--start`` of a command as the API's ``start=`` (m), or None when not given."""
    start = getattr(args, "start", None)
    return None if start is None else (float(start[0]), float(start[1]), float(start[2]))


def add_speed_bracket(
    p: argparse.ArgumentParser, lo: float, hi: float, helps: tuple[str, str, str]
) -> None:
    """``--lo`` and ``--hi`` (m/s; defaults ``lo`` and ``hi``) and ``--tol`` (m/s; default
    5) of a search over impact speed; ``helps`` are their three help texts."""
    lo_help, hi_help, tol_help = helps
    p.add_argument("--lo", type=velocity, default=lo, metavar="M_S", help=lo_help)
    p.add_argument("--hi", type=velocity, default=hi, metavar="M_S", help=hi_help)
    p.add_argument(
        "--tol",
        type=number_type("velocity", "tolerance"),
        default=5.0,
        metavar="M_S",
        help=tol_help,
    )


def check_bracket(args: argparse.Namespace, units: str = "") -> None:
    """Refuse a search range whose ``--lo`` is not below its ``--hi`` (``InputError``;
    ``units``, e.g. ``" (m/s)"``, ends the message)."""
    from pencore.errors import InputError

    if not args.lo < args.hi:
        raise InputError(f"--lo {args.lo:g} must be below --hi {args.hi:g}{units}")


def check_outputs(args: argparse.Namespace) -> tuple[Path | None, Path | None]:
    """Check ``--out`` and (where the command has it) ``--plot`` before any computation:
    the paths to write, or None where not asked."""
    out = check_table_output(args.out) if args.out is not None else None
    plot_path = getattr(args, "plot", None)
    plot = check_plot_output(plot_path) if plot_path is not None else None
    return out, plot


def draw_search(ds: Any) -> Any:
    """The figure of a search's Dataset (:func:`pencore.plotting.search.plot_search`)."""
    from pencore.plotting.search import plot_search

    return plot_search(ds)


def write_outputs(
    ds: Any,
    fields: list[Field],
    out: Path | None,
    plot: Path | None,
    args: argparse.Namespace,
    draw: Any = draw_search,
) -> None:
    """Write a search's or sweep's table to ``out`` and ``draw(ds)`` to ``plot`` (each
    where asked), then print ``fields`` with the paths written in ``args.format``."""
    if out is not None:
        write_table(ds, out, args, f"cli/{args.command}")
    if plot is not None:
        write_plot(draw(ds), plot)
    if out is not None:
        fields.append(Field("output", "output", str(out)))
    if plot is not None:
        fields.append(Field("plot", "plot", str(plot)))
    print_summary(fields, args.format)


def add_search_outputs(p: argparse.ArgumentParser) -> None:
    """The mass, window, ``--numerics``, ``--scan``, ``--out``, ``--plot`` and
    ``--format`` options of a search command."""
    add_run_options(p, "numerical parameter override (repeatable), as for 'simulate'")
    p.add_argument(
        "--scan",
        type=int,
        default=5,
        metavar="N",
        help="coarse scan of N points before bisecting, to detect a verdict that is not "
        "monotone (0: none; default: 5)",
    )
    p.add_argument(
        "--out",
        metavar="FILE.nc|FILE.csv",
        default=None,
        help="write every value tried and its verdict, and the result, as netCDF or CSV",
    )
    p.add_argument(
        "--plot",
        metavar="FILE.png",
        default=None,
        help="draw the search (values tried, verdicts, final bracket) to this image file",
    )
    add_format_option(p)


def search_fields(
    r: Any, quantity: str, units: str, text_units: str, label: str | None = None
) -> list[Field]:
    """The summary of a threshold search (``label``: the value's label, default
    ``quantity``)."""
    value = r.value if math.isfinite(r.value) else math.nan
    shown = f"{value:.6g} {text_units}" if math.isfinite(value) else "not found in the range"
    return [
        Field(quantity, label or quantity, value, units, text=shown),
        Field(f"{quantity}_lo", "bracket low", float(r.lo), units, in_text=False),
        Field(f"{quantity}_hi", "bracket high", float(r.hi), units, in_text=False),
        Field("bracket", "bracket", None,
              text=f"[{r.lo:.6g}, {r.hi:.6g}] {text_units}", in_data=False),
        Field("runs", "runs", int(r.n_evals), "1", text=str(r.n_evals)),
        Field("status", "status", r.status, text=f"{r.status} ({r.message})"),
        Field("message", "message", r.message, in_text=False),
    ]  # fmt: skip
