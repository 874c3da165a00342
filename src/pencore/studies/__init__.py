"""Study functions: the physics side of each workflow study.

Each function takes plain inputs (names, numbers, data frames), runs pencore, and returns
pandas / xarray objects with units and long names. No Snakemake and no file I/O here:
``workflow/scripts/*.py`` read the configuration, call these, and write the results with
:mod:`pencore.io`.

Section 4 of the paper (Figs 7-18), a module per figure or concept:

=========================  ===============================================================
module                     contents
=========================  ===============================================================
``common``                 the paper's projectiles, axes, attribute helpers
``trajectories``           many runs stacked on one time axis (Figs 7, 11, 16)
``fig07_trajectories``     Fig. 7: #2 at 45 deg for velocities around Vcr
``fig08_vcr``              Figs 8 and 12: Vcr on (projectile, obliquity, yaw)
``fig09_turning_angle``    Fig. 9: total turning angle against Lc/L
``fig13_yaw``              Figs 13-14: normal impact with small yaw
``fig15_vci``              Fig. 15: Vci on (projectile, yaw, threshold)
``fig16_spin``             Figs 16-17: initial angular velocity; start-height study
``fig18_omega_c``          Fig. 18: omega_c on (projectile, impact velocity)
``trends``                 trend verdicts within search brackets
``comparison_rows``        row helpers of the comparison table
``comparison_spin``        its rows for the spin claims (Figs 16-18)
``comparison``             :func:`~pencore.studies.comparison.paper_comparison`: the paper's
                           numbers beside pencore's
``config_check``           checks of the workflow configuration a schema cannot express
``parts``                  which studies exist and their job parts (light: the Snakefile's)
``config``                 workflow config -> study parts,
                           :func:`~pencore.studies.config.from_config`,
                           :func:`~pencore.studies.config.gather`
``perforation``            beyond the paper: ballistic limit map, residual velocity curve
``disputed``               the paper's disputed quantities for one setting (a reading)
``attribution``            which reading moves each disputed number (settings joined)
=========================  ===============================================================

Conventions (those of :func:`pencore.simulate`): the target is ``y <= 0``; obliquity
phi1 is the angle of the projectile AXIS from the target normal; yaw phi2 is the velocity
angle minus the axis angle (paper Fig. 10).
"""

from __future__ import annotations
