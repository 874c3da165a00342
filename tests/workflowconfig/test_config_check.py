"""The workflow configuration is checked when the Snakefile is parsed: every bad entry
stops with one line naming the key path and the value (pencore.workflowconfig.config_check)."""

from __future__ import annotations

import copy
import shutil
from pathlib import Path

import pytest
import yaml
from helpers import copy_workflow, run_snakemake

from pencore.errors import ConfigError
from pencore.workflowconfig.config_check import check_config, schema_error_message

REPO = Path(__file__).resolve().parents[2]
SHIPPED = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
SCHEMA = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())


def _set(cfg: dict, path: str, value) -> dict:
    keys = path.split(".")
    node = cfg
    for k in keys[:-1]:
        node = node[int(k)] if isinstance(node, list) else node[k]
    last = keys[-1]
    if isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value
    return cfg


BAD = [
    ("section4.fig8.obliquity_deg", {"min": 15.0, "max": 95.0, "step": 7.5}, "95.0"),
    ("section4.fig8.obliquity_deg", {"min": 75.0, "max": 15.0, "step": 7.5}, "min 75.0"),
    ("section4.fig8.obliquity_deg", {"min": 15.0, "max": 75.0, "step": 0.0}, "step"),
    ("section4.fig8.obliquity_deg", {"min": 15.0, "max": 75.0, "step": -1.0}, "-1.0"),
    ("section4.fig8.obliquity_deg", {"min": 0.0, "max": 89.0, "step": 1e-8}, "points"),
    ("section4.fig8.velocity_range_m_s", {"min": 4000.0, "max": 300.0}, "min 4000.0"),
    ("section4.fig8.velocity_range_m_s", {"min": 300.0, "max": 4e5}, "400000.0"),
    ("section4.fig8.low_velocities_m_s", [50, -100, 150], "-100"),
    ("section4.fig8.low_velocities_m_s", [0, 100], "0.0"),
    ("section4.fig8.start_m", [-1.0, 1.0], "three numbers"),
    ("section4.fig8.start_m", [-1.0, 1e6, 0.0], "1000000.0"),
    ("section4.fig8.projectiles", ["p1", "p2", "p2"], "duplicate names p2"),
    ("section4.fig7.velocities_m_s", [1000, -1641], "-1641"),
    ("section4.fig7.obliquity_deg", 90.0, "90.0"),
    ("section4.fig7.obliquity_deg", -5.0, "-5.0"),
    ("section4.fig9.velocity_m_s", 2e4, "20000.0"),
    ("section4.fig11.yaw_deg", [-1.0, 95.0], "95.0"),
    ("section4.fig11.yaw_deg", [-1.0, 60.0], "reaches 90 deg"),
    ("section4.fig12.obliquity_deg", [30.0, 88.0], "reaches 90 deg"),
    ("section4.fig12.yaw_deg", {"min": 4.0, "max": -4.0, "step": 1.0}, "min 4.0"),
    ("section4.fig13.velocities_m_s", [280, 0.0], "0.0"),
    ("section4.fig15.threshold_deg", 0.0, "threshold 0.0"),
    ("section4.fig15.thresholds_deg", [2.0, -5.0], "-5.0"),
    ("section4.fig15.velocity_range_m_s", {"min": 100.0, "max": 50.0}, "min 100.0"),
    ("section4.fig16.omega_rad_s", [5.0, 1e6], "1000000.0"),
    ("section4.fig16.start_heights_m", [0.0, -0.5], "-0.5"),
    ("section4.fig18.omega_range_rad_s", {"min": 500.0, "max": 0.0}, "min 500.0"),
    ("section4.fig18.velocities_m_s", [500, -750], "-750"),
    ("validation.fig5.velocities_m_s", {"min": 1800, "max": 200, "n": 17}, "min 1800"),
    ("validation.fig5.velocities_m_s", {"min": 200, "max": 1800, "n": 10**9}, "n must be"),
    ("validation.fig5.velocities_m_s", {"min": -200, "max": 1800, "n": 17}, "-200"),
    ("validation.verification.velocities_m_s", {"min": 0, "max": 1500, "n": 15}, "0.0"),
    ("validation.table2.projectiles", ["p1", "p1"], "duplicate names p1"),
    (
        "validation.fig5.cases",
        [{"name": "a", "projectile": "p1", "target": "soil"}] * 2,
        "duplicate names a",
    ),
]


