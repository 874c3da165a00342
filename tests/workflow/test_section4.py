"""Section 4 end to end: a reduced Section 4 configuration through Snakemake, and the
archived Section 4 datasets and comparison table.

The end-to-end run copies the workflow into a temporary directory and runs the section-4
targets with ``.test/config.yaml`` (small grids, coarse tolerances: the mechanics, not
the reported numbers), so the repository's own ``results/`` is never touched. The studies'
own tests are in ``tests/studies/``.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from helpers import REPO, run_snakemake

import pencore
from pencore.io.netcdf import read_netcdf
from pencore.workflowconfig.parts import grid
from pencore.workflowconfig.registry import STUDIES


@pytest.fixture(scope="module")
def s4run(e2e) -> Path:
    """The CI configuration's end-to-end run (tests/workflow/conftest.py) holds every
    Section 4 dataset, figure and the comparison table."""
    return e2e


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
    for s in STUDIES.values():
        for ext in ("png", "pdf"):
            assert (s4run / f"{s.figure}.{ext}").stat().st_size > 5_000, s.id
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
    (s4run / "alt_fig9.yaml").write_text(yaml.safe_dump(cfg))
    r = run_snakemake(
        s4run, "results/paper_comparison.csv", "-n", "--cores", "1", "--configfile", "alt_fig9.yaml"
    )
    out = r.stdout + r.stderr
    assert r.returncode == 0, out
    assert "wildcards: study=fig9, name=turning_angle" in out
    for other in ("study=fig7", "study=fig8", "study=fig13", "study=fig18"):
        assert other not in out, other


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
    for s in STUDIES.values():
        name = s.dataset.removeprefix("results/")
        ds = read_netcdf(ARCHIVE / name)
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
