"""Figures of the studies (matplotlib, Agg canvas, PNG + PDF), a module per figure family.

=================  =====================================================================
module             figures
=================  =====================================================================
``style``          :data:`~pencore.plotting.style.STYLE` (rcParams),
                   :func:`~pencore.plotting.style.new_figure`,
                   :func:`~pencore.plotting.style.save_figure`
``depth``          Section 3: Table 2 bars, Fig. 5, verification runs
``trajectories``   Figs 7, 11, 13-14, 16-17 and the start-height study
``critical``       Figs 8, 12 (Vcr), 15 (Vci), 18 (omega_c)
``turning``        Fig. 9 (turning angle)
``perforation``    beyond the paper: ballistic limit, residual velocity, measured vs predicted
``record``         the concrete record: measured vs predicted, error against diameter, speed
``attribution``    why the numbers differ from the paper: one panel per disputed number
``ensemble``       Monte Carlo ensembles: distributions and convergence against N
``run``            one :func:`pencore.simulate` result (:func:`~pencore.plot_run`)
``search``         one threshold search's history
=================  =====================================================================

Each ``plot_*`` function takes the study's dataset and returns a
:class:`matplotlib.figure.Figure`; :func:`~pencore.plotting.style.save_figure` writes it
(format from the suffix).
:data:`PLOTS` maps the workflow's figure kinds to the functions: the Section 4 studies'
from their records (:mod:`pencore.workflowconfig.registry`), the other figures listed here.
``__all__`` lists the public names, imported from their modules on first use: a job that
renders a table (``tables``, pandas only) does not import matplotlib.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import TYPE_CHECKING

from pencore._lazy import attach
from pencore.workflowconfig import registry

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "STYLE": "style",
        "styled": "style",
        "new_figure": "style",
        "save_figure": "style",
        "plot_table2": "depth",
        "plot_fig5": "depth",
        "plot_verification": "depth",
        "plot_fig7": "trajectories",
        "plot_fig8": "critical",
        "plot_fig9": "turning",
        "plot_fig11": "trajectories",
        "plot_fig12": "critical",
        "plot_fig13": "trajectories",
        "plot_fig15": "critical",
        "plot_fig16": "trajectories",
        "plot_start_height": "trajectories",
        "plot_fig18": "critical",
        "plot_ballistic_limit": "perforation",
        "plot_ballistic_map": "perforation",
        "plot_residual_velocity": "perforation",
        "plot_measurements": "perforation",
        "plot_concrete_record": "record",
        "plot_attribution": "attribution",
        "plot_ensemble": "ensemble",
        "plot_run": "run",
        "plot_search": "search",
    },
    defined=("PLOTS",),
)
del attach

#: The figures outside the Section 4 studies (their rules are written out in
#: ``workflow/rules``): figure kind -> the name of its plotting function here.
_OTHER_PLOTS: dict[str, str] = {
    "table2": "plot_table2",
    "fig5": "plot_fig5",
    "verification": "plot_verification",
    "ballistic_limit": "plot_ballistic_limit",
    "residual_velocity": "plot_residual_velocity",
    "measurements": "plot_measurements",
    "concrete_record": "plot_concrete_record",
    "attribution": "plot_attribution",
    "ensemble": "plot_ensemble",
}


class _PlotTable(Mapping[str, "Callable[..., Figure]"]):
    """Figure kind -> plotting function: the other figures, then each study of
    :data:`pencore.workflowconfig.registry.STUDIES` (its ``plot``), imported when asked."""

    def __getitem__(self, kind: str) -> Callable[..., Figure]:
        ref = _OTHER_PLOTS[kind] if kind in _OTHER_PLOTS else registry.STUDIES[kind].plot
        return registry.resolve(ref, __name__)

    def __iter__(self) -> Iterator[str]:
        yield from _OTHER_PLOTS
        yield from registry.STUDIES

    def __len__(self) -> int:
        return len(_OTHER_PLOTS) + len(registry.STUDIES)


#: Figure kind (as used by the workflow) -> plotting function.
PLOTS: Mapping[str, Callable[..., Figure]] = _PlotTable()
