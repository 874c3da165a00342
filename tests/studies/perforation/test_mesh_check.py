"""pencore.studies.perforation.mesh_check: the map against the same map on finer rings."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from pencore.errors import InputError
from pencore.inputs.numerics import Numerics
from pencore.io.netcdf import read_netcdf
from pencore.studies.perforation.mesh_check import finer_rings, mesh_check

ARCHIVE = Path(__file__).resolve().parents[3] / "results" / "archive" / "near_surface"


def _map():
    return read_netcdf(ARCHIVE / "ballistic_map.nc").load()


def test_finer_rings_scales_the_rings_only():
    base = Numerics()
    fine = finer_rings({"rtol": 1e-6}, 2.0)
    assert (fine.n_nose, fine.n_shank) == (2 * base.n_nose, 2 * base.n_shank)
    assert fine.rtol == 1e-6 and fine.eps == base.eps
    assert finer_rings(None, 0.5).n_nose == round(0.5 * base.n_nose)
    with pytest.raises(InputError, match="ring-mesh factor must be a number > 0"):
        finer_rings(None, 0.0)


def test_a_cell_is_converged_within_the_search_tolerance_and_says_why_not():
    coarse = _map()
    fine = coarse.copy(deep=True)
    tol = float(coarse.attrs["search_tol_m_s"])
    opt = str(coarse.option.values[0])
    cell = {"option": opt, "t_over_d": coarse.t_over_d.values[1], "obliquity": 30.0}
    fine["v_bl"].loc[cell] = coarse["v_bl"].loc[cell] + tol  # on the tolerance: converged
    cell2 = {**cell, "obliquity": 45.0}
    fine["v_bl"].loc[cell2] = coarse["v_bl"].loc[cell2] + 1.5 * tol
    cell3 = {**cell, "obliquity": 15.0}
    fine["v_bl"].loc[cell3] = np.nan
    fine["status"].loc[cell3] = "solver_error"
    fine["message"].loc[cell3] = "the steps stalled"
    num = json.loads(coarse.attrs["numerics_json"])
    fine.attrs["numerics_json"] = json.dumps(
        {**num, "n_nose": 2 * num["n_nose"], "n_shank": 2 * num["n_shank"]}
    )
    check = mesh_check(coarse, fine, 2.0)
    ok = coarse["status"] == "ok"
    assert check["converged"].loc[cell].item() == 1 and check["reason"].loc[cell].item() == ""
    assert check["converged"].loc[cell2].item() == 0
    assert f"moves +{1.5 * tol:.1f} m/s on 2x the rings" in check["reason"].loc[cell2].item()
    assert (
        "on 2x the rings ended solver_error: the steps stalled" in check["reason"].loc[cell3].item()
    )
    assert check.attrs["n_converged"] == int(ok.sum()) - 2
    assert check.attrs["n_nose_fine"] == 2 * check.attrs["n_nose"]
    np.testing.assert_allclose(
        check["difference"].loc[cell2], 1.5 * tol, rtol=1e-12
    )  # fine minus default


def test_maps_on_other_grids_are_refused():
    coarse = _map()
    with pytest.raises(InputError, match="differ in their obliquity values"):
        mesh_check(coarse, coarse.isel(obliquity=slice(0, 3)), 2.0)
