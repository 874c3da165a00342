"""Why pencore's numbers differ from the paper's (plotted by
:mod:`pencore.plotting.attribution`):

=============  ====================================================================
module         contents
=============  ====================================================================
``disputed``   the paper's disputed quantities computed for one setting (a reading)
``settings``   the settings joined: which reading moves each disputed number
=============  ====================================================================
"""
