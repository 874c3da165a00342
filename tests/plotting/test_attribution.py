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


def test_every_group_of_settings_looks_different(archived_figure):
    """No two groups of settings share both colour and marker (a group past the ten colours
    of the cycle wrapped to the first group's blue)."""
    from pathlib import Path

    import xarray as xr

    archive = Path(__file__).resolve().parents[2] / "results" / "archive"
    ds = xr.open_dataset(archive / "attribution" / "attribution.nc")
    groups = list(dict.fromkeys(str(g) for g in ds["group"].values))
    ax = archived_figure("attribution").axes[0]
    style = {}
    for line, group in zip(ax.lines[-len(ds["group"]) :], [str(g) for g in ds["group"].values],
                           strict=True):  # fmt: skip
        style.setdefault(group, (line.get_markeredgecolor(), line.get_marker()))
    assert len(style) == len(groups)
    assert len(set(style.values())) == len(groups), style
