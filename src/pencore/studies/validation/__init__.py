"""Validation and verification against measurements and closed forms (Section 3;
plotted by :mod:`pencore.plotting.depth` and :mod:`pencore.plotting.perforation`):

================  =================================================================
module            contents
================  =================================================================
``table2``        paper Table 2: the soil tests, every candidate run, the selection
``depth``         Fig. 5 and the verification against the closed form
``measurements``  every measured shot run at its measured impact, errors and summaries
================  =================================================================
"""
