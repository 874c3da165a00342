"""Study functions: the physics side of each workflow study, grouped by concept as
:mod:`pencore.plotting` groups their figures.

Each study takes plain inputs (names, numbers, data frames), runs pencore, and returns
pandas / xarray objects with units and long names; ``workflow/scripts/*.py`` read the
configuration, call these, and write the results with :mod:`pencore.io`. A few studies
read the data files they compare with (the measured shots, the paper's claims); none
writes a file or runs Snakemake.

=================  ===============================================================
module             contents
=================  ===============================================================
``common``         the paper's projectiles, axes, attributes, search variables
``config``         a study from its configuration record:
                   :func:`~pencore.studies.config.from_config`,
                   :func:`~pencore.studies.config.gather`
``trajectories``   Figs 7, 11, 13-14, 16-17 and the start-height study
``critical``       Figs 8 and 12 (Vcr), 15 (Vci), 18 (omega_c)
``turning``        Fig. 9: total turning angle against Lc/L
``comparison``     :func:`~pencore.studies.comparison.paper_comparison`: the paper's
                   numbers beside pencore's
``trends``         trend verdicts within search brackets
``validation``     Table 2, Fig. 5, verification, the measured shots
``perforation``    beyond the paper: ballistic limits and residual velocities of plates
``ensemble``       Monte Carlo ensembles of uncertain impacts
``attribution``    the paper's disputed numbers, and which reading moves each
=================  ===============================================================

Which Section 4 studies exist, and their configuration, is in
:mod:`pencore.workflowconfig`.

Conventions (those of :func:`pencore.simulate`): the target is ``y <= 0``; obliquity
phi1 is the angle of the projectile AXIS from the target normal; yaw phi2 is the velocity
angle minus the axis angle (paper Fig. 10).
"""
