"""pencore.plotting.critical: its registered figures drawn from the archive, axes labelled
with units, none empty, legends listing only what is drawn, the paper's star in its
projectile's colour."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.colors import to_hex
from matplotlib.lines import Line2D

from pencore import plotting

KINDS = ("fig8", "fig12", "fig15", "fig18")


@pytest.mark.parametrize("kind", KINDS)
def test_figure_from_the_archive_has_labelled_axes_with_units(kind, archived_figure, figure_check):
    assert plotting.PLOTS[kind].__module__ == "pencore.plotting.critical"
    figure_check(archived_figure(kind))


def _legends(fig):
    return [lg for lg in [*(ax.get_legend() for ax in fig.axes), *fig.legends] if lg]


def _drawn_lines(fig):
    """Lines of the figure that draw at least one finite point."""
    out = []
    for ax in fig.axes:
        for line in ax.lines:
            xy = np.asarray(line.get_xydata(), dtype=float)
            if xy.size and np.isfinite(xy).all(axis=-1).any():
                out.append(line)
    return out


def _open(line: Line2D) -> bool:
    return str(line.get_markerfacecolor()).lower() == "none"


@pytest.mark.parametrize("kind", KINDS)
def test_legend_lists_only_what_is_drawn(kind, archived_figure):
    """A marker or line style in a legend appears in the figure (the search outcomes are
    listed only where a search ended so)."""
    fig = archived_figure(kind)
    drawn = _drawn_lines(fig)
    missing = []
    for lg in _legends(fig):
        for handle, text in zip(lg.legend_handles, lg.get_texts(), strict=True):
            if not isinstance(handle, Line2D):
                continue  # errorbar containers: drawn with their data
            if handle.get_marker() not in (None, "None", "", " "):
                same = [
                    ln
                    for ln in drawn
                    if ln.get_marker() == handle.get_marker()
                    and ln.get_markersize() == handle.get_markersize()
                    and _open(ln) == _open(handle)
                ]
            else:
                same = [ln for ln in drawn if ln.get_linestyle() == handle.get_linestyle()]
            if not same:
                missing.append(text.get_text())
    assert not missing, f"{kind}: legend entries never drawn: {missing}"


@pytest.mark.parametrize("kind", ["fig8", "fig18"])
def test_paper_star_has_the_colour_of_its_projectile(kind, archived_figure):
    """The paper's value for #2 is drawn in #2's colour and named, so that where it sits on
    another projectile's curve it does not read as that one's."""
    fig = archived_figure(kind)
    ax = fig.axes[0]
    stars = [ln for ln in ax.lines if ln.get_marker() == "*"]
    assert len(stars) == 1
    labels = {c.get_label(): c for c in ax.containers}
    p2 = next(c for label, c in labels.items() if label.startswith("#2,"))
    assert to_hex(stars[0].get_color()) == to_hex(p2.lines[0].get_color())
    others = [
        c.lines[0].get_color() for label, c in labels.items() if label[:2] in ("#1", "#3", "#4")
    ]
    assert to_hex(stars[0].get_color()) not in {to_hex(c) for c in others}
    assert any(t.get_text() == "paper, #2" for t in ax.texts)
