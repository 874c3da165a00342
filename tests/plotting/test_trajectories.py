"""pencore.plotting.trajectories: its registered figures drawn from the archive, axes labelled
with units, none empty."""

from __future__ import annotations

import pytest

from pencore import plotting

KINDS = ("fig7", "fig11", "fig13", "fig16", "start_height")


@pytest.mark.parametrize("kind", KINDS)
def test_figure_from_the_archive_has_labelled_axes_with_units(kind, archived_figure, figure_check):
    assert plotting.PLOTS[kind].__module__ == "pencore.plotting.trajectories"
    figure_check(archived_figure(kind))
