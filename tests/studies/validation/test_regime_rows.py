"""The rigid-regime criterion on measured rows: the verdict and error columns, and the split."""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd

from pencore import closedform
from pencore.inputs.laws import concrete_law
from pencore.measured.shots import read_body_shot_table
from pencore.studies.validation.bodies import body_projectile
from pencore.studies.validation.regime import regime_rows, regime_split

ROOT = Path(__file__).resolve().parents[3]


def test_rows_and_split_on_the_scaled_series():
    shots = read_body_shot_table(ROOT / "config/concrete_scaled_series.csv")
    rows = regime_rows(shots, crater="forrestal")
    assert list(rows["row"]) == list(shots["row"]) and rows["rigid"].all()
    r = shots.iloc[0]
    ref = closedform.depth(
        body_projectile(r, "x"), concrete_law(40e6, 2400.0, crater="forrestal"), 450.0
    )
    assert rows["error"].iloc[0] == ref / r["depth_m"] - 1.0
    # 450 m/s into 40 MPa: tip stress S fc + rho V^2 (the law resolved for the rod: the
    # default's size term) over the compiled 1300 MPa yield
    rod = body_projectile(r, "x")
    law = concrete_law(40e6, 2400.0, crater="forrestal")
    s = law.for_projectile(rod.diameter, rod.nose_length).coefficients[0]
    assert math.isclose(rows["ratio"].iloc[0], (s + 2400.0 * 450.0**2) / 1.3e9, rel_tol=1e-15)
    split = regime_split(rows)
    assert list(split.index) == ["kept"] and split.loc["kept", "rows"] == 7


def test_a_row_without_a_strength_is_judged_with_the_assumed_one():
    shots = read_body_shot_table(ROOT / "config/concrete_scaled_series.csv").iloc[:1].copy()
    shots["projectile_yield_pa"] = float("nan")
    shots["striking_velocity_m_s"] = 2500.0
    rows = regime_rows(shots)
    rod = body_projectile(shots.iloc[0], "x")
    s = concrete_law(40e6, 2400.0).for_projectile(rod.diameter, rod.nose_length).coefficients[0]
    assert math.isclose(rows["ratio"].iloc[0], (s + 2400.0 * 2500.0**2) / 1.72e9, rel_tol=1e-15)
    assert not rows["rigid"].iloc[0]
    assert list(regime_split(rows).index) == ["flagged"]
    assert isinstance(rows, pd.DataFrame)
