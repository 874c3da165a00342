"""The workflow's configuration: which studies exist and how they are configured.

What the Snakefile needs at every start, before any study runs, so a layer of its own that
loads no solver, no numba and no data stack (a ``forbidden`` import contract in
``pyproject.toml`` keeps it so), below :mod:`pencore.studies` and
:mod:`pencore.plotting`, which both read its registry:

=====================  ===============================================================
module                 contents
=====================  ===============================================================
``registry``           one :class:`registry.Study` record per Section 4 study
``parts``              a split study's job parts, the ``{min, max, step}`` grids
``config_check``       the input gate of the configuration and the checks a schema
                       cannot express
``config_reference``   the configuration reference generated from the schema
``ensemble_cases``     the checks of an ensemble case's configuration
``sources``            the hashes of pencore's sources that rerun the workflow's rules
=====================  ===============================================================
"""
