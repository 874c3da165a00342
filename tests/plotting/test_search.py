"""plot_search draws every evaluation of a search, by verdict, and the final bracket."""

import numpy as np

from pencore import find_threshold
from pencore.plotting.search import plot_search
from pencore.search.history import search_dataset


def test_points_are_the_evaluations():
    r = find_threshold(lambda v: v >= 300.0, 100.0, 900.0, 5.0)
    ds = search_dataset(r, "vcr", "m s-1", "critical reverse velocity", projectile="p2")
    ax = plot_search(ds).axes[0]
    _, above = ax.lines[1].get_data()
    _, below = ax.lines[2].get_data()
    values = [v for v, _ in r.history]
    assert sorted(above) == sorted(v for v, b in r.history if b)
    assert sorted(below) == sorted(v for v, b in r.history if not b)
    assert len(above) + len(below) == len(values)
    assert ax.get_ylabel() == "vcr tried (m/s)"
    assert ax.get_xlabel() == "Evaluation"
    # the bracket is shaded between lo and hi
    (span,) = ax.patches
    ys = span.get_patch_transform().transform(span.get_path().vertices)[:, 1]
    assert np.isclose(ys.min(), r.lo) and np.isclose(ys.max(), r.hi)
    assert span.get_label() == f"final bracket [{r.lo:.4g}, {r.hi:.4g}]"


def test_not_found_says_so():
    r = find_threshold(lambda v: False, 100.0, 900.0, 5.0, scan=None)
    ds = search_dataset(r, "vcr", "m s-1", "critical reverse velocity")
    ax = plot_search(ds).axes[0]
    assert "no threshold in the range" in ax.get_title()
    assert not ax.patches
