"""The paper as data and its readings: the claims of Li & Flores-Johnson (2011)
(:mod:`claims`, from ``config/paper_claims.csv``), the choices a reading of the paper
fixes (:mod:`choices`), and the attribution of the disagreements (:mod:`attribution`).
"""
