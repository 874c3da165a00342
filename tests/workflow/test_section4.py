"""Section 4 studies: trend logic and the comparison table on synthetic datasets, study
helpers on cheap runs, and a reduced Section 4 configuration end to end through Snakemake.

The end-to-end run copies the workflow into a temporary directory and runs the section-4
targets with ``.test/config.yaml`` (small grids, coarse tolerances: the mechanics, not
the reported numbers), so the repository's own ``results/`` is never touched.
"""

from __future__ import annotations

import json
import logging
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml

import pencore
from pencore.errors import InputError
from pencore.io.netcdf import read_netcdf
from pencore.search.threshold import CriticalResult
from pencore.studies.common import projectile_coords, search_variables, start_from_height
from pencore.studies.comparison import _nose_rows, paper_comparison
from pencore.studies.config import from_config, gather
from pencore.studies.trajectories.stack import stack_trajectories
from pencore.studies.trends import trend
from pencore.workflowconfig.parts import grid, parts_of

REPO = Path(__file__).resolve().parents[2]
NAN = math.nan


# ----------------------------------------------------------------------------- trend logic


def test_trend_falls_holds_and_rises_does_not():
    par = [15.0, 30.0, 45.0]
    down = trend([("a", par, [300, 200, 100], [305, 205, 105])], "falls")
    assert (down.verdict, down.n_with, down.n_against) == ("holds", 2, 0)
    up = trend([("a", par, [100, 200, 300], [105, 205, 305])], "falls")
    assert (up.verdict, up.n_with, up.n_against) == ("does not hold", 0, 2)
    assert "a: 15->30" in up.note()
    assert trend([("a", par, [100, 200, 300], [105, 205, 305])], "rises").verdict == "holds"


def test_trend_mixed_flat_and_order():
    # one step down, one step up: partly
    mixed = trend([("a", [1, 2, 3], [300, 100, 200], [305, 105, 205])], "falls")
    assert mixed.verdict == "partly holds" and (mixed.n_with, mixed.n_against) == (1, 1)
    # overlapping brackets are equal within the tolerance: flat, which does not support
    # the claim on its own
    flat = trend([("a", [1, 2], [100, 102], [105, 107])], "falls")
    assert (flat.verdict, flat.n_flat) == ("does not hold", 1)
    # a flat step beside a falling one still holds
    assert trend([("a", [1, 2, 3], [200, 100, 102], [205, 105, 107])]).verdict == "holds"
    # parameters are sorted before comparing
    unsorted = trend([("a", [45, 15, 30], [100, 300, 200], [105, 305, 205])], "falls")
    assert unsorted.verdict == "holds" and unsorted.n_with == 2


def test_trend_open_brackets_from_out_of_range_searches():
    # above_range: lo = top of the range, hi = NaN (no event up to 500)
    line = ("p", [0.50, 0.52, 0.57], [500, 500, 19.5], [NAN, NAN, 20.0])
    t = trend([line], "falls")
    # >500 -> >500 cannot be compared; >500 -> 20 falls
    assert (t.verdict, t.n_with, t.n_undetermined) == ("holds", 1, 1)
    # a value rising out of the range is against "falls"
    t = trend([("p", [1, 2], [19.5, 500], [20.0, NAN])], "falls")
    assert t.verdict == "does not hold" and t.n_against == 1
    # unknown (both NaN, e.g. max_iter without bounds) is undetermined
    t = trend([("p", [1, 2], [NAN, 10], [NAN, 11])], "falls")
    assert (t.verdict, t.n_undetermined) == ("undetermined", 1)
    with pytest.raises(ValueError):
        trend([], "wobbles")


def _search(values, tol=5.0):
    """CriticalResult for a threshold at ``values`` (NaN -> above_range at 4000)."""
    out = []
    for v in np.ravel(values):
        if np.isnan(v):
            out.append(CriticalResult(NAN, 4000.0, NAN, 2, True, "above_range", "", (), tol))
        else:
            out.append(CriticalResult(v, v - tol / 2, v + tol / 2, 9, True, "ok", "", (), tol))
    return np.array(out, dtype=object).reshape(np.shape(values))


