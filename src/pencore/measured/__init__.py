"""Measured shots as data: what experiments measured, as their sources print them, read and
checked, never run. The shot tables of ``config/`` and their readers
(:mod:`~pencore.measured.shots`), and the public compilation of concrete shots with its
cleaning (:mod:`~pencore.measured.compilation`: every row of the compilation, each with a
status and the reason it is set aside, shipped in ``pencore/measured/data/``, which the
repository's ``config/`` links to). These are not the paper's claims
(:mod:`pencore.paper`). Nothing here runs the model: a contract keeps this package free of
the solver, search, study and plotting layers; the studies that compare with the shots
(:mod:`pencore.studies.validation`) read it.
"""
