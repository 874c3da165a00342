"""Paper Table 2: the five soil tests of Forrestal & Luk (1992), every candidate run.

Each test is run with every candidate projectile and both depth measures; the candidate
closest to the paper's predicted column is selected and reported (the paper does not say
which projectile or depth measure it used). Units: SI (m, m/s); angles in degrees as in
the paper's table.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pencore.errors import InputError
from pencore.inputs.numerics import Numerics, resolve_numerics
from pencore.run.impact import prepare, simulate
from pencore.studies.common import var_attrs

__all__ = ["DEPTH_MEASURES", "TABLE2_INPUT_COLUMNS", "table2", "selection_table"]

#: Depth measures: name in the study -> (variable of a pencore trajectory, long name).
DEPTH_MEASURES: dict[str, tuple[str, str]] = {
    "path_length": ("path_length", "length of the nose-tip path below the target surface"),
    "vertical_depth": (
        "penetration_depth",
        "deepest point of the nose tip below the target surface",
    ),
}

#: The columns of a Table 2 input row.
TABLE2_INPUT_COLUMNS = (
    "test",
    "velocity_m_s",
    "obliquity_deg",
    "yaw_deg",
    "measured_depth_m",
    "paper_predicted_depth_m",
)


# ----------------------------------------------------------------------------- Table 2


def table2(
    rows: pd.DataFrame,
    numerics: Numerics | Mapping[str, Any] | None = None,
    *,
    projectiles: Sequence[str] = ("p1", "p2", "p3", "p4"),
    target: str = "soil",
    measures: Sequence[str] = ("path_length", "vertical_depth"),
    reference: str = "paper_predicted_depth_m",
) -> tuple[pd.DataFrame, xr.Dataset]:
    """Run the Table 2 tests and select the projectile and depth measure the paper used.

    Every test is simulated with every projectile in ``projectiles``; each
    (projectile, measure) pair gives a column of depths. The pair whose column has the
    smallest root-mean-square relative difference from ``rows[reference]`` (the paper's
    predicted depths) is selected; its depths are ``pencore_depth_m``.

    Parameters
    ----------
    rows : pandas.DataFrame
        One row per test with columns
        :data:`~pencore.studies.validation.table2.TABLE2_INPUT_COLUMNS` (and optionally
        ``source``). Velocities in m/s, angles in degrees, depths in m.
    numerics : Numerics or mapping, optional
        Numerical parameters, or overrides of pencore's defaults.
    projectiles : sequence of str
        Candidate projectiles (named projectiles of :mod:`pencore.inputs.library`).
    target : str
        Target name.
    measures : sequence of str
        Candidate depth measures, keys of :data:`DEPTH_MEASURES`.
    reference : str
        Column the candidates are compared with.

    Returns
    -------
    table : pandas.DataFrame
        One row per test: the input columns, ``projectile``, ``depth_measure``,
        ``pencore_depth_m`` (the selected measure), ``pencore_vertical_depth_m``,
        ``pencore_path_length_m``, and relative differences ``rel_diff_vs_paper``
        (pencore - paper) / paper, ``rel_diff_vs_measured`` (pencore - measured) / measured,
        ``paper_rel_diff_vs_measured`` (paper - measured) / measured. ``table.attrs``
        holds the selection.
    dataset : xarray.Dataset
        The same on dimension ``test``, plus every candidate
        ``depth_candidates(projectile, depth_measure, test)`` and its
        ``selection_score(projectile, depth_measure)``.
    """
    _check_table2_args(rows, reference, projectiles, measures)
    projectiles, measures = list(projectiles), list(measures)
    num = resolve_numerics(numerics)
    rows = rows.reset_index(drop=True)
    runs = _run_candidates(rows, projectiles, target, num)
    score, ip, im, rule = _select(runs["depth"], rows, reference, projectiles, measures)
    table = _table(rows, runs, projectiles, ip, im, rule, float(score[ip, im]), target)
    dsout = _dataset(rows, table, runs, score, projectiles, measures, ip, im, rule, reference, num)
    return table, dsout


def selection_table(ds: xr.Dataset, measures: Sequence[str]) -> pd.DataFrame:
    """Every candidate of :func:`table2`'s selection, one row per (projectile, depth
    measure): its RMS relative difference from the paper's predicted column, whether it
    was selected, whether its measure was a candidate (in ``measures``), and its depth (m)
    in every test.

    Parameters
    ----------
    ds : xarray.Dataset
        The Dataset returned by :func:`table2`.
    measures : sequence of str
        The depth measures that were candidates (``table2``'s ``measures``).

    Returns
    -------
    pandas.DataFrame
        Columns ``projectile``, ``depth_measure``, ``rms_rel_diff_vs_paper``, ``selected``,
        ``candidate`` and ``depth_m_test<n>`` for each test number ``n``.
    """
    selection = ds["selection_score"].to_dataframe().reset_index()
    selection = selection.rename(columns={"selection_score": "rms_rel_diff_vs_paper"})
    selection["selected"] = (selection["projectile"] == ds.attrs["chosen_projectile"]) & (
        selection["depth_measure"] == ds.attrs["chosen_depth_measure"]
    )
    selection["candidate"] = selection["depth_measure"].isin(list(measures))
    for t in ds["test"].values:
        col = ds["depth_candidates"].sel(test=t).to_dataframe().reset_index()
        selection[f"depth_m_test{int(t)}"] = col["depth_candidates"].to_numpy()
    return selection


def _check_table2_args(
    rows: pd.DataFrame, reference: str, projectiles: Sequence[str], measures: Sequence[str]
) -> None:
    """The inputs of :func:`table2`, or :class:`~pencore.errors.InputError` naming the gap."""
    missing = [c for c in TABLE2_INPUT_COLUMNS if c not in rows.columns]
    if missing:
        raise InputError(f"Table 2 input lacks column(s) {', '.join(missing)}")
    if reference not in rows.columns:
        raise InputError(f"Table 2 input lacks the reference column {reference!r}")
    if len(rows) == 0:
        raise InputError("Table 2 input has no rows")
    if not projectiles:
        raise InputError("table2 needs at least one candidate projectile")
    bad = [m for m in measures if m not in DEPTH_MEASURES]
    if bad or not measures:
        raise InputError(
            f"unknown depth measure(s) {bad or measures!r}; use {', '.join(DEPTH_MEASURES)}"
        )


def _run_candidates(
    rows: pd.DataFrame, projectiles: list[str], target: str, num: Numerics
) -> dict[str, np.ndarray]:
    """Every test with every candidate projectile: ``depth`` (projectile, every measure of
    :data:`DEPTH_MEASURES`, test; m), ``outcome``, ``final_dev`` (deg) and ``n_steps``
    (projectile, test)."""
    n_t = len(rows)
    depth = np.full((len(projectiles), len(DEPTH_MEASURES), n_t), np.nan)
    outcome = np.empty((len(projectiles), n_t), dtype=object)
    final_dev = np.full((len(projectiles), n_t), np.nan)
    n_steps = np.zeros((len(projectiles), n_t), dtype=np.int64)
    all_measures = list(DEPTH_MEASURES)
    for ip, name in enumerate(projectiles):
        pr = prepare(name, target, num)
        for it, row in rows.iterrows():
            ds = simulate(
                name,
                target,
                float(row["velocity_m_s"]),
                float(row["obliquity_deg"]),
                float(row["yaw_deg"]),
                prepared=pr,
            )
            for im, m in enumerate(all_measures):
                depth[ip, im, it] = float(ds[DEPTH_MEASURES[m][0]])
            outcome[ip, it] = ds.attrs["outcome"]
            final_dev[ip, it] = float(ds["final_deviation"])
            n_steps[ip, it] = int(ds.attrs["n_steps"])
    return {"depth": depth, "outcome": outcome, "final_dev": final_dev, "n_steps": n_steps}


def _select(
    depth: np.ndarray,
    rows: pd.DataFrame,
    reference: str,
    projectiles: list[str],
    measures: list[str],
) -> tuple[np.ndarray, int, int, str]:
    """The RMS relative difference of every candidate from ``rows[reference]``
    (projectile, every measure), the chosen (projectile, measure) indices among the
    allowed ``measures``, and the selection rule in words."""
    all_measures = list(DEPTH_MEASURES)
    ref = rows[reference].to_numpy(dtype=float)
    ok = np.isfinite(ref) & (ref > 0)
    if not ok.any():
        raise InputError(f"reference column {reference!r} has no positive values")
    rel = (depth[..., ok] - ref[ok]) / ref[ok]
    score = np.sqrt(np.mean(rel**2, axis=-1))  # (projectile, all measures)
    cand = np.full_like(score, np.inf)
    sel_m = [all_measures.index(m) for m in measures]
    cand[:, sel_m] = score[:, sel_m]
    ip, im = np.unravel_index(int(np.argmin(cand)), cand.shape)
    rule = (
        f"candidate (projectile in {projectiles}, depth measure in {measures}) with the "
        f"smallest RMS relative difference from column {reference!r} over "
        f"{int(ok.sum())} tests"
    )
    return score, int(ip), int(im), rule


def _table(
    rows: pd.DataFrame,
    runs: dict[str, np.ndarray],
    projectiles: list[str],
    ip: int,
    im: int,
    rule: str,
    chosen_score: float,
    target: str,
) -> pd.DataFrame:
    """One row per test: the inputs, the selected candidate's depths and differences."""
    all_measures = list(DEPTH_MEASURES)
    depth, outcome = runs["depth"], runs["outcome"]
    chosen_p, chosen_m = projectiles[ip], all_measures[im]
    measured = rows["measured_depth_m"].to_numpy(dtype=float)
    paper = rows["paper_predicted_depth_m"].to_numpy(dtype=float)
    chosen = depth[ip, im]
    table = rows[list(TABLE2_INPUT_COLUMNS)].copy()
    table["projectile"] = chosen_p
    table["depth_measure"] = chosen_m
    table["pencore_depth_m"] = chosen
    table["pencore_vertical_depth_m"] = depth[ip, all_measures.index("vertical_depth")]
    table["pencore_path_length_m"] = depth[ip, all_measures.index("path_length")]
    table["rel_diff_vs_paper"] = (chosen - paper) / paper
    table["rel_diff_vs_measured"] = (chosen - measured) / measured
    table["paper_rel_diff_vs_measured"] = (paper - measured) / measured
    table["outcome"] = outcome[ip]
    if "source" in rows.columns:
        table["source"] = rows["source"].to_numpy()
    table.attrs = {
        "chosen_projectile": chosen_p,
        "chosen_depth_measure": chosen_m,
        "chosen_rms_rel_diff": chosen_score,
        "selection_rule": rule,
        "target": target,
    }
    return table


def _dataset(
    rows: pd.DataFrame,
    table: pd.DataFrame,
    runs: dict[str, np.ndarray],
    score: np.ndarray,
    projectiles: list[str],
    measures: list[str],
    ip: int,
    im: int,
    rule: str,
    reference: str,
    num: Numerics,
) -> xr.Dataset:
    """:func:`table2`'s Dataset on dimension ``test``, with every candidate's depths."""
    all_measures = list(DEPTH_MEASURES)
    depth, final_dev, n_steps = runs["depth"], runs["final_dev"], runs["n_steps"]
    chosen_p, chosen_m = projectiles[ip], all_measures[im]
    chosen = depth[ip, im]
    measured = rows["measured_depth_m"].to_numpy(dtype=float)
    paper = rows["paper_predicted_depth_m"].to_numpy(dtype=float)
    target = table.attrs["target"]
    test = rows["test"].to_numpy()
    dm_long = DEPTH_MEASURES[chosen_m][1]
    dsout = xr.Dataset(
        {
            "velocity": (
                "test",
                rows["velocity_m_s"].to_numpy(dtype=float),
                var_attrs("m s-1", "impact velocity V_i"),
            ),
            "obliquity": (
                "test",
                rows["obliquity_deg"].to_numpy(dtype=float),
                var_attrs("degree", "angle of obliquity phi_1"),
            ),
            "yaw": (
                "test",
                rows["yaw_deg"].to_numpy(dtype=float),
                var_attrs("degree", "yaw angle phi_2"),
            ),
            "measured_depth": (
                "test",
                measured,
                var_attrs(
                    "m", "measured penetration depth (Forrestal & Luk 1992, via paper Table 2)"
                ),
            ),
            "paper_predicted_depth": (
                "test",
                paper,
                var_attrs("m", "penetration depth predicted by Li & Flores-Johnson (2011) Table 2"),
            ),
            "pencore_depth": (
                "test",
                chosen,
                var_attrs(
                    "m",
                    f"pencore penetration depth, selected measure: {dm_long}",
                    projectile=chosen_p,
                    depth_measure=chosen_m,
                ),
            ),
            "pencore_vertical_depth": (
                "test",
                table["pencore_vertical_depth_m"].to_numpy(),
                var_attrs("m", DEPTH_MEASURES["vertical_depth"][1]),
            ),
            "pencore_path_length": (
                "test",
                table["pencore_path_length_m"].to_numpy(),
                var_attrs("m", DEPTH_MEASURES["path_length"][1]),
            ),
            "rel_diff_vs_paper": (
                "test",
                table["rel_diff_vs_paper"].to_numpy(),
                var_attrs("1", "(pencore - paper predicted) / paper predicted"),
            ),
            "rel_diff_vs_measured": (
                "test",
                table["rel_diff_vs_measured"].to_numpy(),
                var_attrs("1", "(pencore - measured) / measured"),
            ),
            "paper_rel_diff_vs_measured": (
                "test",
                table["paper_rel_diff_vs_measured"].to_numpy(),
                var_attrs("1", "(paper predicted - measured) / measured"),
            ),
            "final_deviation": (
                "test",
                final_dev[ip],
                var_attrs("degree", "angle between the velocity and the target normal at rest"),
            ),
            "n_steps": ("test", n_steps[ip], var_attrs("1", "accepted integration steps")),
            "depth_candidates": (
                ("projectile", "depth_measure", "test"),
                depth,
                var_attrs("m", "pencore depth of every candidate projectile and depth measure"),
            ),
            "selection_score": (
                ("projectile", "depth_measure"),
                score,
                var_attrs("1", f"RMS relative difference from {reference}"),
            ),
        },
        coords={
            "test": ("test", test, var_attrs("1", "test number in paper Table 2")),
            "projectile": (
                "projectile",
                np.array(projectiles, dtype=object),
                {"long_name": "candidate projectile (paper Table 3)"},
            ),
            "depth_measure": (
                "depth_measure",
                np.array(all_measures, dtype=object),
                {"long_name": "depth measure"},
            ),
        },
        attrs={
            "title": "Paper Table 2: soil penetration (Forrestal & Luk 1992) and pencore",
            "target": target,
            "chosen_projectile": chosen_p,
            "chosen_depth_measure": chosen_m,
            "chosen_rms_rel_diff": float(score[ip, im]),
            "selection_rule": rule,
            "candidate_measures": ",".join(measures),
            "numerics_json": json.dumps(asdict(num), sort_keys=True),
            "Conventions": "CF-1.8",
        },
    )
    if "source" in rows.columns:
        dsout["source"] = (
            "test",
            rows["source"].astype(str).to_numpy(dtype=object),
            {"long_name": "provenance of the row: paper, derived or assumed"},
        )
    return dsout
