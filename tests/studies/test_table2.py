"""pencore.studies.table2: the candidates' table of the Table 2 selection."""

from __future__ import annotations

import numpy as np
import pandas as pd

from pencore.studies.table2 import DEPTH_MEASURES, selection_table, table2

ROWS = pd.DataFrame(
    {
        "test": [2, 3],
        "velocity_m_s": [280.0, 278.0],
        "obliquity_deg": [0.0, 30.0],
        "yaw_deg": [0.0, 0.0],
        "measured_depth_m": [4.98, 5.18],
        "paper_predicted_depth_m": [4.25, 4.21],
    }
)


def test_selection_table_lists_every_candidate_and_marks_the_chosen_one():
    """One row per (projectile, depth measure); the selected row is the allowed candidate
    with the smallest RMS difference, a measure left out is listed but not a candidate,
    and each test's depths are the Dataset's."""
    measures = ["vertical_depth"]
    _, ds = table2(ROWS, projectiles=["p1", "p2"], measures=measures)
    sel = selection_table(ds, measures)
    assert len(sel) == 2 * len(DEPTH_MEASURES)
    assert sel["selected"].sum() == 1
    row = sel[sel["selected"]].iloc[0]
    assert (row["projectile"], row["depth_measure"]) == (
        ds.attrs["chosen_projectile"],
        ds.attrs["chosen_depth_measure"],
    )
    allowed = sel[sel["candidate"]]
    assert set(allowed["depth_measure"]) == set(measures)
    assert row["rms_rel_diff_vs_paper"] == allowed["rms_rel_diff_vs_paper"].min()
    for t in (2, 3):
        for _, r in sel.iterrows():
            want = ds["depth_candidates"].sel(
                projectile=r["projectile"], depth_measure=r["depth_measure"], test=t
            )
            assert r[f"depth_m_test{t}"] == float(want)
    np.testing.assert_array_equal(
        sel["rms_rel_diff_vs_paper"].to_numpy(), ds["selection_score"].values.ravel()
    )
