"""Study functions: the physics side of each workflow study.

Each function takes plain inputs (names, numbers, data frames), runs pencore, and returns
pandas / xarray objects with units and long names. No Snakemake and no file I/O here:
``workflow/scripts/*.py`` read the configuration, call these, and write the results with
:mod:`pencore.io`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import fields, replace
from typing import Any

from ..library import InputError
from ..solver import DEFAULT_NUMERICS, Numerics

__all__ = ["resolve_numerics"]


def resolve_numerics(numerics: Numerics | Mapping[str, Any] | None = None) -> Numerics:
    """A :class:`pencore.Numerics` from an object, a mapping of overrides, or ``None``.

    In a mapping, entries that are ``None`` mean "keep pencore's default" (the workflow's
    config schema fills unset numerics keys with ``null``).
    """
    if numerics is None:
        return DEFAULT_NUMERICS
    if isinstance(numerics, Numerics):
        return numerics
    if not isinstance(numerics, Mapping):
        raise InputError(
            f"numerics must be a pencore.Numerics or a mapping, got {type(numerics).__name__}"
        )
    known = {f.name for f in fields(Numerics)}
    unknown = set(numerics) - known
    if unknown:
        raise InputError(
            f"unknown numerics option(s): {', '.join(sorted(unknown))}; "
            f"known: {', '.join(sorted(known))}"
        )
    overrides = {k: v for k, v in numerics.items() if v is not None}
    return replace(DEFAULT_NUMERICS, **overrides)
