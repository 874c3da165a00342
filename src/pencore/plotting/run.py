"""One call to see a run: the figure of one :func:`pencore.simulate` result.

A top-level function, ``pencore.plot_run(ds)``, rather than an xarray accessor
(``ds.pencore.plot()``): pencore's figures are ``plot_*`` functions of a Dataset
(:mod:`pencore.plotting`), ``import pencore`` loads neither xarray nor matplotlib (an
accessor must be registered by an import before it exists on a Dataset, so
``ds.pencore`` would be there or not depending on what was imported before), and a
Dataset read back from a file (:func:`pencore.read_netcdf`) is plotted the same way.
"""

from __future__ import annotations

import json
import math
import os

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.errors import InputError, hint_keywords
from pencore.io.runs import check_run
from pencore.plotting.style import _c, _pname, new_figure, save_figure, styled

__all__ = ["plot_run", "AGAINST", "layer_faces"]

#: What the histories can be drawn against: time (ms) or the nose tip's depth (m).
AGAINST = ("time", "depth")

_NEEDED = ("tip_x", "tip_y", "deviation", "speed")


@styled
def plot_run(
    ds: xr.Dataset, against: str = "time", path: str | os.PathLike[str] | None = None
) -> Figure:
    """Draw one trajectory: the nose-tip path y(x), the deviation of the velocity from the
    normal, the speed and the axial deceleration.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`pencore.simulate` result (or one read back with
        :func:`pencore.read_netcdf`). Without the load variables (``loads=False``) the
        deceleration panel says so.
    against : {"time", "depth"}, default "time"
        The abscissa of the three history panels: time (ms) or the nose tip's depth below
        the surface (m).
    path : str or path-like, optional
        Also write the figure there (format from the suffix: ``.png``, ``.pdf``, ``.svg``).

    Returns
    -------
    matplotlib.figure.Figure
        Four panels (axes labelled with units): path (with the target's layer
        interfaces and rear face dashed, air gaps shaded, each layer named, when the
        target has more than one layer or a rear face), deviation (deg), speed (m/s),
        deceleration (g on the left axis, m/s^2 on the right).

    Raises
    ------
    InputError
        ``ds`` is not a trajectory (a study's dataset) or ``against`` is not one of
        :data:`~pencore.plotting.run.AGAINST`.

    Examples
    --------
    >>> import pencore
    >>> fig = pencore.plot_run(pencore.simulate("p2", "soil", 1000.0, obliquity=45.0))
    >>> [ax.get_ylabel() for ax in fig.axes[:4]]
    ['Nose tip y (m)', 'Deviation from the normal (deg)', 'Speed (m/s)', 'Deceleration (g)']
    """
    if not isinstance(ds, xr.Dataset) or any(k not in ds for k in _NEEDED) or "time" not in ds.dims:
        raise InputError(
            "plot_run takes one trajectory of pencore.simulate (variables tip_x, tip_y, "
            "deviation, speed on 'time'); a study's dataset has its own plot_* function"
        )
    check_run(ds, "plot_run", ("time", *_NEEDED), nonempty=("time",), numeric=True)  # an empty run
    if against not in AGAINST:
        raise InputError(f"against must be one of {', '.join(AGAINST)}, got {against!r}")
    fig = new_figure(9.0, 6.4)
    axs = fig.subplots(2, 2)
    tx, ty = ds.tip_x.values, ds.tip_y.values
    if against == "time":
        x, xlabel = ds.time.values * 1e3, "Time (ms)"
    else:
        x, xlabel = -ty, "Nose tip depth below the surface (m)"
    ax = axs[0, 0]
    ax.plot(tx, ty, color=_c(0), label="nose tip")
    ax.axhline(0.0, color="0.5", lw=0.8)
    _draw_layers(ax, layer_faces(ds))
    ax.set_xlabel("Nose tip x (m)")
    ax.set_ylabel("Nose tip y (m)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title("Path (target: y ≤ 0)")
    ax = axs[0, 1]
    ax.plot(x, ds.deviation.values, color=_c(1))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("Deviation from the normal (deg)")
    ax = axs[1, 0]
    ax.plot(x, ds.speed.values, color=_c(2))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("Speed (m/s)")
    ax = axs[1, 1]
    ax.set_xlabel(xlabel)
    ax.set_ylabel("Deceleration (g)")
    if "deceleration_g" in ds:
        ax.plot(x, ds.deceleration_g.values, color=_c(3))
        # the Dataset's own g0 (m/s^2 per g), from its largest deceleration
        i = int(np.argmax(np.abs(ds.deceleration_g.values)))
        g0 = float(ds.deceleration.values[i] / ds.deceleration_g.values[i])
        if not np.isfinite(g0):  # no contact load at all
            g0 = 9.80665
        right = ax.secondary_yaxis("right", functions=(lambda g: g * g0, lambda a: a / g0))
        right.set_ylabel("Deceleration (m/s²)")
    else:
        ax.text(0.5, 0.5, "no loads in this dataset", ha="center", transform=ax.transAxes)
    for a in axs.flat[1:]:
        a.grid(alpha=0.3)
    a = ds.attrs
    fig.suptitle(
        f"{_pname(a.get('projectile', ''))} into {a.get('target', '')}: "
        f"{a.get('impact_velocity_m_s', float('nan')):g} m/s, obliquity "
        f"{a.get('obliquity_deg', 0.0):g}°, yaw {a.get('yaw_deg', 0.0):g}° "
        f"({a.get('outcome', '')})",
        fontsize=10,
    )
    if path is not None:  # never onto the file the Dataset was read from
        source = ds.encoding.get("source")
        save_figure(fig, path, protect=[source] if isinstance(source, str) else [])
    return fig


def layer_faces(ds: xr.Dataset) -> list[tuple[float, float, str]]:
    """The target's layers as the run recorded them (``inputs_json``): ``(top, bottom,
    name)`` per layer from the surface down, heights ``y`` in m (the target is
    ``y <= 0``; the last bottom ``-inf`` for a half-space), ``name`` the medium's or
    ``"air gap"``; empty when the Dataset does not record its target."""
    try:
        layers = json.loads(ds.attrs["inputs_json"])["target"]["layers"]
    except (KeyError, TypeError, ValueError):
        return []
    out, top = [], 0.0
    for lay in layers:
        bottom = top - float(lay["thickness"])
        name = "air gap" if lay.get("gap") else str(lay.get("medium", {}).get("name", ""))
        out.append((top, bottom, name))
        top = bottom
    return out


def _draw_layers(ax, faces: list[tuple[float, float, str]]) -> None:  # noqa: ANN001
    """Each interface between layers and a finite target's rear face as a dashed line,
    an air gap shaded, and each layer's medium named at its top, when the target has more
    than one layer or a rear face (a half-space of one medium has only its surface)."""
    if len(faces) < 2 and all(math.isinf(b) for _, b, _ in faces):
        return
    for top, bottom, name in faces:
        if name == "air gap":
            ax.axhspan(bottom, top, color="0.9", lw=0, label="_air gap")
        if math.isfinite(bottom):
            ax.axhline(bottom, color="0.45", lw=0.8, ls="--", label="_layer face")
        ax.text(0.01, top, f" {name}", transform=ax.get_yaxis_transform(), va="top",
                fontsize=7, color="0.3")  # fmt: skip


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
