"""The paper as data: the claims of Li & Flores-Johnson (2011) and its tables
(:mod:`~pencore.paper.claims`, from ``config/paper_claims.csv`` and ``config/table2.csv``) and the
choices a reading of the paper fixes (:mod:`~pencore.paper.choices`). Nothing here runs the model:
the
studies that compare with the paper (:mod:`pencore.studies.comparison`,
:mod:`pencore.studies.disputed`, :mod:`pencore.studies.attribution`) read it.
"""
