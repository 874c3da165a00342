"""Perforation figures (beyond the paper): ballistic limit against slab thickness
and obliquity, residual velocity against impact velocity with the Recht-Ipson fit, and
measured against predicted for the validation against published measurements."""

from __future__ import annotations

import textwrap

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pencore.analysis.errors import summary_statistics
from pencore.errors import InputError, hint_keywords
from pencore.inputs.gate import brief
from pencore.io.runs import check_run
from pencore.plotting.critical import _search_errorbars
from pencore.plotting.style import _MARKERS, _VI, _c, _pname, new_figure, styled

__all__ = [
    "plot_ballistic_limit",
    "plot_residual_velocity",
    "plot_measurements",
    "plot_ballistic_map",
]


@styled
def plot_ballistic_limit(ds: xr.Dataset) -> Figure:
    """v_bl against slab thickness, one line per obliquity, with the search brackets.

    With one thickness and several obliquities, v_bl against obliquity instead (one
    line, the thickness in the legend): a single thickness on the abscissa would stack
    every obliquity's point on one vertical line.
    """
    check_run(ds, "plot_ballistic_limit", ("thickness", "obliquity", "v_bl", "v_bl_lo", "v_bl_hi"),
              made_by="pencore.studies.sweeps.ballistic_table (pencore ballistic-table --out)",
              nonempty=("thickness", "obliquity"), numeric=True)  # fmt: skip
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    th = ds["thickness"].values
    obl = ds["obliquity"].values
    if th.size == 1 and obl.size > 1:
        sub = ds.isel(thickness=0)
        _search_errorbars(ax, obl, sub, "v_bl", _c(0), _MARKERS[0], f"slab {th[0]:g} m")
        ax.set_xlabel("Obliquity (deg)")
    else:
        for k, o in enumerate(obl):
            sub = ds.sel(obliquity=o)
            _search_errorbars(
                ax, th, sub, "v_bl", _c(k), _MARKERS[k % len(_MARKERS)], f"obliquity {o:g}°"
            )
        ax.set_xlabel("Slab thickness (m)")
    ax.set_ylabel(r"Ballistic limit $v_{bl}$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile', ''))} into {ds.attrs.get('medium', '')} "
        f"(model prediction; bracket ≤ {float(ds.attrs.get('search_tol_m_s', np.nan)):g} m/s)",
        fontsize=9,
    )
    return fig


