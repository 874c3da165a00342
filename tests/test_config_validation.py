"""Configuration checks at parse time (pencore.studies.config_check).

In-process: each bad configuration is the shipped ``config/config.yaml`` with one change;
the error must be one line naming the key path and the value. Subprocess: ``snakemake -n
--configfile bad.yaml`` must fail with a short message, not the schema dump.
"""

from __future__ import annotations

import copy
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from snakemake.utils import validate

from pencore.studies.config_check import MAX_GRID_POINTS, ConfigError, check_config, validate_config

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
SHIPPED = yaml.safe_load((REPO / "config" / "config.yaml").read_text())


def _set(cfg: dict, path: str, value) -> None:
    *head, last = path.split(".")
    node = cfg
    for k in head:
        node = node[int(k)] if k.isdigit() else node[k]
    node[int(last) if last.isdigit() else last] = value


def _schema(cfg: dict) -> None:
    validate(cfg, str(SCHEMA))


# (key path to set, value, text the message must contain besides the path)
RELATION_CASES = [
    ("section4.fig8.obliquity_deg", {"min": 60.0, "max": 45.0, "step": 7.5}, "min 60.0 > max"),
    ("section4.fig8.obliquity_deg", {"min": 15.0, "max": 90.0, "step": 7.5}, "90"),
    ("section4.fig8.obliquity_deg", {"min": 15.0, "max": 75.0, "step": 1e-4}, "grid points"),
    ("section4.fig8.velocity_range_m_s", {"min": 4000.0, "max": 300.0}, "min 4000.0 > max"),
    ("section4.fig12.yaw_deg", {"min": 4.0, "max": -4.0, "step": 1.0}, "min 4.0 > max"),
    ("section4.fig12.yaw_deg", {"min": -4.0, "max": 4.0, "step": 1e-4}, "grid points"),
    ("section4.fig12.velocity_range_m_s", {"min": 500.0, "max": 400.0}, "min 500.0 > max"),
    ("section4.fig12.obliquity_deg", [30.0, 95.0], "obliquity"),
    ("section4.fig12.obliquity_deg", [88.0], "obliquity + |yaw|"),
    ("section4.fig12.obliquity_deg", [-90.0], "obliquity"),
    ("section4.fig7.velocities_m_s", [1000, -1641], "velocities must be >= 0"),
    ("section4.fig18.velocities_m_s", [-1000], "velocities must be >= 0"),
    ("section4.fig8.low_velocities_m_s", [50, -100], "velocities must be >= 0"),
    ("validation.fig5.velocities_m_s", {"min": 1800, "max": 200, "n": 17}, "min 1800 > max"),
    ("validation.fig5.velocities_m_s", {"min": 200, "max": 1800, "n": 10**6}, "grid points"),
    ("validation.verification.velocities_m_s", {"min": 900, "max": 100, "n": 3}, "min 900"),
    (
        "validation.verification.velocities_m_s",
        {"min": 100, "max": 900, "n": MAX_GRID_POINTS + 1},
        "grid points",
    ),
    ("validation.fig5.cases.0.v_min", 5000, "v_min > v_max"),
    ("validation.fig5.cases.1.name", "concrete_crh3", "duplicate case name"),
    ("validation.fig5.cases.3.name", "aluminium_crh3", "duplicate case name"),
]


def _verification_dup(cfg):
    cases = cfg["validation"]["verification"]["cases"]
    cases.append(dict(cases[0]))
    return "validation.verification.cases", cases[0]["name"]


@pytest.mark.parametrize(("path", "value", "why"), RELATION_CASES)
def test_relation_errors_name_path_and_value(path, value, why):
    cfg = copy.deepcopy(SHIPPED)
    _set(cfg, path, value)
    with pytest.raises(ConfigError) as info:
        check_config(cfg, REPO)
    msg = str(info.value)
    assert "\n" not in msg
    shown_path = path.rsplit(".", 1)[0] if path.split(".")[-1] in ("v_min", "name") else path
    shown_path = shown_path.replace(".0", "[0]").replace(".1", "[1]").replace(".3", "[3]")
    assert shown_path.split("[")[0] in msg, msg
    assert why in msg, msg
    if path.endswith(("velocities_m_s", "low_velocities_m_s")) and isinstance(value, list):
        assert repr([v for v in value if v < 0][0]) in msg, msg


def test_duplicate_verification_case():
    cfg = copy.deepcopy(SHIPPED)
    path, name = _verification_dup(cfg)
    with pytest.raises(ConfigError, match="duplicate case name") as info:
        check_config(cfg, REPO)
    assert path in str(info.value) and repr(name) in str(info.value)


def test_header_only_table2(tmp_path):
    header = (REPO / "config" / "table2.csv").read_text().splitlines()
    rows = [r for r in header if r and not r.startswith("#")]
    (tmp_path / "t2.csv").write_text(rows[0] + "\n")
    cfg = copy.deepcopy(SHIPPED)
    cfg["validation"]["table2"]["csv"] = "t2.csv"
    with pytest.raises(ConfigError, match=r"validation\.table2\.csv = 't2\.csv'.*no data rows"):
        check_config(cfg, tmp_path)


def test_shipped_and_test_configs_pass():
    check_config(SHIPPED, REPO)
    validate_config(copy.deepcopy(SHIPPED), _schema, REPO)


SCHEMA_CASES = [
    ("section4.fig8.obliquty_deg", [45], "did you mean 'obliquity_deg'"),
    ("section4.fig8.projectiles", "p2", "section4.fig8.projectiles = 'p2'"),
    ("section4.fig7.velocities_m_s", ["fast"], "section4.fig7.velocities_m_s.0 = 'fast'"),
    ("section4.scan_points", -3, "section4.scan_points = -3"),
    ("validation.table2.target", 7, "validation.table2.target = 7"),
]


@pytest.mark.parametrize(("path", "value", "expect"), SCHEMA_CASES)
def test_schema_errors_are_one_short_line(path, value, expect):
    cfg = copy.deepcopy(SHIPPED)
    _set(cfg, path, value)
    with pytest.raises(ConfigError) as info:
        validate_config(cfg, _schema, REPO)
    msg = str(info.value)
    assert "\n" not in msg and len(msg) < 400, msg
    assert expect in msg, msg


def _copy_workflow(dest: Path) -> Path:
    import shutil

    shutil.copy2(REPO / "Snakefile", dest / "Snakefile")
    for d in ("workflow", "config", ".test"):
        shutil.copytree(REPO / d, dest / d)
    return dest


@pytest.mark.parametrize(
    ("bad", "expect"),
    [
        ({"section4": {"fig8": {"obliquty_deg": [45]}}}, "did you mean 'obliquity_deg'"),
        ({"section4": {"fig18": {"velocities_m_s": [1000, -5]}}}, "velocities must be >= 0"),
        ({"section4": {"fig12": {"obliquity_deg": [88.0]}}}, "obliquity + |yaw|"),
    ],
)
def test_snakemake_dry_run_rejects_bad_config_briefly(tmp_path, bad, expect):
    wd = _copy_workflow(tmp_path)
    (wd / "bad.yaml").write_text(yaml.safe_dump(bad))
    r = subprocess.run(
        [sys.executable, "-m", "snakemake", "-n", "--cores", "1", "--configfile", "bad.yaml"],
        cwd=wd,
        capture_output=True,
        text=True,
        timeout=300,
    )
    out = r.stdout + r.stderr
    assert r.returncode != 0
    assert expect in out, out[-2000:]
    assert len(out.splitlines()) < 15, out[-2000:]
    assert "additionalProperties" not in out and "Failed validating" not in out