def _fig8(vcr):
    """Synthetic Fig. 8 dataset on (projectile, obliquity) from an array of Vcr."""
    obl = np.array([15.0, 45.0, 75.0])
    data = search_variables(
        _search(vcr), "vcr", "m s-1", "critical reverse velocity", ("projectile", "obliquity")
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
    df = paper_comparison(fig8=falls, table3=False)
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
    vcr = _rows(df, "Vcr of #2 at 45 deg").iloc[0]
    assert vcr["paper_value"] == 1645.5 and vcr["pencore_value"] == 1574.0
    assert vcr["difference"] == pytest.approx(1574.0 - 1645.5)
    assert vcr["units"] == "m s-1" and vcr["kind"] == "value"
    # the same table from data where Vcr rises with obliquity and with Lc/L
    rises = _fig8(np.array([[600.0, 1574.0, 3000.0], [700.0, 2000.0, 3500.0]]))
    got = dict(
        zip(
            *paper_comparison(fig8=rises, table3=False)[["quantity", "pencore_value"]].T.values,
            strict=True,
        )
    )
    assert got["Fig. 8: Vcr against obliquity"] == "does not hold"
    assert got["Fig. 8: Vcr against Lc/L"] == "does not hold"
    # a search above its range is reported as a bound, not a number
    above = _fig8(np.array([[3000.0, NAN, 600.0], [2100.0, 1100.0, 400.0]]))
    row = _rows(paper_comparison(fig8=above, table3=False), "Vcr of #2").iloc[0]
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
    df = paper_comparison(fig9=fig9, table3=False)
    assert df["pencore_value"].tolist() == ["holds"]
    fig9["delta_theta"] = fig9["delta_theta"][::-1].assign_coords(
        projectile=fig9["projectile"], lc_over_l=fig9["lc_over_l"]
    )
    assert paper_comparison(fig9=fig9, table3=False)["pencore_value"].tolist() == ["does not hold"]

    # Fig. 18: p2 never turns back in range, p4 falls with Vi
    data = search_variables(
        _search(np.array([[NAN, NAN], [62.0, 20.0]])),
        "omega_c",
        "rad s-1",
        "omega_c",
        ("projectile", "velocity"),
    )
    fig18 = xr.Dataset(
        data,
        coords={**projectile_coords(["p2", "p4"]), "velocity": ("velocity", [500.0, 1000.0])},
    )
    df = paper_comparison(fig18=fig18, table3=False)
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
    df = paper_comparison(fig7=fig7, table3=False)
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
    data = search_variables(_search(np.full((2, 2, 3), 1000.0)), "vcr", "m s-1", "Vcr", dims)
    data["nose_direction"] = (dims, nd)
    ds = xr.Dataset(
        data,
        coords={
            **projectile_coords(["p2", "p4"]),
            "obliquity": ("obliquity", [30.0, 60.0]),
            "yaw": ("yaw", yaw),
        },
    )
    got = {r["quantity"]: r["pencore_value"] for r in _nose_rows(ds)}
    assert got["Fig. 12: nose points +x at Vcr for every negative yaw"] == "yes"
    assert got["Fig. 12: flip to -x more likely at 30 than 60 deg"] == "yes"  # 2 vs 1
    assert got["Fig. 12: flip to -x more likely for larger Lc/L (p4 than p2)"] == "yes"
    assert got["Fig. 12: the flip to -x happens only for yaw > 1 deg"] == "yes"
    ds["nose_direction"][0, 0, 0] = "-x"  # a negative yaw that flips
    got = {r["quantity"]: r["pencore_value"] for r in _nose_rows(ds)}
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


# ----------------------------------------------------------------------------- helpers


def test_grid_start_and_parts():
    np.testing.assert_allclose(grid(15, 75, 7.5), np.arange(15, 75.1, 7.5))
    assert grid(-4, 4, 1).tolist() == [-4, -3, -2, -1, 0, 1, 2, 3, 4]
    with pytest.raises(InputError):
        grid(1, 0, 1)
    assert start_from_height(0.0) is None
    assert start_from_height(0.5) == (0.0, 0.5, 0.0)
    with pytest.raises(InputError):
        start_from_height(-1)
    cfg = {"projectiles": ["p2", "p4"], "obliquity_deg": [30.0, 60.0]}
    assert parts_of("fig12", cfg) == [
        {"projectile": p, "obliquity": o} for p in ("p2", "p4") for o in (30.0, 60.0)
    ]
    assert parts_of("fig8", cfg) == [{"projectile": "p2"}, {"projectile": "p4"}]
    with pytest.raises(InputError):
        from_config("fig99", {}, {})
    with pytest.raises(InputError, match="projectile"):
        from_config("fig8", {}, {})


def test_stack_trajectories_shared_axis():
    pr = pencore.prepare("p2", "soil")
    runs = {
        (i,): pencore.simulate("p2", "soil", v, 45.0, prepared=pr)
        for i, v in enumerate((300.0, 600.0))
    }
    ds = stack_trajectories(
        runs, {"velocity": (np.array([300.0, 600.0]), {"units": "m s-1"})}, n_time=80
    )
    assert ds["tip_x"].dims == ("velocity", "time")
    assert 80 <= ds.sizes["time"] <= 82  # + each run's last time
    for name, var in ds.data_vars.items():
        assert "long_name" in var.attrs and "units" in var.attrs, name
    for i, run in runs.items():
        t_end = float(run["time"][-1])
        row = ds.isel(velocity=i[0])
        # exact at the run's own last sample, NaN after it
        assert float(row["tip_y"].sel(time=t_end)) == pytest.approx(float(run["tip_y"][-1]))
        assert np.isnan(row["tip_y"].where(ds["time"] > t_end, drop=True)).all()
        assert float(row["penetration_depth"]) == float(run["penetration_depth"])
        assert float(row["final_deviation"]) == pytest.approx(pencore.analysis.final_deviation(run))


def test_gather_joins_parts_in_any_order():
    def part(p, o):
        data = search_variables(
            _search(np.array([[[1000.0 + o]]])),
            "vcr",
            "m s-1",
            "Vcr",
            ("projectile", "obliquity", "yaw"),
        )
        return xr.Dataset(
            data,
            coords={
                **projectile_coords([p]),
                "obliquity": ("obliquity", [o]),
                "yaw": ("yaw", [0.0]),
            },
        )

    ds = gather("fig12", [part("p4", 60.0), part("p2", 60.0), part("p4", 30.0), part("p2", 30.0)])
    assert ds["vcr"].dims == ("projectile", "obliquity", "yaw")
    assert ds["projectile"].values.tolist() == ["p4", "p2"]
    assert ds["obliquity"].values.tolist() == [30.0, 60.0]
    assert ds["vcr"].sel(projectile="p2", obliquity=60.0).item() == 1060.0
    np.testing.assert_allclose(ds["lc_over_l"], [0.5708, 0.5246], atol=1e-3)


# ----------------------------------------------------------------------------- end to end

#: Figure files: the name alone is unique (figNN_ prefix), so report downloads do not clash.
S4_FIGURES = (
    "fig7/fig07_trajectories",
    "fig8/fig08_vcr",
    "fig9/fig09_turning_angle",
    "fig11/fig11_trajectories",
    "fig12/fig12_vcr_yaw",
    "fig13/fig13_trajectories",
    "fig15/fig15_vci",
    "fig16/fig16_trajectories",
    "fig16/fig16_start_height",
    "fig18/fig18_omega_c",
)


def test_figure_file_names_are_unique():
    names = [f.rsplit("/", 1)[1] for f in S4_FIGURES] + ["table2", "fig5", "verification"]
    assert len(set(names)) == len(names)


def _snakemake(cwd: Path, *args: str, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "snakemake", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


@pytest.fixture(scope="module")
def s4run(tmp_path_factory) -> Path:
    wd = tmp_path_factory.mktemp("s4")
    shutil.copy2(REPO / "Snakefile", wd / "Snakefile")
    for d in ("workflow", "config", ".test"):
        shutil.copytree(REPO / d, wd / d)
    targets = ["results/paper_comparison.csv"] + [
        f"results/{f}.{ext}" for f in S4_FIGURES for ext in ("png", "pdf")
    ]
    r = _snakemake(wd, *targets, "--cores", "2", "--configfile", ".test/config.yaml")
    assert r.returncode == 0, r.stderr[-4000:]
    return wd


@pytest.mark.slow
def test_e2e_fig8_vcr_file_contract(s4run):
    ds = read_netcdf(s4run / "results/fig8/vcr.nc")
    assert ds["vcr"].dims == ("projectile", "obliquity")
    assert ds["vcr"].attrs["units"] == "m s-1"
    assert ds["obliquity"].attrs["units"] == "degree"
    assert ds["projectile"].values.tolist() == ["p2", "p4"]  # .test/config.yaml
    assert ds["obliquity"].values.tolist() == [45.0, 60.0]
    for v in ("vcr_lo", "vcr_hi", "status", "n_evals"):
        assert v in ds
    ok = ds["status"] == "ok"
    assert ok.any()
    assert ((ds["vcr_hi"] - ds["vcr_lo"]).where(ok) <= 100.0 + 1e-9).all()
    assert (ds["vcr"].where(ok) > 300.0).all()
    assert json.loads(ds.attrs["config_json"])["section4.fig8"]["projectiles"] == ["p2", "p4"]


@pytest.mark.slow
def test_e2e_datasets_dims_units_provenance(s4run):
    expected_dims = {
        "fig7/trajectories": {"velocity", "time"},
        "fig9/turning_angle": {"projectile", "bracket_fraction", "time"},
        "fig11/trajectories": {"yaw", "time"},
        "fig12/vcr_yaw": {"projectile", "obliquity", "yaw"},
        "fig13/trajectories": {"convention", "velocity", "time"},
        "fig15/vci": {"projectile", "yaw", "threshold"},
        "fig16/trajectories": {"omega", "time"},
        "fig16/start_height": {"start_height", "omega"},
        "fig18/omega_c": {"projectile", "velocity"},
    }
    for name, dims in expected_dims.items():
        ds = read_netcdf(s4run / f"results/{name}.nc")
        assert set(ds.dims) >= dims, (name, dict(ds.sizes))
        for vname, var in ds.data_vars.items():
            assert "units" in var.attrs and "long_name" in var.attrs, (name, vname)
        for key in ("study", "pencore_version", "git_commit", "config_json", "numerics_json"):
            assert key in ds.attrs, (name, key)
    f13 = read_netcdf(s4run / "results/fig13/trajectories.nc")
    assert set(f13["convention"].values) == {"axis_tilted", "velocity_tilted"}
    phi = f13["final_deviation"].sel(convention="axis_tilted", velocity=280.0)
    assert float(phi) == pytest.approx(0.163, abs=0.01)  # paper 0.16
    f12 = read_netcdf(s4run / "results/fig12/vcr_yaw.nc")
    assert set(np.unique(f12["nose_direction"].values)) <= {"+x", "-x", ""}
    f15 = read_netcdf(s4run / "results/fig15/vci.nc")
    assert f15.attrs["yaw_convention"] == "axis_tilted"


@pytest.mark.slow
def test_e2e_comparison_figures_logs_benchmarks(s4run):
    df = pd.read_csv(s4run / "results/paper_comparison.csv")
    assert list(df.columns[:6]) == [
        "quantity",
        "paper_value",
        "pencore_value",
        "difference",
        "units",
        "note",
    ]
    trends = df[df["kind"] == "trend"]
    assert len(trends) >= 8
    assert set(trends["pencore_value"]) <= {
        "holds",
        "partly holds",
        "does not hold",
        "undetermined",
    }
    assert df["quantity"].str.startswith("Table 2").sum() == 5
    assert df["quantity"].str.contains("axis_tilted").any()
    assert df["quantity"].str.contains("velocity_tilted").any()
    for f in S4_FIGURES:
        for ext in ("png", "pdf"):
            assert (s4run / f"results/{f}.{ext}").stat().st_size > 5_000, f
    bench = sorted((s4run / "results/benchmarks/section4").glob("*.tsv"))
    assert any(b.name.startswith("fig8_part_") for b in bench)
    for b in bench:
        assert pd.read_csv(b, sep="\t")["s"].iloc[0] >= 0
    logs = s4run / "results/logs/section4"
    assert (logs / "paper_comparison.log").is_file()
    assert "comparison with the paper" in (logs / "paper_comparison.log").read_text()


@pytest.mark.slow
def test_e2e_rerun_is_targeted(s4run):
    cfg = yaml.safe_load((s4run / ".test/config.yaml").read_text())
    cfg["section4"]["fig9"]["bracket_fractions"] = [0.05, 0.1]
    (s4run / "alt.yaml").write_text(yaml.safe_dump(cfg))
    r = _snakemake(
        s4run, "results/paper_comparison.csv", "-n", "--cores", "1", "--configfile", "alt.yaml"
    )
    out = r.stdout + r.stderr
    assert r.returncode == 0, out
    assert "wildcards: study=fig9, name=turning_angle" in out
    for other in ("study=fig7", "study=fig8", "study=fig13", "study=fig18"):
        assert other not in out, other


# ----------------------------------------------------------------------------- archive

ARCHIVE = REPO / "results" / "archive"


def test_archived_fig8_contract_and_bracket_is_real():
    """The committed Fig. 8 dataset: the required layout, and one bracket re-simulated."""
    ds = read_netcdf(ARCHIVE / "fig8" / "vcr.nc")
    assert ds["vcr"].dims == ("projectile", "obliquity")
    assert ds["vcr"].attrs["units"] == "m s-1"
    assert ds["projectile"].values.tolist() == ["p1", "p2", "p3", "p4"]
    np.testing.assert_allclose(ds["obliquity"], grid(15, 75, 7.5))
    assert ds["obliquity"].attrs["units"] == "degree"
    ok = ds["status"] == "ok"
    assert ((ds["vcr_hi"] - ds["vcr_lo"]).where(ok) <= 5.0 + 1e-9).all()
    cfg = json.loads(ds.attrs["config_json"])
    cell = ds.sel(projectile="p4", obliquity=60.0)
    kw = dict(start=tuple(cfg["section4.fig8"]["start_m"]), stop_at_reversal=True)
    lo = pencore.simulate("p4", "soil", float(cell["vcr_lo"]), 60.0, **kw)
    hi = pencore.simulate("p4", "soil", float(cell["vcr_hi"]), 60.0, **kw)
    assert (lo.attrs["reversed"], hi.attrs["reversed"]) == (0, 1)


def test_archived_section4_datasets_and_comparison():
    for name in (re.sub(r"/fig\d\d_", "/", f) for f in S4_FIGURES):  # dataset names
        ds = read_netcdf(ARCHIVE / f"{name}.nc")
        assert ds.attrs["study"].startswith("section4/"), name
        assert ds.attrs["config_sha256"] == ds.attrs["source_config_sha256"], name
        if "time" in ds.dims:
            assert ds.sizes["time"] <= 1000, name
    df = pd.read_csv(ARCHIVE / "paper_comparison.csv")
    assert {"quantity", "paper_value", "pencore_value", "difference", "units", "note"} <= set(
        df.columns
    )
    # the facts the reproduction is built on (see config/config.yaml)
    phi = df.set_index("quantity")["pencore_value"]
    key = "Fig. 13: deviation phi of #4, yaw 0.1 deg, Vi = 280 m/s, axis_tilted (configured)"
    assert float(phi[key]) == pytest.approx(0.163, abs=0.005)
    assert float(phi["Vcr of #2 at 45 deg obliquity (Fig. 7)"]) == pytest.approx(1574, abs=10)


def test_find_threshold_logs_progress(caplog):
    """Long searches report bracket, evaluations and verdicts on the pencore.search logger."""
    from pencore.search.threshold import find_threshold

    with caplog.at_level(logging.INFO, logger="pencore.search"):
        r = find_threshold(lambda v: v > 3.3, 0.0, 10.0, 0.5, scan=3, name="Vtest")
    assert r.status == "ok"
    msgs = [rec.getMessage() for rec in caplog.records if rec.name == "pencore.search"]
    assert msgs[0] == "Vtest: search in [0, 10], tol 0.5"
    assert any(m.startswith("Vtest: evaluation 1 at 0 -> False") for m in msgs)
    assert len([m for m in msgs if ": evaluation " in m]) == r.n_evals
    assert msgs[-1].startswith(f"Vtest: ok after {r.n_evals} evaluations")