@styled
def plot_residual_velocity(ds: xr.Dataset) -> Figure:
    """Residual speed of the runs and the fitted Recht-Ipson curve (when one was made)."""
    fit = ("recht_ipson_a", "recht_ipson_p", "v_bl_m_s")
    check_run(ds, "plot_residual_velocity", ("velocity", "residual_velocity"), fit,
              made_by="pencore.studies.sweeps.residual_curve (pencore residual-velocity --out)",
              nonempty=("velocity",), numeric=True)  # fmt: skip
    a, p, vb = (_attr_number(ds, k, "plot_residual_velocity") for k in fit)
    fig = new_figure(6.4, 4.6)
    ax = fig.add_subplot()
    v = np.asarray(ds["velocity"].values, dtype=float)
    ax.plot(v, ds["residual_velocity"].values, "o", color=_c(0), label="pencore runs")
    if np.isfinite(a) and np.isfinite(vb):
        vf = np.linspace(min(v.min(), vb), v.max(), 400)
        vr = a * np.maximum(vf**p - vb**p, 0.0) ** (1.0 / p)
        ax.plot(
            vf,
            vr,
            "-",
            color=_c(1),
            label=rf"Recht-Ipson, $a$ = {a:.3f}, $p$ = {p:.3f}, $v_{{bl}}$ = {vb:.1f} m/s",
        )
    ax.plot(v, v, ":", color="0.5", lw=0.8, label="$v_r = v_i$")
    ax.set_xlabel(_VI)
    ax.set_ylabel(r"Residual velocity $v_r$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
    thickness = float(ds.attrs.get("thickness_m", np.nan))
    body = str(ds.attrs.get("medium", ""))
    if np.isfinite(thickness):  # a target without its thickness is named alone
        body += f" slab {thickness:g} m"
    ax.set_title(
        f"{_pname(ds.attrs.get('projectile', ''))}, {body}, obliquity "
        f"{ds.attrs.get('obliquity_deg', 0.0):g}° (model prediction)",
        fontsize=9,
    )
    return fig


def _attr_number(ds: xr.Dataset, key: str, what: str) -> float:
    """The attribute ``key`` as a float (NaN is a number: no fit); one line if it is not."""
    value = ds.attrs[key]
    try:
        return float(np.asarray(value, dtype=float))
    except (TypeError, ValueError):
        raise InputError(
            f"{what}: attribute {key} must be a number, got {brief(value)}; is this Dataset edited?"
        ) from None


@styled
def plot_measurements(ds: xr.Dataset) -> Figure:
    """Measured against predicted, one panel per quantity, log-log, with the statistics.

    The 1:1 line and +-10 % / +-20 % bands; marker: the data file; colour: the target law;
    filled: a shot whose projectile stayed rigid by its authors' limits, open: one that
    deformed or eroded (left out of the statistics). The box gives, per data file and law,
    the rigid shots' number, bias (mean of predicted / measured - 1) and mean absolute
    relative error (:func:`pencore.analysis.errors.summary_statistics`; a body shot table's
    sets pooled, each set's in :func:`pencore.studies.validation.measurements.summary`).
    """
    quantities = list(ds["quantity"].values)
    fig = new_figure(5.6 * len(quantities), 7.0)
    rigid_all = ds["rigid"].values.astype(bool) if "rigid" in ds else None
    targets = list(dict.fromkeys(str(t) for t in ds["target"].values))
    # one marker per data file (the config entry: the shot names' prefix); a body shot
    # table's sets share their file's marker and are pooled in the box
    entry_all = np.array([str(s).split(":", 1)[0] for s in ds["shot"].values])
    entries = list(dict.fromkeys(entry_all))
    for iq, q in enumerate(quantities):
        ax = fig.add_subplot(1, len(quantities), iq + 1)
        sel = (ds["quantity_of_shot"].values == q) & np.isfinite(ds["measured"].values)
        sub = ds.isel(shot=np.flatnonzero(sel))
        entry = entry_all[sel]
        units = str(sub["measured_units"].values[0]).replace("m s-1", "m/s")
        m, p = sub["measured"].values, sub["predicted"].values
        rel = sub["rel_error"].values
        rigid = rigid_all[sel] if rigid_all is not None else np.ones(m.shape, bool)
        pos = (m > 0) & (p > 0)
        lo, hi = 0.7 * float(min(m[pos].min(), p[pos].min())), 1.4 * float(max(m.max(), p.max()))
        x = np.geomspace(lo, hi, 50)
        ax.plot(x, x, "-", color="0.3", lw=0.8, label="predicted = measured")
        for f, alpha in ((0.1, 0.18), (0.2, 0.09)):
            ax.fill_between(x, x * (1 - f), x * (1 + f), color="0.5", alpha=alpha, lw=0,
                            label=f"±{f:.0%}")  # fmt: skip
        lines = []
        for name in entries:
            for tgt in targets:
                d = (entry == name) & (sub["target"].values == tgt)
                if not d.any():
                    continue
                mk, col = _MARKERS[entries.index(name) % len(_MARKERS)], _c(targets.index(tgt))
                label = f"{sub['label'].values[d][0]}: {tgt}"
                ax.plot(m[d & rigid], p[d & rigid], mk, color=col, ms=6, ls="none", label=label)
                ax.plot(m[d & ~rigid], p[d & ~rigid], mk, mfc="none", color=col, ms=5,
                        ls="none", alpha=0.7)  # fmt: skip
                st = summary_statistics(rel[d & rigid])
                n = st["n"]
                lines.append(
                    f"{name}, {tgt}: "
                    + (
                        f"n = {n}, bias {st['bias']:+.1%}, mean |e| {st['mean_abs_rel_error']:.1%}"
                        if n
                        else "no rigid shot"
                    )
                )
        ax.text(0.02, 0.98, "rigid shots:\n" + "\n".join(lines), transform=ax.transAxes,
                va="top", fontsize=6.5,
                bbox={"facecolor": "white", "edgecolor": "0.7", "alpha": 0.9})  # fmt: skip
        ax.plot([], [], "o", mfc="none", color="0.4", ls="none",
                label="open: projectile deformed or eroded")  # fmt: skip
        qname = q.replace("_", " ")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(f"Measured {qname} ({units})")
        ax.set_ylabel(f"pencore {qname} ({units})")
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_aspect("equal")
        ax.grid(alpha=0.3, which="both")
    handles, labels = fig.axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", fontsize=6.5, frameon=False, ncol=1)
    return fig


@styled
def plot_ballistic_map(
    bl_map: xr.Dataset, cmp: xr.Dataset | None = None, mesh: xr.Dataset | None = None
) -> Figure:
    """Ballistic-limit map and the obliquity ratio, with the line-of-sight rule.

    Left: ``v_bl`` against plate thickness (calibers) for each obliquity, the paper's
    model (option ``none``, else the first), with the line-of-sight rule
    ``v_bl(0) sec(theta)`` dashed.
    Right: ``v_bl(theta) / v_bl(0)`` against obliquity at the map's thickness nearest
    the measured plates' median, one line per near-surface option, ``sec(theta)``
    dashed, and the measured ratios (``cmp``,
    :func:`~pencore.studies.perforation.obliquity.compare_obliquity`) as points.
    With the ring-mesh check (``mesh``, :func:`~pencore.studies.perforation.mesh_check.mesh_check`)
    a cell that is not converged is ringed, and every cell drawn without a number (a
    failed search) or ringed is listed under the figure with its reason.
    """
    fig = new_figure(11.0, 4.6)
    ax, bx = fig.subplots(1, 2)
    names = [str(o) for o in bl_map["option"].values]
    first = "none" if "none" in names else names[0]
    base = bl_map.sel(option=first)
    tod = base["t_over_d"].values
    notes: list[str] = []

    def flag(axis, x, y, option, t, o):
        """Ring a cell the mesh check did not pass and note why (once per cell)."""
        if mesh is None:
            return
        reason = str(mesh["reason"].sel(option=option, t_over_d=t, obliquity=o).values)
        if reason:
            if np.isfinite(y):
                axis.plot([x], [y], "o", ms=11, mfc="none", color="0.2", lw=0.8)
            note = f"{option}, t/d {t:g}, {o:g}°: {reason}"
            if note not in notes:
                notes.append(note)

    for k, o in enumerate(base["obliquity"].values):
        c = _c(k)
        ax.plot(tod, base["v_bl"].sel(obliquity=o), "-", color=c,
                marker=_MARKERS[k % len(_MARKERS)], label=f"{o:g}°")  # fmt: skip
        if o > 0:
            ax.plot(tod, base["v_bl_los"].sel(obliquity=o), "--", color=c, lw=1)
        for t in tod:
            flag(ax, t, float(base["v_bl"].sel(obliquity=o, t_over_d=t)), first, t, o)
    ax.plot([], [], "k--", lw=1, label=r"line of sight $v_{bl}(0)\,\sec\theta$")
    if mesh is not None and (mesh["reason"] != "").any():
        factor = float(mesh.attrs.get("mesh_factor", 2))
        ax.plot([], [], "o", ms=11, mfc="none", color="0.2", lw=0.8,
                label=f"not converged on {factor:g}x the rings")  # fmt: skip
    ax.set_xlabel("Plate thickness / projectile diameter")
    ax.set_ylabel(r"Ballistic limit $v_{bl}$ (m/s)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False, title="obliquity", title_fontsize=8)
    model = "the paper's model, no near-surface option" if first == "none" else f"option {first}"
    ax.set_title(
        f"{_pname(bl_map.attrs.get('projectile', ''))} into {bl_map.attrs.get('medium', '')}"
        f" ({model})",
        fontsize=9,
    )
    x0 = float(np.median(cmp["t_over_d"].values)) if cmp is not None else float(np.median(tod))
    t_pick = float(tod[np.argmin(np.abs(tod - x0))])
    obl = bl_map["obliquity"].values
    for k, o in enumerate(bl_map["option"].values):
        ratio = bl_map["ratio"].sel(option=o, t_over_d=t_pick)
        bx.plot(obl, ratio, "-", color=_c(k),
                marker=_MARKERS[k % len(_MARKERS)], label=f"pencore, {o}")  # fmt: skip
        for j, th in enumerate(obl):
            r = float(ratio.values[j])
            flag(bx, th, r, str(o), t_pick, th)
            if not np.isfinite(r):
                sub = bl_map.sel(option=o, t_over_d=t_pick, obliquity=th)
                status = str(sub["status"].values) if "status" in sub else "no limit"
                note = f"{o}, t/d {t_pick:g}, {th:g}°: no point drawn, the search ended {status}"
                if note not in notes:
                    notes.append(note)
    th = np.linspace(0.0, float(obl.max()), 61)
    bx.plot(th, 1.0 / np.cos(np.radians(th)), "k--", lw=1, label=r"line of sight $\sec\theta$")
    if cmp is not None:
        alu = np.char.startswith(cmp["material"].values.astype(str), "AA")
        for sel, mk, lab in ((alu, "o", "measured, aluminium"), (~alu, "s", "measured, steel")):
            if sel.any():
                bx.plot(cmp["obliquity"].values[sel], cmp["measured_ratio"].values[sel], mk,
                        mfc="none", color="k", label=lab)  # fmt: skip
    bx.set_xlabel("Obliquity θ (deg)")
    bx.set_ylabel(r"$v_{bl}(\theta)\,/\,v_{bl}(0)$")
    bx.grid(alpha=0.3)
    bx.legend(fontsize=7, frameon=False)
    bx.set_title(f"obliquity ratio, pencore at t/d = {t_pick:g}", fontsize=9)
    if mesh is not None:  # every cell the check did not pass, drawn or not
        reasons = mesh["reason"].to_series()
        for (option, t, o), reason in reasons[reasons != ""].items():
            note = f"{option}, t/d {t:g}, {o:g}°: {reason}"
            if note not in notes:
                notes.append(note)
    if mesh is not None and not notes:
        notes.append(
            f"ring-mesh check: all {mesh.attrs.get('n_cells', '')} cells of the map agree "
            f"within the search tolerance ({mesh.attrs.get('search_tol_m_s', np.nan):g} m/s) "
            f"on {mesh.attrs.get('mesh_factor', 2):g}x the rings"
        )
    if notes:
        frac = min(0.5, 0.03 + 0.028 * len(notes))
        fig.set_figheight(fig.get_figheight() / (1.0 - frac))
        fig.get_layout_engine().set(rect=(0.0, frac, 1.0, 1.0 - frac))
        fig.text(0.01, 0.005, "\n".join(textwrap.shorten(n, 190) for n in notes),
                 fontsize=6.5, va="bottom", ha="left")  # fmt: skip
    return fig


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
