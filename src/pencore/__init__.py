"""pencore: 3-D rigid-projectile penetration with the differential area force law.

Reproduces and extends Li & Flores-Johnson, "Hard projectile penetration and trajectory
stability", Int. J. Impact Engineering 38 (2011) 815-823. SI units throughout; angles in
degrees only at the user-facing edges (``simulate`` arguments, datasets, CLI, plots).

The public names below are imported on first use (PEP 562), and so are submodules
accessed as attributes (``pencore.library``): a process that only reads or plots results
(``pencore.io``, ``pencore.plotting``, the workflow's figure jobs) then does not load
numba and the solver, about 0.4 s of every such job.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

#: public name -> the submodule that defines it
_EXPORTS = {
    "ConeNose": "geometry",
    "Cylinder": "geometry",
    "FlatNose": "geometry",
    "OgiveNose": "geometry",
    "Projectile": "geometry",
    "Medium": "target",
    "Layer": "target",
    "Target": "target",
    "InputError": "library",
    "SolverError": "solver",
    "Numerics": "solver",
    "ShankModel": "models",
    "Emulation": "models",
    "get_projectile": "library",
    "get_target": "library",
    "table3_fit": "library",
    "prepare": "solver",
    "simulate": "solver",
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
    from .geometry import ConeNose, Cylinder, FlatNose, OgiveNose, Projectile
    from .library import InputError, get_projectile, get_target, table3_fit
    from .models import Emulation, ShankModel
    from .solver import Numerics, SolverError, prepare, simulate
    from .target import Layer, Medium, Target
