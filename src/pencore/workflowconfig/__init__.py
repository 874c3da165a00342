"""The workflow's configuration: which studies exist and how they are configured.

What the Snakefile needs at every start, before any study runs, so a layer of its own that
loads no solver, no numba and no data stack (an import contract in ``pyproject.toml``
keeps it so):

=====================  ===============================================================
module                 contents
=====================  ===============================================================
``registry``           one :class:`registry.Study` record per Section 4 study
=====================  ===============================================================
"""
