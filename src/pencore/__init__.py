"""pencore: 3-D rigid-projectile penetration with the differential area force law.

Reproduces and extends Li & Flores-Johnson, "Hard projectile penetration and trajectory
stability", Int. J. Impact Engineering 38 (2011) 815-823. SI units throughout; angles in
degrees only at the user-facing edges (``simulate`` arguments, datasets, CLI, plots).
"""

__version__ = "0.1.0"

from .geometry import ConeNose, Cylinder, FlatNose, OgiveNose, Projectile  # noqa: E402
from .library import InputError, get_projectile, get_target, table3_fit  # noqa: E402
from .models import Emulation, ShankModel  # noqa: E402
from .solver import Numerics, SolverError, prepare, simulate  # noqa: E402
from .target import Layer, Medium, Target  # noqa: E402

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
