"""pencore: 3-D rigid-projectile penetration with the differential area force law.

Reproduces and extends Li & Flores-Johnson, "Hard projectile penetration and trajectory
stability", Int. J. Impact Engineering 38 (2011) 815-823. SI units throughout; angles in
degrees only at the user-facing edges (``simulate`` arguments, datasets, CLI, plots).

The public names below are imported on first use (PEP 562), and so are submodules
accessed as attributes (``pencore.search``): a process that only reads or plots results
(``pencore.io``, ``pencore.plotting``, the workflow's figure jobs) then does not load
numba and the solver, about 0.4 s of every such job.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from pencore.version import __version__

#: public name -> the submodule that defines it
_EXPORTS = {
    "ConeNose": "inputs.geometry",
    "Cylinder": "inputs.geometry",
    "FlatNose": "inputs.geometry",
    "OgiveNose": "inputs.geometry",
    "Projectile": "inputs.geometry",
    "Medium": "inputs.target",
    "Layer": "inputs.target",
    "Target": "inputs.target",
    "InputError": "errors",
    "SolverError": "errors",
    "Numerics": "inputs.numerics",
    "ShankModel": "inputs.models",
    "Emulation": "inputs.models",
    "get_projectile": "inputs.library",
    "get_target": "inputs.library",
    "table3_fit": "inputs.library",
    "prepare": "run.impact",
    "simulate": "run.impact",
}

__all__ = [
    "__version__",
    "ConeNose",
    "Cylinder",
    "FlatNose",
    "OgiveNose",
    "Projectile",
    "Medium",
    "Layer",
    "Target",
    "InputError",
    "SolverError",
    "Numerics",
    "ShankModel",
    "Emulation",
    "get_projectile",
    "get_target",
    "table3_fit",
    "prepare",
    "simulate",
]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is not None:
        value = getattr(importlib.import_module(f".{module}", __name__), name)
        globals()[name] = value
        return value
    try:
        return importlib.import_module(f".{name}", __name__)
    except ModuleNotFoundError as exc:
        if exc.name != f"{__name__}.{name}":
            raise  # a submodule exists but something it imports does not
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None


def __dir__() -> list[str]:
    return sorted({*globals(), *_EXPORTS})


if TYPE_CHECKING:  # for type checkers and editors: the names as if imported eagerly
    from pencore.errors import InputError, SolverError
    from pencore.inputs.geometry import ConeNose, Cylinder, FlatNose, OgiveNose, Projectile
    from pencore.inputs.library import get_projectile, get_target, table3_fit
    from pencore.inputs.models import Emulation, ShankModel
    from pencore.inputs.numerics import Numerics
    from pencore.inputs.target import Layer, Medium, Target
    from pencore.run.impact import prepare, simulate
