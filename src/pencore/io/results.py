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

from pencore.errors import hint_keywords
from pencore.io.atomic import TEMP_MARK

__all__ = ["readable_netcdf", "set_aside_unreadable", "unreadable_message"]


def unreadable_message(path: str | os.PathLike[str], exc: BaseException) -> str:
    """The one line for a netCDF file that cannot be read: the file, the cause, the fix."""
    cause = " ".join(str(exc).split())[:160] or type(exc).__name__
    return (
        f"netCDF file {str(path)!r} cannot be read ({cause}): it is corrupt or truncated; "
        f"delete it and rerun (the workflow makes it again: snakemake --cores 2 {path})"
    )


#: The HDF5 format signature that starts a netCDF-4 file's superblock.
HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


def hdf5_stored_end(path: str | os.PathLike[str]) -> int | None:
    """The file size an HDF5 (netCDF-4) file's superblock records (bytes: its base
    address plus its end-of-file address), read from the file's first bytes; None if the
    file has no superblock of a version this reads (0-3).

    HDF5 writes the end-of-file address when it closes a file, and refuses to open one
    that is shorter ("truncated file"); comparing it with the size on disk is that test
    without loading the library (HDF5 File Format Specification, version 3, section II.A:
    the superblock's "End of File Address").
    """
    with open(path, "rb") as f:
        offset = 0
        while True:  # the superblock is at 0 or after a user block of 512 * 2^k bytes
            f.seek(offset)
            head = f.read(128)
            if len(head) < 48:
                return None
            if head[:8] == HDF5_SIGNATURE:
                break
            offset = 512 if offset == 0 else 2 * offset
    version = head[8]
    if version in (0, 1):
        size_of_offsets, first = head[13], (24 if version == 0 else 28)
    elif version in (2, 3):
        size_of_offsets, first = head[9], 12
    else:
        return None
    # base address, then (v0/1) free-space info or (v2/3) superblock extension, then EOF
    at = first + 2 * size_of_offsets
    raw = head[at : at + size_of_offsets]
    if size_of_offsets not in (2, 4, 8) or len(raw) < size_of_offsets:
        return None
    base = int.from_bytes(head[first : first + size_of_offsets], "little")
    return offset + base + int.from_bytes(raw, "little") if base == 0 else None


def readable_netcdf(path: str | os.PathLike[str]) -> str | None:
    """None when ``path`` opens as netCDF, else the reason in words.

    A netCDF-4 file is checked by its superblock (:func:`hdf5_stored_end`: a file shorter
    than the size it records is truncated), which costs a read of its first bytes; any
    other file is opened with the netCDF library, which reads its header. A file whose
    size is right but whose contents are damaged passes here and is named, with what to
    run, by :func:`pencore.io.netcdf.read_netcdf` when a rule reads it.
    """
    try:
        end = hdf5_stored_end(path)
    except OSError as exc:
        return " ".join(str(exc).split())[:160]
    if end is not None:
        size = os.path.getsize(path)
        return None if size >= end else f"truncated: {size} of {end} bytes"
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


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
