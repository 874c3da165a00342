"""The Snakemake workflow: DAG, lint, config schema, an end-to-end run, the archive.

The end-to-end run copies the workflow into a temporary directory and runs the small
configuration ``.test/config.yaml`` there (about 15 s with numba's on-disk cache), so the
repository's own ``results/`` is never touched.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from helpers import copy_workflow, run_snakemake
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

import pencore
from pencore.inputs.library import projectile_names, target_names
from pencore.inputs.numerics import resolve_numerics
from pencore.io.netcdf import read_netcdf

REPO = Path(__file__).resolve().parents[2]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
STUDY_RULES = ("table2", "fig5", "verification")
FIGURE_RULES = ("table2_figure", "fig5_figure", "verification_figure")


def _shipped_config() -> dict:
    return yaml.safe_load((REPO / "config" / "config.yaml").read_text())


# ----------------------------------------------------------------------------- DAG, lint


@pytest.fixture(scope="module")
def workdir(tmp_path_factory) -> Path:
    return copy_workflow(tmp_path_factory.mktemp("workflow"))


def test_dry_run_lists_every_study(workdir):
    r = run_snakemake(workdir, "-n", "--cores", "1")
    assert r.returncode == 0, r.stderr + r.stdout
    out = r.stdout + r.stderr
    for rule in (*STUDY_RULES, *FIGURE_RULES, "perforation_study", "perforation_figure", "all"):
        assert f"rule {rule}:" in out, f"rule {rule} missing from the dry run"
    # the archive is refreshed on request only, never by `all`
    assert "archive_dataset" not in out


def test_the_reproduction_checks_the_near_surface_map_on_finer_rings(workdir):
    # the ring-mesh check is part of `all` (its dataset, and the figure that marks the
    # cells it does not pass) and of the archive, beside the map
    r = run_snakemake(workdir, "-n", "--cores", "1")
    out = r.stdout + r.stderr
    for rule in ("near_surface_mesh_part", "near_surface_mesh"):
        assert f"rule {rule}:" in out, f"rule {rule} missing from the dry run"
    figure = out[out.index("rule near_surface_figure:") :].split("\n\n", 1)[0]
    assert "results/near_surface/mesh_check.nc" in figure
    r = run_snakemake(workdir, "-n", "--cores", "1", "archive")
    assert "results/archive/near_surface/mesh_check.nc" in r.stdout


def test_dry_run_with_workflow_profiles(workdir):
    r = run_snakemake(workdir, "-n", "--workflow-profile", "workflow/profiles/default")
    assert r.returncode == 0, r.stderr + r.stdout
    assert "Using workflow specific profile workflow/profiles/default" in r.stdout + r.stderr


def test_profile_keys_are_snakemake_options():
    help_text = run_snakemake(REPO, "--help").stdout
    for name in ("default", "slurm"):
        prof = yaml.safe_load((REPO / "workflow" / "profiles" / name / "config.yaml").read_text())
        for key in prof:
            if key in ("__use_yte__", "__definitions__"):  # YTE's, read by Snakemake
                continue
            assert f"--{key}" in help_text, f"profile {name}: {key!r} is not a snakemake option"


def _dry_run_resources(out: str) -> dict[str, dict[str, str]]:
    """``rule name -> {resource: value}`` of the first job of each rule a dry run lists."""
    found: dict[str, dict[str, str]] = {}
    for block in re.split(r"\n(?=(?:local)?rule \w+:)", out):
        rule = re.match(r"(?:local)?rule (\w+):", block)
        res = re.search(r"^\s+resources: (.*)$", block, flags=re.M)
        if rule and res and rule.group(1) not in found:
            pairs = (item.split("=", 1) for item in res.group(1).split(", "))
            found[rule.group(1)] = dict(pairs)
    return found


def test_slurm_profile_adds_the_site_partition_and_account(workdir):
    """The cluster page's command: the site's partition and account (two environment
    variables the profile reads) join the profile's resources; the gather job keeps its
    runtime and cpus_per_task, the chunks their memory. ``--default-resources`` on the
    command line would replace them (checked too: the reason the page does not use it)."""
    target = ["results/ensemble/p2_soil_oblique.nc", "-n", "--forceall"]
    args = [*target, "--workflow-profile", "workflow/profiles/slurm"]
    args += ["--configfile", ".test/config.yaml"]
    env = {k: v for k, v in os.environ.items() if not k.startswith("PENCORE_SLURM_")}
    site = {**env, "PENCORE_SLURM_PARTITION": "short", "PENCORE_SLURM_ACCOUNT": "proj-42"}
    plain = run_snakemake(workdir, *args, env=env)
    given = run_snakemake(workdir, *args, env=site)
    for r in (plain, given):
        assert r.returncode == 0, r.stderr[-3000:]
    before = _dry_run_resources(plain.stdout + plain.stderr)
    after = _dry_run_resources(given.stdout + given.stderr)
    assert set(before) == set(after) == {"ensemble_chunk", "ensemble_gather"}
    for rule, res in before.items():
        assert "slurm_partition" not in res and "slurm_account" not in res
        assert after[rule] == {**res, "slurm_partition": "short", "slurm_account": "proj-42"}
    assert after["ensemble_gather"]["runtime"] == "30"  # the profile's default
    assert after["ensemble_gather"]["cpus_per_task"] == "1"
    assert after["ensemble_chunk"]["runtime"] == "15"  # the profile's set-resources
    assert after["ensemble_chunk"]["mem_mb"] == "2000"
    replaced = run_snakemake(
        workdir, *args[:-2], "--default-resources", "slurm_partition=short",
        "--configfile", ".test/config.yaml", env=env,
    )  # fmt: skip
    lost = _dry_run_resources(replaced.stdout + replaced.stderr)
    assert "cpus_per_task" not in lost["ensemble_gather"]
    assert lost["ensemble_chunk"]["mem_mb"] != "2000"


def test_archive_target_dry_run(workdir):
    r = run_snakemake(workdir, "-n", "--cores", "1", "archive")
    assert r.returncode == 0, r.stderr + r.stdout
    for study in STUDY_RULES:
        assert f"results/archive/validation/{study}.nc" in r.stdout


def test_lint_clean(workdir):
    r = run_snakemake(workdir, "--lint")
    assert r.returncode == 0, r.stdout + r.stderr


# ----------------------------------------------------------------------------- schema


def _validate(cfg: dict) -> dict:
    validate(cfg, str(SCHEMA))
    return cfg


def test_shipped_and_test_configs_validate():
    _validate(_shipped_config())
    _validate(yaml.safe_load((REPO / ".test" / "config.yaml").read_text()))


def test_schema_fills_defaults_of_an_empty_config():
    cfg = _validate({})
    assert cfg["numerics"] and all(v is None for v in cfg["numerics"].values())
    assert resolve_numerics(cfg["numerics"]) == pencore.Numerics()
    assert cfg["validation"]["table2"]["projectiles"] == ["p1", "p2", "p3", "p4"]
    assert cfg["validation"]["fig5"]["cases"][0]["projectile"] == "grout_crh3"
    assert cfg["section4"]["yaw_convention"] == "axis_tilted"
    assert cfg["section4"]["fig8"]["projectiles"] == ["p1", "p2", "p3", "p4"]


def _bad(mutate) -> str:
    cfg = _shipped_config()
    mutate(cfg)
    with pytest.raises(WorkflowError) as err:
        _validate(cfg)
    return str(err.value)


def test_schema_rejects_unknown_projectile():
    msg = _bad(lambda c: c["validation"]["table2"].update(projectiles=["p2", "p9"]))
    assert "'p9' is not one of" in msg


def test_schema_rejects_unknown_case_projectile():
    msg = _bad(lambda c: c["validation"]["fig5"]["cases"][0].update(projectile="bullet"))
    assert "'bullet' is not one of" in msg


def test_schema_rejects_negative_velocity():
    msg = _bad(lambda c: c["validation"]["verification"]["velocities_m_s"].update(min=-100))
    assert "-100 is less than or equal to the minimum of 0" in msg
    msg = _bad(lambda c: c["validation"]["fig5"]["cases"][1].update(v_max=-1))
    assert "-1 is less than or equal to the minimum of 0" in msg


def test_schema_rejects_missing_key():
    msg = _bad(lambda c: c["validation"]["fig5"]["cases"][0].pop("target"))
    assert "'target' is a required property" in msg
    msg = _bad(lambda c: c["validation"]["verification"]["velocities_m_s"].pop("n"))
    assert "'n' is a required property" in msg


def test_schema_rejects_unknown_keys():
    msg = _bad(lambda c: c["validation"]["table2"].update(projectile="p2"))
    assert "'projectile' was unexpected" in msg
    msg = _bad(lambda c: c["numerics"].update(rtoll=1e-6))
    assert "'rtoll' was unexpected" in msg
    msg = _bad(lambda c: c["section4"]["fig7"].update(velocities=[1641, 1650]))
    assert "'velocities' was unexpected" in msg
    msg = _bad(lambda c: c["section4"].update(yaw_convention="sideways"))
    assert "'sideways' is not one of" in msg


def _walk_properties(node: dict, path: str = ""):
    for key, sub in node.get("properties", {}).items():
        yield f"{path}.{key}", sub
        yield from _walk_properties(sub, f"{path}.{key}")
    for key, sub in node.get("$defs", {}).items():
        yield from _walk_properties(sub, f"$defs.{key}")


def test_schema_every_key_has_type_description_default():
    schema = yaml.safe_load(SCHEMA.read_text())
    defs = schema["$defs"]
    for path, sub in _walk_properties(schema):
        ref = sub.get("$ref")
        target = defs[ref.rsplit("/", 1)[-1]] if ref else sub
        assert "type" in target, f"{path} has no type"
        assert "description" in sub or "description" in target, f"{path} has no description"
        # a key has a default, or says why it has none (the fields of a distribution
        # are required by its kind)
        assert "default" in sub or sub.get("x-no-default"), f"{path} has no default"


def test_schema_names_match_pencore():
    schema = yaml.safe_load(SCHEMA.read_text())
    assert sorted(schema["$defs"]["projectile"]["enum"]) == projectile_names()
    assert sorted(schema["$defs"]["target"]["enum"]) == target_names()
    assert set(schema["properties"]["numerics"]["properties"]) == set(
        pencore.Numerics.__dataclass_fields__
    )


def test_table2_csv_is_the_papers_table2():
    # the paper's Table 2 as printed (measured and predicted columns)
    rows = pd.read_csv(REPO / "config" / "table2.csv")
    assert rows["test"].tolist() == [2, 3, 4, 5, 6]
    assert rows["paper_predicted_depth_m"].tolist() == [4.25, 4.21, 4.25, 4.22, 4.21]
    assert rows["measured_depth_m"].tolist() == [4.98, 5.18, 5.18, 5.02, 4.82]
    assert rows["source"].str.startswith("paper").all()
    # the paper quotes a largest experiment-prediction difference of 18.7 %
    rel = (rows["paper_predicted_depth_m"] - rows["measured_depth_m"]) / rows["measured_depth_m"]
    assert abs(rel).max() == pytest.approx(0.187, abs=5e-4)


def test_fig5_draws_every_shipped_shot():
    cfg = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
    files = cfg["validation"]["fig5"]["shots"]
    # the shot tables, and of the body shot table the grout sets of the paper's law
    body = cfg["validation"]["fig5"]["body_shots"]
    assert files + list(body) == [e["csv"] for e in cfg["validation"]["measurements"][1:]]
    for f in files + list(body):
        assert not pd.read_csv(REPO / f, comment="#").empty


# ----------------------------------------------------------------------------- end to end


def _check_cf(ds):
    for name, var in ds.data_vars.items():
        if var.dtype.kind == "f":
            assert "units" in var.attrs, f"{name} has no units"
            assert "long_name" in var.attrs, f"{name} has no long_name"
    for key in (
        "study",
        "pencore_version",
        "git_commit",
        "config_json",
        "config_sha256",
        "created_utc",
        "numerics_json",
    ):
        assert key in ds.attrs, f"missing provenance attribute {key}"
    assert ds.attrs["pencore_version"] == pencore.__version__
    json.loads(ds.attrs["config_json"])


@pytest.mark.slow
def test_e2e_table2(e2e):
    ds = read_netcdf(e2e / "results/validation/table2.nc")
    _check_cf(ds)
    assert ds.sizes["test"] == 5
    assert list(ds["projectile"].values) == ["p1", "p2"]
    assert set(ds["depth_measure"].values) == {"path_length", "vertical_depth"}
    assert ds["pencore_depth"].attrs["units"] == "m"
    # the paper's predicted column is reproduced by projectile #2 and the path length
    assert ds.attrs["chosen_projectile"] == "p2"
    assert ds.attrs["chosen_depth_measure"] == "path_length"
    np.testing.assert_allclose(ds["pencore_depth"], ds["paper_predicted_depth"], rtol=0.05)
    # physics bounds: the path is at least the vertical depth; normal shots agree
    assert (ds["pencore_path_length"] >= ds["pencore_vertical_depth"] - 1e-9).all()
    normal = (ds["obliquity"] == 0) & (ds["yaw"] == 0)
    np.testing.assert_allclose(
        ds["pencore_path_length"].where(normal, drop=True),
        ds["pencore_vertical_depth"].where(normal, drop=True),
        rtol=1e-9,
    )
    # oblique shots (30 deg) go about cos(30) as deep as they travel
    oblique = ds.sel(test=[3, 4])
    ratio = oblique["pencore_vertical_depth"] / oblique["pencore_path_length"]
    assert ((ratio > 0.8) & (ratio < 0.92)).all()
    table = pd.read_csv(e2e / "results/validation/table2.csv")
    for col in (
        "test",
        "velocity_m_s",
        "obliquity_deg",
        "yaw_deg",
        "measured_depth_m",
        "paper_predicted_depth_m",
        "pencore_depth_m",
        "pencore_vertical_depth_m",
        "pencore_path_length_m",
        "rel_diff_vs_paper",
        "rel_diff_vs_measured",
        "projectile",
        "depth_measure",
        "source",
    ):
        assert col in table.columns
    np.testing.assert_allclose(table["pencore_depth_m"], ds["pencore_depth"], rtol=1e-5)
    sel = pd.read_csv(e2e / "results/validation/table2_selection.csv")
    assert sel["selected"].sum() == 1
    assert sel.loc[sel["selected"], "rms_rel_diff_vs_paper"].item() == pytest.approx(
        sel["rms_rel_diff_vs_paper"].min()
    )


@pytest.mark.slow
def test_e2e_fig5_and_verification(e2e):
    f5 = read_netcdf(e2e / "results/validation/fig5.nc")
    _check_cf(f5)
    # 31 spherical-nose shots and the 11 grout shots of the body table
    assert dict(f5.sizes) == {"case": 3, "velocity": 3, "experiment": 42}
    pen, cf = f5["pencore_depth"], f5["closedform_depth"]
    assert ((pen > 0.5 * cf) & (pen < 2.0 * cf)).all()
    assert float(abs(f5["rel_diff"]).max()) < 1e-2
    assert (pen.diff("velocity") > 0).all(), "depth must grow with impact velocity"
    assert set(f5["experiment_projectile"].values) == {
        "al_sphere_var4340",
        "grout_crh3",
        "grout_crh4p25",
    }

    ver = read_netcdf(e2e / "results/validation/verification.nc")
    _check_cf(ver)
    assert dict(ver.sizes) == {"case": 2, "velocity": 3}
    pen, cf = ver["pencore_depth"], ver["closedform_depth"]
    assert ((pen > 0.5 * cf) & (pen < 2.0 * cf)).all()
    assert float(ver["max_abs_rel_diff"]) == pytest.approx(float(abs(ver["rel_diff"]).max()))
    assert float(ver["max_abs_rel_diff"]) < 1e-2
    assert (
        "largest |pencore - closed form|"
        in (e2e / "results/validation/verification.txt").read_text()
    )


@pytest.mark.slow
def test_e2e_figures_logs_benchmarks(e2e):
    res = e2e / "results"
    for name in STUDY_RULES:
        for ext in ("png", "pdf"):
            assert (res / f"validation/{name}.{ext}").stat().st_size > 5_000
        assert (res / f"logs/validation/{name}.log").is_file()
        bench = pd.read_csv(res / f"benchmarks/validation/{name}.tsv", sep="\t")
        assert bench["s"].iloc[0] > 0


@pytest.mark.slow
def test_e2e_says_the_long_jobs_start_first(e2e):
    """The run's first line after the DAG says the longest jobs went first, before the
    first "N of M steps done" line that waits for one of them (the Snakefile's onstart)."""
    log = (e2e.parent / "snakemake.log").read_text()
    said = [ln for ln in log.splitlines() if ln.startswith("pencore: the ")]
    assert len(said) == 1, said
    # the jobs named are the prioritised ones (priority 1: the near-surface map's parts,
    # its mesh check's, the attribution settings)
    named = said[0].split("longest jobs (", 1)[1].split(")", 1)[0].split(", ")
    prioritised = ("near_surface_part", "near_surface_mesh_part", "attribution_settings_")
    named = [n for n in named if n != "..."]
    assert named and all(n.startswith(prioritised) for n in named), named
    assert log.index(said[0]) < log.index(" steps (")


@pytest.mark.slow
def test_e2e_rerun_is_targeted(e2e):
    r = run_snakemake(e2e, "-n", "--cores", "1", "--configfile", ".test/config.yaml")
    assert r.returncode == 0
    assert "Nothing to be done" in r.stdout + r.stderr
    cfg = yaml.safe_load((e2e / ".test/config.yaml").read_text())
    cfg["validation"]["verification"]["velocities_m_s"]["n"] = 4
    (e2e / "alt_verification.yaml").write_text(yaml.safe_dump(cfg))
    r = run_snakemake(e2e, "-n", "--cores", "1", "--configfile", "alt_verification.yaml")
    out = r.stdout + r.stderr
    assert r.returncode == 0, out
    assert "rule verification:" in out and "params have changed" in out
    for other in ("table2", "fig5", "table2_figure", "fig5_figure"):
        assert f"rule {other}:" not in out


def _planned_rules(out: str) -> set[str]:
    return set(re.findall(r"^(?:local)?rule (\w+):", out, flags=re.M))


def _dry_run_with_src(wd: Path, src: Path) -> set[str]:
    env = {**os.environ, "PYTHONPATH": str(src)}
    r = run_snakemake(wd, "-n", "--cores", "1", "--configfile", ".test/config.yaml", env=env)
    assert r.returncode == 0, r.stderr[-3000:]
    return _planned_rules(r.stdout + r.stderr)


@pytest.mark.slow
def test_e2e_rerun_scope_plotting_vs_physics(e2e, tmp_path):
    """A plotting edit replots only; a physics edit reruns the solver rules."""
    src = tmp_path / "src"
    shutil.copytree(
        REPO / "src" / "pencore", src / "pencore", ignore=shutil.ignore_patterns("__pycache__")
    )
    assert _dry_run_with_src(e2e, src) == set()  # same content, same hashes

    style = src / "pencore" / "plotting" / "style.py"
    original = style.read_text()
    style.write_text(original + "\n# a comment\n")
    planned = _planned_rules_nonempty(_dry_run_with_src(e2e, src))
    # figure and HTML-table rules (both render with pencore.plotting), and the target rule
    assert all(n.endswith(("_figure", "_html")) or n == "all" for n in planned), planned
    assert {"table2_figure", "fig5_figure", "verification_figure"} <= planned
    style.write_text(original)

    physics = src / "pencore" / "studies" / "common.py"
    physics.write_text(physics.read_text() + "\n# a comment\n")
    planned = _planned_rules_nonempty(_dry_run_with_src(e2e, src))
    assert {"table2", "fig5", "verification", "s4_study", "s4_part_fig8_0"} <= planned, planned


def _planned_rules_nonempty(planned: set[str]) -> set[str]:
    assert planned, "the dry run planned nothing"
    return planned


@pytest.mark.slow
def test_e2e_report(e2e):
    r = run_snakemake(e2e, "--configfile", ".test/config.yaml", "--report", "results/report.html")
    assert r.returncode == 0, r.stderr[-3000:]
    assert (e2e / "results/report.html").stat().st_size > 100_000


# ----------------------------------------------------------------------------- archive

ARCHIVE = REPO / "results" / "archive"
#: Relative tolerance between an archived number and a fresh run: the solver is
#: deterministic, so this only absorbs changes of numerics defaults below 0.1 %.
ARCHIVE_RTOL = 1e-3


def test_archive_is_small_and_has_provenance():
    files = sorted(ARCHIVE.rglob("*.nc"))
    assert {f.relative_to(ARCHIVE).as_posix() for f in files} >= {
        f"validation/{s}.nc" for s in STUDY_RULES
    }
    assert sum(f.stat().st_size for f in files) < 20e6
    for f in files:
        ds = read_netcdf(f)
        assert ds.attrs["config_sha256"] == ds.attrs["source_config_sha256"]
        for k in ("study", "git_commit", "config_json", "pencore_version"):
            assert k in ds.attrs


def test_archived_table2_matches_fresh_run():
    ds = read_netcdf(ARCHIVE / "validation" / "table2.nc")
    proj, measure = ds.attrs["chosen_projectile"], ds.attrs["chosen_depth_measure"]
    variable = {"path_length": "path_length", "vertical_depth": "penetration_depth"}[measure]
    numerics = resolve_numerics(_validate(_shipped_config())["numerics"])
    row = ds.sel(test=3)  # the oblique shot: exercises the full 3-D motion
    fresh = pencore.simulate(
        proj,
        ds.attrs["target"],
        float(row["velocity"]),
        float(row["obliquity"]),
        float(row["yaw"]),
        numerics=numerics,
    )
    assert float(fresh[variable]) == pytest.approx(float(row["pencore_depth"]), rel=ARCHIVE_RTOL)


def test_archived_config_is_the_shipped_one():
    ds = read_netcdf(ARCHIVE / "validation" / "table2.nc")
    cfg = _validate(_shipped_config())
    archived = json.loads(ds.attrs["config_json"])
    assert archived["validation.table2"] == cfg["validation"]["table2"]
    assert archived["numerics"] == cfg["numerics"]


@pytest.mark.parametrize(
    ("raise_", "one_line"),
    [("SolverError('the steps stalled at t = 1 s')", True), ("KeyError('bug')", False)],
)
def test_workflow_script_errors_are_one_line(tmp_path, raise_, one_line):
    # a job that fails with pencore's own error prints one line naming it (the rule's
    # log keeps the traceback); anything else is a bug and keeps its traceback
    scripts = Path(__file__).resolve().parents[2] / "workflow" / "scripts"
    log = tmp_path / "job.log"
    code = (
        f"import sys; sys.path.insert(0, {str(scripts)!r})\n"
        "from _common import start_log\n"
        "from types import SimpleNamespace\n"
        "from pencore.run.impact import SolverError\n"
        f"start_log(SimpleNamespace(log=[{str(log)!r}], input=[]), 'job')\n"
        f"raise {raise_}\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 1
    assert "Traceback" in log.read_text()
    if one_line:
        assert r.stderr.strip().splitlines() == [
            f"job: error: the steps stalled at t = 1 s (details in {log})"
        ]
    else:
        assert "Traceback" in r.stderr


def test_a_workflow_job_never_replaces_its_own_input(tmp_path):
    # the job's inputs are protected from every writer of the job (the output gate)
    scripts = Path(__file__).resolve().parents[2] / "workflow" / "scripts"
    src = tmp_path / "in.nc"
    src.write_bytes(b"input bytes")
    code = (
        f"import sys; sys.path.insert(0, {str(scripts)!r})\n"
        "from types import SimpleNamespace\n"
        "import xarray as xr\n"
        "from _common import start_log\n"
        "from pencore.io.netcdf import write_netcdf\n"
        f"start_log(SimpleNamespace(log=[{str(tmp_path / 'job.log')!r}], input=[{str(src)!r}]),"
        " 'job')\n"
        f"write_netcdf(xr.Dataset(), {str(src)!r}, config_slice={{}}, study='t')\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 1
    assert "input of this run" in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert src.read_bytes() == b"input bytes"
