"""The paper as data: the claims of Li & Flores-Johnson (2011) and its tables
(:mod:`~pencore.paper.claims`, from ``paper_claims.csv`` and ``table2.csv``, shipped in
``pencore/paper/data/``, which the repository's ``config/`` links to) and the choices a
reading of the paper fixes (:mod:`~pencore.paper.choices`; the mass distributions Table 3
leaves open: :mod:`~pencore.paper.bodies`). The measured shots of its validation sources
and their kin are not the paper's claims: they are in :mod:`pencore.measured`. Nothing
here runs the model: the
studies that compare with the paper (:mod:`pencore.studies.comparison`,
:mod:`pencore.studies.attribution.disputed`, :mod:`pencore.studies.attribution.settings`) read it.
"""
