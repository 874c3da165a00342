"""Critical values of Section 4 on grids of the impact (plotted by
:mod:`pencore.plotting.critical`):

=============  ====================================================================
module         contents
=============  ====================================================================
``vcr``        Figs 8 and 12: Vcr on (projectile, obliquity, yaw), the final nose direction
``vci``        Fig. 15: Vci on (projectile, yaw, deviation threshold)
``omega_c``    Fig. 18: omega_c on (projectile, impact velocity)
=============  ====================================================================
"""
