"""pencore.plotting.attribution: its registered figures drawn from the archive, axes labelled
with units, none empty."""

from __future__ import annotations

import pytest

from pencore import plotting

KINDS = ("attribution",)


@pytest.mark.parametrize("kind", KINDS)
def test_figure_from_the_archive_has_labelled_axes_with_units(kind, archived_figure, figure_check):
    assert plotting.PLOTS[kind].__module__ == "pencore.plotting.attribution"
    figure_check(archived_figure(kind))


def test_panel_titles_fit_inside_the_figure_and_apart(archived_figure):
    """Every panel title lies inside the saved figure and clear of its neighbours' (a long
    last title was cut off at the right edge)."""
    fig = archived_figure("attribution")
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    page = fig.bbox
    boxes = [ax.title.get_window_extent(renderer) for ax in fig.axes if ax.get_title()]
    assert len(boxes) == len(fig.axes)
    for b in boxes:
        assert page.x0 <= b.x0 and b.x1 <= page.x1 and page.y0 <= b.y0 and b.y1 <= page.y1
    for left, right in zip(boxes, boxes[1:], strict=False):
        assert left.x1 <= right.x0