@pytest.mark.parametrize(("path", "value", "needle"), BAD, ids=[f"{p}={v}"[:60] for p, v, _ in BAD])
def test_bad_entry_names_its_key_path(path, value, needle):
    cfg = _set(copy.deepcopy(SHIPPED), path, value)
    with pytest.raises(ConfigError) as info:
        check_config(cfg, REPO)
    msg = str(info.value)
    assert "\n" not in msg
    # a combination (obliquity + yaw) is reported at its study's path
    study = path.rsplit(".", 1)[0]
    assert msg.startswith(f"config {path}:") or msg.startswith(f"config {study}:"), msg
    assert needle in msg, msg


def test_shipped_and_test_configs_pass():
    check_config(SHIPPED, REPO)
    small = yaml.safe_load((REPO / ".test" / "config.yaml").read_text())
    check_config(small, REPO)


def test_header_only_table2_csv(tmp_path):
    header = (REPO / "config" / "table2.csv").read_text().splitlines()[0]
    (tmp_path / "t2.csv").write_text(header + "\n")
    shutil.copytree(REPO / "config", tmp_path / "config")  # the other tables it names
    cfg = _set(copy.deepcopy(SHIPPED), "validation.table2.csv", "t2.csv")
    with pytest.raises(ConfigError, match=r"validation\.table2\.csv: .*no rows"):
        check_config(cfg, tmp_path)


@pytest.mark.parametrize(
    ("path", "value", "needles"),
    [
        ("section4.fig8.obliquty_deg", 30, ["section4.fig8.obliquty_deg", "'obliquity_deg'"]),
        ("numerics.rtoll", 1e-6, ["numerics.rtoll", "did you mean 'rtol'"]),
        ("sectoin4", {}, ["sectoin4", "did you mean 'section4'"]),
        ("section4.velocity_tol_m_s", -5.0, ["section4.velocity_tol_m_s", "-5.0"]),
        ("section4.fig8.projectiles", ["p9"], ["section4.fig8.projectiles.0", "'p9'"]),
    ],
)
def test_schema_errors_are_one_short_line(path, value, needles):
    cfg = _set(copy.deepcopy(SHIPPED), path, value)
    msg = schema_error_message(cfg, SCHEMA)
    assert "\n" not in msg and len(msg) < 400, msg
    for needle in needles:
        assert needle in msg, msg


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        ("section4:\n  fig8:\n    obliquity_deg: {min: 15.0, max: 95.0, step: 7.5}\n",
         "config section4.fig8.obliquity_deg: obliquity 95.0 deg"),
        ("section4:\n  fig8:\n    obliquty_deg: 30\n",
         "config section4.fig8.obliquty_deg: unknown key; did you mean 'obliquity_deg'?"),
        # keys that name a thing: a target of a measurement set, a shot set of Fig. 5
        ("validation:\n  measurements:\n    - {name: al, csv: config/aluminium_ogive_shots.csv,"
         " targets: [aluminum]}\n",
         "config validation.measurements[0].targets[0]: unknown target 'aluminum'"),
        ("validation:\n  fig5:\n    body_shots:\n      config/concrete_ogive_shots.csv:\n"
         "        forrestal1996_d12.9_crh3_fc13: grout_crh3\n",
         "no set 'forrestal1996_d12.9_crh3_fc13' in 'config/concrete_ogive_shots.csv'"),
    ],
)  # fmt: skip
def test_snakemake_stops_at_parse_time_with_a_short_message(tmp_path, text, needle):
    copy_workflow(tmp_path)
    (tmp_path / "bad.yaml").write_text(text)
    r = run_snakemake(tmp_path, "-n", "--cores", "1", "--configfile", "bad.yaml", timeout=300)
    out = r.stdout + r.stderr
    assert r.returncode != 0
    assert needle in out, out
    assert len(out.strip().splitlines()) <= 5, out  # no schema dump, no traceback
