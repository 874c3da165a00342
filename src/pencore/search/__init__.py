"""Critical values as thresholds of a yes/no verdict.

=================  ==============================================================
module             contents
=================  ==============================================================
``threshold``      :func:`threshold.find_threshold` and :class:`threshold.CriticalResult`
``critical``       Vcr, Vci and omega_c of the paper (Sections 4.2-4.3)
``perforation``    the ballistic limit of a finite target, the Recht-Ipson curve
=================  ==============================================================

``__all__`` lists the public names (imported from their modules on first use).
"""

from pencore._lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "vcr": "critical",
        "vci": "critical",
        "omega_c": "critical",
        "find_threshold": "threshold",
        "CriticalResult": "threshold",
        "ballistic_limit": "perforation",
        "residual_velocity": "perforation",
        "perforates": "perforation",
        "recht_ipson": "perforation",
        "fit_recht_ipson": "perforation",
    },
)
del attach
