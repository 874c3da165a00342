"""pencore.studies.validation: inputs, selection rule, closed-form agreement."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.inputs.numerics import resolve_numerics
from pencore.studies.table2 import table2
from pencore.studies.validation import fig5, velocity_grid, verification

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


def test_resolve_numerics():
    num = resolve_numerics({"rtol": None, "n_nose": 24})
    assert num.n_nose == 24 and num.rtol == resolve_numerics(None).rtol
    with pytest.raises(InputError, match="unknown key 'rtoll'; did you mean 'rtol'"):
        resolve_numerics({"rtoll": 1e-6})


def test_velocity_grid():
    np.testing.assert_allclose(velocity_grid(100, 300, 3), [100, 200, 300])
    with pytest.raises(InputError, match="0 < min < max"):
        velocity_grid(300, 100, 3)
    with pytest.raises(InputError, match="0 < min < max"):
        velocity_grid(-1, 100, 3)


CASES = [
    {"name": "c3", "projectile": "concrete_crh3", "target": "concrete", "v_max": 500},
    {"name": "a05", "projectile": "aluminium_crh0p5", "target": "aluminium"},
]


def test_fig5_ranges_and_experiments():
    exp = pd.DataFrame(
        {
            "target": ["concrete"],
            "projectile": ["concrete_crh3"],
            "velocity_m_s": [400.0],
            "depth_m": [0.7],
            "source": ["assumed"],
        }
    )
    ds = fig5(CASES, [400.0, 800.0], experiments=exp)
    assert np.isnan(float(ds["pencore_depth"].sel(case="c3", velocity=800.0)))
    assert float(ds["experiment_pencore_depth"][0]) == pytest.approx(
        float(ds["pencore_depth"].sel(case="c3", velocity=400.0))
    )
    assert ds["crh"].values.tolist() == [3.0, 0.5]
    bad = exp.assign(projectile="p2")
    with pytest.raises(InputError, match="matches no Fig. 5 case"):
        fig5(CASES, [400.0], experiments=bad)


def test_verification_against_closed_form():
    ds = verification(CASES, [300.0, 500.0])
    assert float(ds["max_abs_rel_diff"]) < 5e-3
    assert ds.attrs["max_abs_rel_diff_case"] in {"c3", "a05"}
