"""The attribution study of the workflow (pencore.studies.attribution.settings): settings checked,
parts joined on `setting`, the default row is the model's own result, table verdicts."""

from __future__ import annotations

import numpy as np
import pytest

from pencore.errors import ConfigError, InputError
from pencore.paper.choices import check_settings
from pencore.paper.claims import disputed_values
from pencore.studies.attribution.disputed import disputed_quantities
from pencore.studies.attribution.settings import (
    NUMBERS,
    _miss,
    attribution_table,
    gather,
    run_setting,
)
from pencore.workflowconfig.config_check import check_config


@pytest.mark.parametrize(
    "settings, needle",
    [
        ([], "no settings"),
        ([{"name": "a", "choices": {}}, {"name": "a", "choices": {}}], "duplicate name"),
        ([{"name": "a", "choices": {"spin_abut": "tip"}}], "did you mean"),
        ([{"name": "a", "choices": {"reversal": "bounces"}}], "reversal must be one of"),
        ([{"name": "a", "choices": {}, "colour": "red"}], "colour"),
    ],
)
def test_bad_settings_one_line(settings, needle):
    with pytest.raises(InputError, match=needle) as e:
        check_settings(settings)
    assert "\n" not in str(e.value)


def test_config_check_catches_bad_settings_at_parse_time():
    with pytest.raises(ConfigError, match="config attribution.settings: .*did you mean"):
        check_config({"attribution": {"settings": [{"name": "a", "choices": {"frction": 0.1}}]}})


def test_miss_definitions():
    lo, hi = disputed_values()["vcr_bracket"]
    mid = 0.5 * (lo + hi)
    # inside the bracket: no miss; outside: the distance to the bracket over the midpoint
    got = _miss("vcr", np.array([lo, 0.5 * (lo + hi), hi, hi + 0.03 * mid]), mid)
    assert got[:3].tolist() == [0.0, 0.0, 0.0]
    assert got[3] == pytest.approx(0.03)
    assert _miss("turn_back_25", np.array([0.0, 1.0]), 1.0).tolist() == [1.0, 0.0]
    assert _miss("alpha_5", np.array([0.14 * 1.1]), 0.14)[0] == pytest.approx(0.1)


def test_gather_default_row_is_the_model_and_table_verdicts():
    default = {"name": "default", "label": "as written", "group": "default", "choices": {}}
    exits = {"name": "exits", "label": "comes back out", "choices": {"reversal": "exits"}}
    ds = gather([run_setting(default), run_setting(exits)])
    assert list(ds["setting"].values) == ["default", "exits"]
    assert ds["alpha"].dims == ("setting", "omega")
    ref = disputed_quantities({})
    # the default row is the model's own result, bit for bit (same code, same machine)
    assert float(ds["vcr"].sel(setting="default")) == float(ref["vcr"])
    np.testing.assert_array_equal(ds["alpha"].sel(setting="default").values, ref["alpha"].values)
    # the "comes back out" reading moves Vcr up into the paper's 3 % band (1629 m/s)
    # and leaves every normal-impact number unchanged
    assert float(ds["vcr"].sel(setting="exits")) > float(ds["vcr"].sel(setting="default"))
    assert (
        float(ds["miss_vcr"].sel(setting="exits"))
        <= 0.03
        < float(ds["miss_vcr"].sel(setting="default"))
    )
    assert float(ds["depth_280"].sel(setting="exits")) == float(ref["depth_280"])
    table = attribution_table(ds)
    assert len(table) == len(NUMBERS) + 1
    assert table.iloc[-1]["within 3%"] == ("yes" if ds["within_tolerance_all"].any() else "no")
    vcr_row = table[table["paper number"].str.startswith("Vcr")].iloc[0]
    assert vcr_row["closest setting"] == "comes back out"
