"""The attribution study's computation (pencore.studies.attribution.disputed): one setting, every
disputed quantity."""

import math

import pytest

import pencore
from pencore import analysis
from pencore.paper.claims import disputed_values
from pencore.studies.attribution.disputed import disputed_quantities, relative_differences


@pytest.fixture(scope="module")
def default():
    return disputed_quantities({})


def test_default_setting_gives_pencores_own_numbers(default):
    """The default setting is pencore's model: alpha is the simulate()'s final
    deviation, Table-2 depth its path length, and Vcr's bracket straddles the verdict."""
    ds = default
    run = pencore.simulate("p2", "soil", 1000.0, omega=20.0)
    assert float(ds.alpha.sel(omega=20.0)) == analysis.final_deviation(run)
    assert float(ds.depth_280) == float(pencore.simulate("p2", "soil", 280.0).path_length)
    assert float(ds.vcr_hi) - float(ds.vcr_lo) <= 5.0
    for v, rev in ((float(ds.vcr_lo), 0), (float(ds.vcr_hi), 1)):
        r = pencore.simulate("p2", "soil", v, 45.0, start=(-1.0, 1.0, 0.0), stop_at_reversal=True)
        assert r.attrs["reversed"] == rev
    assert not bool(ds.turned_back.sel(omega=25.0))


def test_every_variable_has_units_and_the_paper_values(default):
    for name, var in default.variables.items():
        assert "units" in var.attrs, name
    assert float(default.paper_alpha.sel(omega=20.0)) == disputed_values()["alpha"][20.0]
    assert math.isnan(float(default.paper_alpha.sel(omega=25.0)))
    rel = relative_differences(default)
    assert rel["turn_back_25_agrees"] == 0.0  # the model as written does not turn back
    assert -0.05 < rel["vcr"] < 0.0


@pytest.mark.parametrize(
    "choices, match",
    [
        ({"shank_model": "cavity"}, "did you mean 'shank'"),
        ({"spin_about": "nose"}, "spin_about"),
        ({"yaw_reading": "tilted"}, "yaw convention"),
        ({"friction": -0.1}, "friction"),
        ({"start_height": -1.0}, "start height"),
        ({"numerics": 3}, "numerics"),
        ([("shank", "dafl")], "mapping"),
        ({"body": {"kind": "hollow"}}, "body kind must be one of .*fit_spin"),
        ({"body": {"kind": "fit_spin", "lc_over_l": 0.6}}, "lc_over_l"),
    ],
)
def test_bad_settings_are_one_line_input_errors(choices, match):
    with pytest.raises(pencore.InputError, match=match):
        disputed_quantities(choices)
