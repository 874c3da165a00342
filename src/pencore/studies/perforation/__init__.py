"""Beyond the paper: perforation of finite plates (plotted by
:mod:`pencore.plotting.perforation`):

=============  ====================================================================
module         contents
=============  ====================================================================
``slabs``      ballistic limit map, residual velocity curve with its Recht-Ipson fit
``obliquity``  ballistic-limit maps per near-surface option against measured oblique
               ballistic limits
=============  ====================================================================
"""
