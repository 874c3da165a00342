"""pencore.studies.validation.table2: the candidates' table of the Table 2 selection."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.studies.validation.table2 import DEPTH_MEASURES, selection_table, table2

ROWS = pd.DataFrame(
    {
        "test": [2, 3],
        "velocity_m_s": [280.0, 278.0],
        "obliquity_deg": [0.0, 30.0],
        "yaw_deg": [0.0, 0.0],
        "measured_depth_m": [4.98, 5.18],
        "paper_predicted_depth_m": [4.25, 4.21],
        "source": ["paper", "paper"],
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


def test_table2_selects_the_closest_candidate():
    table, ds = table2(ROWS, projectiles=["p1", "p2"])
    score = ds["selection_score"]
    best = score.where(score == score.min(), drop=True)
    assert ds.attrs["chosen_projectile"] == str(best["projectile"].item()) == "p2"
    assert ds.attrs["chosen_depth_measure"] == str(best["depth_measure"].item())
    assert table.attrs["chosen_projectile"] == "p2"
    assert (table["projectile"] == "p2").all()
    # restricting the measures restricts the choice
    _, ds_v = table2(ROWS, projectiles=["p2"], measures=["vertical_depth"])
    assert ds_v.attrs["chosen_depth_measure"] == "vertical_depth"
    np.testing.assert_allclose(ds_v["pencore_depth"], ds_v["pencore_vertical_depth"])


def test_table2_rejects_bad_input():
    with pytest.raises(InputError, match="lacks column"):
        table2(ROWS.drop(columns="yaw_deg"))
    with pytest.raises(InputError, match="unknown depth measure"):
        table2(ROWS, measures=["depth"])
    with pytest.raises(InputError, match="no rows"):
        table2(ROWS.iloc[:0])
