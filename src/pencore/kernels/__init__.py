"""Compiled (numba) kernels: the DAFL loads on the projectile's surface and their
velocity Jacobian, the rigid-body right-hand side, and the state helpers the
integrators inline.

==================  ==============================================================
module              contents
==================  ==============================================================
``windows``         depth windows of the contact stress (crater, free surface)
``bands``           what the band a surface ring stands for spans
``arcs``            arc sets on a ring and closed-form integrals over them
``friction``        Coulomb friction on the loaded arcs of a ring
``wholering``       normal-stress integrals of whole immersed rings, all at once
``dynamics``        contact force and moment (paper Eqs 5-11), rigid-body equations
``contact_points``  point loads (panels, shank ring points), the nose-tip path
``panels``          the point-load surfaces (built once per problem, not compiled)
``forces``          the right-hand side with a selectable shank model and surface
``jacobian``        closed-form velocity Jacobian of the ring loads
``state``           outcome codes, stopping test, LU solve, quaternion helpers
``cache``           where compiled code is kept, shipped and found (set up on import)
``buildcache``      the build step's cache of compiled kernels (standard library only)
==================  ==============================================================

Compile-time habit: a value passed to another compiled function is never a literal
constant (counters start as ``np.int64(0)``, flags are run-time booleans), because numba
compiles the callee once more for a literal's own type; the first use compiles each
function once (``benchmarks/bench_compile.py`` lists any that compile twice).
"""

#: Internal: nothing here is public API (the user's entry points are :mod:`pencore`'s names).
__all__: list[str] = []

from pencore.kernels.cache import _register_locator, import_numba, invalidate_stale_caches

import_numba()  # a NUMBA_* setting numba refuses is one line (InputError), not a traceback
_register_locator()  # before any compiled function is defined
invalidate_stale_caches()
