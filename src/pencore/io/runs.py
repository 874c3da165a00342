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


def check_run(
    ds: Any,
    what: str,
    variables: Iterable[str] = (),
    attrs: Iterable[str] = (),
    made_by: str = "pencore.simulate",
    nonempty: Iterable[str] = (),
    numeric: bool = False,
) -> None:
    """Refuse ``ds`` unless it is an :class:`xarray.Dataset` with ``variables`` and
    ``attrs``, and at least one point along each of the dimensions ``nonempty``.

    Parameters
    ----------
    ds : Any
        What the caller was given.
    what : str
        The function's name, for the message.
    variables, attrs : iterable of str
        The data variables (or coordinates) and attributes the function reads.
    made_by : str
        What makes the Dataset the function takes, for the message
        (``"pencore.simulate"``, ``"pencore.search.history.search_dataset"``).
    nonempty : iterable of str
        Dimensions that must hold at least one point (a run's ``time``).
    numeric : bool
        Whether ``variables`` must hold numbers (an edited Dataset may hold text, which
        matplotlib would draw as categories without a word).

    Raises
    ------
    InputError
        One line: the type given, the names the Dataset lacks, or the dimension it has no
        point along.

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

    variables = list(variables)

    if not isinstance(ds, xr.Dataset):
        shown = repr(ds)
        shown = shown if len(shown) <= 40 else shown[:37] + "..."
        raise InputError(
            f"{what} needs a Dataset made by {made_by}, got {type(ds).__name__} {shown}"
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
            f"{what} needs a Dataset made by {made_by}; this one lacks {' and '.join(parts)}"
        )
    if numeric:
        for v in variables:
            if ds[v].dtype.kind not in "iuf":
                raise InputError(
                    f"{what} needs a Dataset made by {made_by}; its variable {v} holds "
                    f"{ds[v].dtype} values, not numbers"
                )
    for dim in nonempty:
        if ds.sizes.get(dim, 0) == 0:
            raise InputError(
                f"{what} needs a Dataset made by {made_by}; this one has no point along {dim!r}"
            )
