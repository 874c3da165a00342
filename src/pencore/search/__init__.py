"""Critical values as thresholds of a yes/no verdict.

=================  ==============================================================
module             contents
=================  ==============================================================
``threshold``      :func:`threshold.find_threshold` and :class:`threshold.CriticalResult`
``critical``       Vcr, Vci and omega_c of the paper (Sections 4.2-4.3)
``perforation``    the ballistic limit of a finite target, the Recht-Ipson curve
=================  ==============================================================
"""
