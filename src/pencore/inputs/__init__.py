"""Inputs of a run: the projectile, the target, the numerics and the model choices.

=================  ==============================================================
module             contents
=================  ==============================================================
``limits``         the valid range of every quantity (:data:`~pencore.inputs.limits.LIMITS`), checks
``geometry``       projectile bodies of revolution, mass properties, surface rings
``target``         media (resistance and friction laws, depth windows), layers
``laws``           resistance laws from material properties (concrete, metal, soil)
``library``        the named projectiles and targets, YAML files, the Table-3 fit
``models``         shank contact models and paper-emulation numerics
``numerics``       :class:`numerics.Numerics` and :func:`numerics.resolve_numerics`
``conventions``    the named readings of the paper's words (yaw conventions, spin)
=================  ==============================================================

Nothing here runs the solver or imports numba.
"""

from pencore._lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Projectile": "geometry",
        "OgiveNose": "geometry",
        "ConeNose": "geometry",
        "FlatNose": "geometry",
        "Cylinder": "geometry",
        "MassProperties": "geometry",
        "Medium": "target",
        "Layer": "target",
        "Target": "target",
        "concrete_law": "laws",
        "metal_law": "laws",
        "soil_law": "laws",
        "cavity_expansion": "laws",
        "CavityExpansion": "laws",
        "forrestal_s": "laws",
        "medium_from_law": "laws",
        "Numerics": "numerics",
        "ShankModel": "models",
        "Emulation": "models",
        "get_projectile": "library",
        "get_target": "library",
        "projectile_names": "library",
        "target_names": "library",
        "projectile_from_dict": "library",
        "target_from_dict": "library",
        "table3_fit": "library",
        "Table3Fit": "library",
        "LIMITS": "limits",
        "Limit": "limits",
        "normal_impact_angles": "conventions",
    },
)
del attach
