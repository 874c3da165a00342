"""pencore.workflowconfig.ensemble_cases: an ensemble case is checked before any run,
and a bad one stops with one line naming the key and what is allowed."""

import pytest
import yaml
from helpers import ENSEMBLE_CASE, REPO

from pencore.errors import InputError
from pencore.workflowconfig.ensemble_cases import CASE_KEYS, check_case

CASE = ENSEMBLE_CASE


def test_a_good_case_is_returned_with_every_variable_spelt_out():
    out = check_case(CASE)
    assert set(out) <= set(CASE_KEYS)
    assert out["yaw_deg"] == {"dist": "fixed", "value": 0.5}
    assert out["velocity_m_s"]["sd"] == 150


def test_the_shipped_cases_pass():
    cases = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["ensemble"]["cases"]
    assert cases
    for case in cases:
        assert check_case(case)["name"] == case["name"]


@pytest.mark.parametrize(
    "edit, needle",
    [
        ({"velocity_m_s": {"dist": "gamma", "k": 2}}, "dist must be one of"),
        ({"obliquity_deg": {"dist": "uniform", "min": 60, "max": 30}}, "min < max"),
        ({"yaw_deg": {"dist": "normal", "mean": 0, "sd": -1}}, "sd > 0"),
        ({"yaw_deg": {"dist": "normal", "mean": 0}}, "needs 'sd'"),
        ({"obliquity_deg": {"dist": "normal", "mean": 45, "sd": 20}}, "set min/max"),
        ({"velocity_m_s": {"dist": "normal", "mean": 100, "sd": 50}}, "set min/max"),
        ({"velocity_m_s": True}, "must be a number or a distribution"),
        ({"yaw_deg": {"dist": "fixed", "value": float("nan")}}, "finite number"),
        ({"n_samples": 0}, r"n_samples must be in \[1, 1e\+06\], got 0"),
        ({"n_samples": 10**9}, r"n_samples must be in \[1, 1e\+06\], got 1000000000"),
        ({"n_chunks": 3000}, r"n_chunks must be in \[1, 1000\], got 3000"),
        ({"n_samples": 500, "n_chunks": 600}, "n_chunks <= n_samples"),
        ({"n_samples": 2.5}, "whole number"),
        ({"sed": 1}, "did you mean"),
        ({"velocity_m_s": {"dist": "uniform", "min": 1, "max": 2, "mode": 1}}, "mode"),
    ],
)
def test_bad_cases_one_line(edit, needle):
    with pytest.raises(InputError, match=needle) as e:
        check_case({**CASE, **edit})
    assert "\n" not in str(e.value)


def test_the_yaw_convention_is_checked_and_spelt_out():
    assert check_case(CASE)["yaw_convention"] == "velocity_tilted"
    assert check_case({**CASE, "yaw_convention": "axis_tilted"})["yaw_convention"] == "axis_tilted"
    with pytest.raises(InputError, match="yaw_convention must be one of axis_tilted") as e:
        check_case({**CASE, "yaw_convention": "axis"})
    assert "\n" not in str(e.value)


def test_the_ensembles_pages_angle_of_attack_case_is_a_valid_case():
    import re

    page = (REPO / "docs" / "user-guide" / "ensembles.md").read_text()
    (block,) = [b for b in re.findall(r"```yaml\n(.*?)```", page, re.S) if "axis_tilted" in b]
    (case,) = yaml.safe_load(block)["ensemble"]["cases"]
    out = check_case(case)
    assert out["yaw_convention"] == "axis_tilted" and out["obliquity_deg"]["value"] == 20.0
