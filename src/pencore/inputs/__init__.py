"""Inputs of a run: the projectile, the target, the numerics and the model choices.

=================  ==============================================================
module             contents
=================  ==============================================================
``limits``         the valid range of every quantity (:data:`limits.LIMITS`), checks
``geometry``       projectile bodies of revolution, mass properties, surface rings
``target``         media (resistance and friction laws, depth windows), layers
``library``        the named projectiles and targets, YAML files, the Table-3 fit
``models``         shank contact models and paper-emulation numerics
``numerics``       :class:`numerics.Numerics` and :func:`numerics.resolve_numerics`
``conventions``    the named readings of the paper's words (yaw conventions, spin)
=================  ==============================================================

Nothing here runs the solver or imports numba.
"""
