"""pencore.studies.comparison: the comparison table on synthetic datasets: trends follow
the data, verdict rows, nose-direction statements, Table 2 and Table 3 rows."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from helpers import search_results

from pencore.errors import InputError
from pencore.paper.claims import load_claims
from pencore.studies.common import projectile_coords, search_variables
from pencore.studies.comparison import _nose_rows, paper_comparison
from pencore.workflowconfig.registry import STUDIES

NAN = np.nan


def _fig8(vcr):
    """Synthetic Fig. 8 dataset on (projectile, obliquity) from an array of Vcr."""
    obl = np.array([15.0, 45.0, 75.0])
    data = search_variables(
        search_results(vcr),
        "vcr",
        "m s-1",
        "critical reverse velocity",
        ("projectile", "obliquity"),
    )
    return xr.Dataset(
        data,
        coords={
            **projectile_coords(["p2", "p4"]),
            "obliquity": ("obliquity", obl, {"units": "degree"}),
        },
    )


def _rows(df, start):
    return df[df["quantity"].str.startswith(start)]


def test_comparison_fig8_trends_follow_the_data():
    falls = _fig8(np.array([[3000.0, 1574.0, 600.0], [2100.0, 1100.0, 400.0]]))
    df = paper_comparison(datasets={"fig8": falls}, table3=False)
    assert list(df.columns[:6]) == [
        "quantity",
        "paper_value",
        "pencore_value",
        "difference",
        "units",
        "note",
    ]
    got = dict(zip(df["quantity"], df["pencore_value"], strict=True))
    assert got["Fig. 8: Vcr against obliquity"] == "holds"
    assert got["Fig. 8: Vcr against Lc/L"] == "holds"
    # the claims find the dataset by their study; the rows name the registry's file
    assert df["source"].str.startswith(STUDIES["fig8"].dataset).all()
    vcr = _rows(df, "Vcr of #2 at 45 deg").iloc[0]
    assert vcr["paper_value"] == 1645.5 and vcr["pencore_value"] == 1574.0
    assert vcr["difference"] == pytest.approx(1574.0 - 1645.5)
    assert vcr["units"] == "m s-1" and vcr["kind"] == "value"
    # the same table from data where Vcr rises with obliquity and with Lc/L
    rises = _fig8(np.array([[600.0, 1574.0, 3000.0], [700.0, 2000.0, 3500.0]]))
    got = dict(
        zip(
            *paper_comparison(datasets={"fig8": rises}, table3=False)[
                ["quantity", "pencore_value"]
            ].T.values,
            strict=True,
        )
    )
    assert got["Fig. 8: Vcr against obliquity"] == "does not hold"
    assert got["Fig. 8: Vcr against Lc/L"] == "does not hold"
    # a search above its range is reported as a bound, not a number
    above = _fig8(np.array([[3000.0, NAN, 600.0], [2100.0, 1100.0, 400.0]]))
    row = _rows(paper_comparison(datasets={"fig8": above}, table3=False), "Vcr of #2").iloc[0]
    assert row["pencore_value"] == "> 4000" and "above_range" in row["note"]


def test_comparison_fig9_fig18_and_verdict_rows():
    fig9 = xr.Dataset(
        {
            "delta_theta": (
                ("projectile", "bracket_fraction"),
                np.array([[1.1, 1.2], [1.2, 1.3], [1.3, 1.4], [1.7, 1.8]]),
                {"units": "degree", "long_name": "turning angle"},
            )
        },
        coords={
            **projectile_coords(["p1", "p2", "p3", "p4"]),
            "bracket_fraction": ("bracket_fraction", [0.02, 0.05]),
        },
        attrs={"primary_bracket_fraction": 0.05},
    )
    df = paper_comparison(datasets={"fig9": fig9}, table3=False)
    assert df["pencore_value"].tolist() == ["holds"]
    fig9["delta_theta"] = fig9["delta_theta"][::-1].assign_coords(
        projectile=fig9["projectile"], lc_over_l=fig9["lc_over_l"]
    )
    assert paper_comparison(datasets={"fig9": fig9}, table3=False)["pencore_value"].tolist() == [
        "does not hold"
    ]

    # Fig. 18: p2 never turns back in range, p4 falls with Vi
    data = search_variables(
        search_results(np.array([[NAN, NAN], [62.0, 20.0]])),
        "omega_c",
        "rad s-1",
        "omega_c",
        ("projectile", "velocity"),
    )
    fig18 = xr.Dataset(
        data,
        coords={**projectile_coords(["p2", "p4"]), "velocity": ("velocity", [500.0, 1000.0])},
    )
    df = paper_comparison(datasets={"fig18": fig18}, table3=False)
    got = dict(zip(df["quantity"], df["pencore_value"], strict=True))
    assert got["omega_c of #2 at 1000 m/s (Figs 16-17)"] == "> 4000"
    assert got["Fig. 18: omega_c against impact velocity"] == "holds"
    assert got["Fig. 18: omega_c against Lc/L"] == "holds"

    # Fig. 7 verdicts: a dataset where 1641 turns back disagrees with the paper
    fig7 = xr.Dataset(
        {
            "reversed": ("velocity", np.array([1, 1, 1], dtype=np.int8)),
            "x_linear": ("velocity", [6.9, 7.0, 7.1]),
        },
        coords={"velocity": [1641.0, 1650.0, 1700.0]},
    )
    df = paper_comparison(datasets={"fig7": fig7}, table3=False)
    verdicts = df[df["kind"] == "verdict"].set_index("quantity")["difference"]
    assert verdicts.str.contains("1641").index.size == 3
    assert verdicts[verdicts.index.str.contains("1641")].item() == "differs"
    assert verdicts[verdicts.index.str.contains("1650")].item() == "agrees"


def test_comparison_nose_direction_statements():
    dims = ("projectile", "obliquity", "yaw")
    yaw = np.array([-1.0, 0.0, 2.0])
    nd = np.array(
        [[["+x", "+x", "-x"], ["+x", "+x", "+x"]], [["+x", "+x", "-x"], ["+x", "+x", "-x"]]],
        dtype=object,
    )
    data = search_variables(search_results(np.full((2, 2, 3), 1000.0)), "vcr", "m s-1", "Vcr", dims)
    data["nose_direction"] = (dims, nd)
    ds = xr.Dataset(
        data,
        coords={
            **projectile_coords(["p2", "p4"]),
            "obliquity": ("obliquity", [30.0, 60.0]),
            "yaw": ("yaw", yaw),
        },
    )
    got = {r["quantity"]: r["pencore_value"] for r in _nose_rows(ds, "results/fig12/vcr_yaw.nc")}
    assert got["Fig. 12: nose points +x at Vcr for every negative yaw"] == "yes"
    assert got["Fig. 12: flip to -x more likely at 30 than 60 deg"] == "yes"  # 2 vs 1
    assert got["Fig. 12: flip to -x more likely for larger Lc/L (p4 than p2)"] == "yes"
    assert got["Fig. 12: the flip to -x happens only for yaw > 1 deg"] == "yes"
    ds["nose_direction"][0, 0, 0] = "-x"  # a negative yaw that flips
    got = {r["quantity"]: r["pencore_value"] for r in _nose_rows(ds, "results/fig12/vcr_yaw.nc")}
    assert got["Fig. 12: nose points +x at Vcr for every negative yaw"] == "no"
    assert got["Fig. 12: the flip to -x happens only for yaw > 1 deg"] == "no"


def test_comparison_table2_and_table3_rows():
    t2 = pd.DataFrame(
        {
            "test": [2],
            "velocity_m_s": [280.0],
            "obliquity_deg": [0.0],
            "yaw_deg": [0.0],
            "measured_depth_m": [4.98],
            "paper_predicted_depth_m": [4.25],
            "pencore_depth_m": [4.15],
            "projectile": ["p2"],
            "depth_measure": ["path_length"],
        }
    )
    df = paper_comparison(table2=t2)
    row = _rows(df, "Table 2 test 2").iloc[0]
    assert row["difference"] == pytest.approx(-0.10) and row["units"] == "m"
    t3 = _rows(df, "Table 3")
    assert len(t3) == 8
    lcl = t3[t3["quantity"].str.endswith("Lc/L")]
    assert (lcl["difference"].astype(float).abs() < 1e-3).all()


def test_comparison_names_an_unknown_study():
    """A dataset under an id the registry lacks, or a claim whose study names no Section 4
    dataset, is one line naming the offending value."""
    with pytest.raises(InputError, match="'fig99'") as e:
        paper_comparison(datasets={"fig99": xr.Dataset()}, table3=False)
    assert "\n" not in str(e.value)
    claims = load_claims().copy()
    claims.loc[claims["computed_by"] == "fig8_lc", "study"] = "fig8/elsewhere"
    with pytest.raises(InputError, match="fig8/elsewhere") as e:
        paper_comparison(claims=claims, table3=False)
    assert "\n" not in str(e.value)
