"""Shared pieces of the plotting tests: the archived dataset(s) of every registered
figure, and the check that a rendered figure's axes are labelled with units.

The figures are drawn from ``results/archive/`` (the datasets the documentation shows), as
the workflow's figure rules call them (``workflow/scripts/plot.py``: one dataset; the
ballistic map: ``workflow/scripts/near_surface_figure.py``: the map and the obliquity
ratio), on the Agg canvas: no solver run.
"""

from __future__ import annotations

import io
import re
from collections.abc import Callable
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from pencore import plotting  # noqa: E402
from pencore.io.netcdf import read_netcdf  # noqa: E402

ARCHIVE = Path(__file__).resolve().parents[2] / "results" / "archive"

#: Figure kind of :data:`pencore.plotting.PLOTS` -> its archived dataset(s), in the order
#: the plotting function takes them.
ARCHIVED: dict[str, tuple[str, ...]] = {
    "table2": ("validation/table2.nc",),
    "fig5": ("validation/fig5.nc",),
    "verification": ("validation/verification.nc",),
    "measurements": ("validation/measurements.nc",),
    "concrete_record": ("validation/concrete_record.nc",),
    "fig7": ("fig7/trajectories.nc",),
    "fig8": ("fig8/vcr.nc",),
    "fig9": ("fig9/turning_angle.nc",),
    "fig11": ("fig11/trajectories.nc",),
    "fig12": ("fig12/vcr_yaw.nc",),
    "fig13": ("fig13/trajectories.nc",),
    "fig15": ("fig15/vci.nc",),
    "fig16": ("fig16/trajectories.nc",),
    "start_height": ("fig16/start_height.nc",),
    "fig18": ("fig18/omega_c.nc",),
    "ballistic_limit": ("perforation/ballistic_limit.nc",),
    "residual_velocity": ("perforation/residual_velocity.nc",),
    "attribution": ("attribution/attribution.nc",),
    "ensemble": ("ensemble/p2_soil_oblique.nc",),
}

#: The units an axis label may end with, in parentheses ("(m/s)", "(deg, signed)").
UNITS = {"m", "mm", "m/s", "s", "deg", "rad/s", "%", "kg"}

#: Quantities without a unit, recognised by name: ratios, counts, probabilities, slopes
#: and test numbers.
UNITLESS = (
    r"L_c/L",  # nose-to-centre-of-mass length over the length
    r"^slope dy/dx",
    r"^median relative error \(predicted / measured - 1\)$",
    r"^Samples$",
    r"^Number of samples",
    r"^Probability of",
    r"^Test \(paper Table 2\)$",
    r" / projectile diameter$",
    r"v_\{bl\}\(\\theta\)\\,/\\,v_\{bl\}\(0\)",
)


def carries_unit(label: str) -> bool:
    """Whether an axis label ends with a unit of :data:`UNITS` in parentheses, or names a
    quantity of :data:`UNITLESS`."""
    m = re.search(r"\(([^()]*)\)\s*$", label)
    if m and m.group(1).split(",")[0].strip() in UNITS:
        return True
    return any(re.search(p, label) for p in UNITLESS)


def _has_finite_data(ax: Axes) -> bool:
    """Whether the axes draws at least one finite data point (a line, a marker set, a
    bar or an image)."""
    for line in ax.lines:
        xy = np.asarray(line.get_xydata(), dtype=float)
        if xy.size and np.isfinite(xy).all(axis=-1).any():
            return True
    for coll in ax.collections:
        off = np.asarray(coll.get_offsets(), dtype=float)
        if off.size and np.isfinite(off).all(axis=-1).any():
            return True
        if any(len(p.vertices) for p in coll.get_paths()):
            return True
    return bool(ax.patches or ax.images)


def _categorical(ax: Axes, which: str) -> bool:
    """Whether the axis's tick labels, or those of a sibling it shares the axis with, are
    words (a category axis: settings, yes/no)."""
    shared = ax.get_shared_x_axes() if which == "x" else ax.get_shared_y_axes()
    number = re.compile(r"^[\s$−\-+0-9.,eE^{}\\mathrm×⋅]*$")
    for a in [ax, *shared.get_siblings(ax)]:
        ticks = (a.get_xticklabels if which == "x" else a.get_yticklabels)()
        texts = [t.get_text() for t in ticks if t.get_text()]
        if texts and not any(number.match(t) for t in texts):
            return True
    return False


def _label(ax: Axes, which: str) -> str:
    """The axis's label, else a sibling's it shares the axis with (stacked panels, twin
    axes), else, on a numeric x axis, the panel title that names the quantity (dot-plot
    panels); ``""`` for an unlabelled category axis."""
    get = (lambda a: a.get_xlabel()) if which == "x" else (lambda a: a.get_ylabel())
    shared = ax.get_shared_x_axes() if which == "x" else ax.get_shared_y_axes()
    for a in [ax, *shared.get_siblings(ax)]:
        if get(a):
            return get(a)
    if _categorical(ax, which):
        return ""
    return ax.get_title() if which == "x" else ""


def check_figure(fig: Figure) -> None:
    """Render ``fig`` (Agg, PNG) and assert that it has axes, every visible one draws
    finite data, and each of its axes is labelled with a unit (:func:`carries_unit`),
    a shared label or a category axis whose ticks name the items."""
    assert isinstance(fig, Figure)
    fig.savefig(io.BytesIO(), format="png", dpi=40)
    visible = [ax for ax in fig.axes if ax.axison]
    assert visible, "the figure has no axes"
    for i, ax in enumerate(visible):
        where = f"axes {i} ({ax.get_title()!r})"
        assert _has_finite_data(ax), f"{where} is empty"
        for which in "xy":
            label = _label(ax, which)
            if not label and _categorical(ax, which):
                continue
            assert label, f"{where}: no {which} label"
            assert carries_unit(label), f"{where}: {which} label {label!r} names no unit"


def render(kind: str) -> Figure:
    """The figure ``kind`` of :data:`pencore.plotting.PLOTS` from its archived dataset(s)."""
    return plotting.PLOTS[kind](*(read_netcdf(ARCHIVE / f) for f in ARCHIVED[kind]))


@pytest.fixture(scope="session")
def figure_check() -> Callable[[Figure], None]:
    """:func:`check_figure`."""
    return check_figure


@pytest.fixture(scope="session")
def archived_figure() -> Callable[[str], Figure]:
    """:func:`render`."""
    return render


@pytest.fixture(scope="session")
def archived() -> dict[str, tuple[str, ...]]:
    """:data:`ARCHIVED`."""
    return ARCHIVED
