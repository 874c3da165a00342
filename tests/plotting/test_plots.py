"""pencore.plotting.PLOTS: every registered figure has an archived dataset and a test in
the file of its module; the figure check itself fails on an unlabelled, unit-less or
empty axes."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from matplotlib.figure import Figure

from pencore import plotting

HERE = Path(__file__).resolve().parent


def test_every_registered_figure_is_archived_and_tested_in_its_module_file(archived):
    assert set(archived) == set(plotting.PLOTS)
    for kind, plot in plotting.PLOTS.items():
        module = plot.__module__.rsplit(".", 1)[1]
        tree = ast.parse((HERE / f"test_{module}.py").read_text())
        kinds = next(
            ast.literal_eval(node.value)
            for node in tree.body
            if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "KINDS"
        )
        assert kind in kinds, (kind, module)


def _figure(xlabel: str, ylabel: str, data: bool = True) -> Figure:
    fig = Figure()
    ax = fig.add_subplot()
    if data:
        ax.plot([0.0, 1.0], [0.0, 1.0])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    return fig


def test_the_check_passes_labelled_axes_and_fails_the_rest(figure_check):
    figure_check(_figure("Impact velocity (m/s)", "Penetration depth (m)"))
    figure_check(_figure("$L_c/L$", "deviation (deg, signed)"))
    with pytest.raises(AssertionError, match="no y label"):
        figure_check(_figure("Impact velocity (m/s)", ""))
    with pytest.raises(AssertionError, match="names no unit"):
        figure_check(_figure("Impact velocity", "Penetration depth (m)"))
    with pytest.raises(AssertionError, match="names no unit"):
        figure_check(_figure("Impact velocity (furlongs)", "Penetration depth (m)"))
    with pytest.raises(AssertionError, match="is empty"):
        figure_check(_figure("Impact velocity (m/s)", "Penetration depth (m)", data=False))
    with pytest.raises(AssertionError, match="no axes"):
        figure_check(Figure())
