"""The check every function that reads a run's Dataset makes first: that it is an
:class:`xarray.Dataset` holding the variables and attributes the function reads.

A wrong type or a Dataset from elsewhere (a foreign netCDF file, a study's table) would
otherwise end in a ``KeyError`` deep inside xarray, or worse in an answer (an outcome
attribute read as missing is "not perforated"); :func:`check_run` makes it one
:class:`~pencore.InputError` line naming the function, what it got and what it lacks.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from pencore.errors import InputError

__all__ = ["check_run"]


def check_run(ds: Any, what: str, variables: Iterable[str] = (), attrs: Iterable[str] = ()) -> None:
    """Refuse ``ds`` unless it is an :class:`xarray.Dataset` with ``variables`` and
    ``attrs``.

    Parameters
    ----------
    ds : Any
        What the caller was given.
    what : str
        The function's name, for the message.
    variables, attrs : iterable of str
        The data variables (or coordinates) and attributes the function reads.

    Raises
    ------
    InputError
        One line: the type given, or the names the Dataset lacks.

    Examples
    --------
    >>> import xarray as xr
    >>> check_run(42, "perforates")
    Traceback (most recent call last):
    ...
    pencore.errors.InputError: perforates needs a Dataset made by pencore.simulate, got int 42
    >>> check_run(xr.Dataset(), "residual_velocity", attrs=["outcome"])
    Traceback (most recent call last):
    ...
    pencore.errors.InputError: residual_velocity needs a Dataset made by pencore.simulate; this one lacks the attribute(s) outcome
    """  # noqa: E501
    import xarray as xr

    if not isinstance(ds, xr.Dataset):
        shown = repr(ds)
        shown = shown if len(shown) <= 40 else shown[:37] + "..."
        raise InputError(
            f"{what} needs a Dataset made by pencore.simulate, got {type(ds).__name__} {shown}"
        )
    missing = [v for v in variables if v not in ds.variables]
    missing_attrs = [a for a in attrs if a not in ds.attrs]
    if missing or missing_attrs:
        parts = []
        if missing:
            parts.append(f"the variable(s) {', '.join(missing)}")
        if missing_attrs:
            parts.append(f"the attribute(s) {', '.join(missing_attrs)}")
        raise InputError(
            f"{what} needs a Dataset made by pencore.simulate; this one lacks {' and '.join(parts)}"
        )
