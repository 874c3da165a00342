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
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping

from matplotlib.figure import Figure

from pencore.plotting.attribution import plot_attribution
from pencore.plotting.critical import plot_fig8, plot_fig12, plot_fig15, plot_fig18
from pencore.plotting.depth import plot_fig5, plot_table2, plot_verification
from pencore.plotting.ensemble import plot_ensemble
from pencore.plotting.perforation import (
    plot_ballistic_limit,
    plot_ballistic_map,
    plot_measurements,
    plot_residual_velocity,
)
from pencore.plotting.run import plot_run
from pencore.plotting.search import plot_search
from pencore.plotting.style import STYLE, new_figure, save_figure, styled
from pencore.plotting.trajectories import (
    plot_fig7,
    plot_fig11,
    plot_fig13,
    plot_fig16,
    plot_start_height,
)
from pencore.plotting.turning import plot_fig9
from pencore.workflowconfig import registry

__all__ = [
    "STYLE",
    "styled",
    "new_figure",
    "save_figure",
    "plot_table2",
    "plot_fig5",
    "plot_verification",
    "plot_fig7",
    "plot_fig8",
    "plot_fig9",
    "plot_fig11",
    "plot_fig12",
    "plot_fig13",
    "plot_fig15",
    "plot_fig16",
    "plot_start_height",
    "plot_fig18",
    "plot_ballistic_limit",
    "plot_ballistic_map",
    "plot_residual_velocity",
    "plot_measurements",
    "plot_attribution",
    "plot_ensemble",
    "plot_run",
    "plot_search",
    "PLOTS",
]

#: The figures outside the Section 4 studies (their rules are written out in ``workflow/rules``).
_OTHER_PLOTS: dict[str, Callable[..., Figure]] = {
    "table2": plot_table2,
    "fig5": plot_fig5,
    "verification": plot_verification,
    "ballistic_limit": plot_ballistic_limit,
    "residual_velocity": plot_residual_velocity,
    "measurements": plot_measurements,
    "attribution": plot_attribution,
    "ensemble": plot_ensemble,
}


class _PlotTable(Mapping[str, Callable[..., Figure]]):
    """Figure kind -> plotting function: the other figures, then each study of
    :data:`pencore.workflowconfig.registry.STUDIES` (its ``plot``), read when asked."""

    def __getitem__(self, kind: str) -> Callable[..., Figure]:
        if kind in _OTHER_PLOTS:
            return _OTHER_PLOTS[kind]
        return registry.resolve(registry.STUDIES[kind].plot, __name__)

    def __iter__(self) -> Iterator[str]:
        yield from _OTHER_PLOTS
        yield from registry.STUDIES

    def __len__(self) -> int:
        return len(_OTHER_PLOTS) + len(registry.STUDIES)


#: Figure kind (as used by the workflow) -> plotting function.
PLOTS: Mapping[str, Callable[..., Figure]] = _PlotTable()
