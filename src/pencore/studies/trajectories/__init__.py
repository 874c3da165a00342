"""Trajectory studies of Section 4: many runs stacked on one time axis (plotted by
:mod:`pencore.plotting.trajectories`):

=============  ====================================================================
module         contents
=============  ====================================================================
``stack``      runs on a shared time axis, a set of runs along one parameter
``oblique``    Fig. 7: #2 at 45 deg for velocities around Vcr
``yaw``        Fig. 11: oblique impact with yaw; Figs 13-14: normal impact, small yaw
``spin``       Figs 16-17: initial angular velocity; the start-height study
=============  ====================================================================
"""
