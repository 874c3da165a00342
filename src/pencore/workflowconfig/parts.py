"""How a split study's configuration becomes job parts
(:func:`~pencore.workflowconfig.parts.parts_of`; which studies
are split, and by what, is their record in :mod:`pencore.workflowconfig.registry`), with
the ``{min, max, step}`` grids of the configuration
(:func:`~pencore.workflowconfig.parts.grid`), and the settings a job runs
(:func:`~pencore.workflowconfig.parts.round_robin`).

Light (numpy and :mod:`pencore.errors` only): the workflow asks for the parts at every
Snakemake start, before any study runs.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from pencore.errors import InputError
from pencore.workflowconfig import registry

__all__ = ["grid", "values", "value_range", "parts_of", "round_robin", "remade_target"]


def grid(min: float, max: float, step: float) -> np.ndarray:
    """Values from ``min`` to ``max`` inclusive in steps of ``step`` (rounded to 1e-9)."""
    lo, hi, st = float(min), float(max), float(step)
    if not (math.isfinite(lo) and math.isfinite(hi) and math.isfinite(st) and st > 0 and hi >= lo):
        raise InputError(f"grid needs min <= max and step > 0, got {min}, {max}, {step}")
    n = int(math.floor((hi - lo) / st + 1e-9)) + 1
    return np.round(lo + st * np.arange(n), 9)


def values(v: Any) -> list[float]:
    """A list of numbers, or a ``{min, max, step}`` grid (:func:`grid`)."""
    if isinstance(v, Mapping):
        return [float(x) for x in grid(v["min"], v["max"], v["step"])]
    return [float(x) for x in v]


def value_range(d: Mapping[str, Any]) -> tuple[float, float]:
    """``(min, max)`` of a ``{min, max}`` range of the configuration, with min < max."""
    lo, hi = float(d["min"]), float(d["max"])
    if not lo < hi:
        raise InputError(f"range needs min < max, got {dict(d)}")
    return lo, hi


def parts_of(study: str, cfg: Mapping[str, Any]) -> list[dict[str, Any]]:
    """Job parts of a split study: ``[{"projectile": "p1"}, ...]``, or with
    ``"obliquity"`` too (deg) when its record splits by obliquity, from the study's
    configuration entry ``cfg`` (its ``projectiles`` and ``obliquity_deg``)."""
    record = registry.study(study)
    if not record.split_by:
        raise InputError(f"{study!r} is not split into parts")
    parts: list[dict[str, Any]] = [{"projectile": p} for p in cfg["projectiles"]]
    if "obliquity" in record.split_by:
        parts = [{**part, "obliquity": o} for part in parts for o in values(cfg["obliquity_deg"])]
    return parts


def round_robin(names: Sequence[str], n_jobs: int) -> list[list[str]]:
    """``names`` dealt into at most ``n_jobs`` lists in turn (the i-th name to list
    ``i % n_jobs``), empty lists left out: the settings of a study that one job each would
    spend more on its process start and kernel load than on its runs.

    >>> round_robin(["a", "b", "c"], 2)
    [['a', 'c'], ['b']]
    """
    if isinstance(n_jobs, bool) or not isinstance(n_jobs, int) or n_jobs < 1:
        raise InputError(f"the number of jobs must be a whole number >= 1, got {n_jobs!r}")
    return [list(names[k::n_jobs]) for k in range(min(n_jobs, len(names)))]


#: An ensemble chunk part, as the workflow names it: ``results/ensemble/<name>/parts/<k>.nc``.
_ENSEMBLE_PART = re.compile(r"results/ensemble/(?P<name>[^/]+)/parts/(?P<chunk>[0-9]+)\.nc")


def remade_target(path: str, rules: Iterable[Any], ensembles: Mapping[str, Any]) -> str | None:
    """``path`` when a rule of this workflow makes it, else None: a result set aside as
    unreadable is asked for again only if this configuration still produces it.

    Parameters
    ----------
    path : str
        The file set aside, relative to the workflow's directory.
    rules : iterable
        Snakemake's rules (each with ``name`` and ``is_producer(path)``).
    ensembles : mapping
        Ensemble cases by name: a chunk part beyond its case's ``n_chunks`` (left by an
        earlier configuration) is not made again.
    """
    part = _ENSEMBLE_PART.fullmatch(path)
    if part:
        case = ensembles.get(part["name"])
        if case is None or int(part["chunk"]) >= int(case.get("n_chunks", 1)):
            return None
    for rule in rules:
        if rule.name != "all" and rule.is_producer(path):
            return path
    return None
