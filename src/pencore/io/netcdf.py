"""netCDF input/output: provenance, compression, atomic writes, archiving.

Every dataset that leaves pencore for disk goes through :func:`write_netcdf`, which
records where it came from (pencore version, git commit, the exact inputs that made it
and their hash, creation time, study name), compresses the floating-point variables,
and writes atomically so an interrupted run never leaves a truncated file behind.

:func:`downsample` thins the ``time`` axis of trajectories before they are archived
(``results/archive/``): the first and last samples, and the extremes of the listed
variables (by default the deepest point of the nose tip), are always kept, so the
penetration depth read from an archived trajectory equals the one computed.
"""

from __future__ import annotations

import datetime as _dt
import functools
import hashlib
import json
import os
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from pencore.errors import InputError, ResultError, WriteError, hint_keywords
from pencore.io.atomic import atomic_path, describe_os_error
from pencore.io.outputs import NETCDF_SUFFIXES, check_destination, note_input
from pencore.io.results import unreadable_message
from pencore.version import __version__

__all__ = [
    "config_hash",
    "file_sha256",
    "git_commit",
    "provenance_attrs",
    "write_netcdf",
    "read_netcdf",
    "downsample",
]

#: zlib level used for every floating-point variable (4: most of the gain, little cost).
COMPLEVEL = 4

#: ``src/pencore``: the sources the provenance's commit and dirty flag refer to.
_PACKAGE_DIR = Path(__file__).resolve().parents[1]


def _canonical_json(obj: Any) -> str:
    """JSON with sorted keys and no whitespace (stable input for hashing)."""
    return json.dumps(obj, sort_keys=True, separators=(",", ":"), default=_json_default)


def _json_default(x: Any) -> Any:
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, Path):
        return str(x)
    if isinstance(x, Mapping):
        return dict(x)
    if isinstance(x, Sequence) and not isinstance(x, str | bytes):
        return list(x)
    return str(x)


def config_hash(config_slice: Mapping[str, Any]) -> str:
    """sha256 (hex) of the canonical JSON of ``config_slice``."""
    return hashlib.sha256(_canonical_json(config_slice).encode()).hexdigest()


