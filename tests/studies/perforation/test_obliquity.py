"""Ballistic-limit map, the line-of-sight rule and the measured obliquity ratios."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from pencore.errors import InputError
from pencore.studies.perforation.obliquity import (
    ballistic_map,
    compare_obliquity,
    load_oblique,
    obliquity_summary,
)

CSV = Path(__file__).resolve().parents[3] / "config" / "oblique_ballistic_limits.csv"


def test_shipped_file_loads_with_sources_and_ratios():
    df = load_oblique(CSV)
    assert df["source"].str.len().min() > 0 and df["read_in"].str.len().min() > 0
    normal = df[df["obliquity_deg"] == 0]
    assert np.all(normal["measured_ratio"] == 1.0)
    row = df[(df["series"] == "forrestal2014_bullet") & (df["obliquity_deg"] == 45)]
    assert float(row["measured_ratio"].iloc[0]) == pytest.approx(718 / 501)


def test_bad_rows_are_named(tmp_path):
    text = CSV.read_text()
    p = tmp_path / "x.csv"
    p.write_text(text.replace("Gallardy, ARL-MR-0930 (2016)", ""))
    with pytest.raises(InputError, match="no source"):
        load_oblique(p)
    lines = [
        x
        for x in text.splitlines()
        if not x.startswith("ryan2016_bis_9p8,BIS UHH steel,0.0098,.30 cal APM2,0.00762,0,")
    ]
    p.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match="without a 0 deg row"):
        load_oblique(p)


def _toy_map(ratio_30: float) -> xr.Dataset:
    tod = np.array([2.0, 3.0])
    obl = np.array([0.0, 15.0, 30.0, 45.0])
    r = np.ones((1, 2, 4))
    r[0, :, 2] = ratio_30
    r[0, :, 1] = 1.02
    r[0, :, 3] = 1.3
    ds = xr.Dataset(
        {"ratio": (("option", "t_over_d", "obliquity"), r)},
        coords={"option": ["none"], "t_over_d": tod, "obliquity": obl},
    )
    ds.attrs = {"projectile": "toy", "medium": "toy", "options_json": "{}"}
    return ds


def test_comparison_statistics_by_hand():
    df = load_oblique(CSV)
    cmp = compare_obliquity(df, _toy_map(1.1))
    obl = df[df["obliquity_deg"] > 0]
    alu = obl["material"].str.startswith("AA") & (obl["t_over_d"] >= 2.0) & (obl["t_over_d"] <= 3.0)
    meas = obl["measured_ratio"][alu].to_numpy()
    pred = np.where(
        obl["obliquity_deg"][alu] == 30, 1.1, np.where(obl["obliquity_deg"][alu] == 15, 1.02, 1.3)
    )
    e = pred / meas - 1.0
    s = cmp.sel(model="none", material_class="aluminium")
    assert float(s["stat_n"]) == alu.sum()
    assert float(s["stat_rms_rel_error"]) == pytest.approx(math.sqrt(np.mean(e**2)))
    # line of sight uses every row
    los = cmp.sel(model="line_of_sight", material_class="all")
    e_los = 1.0 / np.cos(np.radians(obl["obliquity_deg"])) / obl["measured_ratio"] - 1.0
    assert float(los["stat_mean_rel_error"]) == pytest.approx(float(e_los.mean()))
    # steel plates lie outside the toy map: no pencore ratio there
    steel = cmp["material"].values == "BIS UHH steel"
    assert np.all(np.isnan(cmp["pencore_ratio"].sel(option="none").values[steel]))
    assert "| line_of_sight | all |" in obliquity_summary(cmp)


def test_map_has_the_line_of_sight_rule():
    ds = ballistic_map("al_ogive_var4340", "aluminium", [2.0], [0.0, 30.0], {"none": {}}, tol=4.0)
    v0 = float(ds["v_bl"].sel(option="none", t_over_d=2.0, obliquity=0.0))
    v30 = float(ds["v_bl"].sel(option="none", t_over_d=2.0, obliquity=30.0))
    assert v30 > v0 > 0.0
    assert float(ds["v_bl_los"].sel(option="none", t_over_d=2.0, obliquity=30.0)) == pytest.approx(
        v0 / math.cos(math.radians(30.0))
    )
    assert float(ds["ratio"].sel(option="none", t_over_d=2.0, obliquity=30.0)) == pytest.approx(
        v30 / v0
    )
    with pytest.raises(InputError, match="unknown key"):
        ballistic_map("al_ogive_var4340", "aluminium", [2.0], [0.0], {"x": {"crater": 2.0}})
