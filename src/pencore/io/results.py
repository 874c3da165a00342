"""Result files that cannot be read: the message that names them, and the open test
the workflow makes when it starts.

A netCDF result truncated by a crash, a full disk or a copy cut short would pass as up
to date (its time stamp is newer than its inputs). :func:`set_aside_unreadable`, run by
the Snakefile before the workflow plans its jobs, opens every ``results/**/*.nc`` and
renames each that fails to ``<name>.corrupt``, so a plain rerun makes it again; a rule
that reads one anyway (:func:`pencore.io.netcdf.read_netcdf`) fails with one line naming
the file and what to run (:func:`unreadable_message`). This module loads no xarray, so
the workflow's start stays light.
"""

from __future__ import annotations

import os
from pathlib import Path

from pencore.io.atomic import TEMP_MARK

__all__ = ["readable_netcdf", "set_aside_unreadable", "unreadable_message"]


def unreadable_message(path: str | os.PathLike[str], exc: BaseException) -> str:
    """The one line for a netCDF file that cannot be read: the file, the cause, the fix."""
    cause = " ".join(str(exc).split())[:160] or type(exc).__name__
    return (
        f"netCDF file {str(path)!r} cannot be read ({cause}): it is corrupt or truncated; "
        f"delete it and rerun (the workflow makes it again: snakemake --cores 2 {path})"
    )


def readable_netcdf(path: str | os.PathLike[str]) -> str | None:
    """None when ``path`` opens as netCDF, else the reason in words. An open test: the
    HDF5 library compares the file's end with the end its header records, so a
    truncated file fails it without its data being read."""
    try:
        import netCDF4

        with netCDF4.Dataset(path, "r") as nc:
            list(nc.variables)
    except Exception as exc:  # noqa: BLE001 - any failure of the library is "unreadable"
        return " ".join(str(exc).split())[:160] or type(exc).__name__
    return None


def set_aside_unreadable(folder: str | os.PathLike[str]) -> list[tuple[Path, str]]:
    """Rename every netCDF file under ``folder`` that fails :func:`readable_netcdf` to
    ``<name>.corrupt`` (kept for inspection, replacing an older one), so that the
    workflow, missing it, makes it again on a plain rerun. Returns ``(path, reason)``
    of each file set aside; the workflow prints one line for each."""
    found: list[tuple[Path, str]] = []
    root = Path(folder)
    if not root.is_dir():
        return found
    for path in sorted(root.rglob("*.nc")):
        if TEMP_MARK in path.name or not path.is_file():
            continue
        reason = readable_netcdf(path)
        if reason is not None:
            os.replace(path, path.with_name(path.name + ".corrupt"))
            found.append((path, reason))
    return found