def file_sha256(path: str | os.PathLike[str]) -> str:
    """sha256 (hex) of a file's bytes (to record input files in a config slice)."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


@functools.cache
def git_commit() -> tuple[str, str]:
    """(commit, dirty) of the repository holding the pencore sources.

    ``commit`` is ``git rev-parse HEAD`` run in the package directory, or ``'unknown'``
    (not a git checkout, git missing). ``dirty`` is ``'true'`` when the pencore sources
    differ from that commit, ``'false'`` when they do not, ``'unknown'`` otherwise.
    """

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            ["git", *args], cwd=_PACKAGE_DIR, capture_output=True, text=True, timeout=10
        )

    try:
        head = run("rev-parse", "HEAD")
    except (OSError, subprocess.SubprocessError):
        return "unknown", "unknown"
    if head.returncode != 0:
        return "unknown", "unknown"
    commit = head.stdout.strip()
    try:
        diff = run("diff", "--quiet", "HEAD", "--", ".")
        dirty = {0: "false", 1: "true"}.get(diff.returncode, "unknown")
    except (OSError, subprocess.SubprocessError):
        dirty = "unknown"
    return commit, dirty


def provenance_attrs(config_slice: Mapping[str, Any], study: str) -> dict[str, str]:
    """The provenance attributes :func:`write_netcdf` adds to a dataset."""
    commit, dirty = git_commit()
    return {
        "study": str(study),
        "pencore_version": __version__,
        "git_commit": commit,
        "git_dirty": dirty,
        "config_json": _canonical_json(config_slice),
        "config_sha256": config_hash(config_slice),
        "created_utc": _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
    }


def _netcdf_safe_attrs(attrs: Mapping[str, Any]) -> dict[str, Any]:
    """netCDF attributes must be strings, numbers or 1-D numeric arrays."""
    out: dict[str, Any] = {}
    for k, v in attrs.items():
        if v is None:
            out[k] = ""
        elif isinstance(v, bool | np.bool_):
            out[k] = int(v)
        elif isinstance(v, str | int | float | np.number):
            out[k] = v
        elif isinstance(v, np.ndarray) and v.dtype.kind in "iuf":
            out[k] = v
        elif isinstance(v, list | tuple) and all(
            isinstance(e, int | float) and not isinstance(e, bool) for e in v
        ):
            out[k] = np.asarray(v)
        else:
            out[k] = _canonical_json(v)
    return out


def write_netcdf(
    ds: xr.Dataset,
    path: str | os.PathLike[str],
    *,
    config_slice: Mapping[str, Any],
    study: str,
    protect: Sequence[str | os.PathLike[str]] = (),
) -> Path:
    """Write ``ds`` to ``path`` with provenance, compression and an atomic replace.

    Only a regular file (or nothing) at ``path`` is replaced, and never one of
    ``protect`` (the run's own input files): :func:`pencore.io.outputs.check_replaceable`.

    Parameters
    ----------
    ds : xarray.Dataset
        Dataset to write; it is not modified.
    path : path-like
        Destination; must end in ``.nc``. Parent directories are created. The output
        gate's rules hold (:mod:`pencore.io.outputs`): not a directory, a read-only file,
        the file ``ds`` was read from, or an input of the open call.
    config_slice : mapping
        The exact inputs (configuration entries) that produced ``ds``; stored as
        canonical JSON in the ``config_json`` attribute with its sha256 in
        ``config_sha256``.
    study : str
        Name of the study (for example ``'validation/table2'``).
    protect : sequence of path-like, optional
        Files that must never be replaced (the run's own inputs).

    Returns
    -------
    pathlib.Path
        The written path.

    Raises
    ------
    TypeError
        ``ds`` is not an :class:`xarray.Dataset`.
    WriteError
        The file could not be written (the path is a directory or one of ``protect``, no
        permission, disk full...); nothing is left behind, and the one-line message names
        the path and the cause.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 280.0)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = pencore.write_netcdf(
    ...         ds, Path(tmp) / "p2.nc", config_slice={"velocity": 280.0}, study="example"
    ...     )
    ...     back = pencore.read_netcdf(path)
    >>> print(path.name, back.attrs["study"], back.attrs["config_json"])
    p2.nc example {"velocity":280.0}

    Notes
    -----
    Attributes added: ``study``, ``pencore_version``, ``git_commit`` (``'unknown'`` when
    git cannot tell), ``git_dirty``, ``config_json``, ``config_sha256``, ``created_utc``.
    Every floating-point variable and coordinate is zlib-compressed (level 4). The file is
    written through :func:`pencore.io.atomic.atomic_path`: to a temporary file in the same
    directory, flushed to the disk, then renamed into place, so a failed or killed write
    leaves no file behind; any failure raises :class:`pencore.errors.WriteError` (an
    ``OSError``) with a one-line message naming the path and the cause.
    """
    if not isinstance(ds, xr.Dataset):
        raise TypeError(f"write_netcdf needs an xarray.Dataset, got {type(ds).__name__}")
    # the file a Dataset was read from is its input: never replaced by it
    source = ds.encoding.get("source")
    protect = [*protect, *([source] if isinstance(source, str) else [])]
    path = check_destination(path, NETCDF_SUFFIXES, protect)  # before a folder is made
    try:  # inside the promise: any failure to write is one WriteError line
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise WriteError(
            f"cannot write {str(path)!r}: its folder {str(path.parent)!r} cannot be made "
            f"({describe_os_error(exc)}); nothing was written",
            exc.errno,
        ) from None
    out = ds.copy(deep=False)
    out.attrs = _netcdf_safe_attrs({**ds.attrs, **provenance_attrs(config_slice, study)})
    for name in out.variables:
        out[name].attrs = _netcdf_safe_attrs(out[name].attrs)
    out, encoding = cf_encoding(out)
    with atomic_path(path, protect=protect, suffixes=NETCDF_SUFFIXES) as tmp:
        out.to_netcdf(tmp, engine="netcdf4", encoding=encoding)
    return path


#: The CF version the files declare: the newest one the official CF checker
#: (``cfchecker``, run by ``.ci/cf_check.py``) verifies. The files use nothing newer.
CF_CONVENTIONS = "CF-1.8"

#: The name on disk of the ``time`` dimension of trajectories. pencore's ``time`` is the
#: time elapsed since the start of a run (s), not a CF time coordinate: CF 1.10 section
#: 4.4 says a time coordinate value represents a date/time and its units must contain a
#: reference date/time (``seconds since 1992-10-8 15:15:42.5 -6:00``), and a simulated
#: impact has no date. It is therefore written as a generic coordinate (CF section 4:
#: coordinates may be any continuous quantity) with units ``s`` and a long_name, without
#: ``standard_name = "time"`` or ``axis = "T"``. CF standardises no variable or dimension
#: names (section 2.3), but tools take a dimension named ``time`` for a CF time axis
#: (the IOOS compliance-checker then asks for ``standard_name = "time"``, which in turn
#: asks for ``since`` units), so on disk the dimension is named for what it is.
#: :func:`read_netcdf` gives it back its in-memory name ``time``.
ELAPSED_TIME = "elapsed_time"

_ELAPSED_TIME_COMMENT = (
    "time elapsed since the start of the run; not a CF time coordinate (no reference "
    "date/time); pencore.io.netcdf.read_netcdf names it 'time'"
)


def cf_encoding(ds: xr.Dataset) -> tuple[xr.Dataset, dict[str, dict[str, Any]]]:
    """A copy of ``ds`` and its netCDF encoding, such that the file is CF-compliant.

    * ``Conventions`` is :data:`CF_CONVENTIONS`; ``history`` records when and by which
      pencore version (and study) the file was written;
    * the ``time`` dimension and its coordinate (elapsed time since the start of a run)
      are named :data:`ELAPSED_TIME`, with a ``comment`` saying why;
    * text variables are written as character arrays (CF-1.8 has no variable-length
      strings), read back as text by xarray;
    * 64-bit integers become 32-bit where the values fit, booleans 8-bit integers;
    * coordinate variables carry no ``_FillValue``;
    * floating-point variables are zlib-compressed (level :data:`COMPLEVEL`).
    """
    out = ds.copy(deep=False)
    stamp = out.attrs.get("created_utc", "")
    study = out.attrs.get("study", "")
    line = f"{stamp} written by pencore {__version__}" + (f" (study {study})" if study else "")
    out.attrs["Conventions"] = CF_CONVENTIONS
    out.attrs["history"] = line.strip()
    if "time" in out.dims and ELAPSED_TIME not in out.variables:
        out = out.rename({"time": ELAPSED_TIME})
        if ELAPSED_TIME in out.variables:
            out[ELAPSED_TIME].attrs = {
                **out[ELAPSED_TIME].attrs,
                "comment": _ELAPSED_TIME_COMMENT,
            }
    encoding: dict[str, dict[str, Any]] = {}
    for name, var in out.variables.items():
        enc: dict[str, Any] = {}
        kind = var.dtype.kind
        if kind == "f" and var.ndim > 0:
            enc.update(zlib=True, complevel=COMPLEVEL)
        elif kind in "OUS":
            enc["dtype"] = "S1"
        elif kind == "b":
            out[name] = var.astype("int8")
            out[name].attrs = var.attrs
        elif kind in "iu" and var.dtype.itemsize == 8:
            info = np.iinfo(np.int32)
            values = var.values
            if values.size == 0 or (values.min() >= info.min and values.max() <= info.max):
                enc["dtype"] = "int32"
        if name in out.coords or name in out.dims:
            enc["_FillValue"] = None
        if enc:
            encoding[str(name)] = enc
    return out, encoding


def read_netcdf(path: str | os.PathLike[str]) -> xr.Dataset:
    """Read a netCDF file fully into memory (the file is closed on return).

    The elapsed-time dimension, ``elapsed_time`` on disk
    (:data:`pencore.io.netcdf.ELAPSED_TIME`), is named ``time`` again (without the
    ``comment`` :func:`pencore.io.netcdf.cf_encoding` added), so a written Dataset reads
    back with the names it had; files written before the rename read unchanged.

    Parameters
    ----------
    path : str or path-like
        The file: a trajectory of :func:`~pencore.write_netcdf` or ``pencore simulate
        --out``, a study's result, or a file of the archive (``results/archive/``).

    Returns
    -------
    xarray.Dataset
        The file's variables and attributes, loaded.

    Raises
    ------
    InputError
        ``path`` is not a path (a number, None).
    FileNotFoundError
        No file at ``path``.
    pencore.errors.ResultError
        The file cannot be read (corrupt or truncated): one line naming it and how to
        make it again.

    Examples
    --------
    A trajectory written and read back has the names, values and units it had:

    >>> import tempfile
    >>> from pathlib import Path
    >>> import pencore
    >>> ds = pencore.simulate("p2", "soil", 280.0)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = pencore.write_netcdf(ds, Path(tmp) / "p2.nc", config_slice={}, study="example")
    ...     back = pencore.read_netcdf(path)
    >>> list(back.tip_y.dims), back.penetration_depth.units
    (['time'], 'm')
    >>> bool(back.penetration_depth == ds.penetration_depth)
    True
    >>> pencore.read_netcdf("no-such-file.nc")
    Traceback (most recent call last):
    ...
    FileNotFoundError: no netCDF file at 'no-such-file.nc'
    """
    if not isinstance(path, str | os.PathLike):
        raise InputError(
            f"read_netcdf needs a file path (str or path-like), got {type(path).__name__} "
            f"{str(path)[:40]!r}"
        )
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"no netCDF file at {str(path)!r}")
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except MemoryError:
        raise ResultError(
            f"netCDF file {str(path)!r} is too large to load into memory "
            f"({path.stat().st_size / 2**30:.3g} GiB on disk); open it lazily with "
            "xarray.open_dataset instead"
        ) from None
    except (OSError, RuntimeError, ValueError, KeyError) as exc:
        raise ResultError(unreadable_message(path, exc)) from None
    note_input(path)  # no writer of the same call may replace it
    if ELAPSED_TIME in ds.dims and "time" not in ds.variables:
        ds = ds.rename({ELAPSED_TIME: "time"})
        if "time" in ds.variables and ds["time"].attrs.get("comment") == _ELAPSED_TIME_COMMENT:
            ds["time"].attrs = {k: v for k, v in ds["time"].attrs.items() if k != "comment"}
    return ds


def downsample(
    ds: xr.Dataset,
    n: int = 400,
    *,
    dim: str = "time",
    keep_extrema: Sequence[str] = ("tip_y",),
) -> xr.Dataset:
    """Thin the ``dim`` axis of a trajectory to about ``n`` samples for archiving.

    Keeps the first and last samples, ``n`` samples evenly spaced in index between them,
    and the index of the minimum and maximum of each variable in ``keep_extrema`` that is
    present (by default ``tip_y``, so the deepest point of the nose tip survives). Scalar
    variables and attributes are untouched. Datasets without ``dim``, or no longer than
    ``n``, are returned unchanged.

    Parameters
    ----------
    ds : xarray.Dataset
    n : int
        Target number of samples (>= 2). A few more may be kept for the extrema.
    dim : str
        Dimension to thin.
    keep_extrema : sequence of str
        Variables whose minimum and maximum along ``dim`` must be kept. For variables
        with other dimensions too, the extremes over every other index are kept.

    Returns
    -------
    xarray.Dataset
        With attribute ``downsampled_from`` (original length) when thinned.
    """
    n = int(n)
    if n < 2:
        raise ValueError(f"downsample needs n >= 2, got {n}")
    if dim not in ds.dims or ds.sizes[dim] <= n:
        return ds
    size = ds.sizes[dim]
    keep = set(np.unique(np.round(np.linspace(0, size - 1, n)).astype(int)).tolist())
    for name in keep_extrema:
        if name in ds.variables and dim in ds[name].dims:
            arr = ds[name].transpose(dim, ...).values.reshape(size, -1)
            finite = np.where(np.isfinite(arr), arr, np.nan)
            for col in range(finite.shape[1]):
                c = finite[:, col]
                if np.isfinite(c).any():
                    keep.add(int(np.nanargmin(c)))
                    keep.add(int(np.nanargmax(c)))
    idx = np.array(sorted(keep))
    out = ds.isel({dim: idx})
    out.attrs = {**ds.attrs, "downsampled_from": int(size), "downsampled_dim": dim}
    return out


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
