"""pencore: 3-D rigid-projectile penetration with the differential area force law.

Reproduces and extends Li & Flores-Johnson, "Hard projectile penetration and trajectory
stability", Int. J. Impact Engineering 38 (2011) 815-823. SI units throughout; angles in
degrees only at the user-facing edges (``simulate`` arguments, datasets, CLI, plots).

Every entry point a user calls is a name of this package (``pencore.simulate``,
``pencore.vcr``, ``pencore.read_netcdf``, ``pencore.final_deviation``...; ``__all__``
lists them, the API reference documents each); the topic subpackages (:mod:`pencore.run`,
:mod:`pencore.search`, :mod:`pencore.io`, :mod:`pencore.analysis`, :mod:`pencore.inputs`)
hold the same names and a few more, and the modules that define them stay importable.

The public names are imported on first use (PEP 562), and so are submodules accessed as
attributes (``pencore.search``): a process that only reads or plots results
(``pencore.io``, ``pencore.plotting``, the workflow's figure jobs) then does not load
numba and the solver, about 0.4 s of every such job.
"""

# ruff: noqa: F401  (the imports under TYPE_CHECKING are for type checkers; __all__ is attach's)

from typing import TYPE_CHECKING

from pencore._lazy import attach
from pencore.version import __version__

#: public name -> the submodule that defines it, grouped as the API reference is
_EXPORTS = {
    # running an impact
    "simulate": "run.impact",
    "prepare": "run.impact",
    # critical values and ballistic limits
    "vcr": "search.critical",
    "vci": "search.critical",
    "omega_c": "search.critical",
    "find_threshold": "search.threshold",
    "CriticalResult": "search.threshold",
    "ballistic_limit": "search.perforation",
    "residual_velocity": "search.perforation",
    "perforates": "search.perforation",
    "recht_ipson": "search.perforation",
    "fit_recht_ipson": "search.perforation",
    # reading and writing results
    "plot_run": "plotting.run",
    "read_netcdf": "io.netcdf",
    "write_netcdf": "io.netcdf",
    "read_table": "io.tables",
    # analysis of a trajectory
    "final_deviation": "analysis.deviation",
    "deviation_from_normal": "analysis.deviation",
    "nose_direction": "analysis.deviation",
    "reversed_in_target": "analysis.deviation",
    "turning_angle": "analysis.turning",
    "TurningAngle": "analysis.turning",
    "inflection_points": "analysis.curvature",
    "inflection_points_ds": "analysis.curvature",
    "Inflections": "analysis.curvature",
    "slope": "analysis.curvature",
    "slope_ds": "analysis.curvature",
    "signed_curvature": "analysis.curvature",
    # inputs and the library
    "Projectile": "inputs.geometry",
    "OgiveNose": "inputs.geometry",
    "ConeNose": "inputs.geometry",
    "FlatNose": "inputs.geometry",
    "Cylinder": "inputs.geometry",
    "Medium": "inputs.target",
    "Layer": "inputs.target",
    "Target": "inputs.target",
    "concrete_law": "inputs.laws",
    "metal_law": "inputs.laws",
    "soil_law": "inputs.laws",
    "Numerics": "inputs.numerics",
    "ShankModel": "inputs.models",
    "Emulation": "inputs.models",
    "get_projectile": "inputs.library",
    "get_target": "inputs.library",
    "projectile_names": "inputs.library",
    "target_names": "inputs.library",
    "table3_fit": "inputs.library",
    # errors
    "InputError": "errors",
    "ArgumentError": "errors",
    "GeometryError": "errors",
    "TargetError": "errors",
    "ConfigError": "errors",
    "SolverError": "errors",
    "WriteError": "errors",
    "ResultError": "errors",
    "PlausibilityWarning": "errors",
    "RigidRegimeWarning": "errors",
}

__getattr__, __dir__, __all__ = attach(__name__, _EXPORTS, defined=("__version__",))

if TYPE_CHECKING:  # for type checkers and editors: the names as if imported eagerly
    from pencore.analysis.curvature import (
        Inflections,
        inflection_points,
        inflection_points_ds,
        signed_curvature,
        slope,
        slope_ds,
    )
    from pencore.analysis.deviation import (
        deviation_from_normal,
        final_deviation,
        nose_direction,
        reversed_in_target,
    )
    from pencore.analysis.turning import TurningAngle, turning_angle
    from pencore.errors import (
        ArgumentError,
        ConfigError,
        GeometryError,
        InputError,
        PlausibilityWarning,
        ResultError,
        RigidRegimeWarning,
        SolverError,
        TargetError,
        WriteError,
    )
    from pencore.inputs.geometry import ConeNose, Cylinder, FlatNose, OgiveNose, Projectile
    from pencore.inputs.laws import concrete_law, metal_law, soil_law
    from pencore.inputs.library import (
        get_projectile,
        get_target,
        projectile_names,
        table3_fit,
        target_names,
    )
    from pencore.inputs.models import Emulation, ShankModel
    from pencore.inputs.numerics import Numerics
    from pencore.inputs.target import Layer, Medium, Target
    from pencore.io.netcdf import read_netcdf, write_netcdf
    from pencore.io.tables import read_table
    from pencore.plotting.run import plot_run
    from pencore.run.impact import prepare, simulate
    from pencore.search.critical import omega_c, vci, vcr
    from pencore.search.perforation import (
        ballistic_limit,
        fit_recht_ipson,
        perforates,
        recht_ipson,
        residual_velocity,
    )
    from pencore.search.threshold import CriticalResult, find_threshold

del TYPE_CHECKING, attach
