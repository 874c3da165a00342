"""The inverse step of the attribution study (pencore.studies.attribution.inverse): the mass
properties of #2 fitted to the spin numbers, recorded as fitted with the data fitted to,
and judged on the others."""

from __future__ import annotations

import numpy as np
import pytest

import pencore
from pencore.paper.bodies import build_body
from pencore.studies.attribution.disputed import disputed_quantities
from pencore.studies.attribution.inverse import FITTED_TO
from pencore.studies.attribution.settings import attribution_table, gather, run_setting


@pytest.fixture(scope="module")
def fitted():
    st = {
        "name": "fit",
        "label": "fitted",
        "group": "mass",
        "choices": {"body": {"kind": "fit_spin"}},
    }
    return run_setting(st)


def test_fit_is_recorded_with_the_numbers_it_was_fitted_to(fitted):
    ds = fitted.isel(setting=0)
    assert str(ds["fitted_to"].values) == ";".join(FITTED_TO) == "alpha_20;turn_back_25"
    assert float(ds["body_lc_over_l"]) == pytest.approx(float(ds["fitted_lc_over_l"]), abs=1e-12)
    solid = pencore.get_projectile("p2").mass_properties()
    assert float(ds["body_i_transverse"]) == pytest.approx(
        float(ds["fitted_i_transverse_factor"]) * solid.i_transverse, rel=1e-12
    )
    # the fitted numbers: the turn-back at 25 (and none at 20), alpha(20) near the paper's
    assert int(ds["fit_reproduced"]) == 1
    assert bool(ds["turned_back"].sel(omega=25.0)) and not bool(ds["turned_back"].sel(omega=20.0))
    assert float(ds["alpha"].sel(omega=20.0)) == pytest.approx(2.86, rel=0.03)


def test_fitted_body_is_the_given_body_it_names(fitted):
    """The fitted values, given back as a body, give the same alpha bit for bit."""
    ds = fitted.isel(setting=0)
    spec = {
        "kind": "given",
        "lc_over_l": float(ds["fitted_lc_over_l"]),
        "i_transverse_factor": float(ds["fitted_i_transverse_factor"]),
    }
    q = build_body("p2", spec).projectile
    run = pencore.simulate(q, "soil", 1000.0, omega=20.0)
    assert pencore.final_deviation(run) == float(ds["alpha"].sel(omega=20.0))


def test_table_never_offers_a_fitted_number_as_reproduced(fitted):
    default = run_setting({"name": "default", "label": "as written", "choices": {}})
    table = attribution_table(gather([default, fitted]))
    row = table[table["paper number"].str.startswith("alpha of #2 at 20")].iloc[0]
    assert row["closest setting"] == "as written"
    assert "fitted (fitted)" in row["settings within"]


def test_default_inertia_reproduces_the_default_deviation_exactly():
    ref = disputed_quantities({})
    same = disputed_quantities({"body": {"kind": "given", "i_transverse_factor": 1.0}})
    np.testing.assert_array_equal(same["alpha"].values, ref["alpha"].values)
    assert float(same["vcr"]) == float(ref["vcr"])
    np.testing.assert_array_equal(same["phi_p4"].values, ref["phi_p4"].values)


def test_a_mass_case_runs_the_body_it_names():
    """The dataset of a mass case records the body it ran: Table 3's rounding edge of
    #2's Lc/L at the solid body's mass; #4's body (Lc/L 0.65 of #2 moves #4's to 0.696)
    needs a rear half denser than any alloy and says so."""
    ds = disputed_quantities({"body": {"kind": "lc", "lc_over_l": 0.5255}})
    solid = pencore.get_projectile("p2").mass_properties()
    assert float(ds["body_mass"]) == pytest.approx(solid.mass, rel=1e-12)
    assert float(ds["body_lc_over_l"]) == pytest.approx(0.5255, abs=1e-12)
    assert int(ds["body_buildable"]) == 1 and int(ds["body_p4_buildable"]) == 1
    assert "front half 5121, rear half 5179" in ds.attrs["body_description"]
    far = disputed_quantities({"body": {"kind": "lc", "lc_over_l": 0.65}})
    assert int(far["body_buildable"]) == 1 and int(far["body_p4_buildable"]) == 0
