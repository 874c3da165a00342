"""pencore.studies.validation.depth: inputs, selection rule, closed-form agreement."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.inputs.library import get_projectile
from pencore.inputs.numerics import resolve_numerics
from pencore.studies.validation.depth import fig5, velocity_grid, verification


def test_resolve_numerics():
    num = resolve_numerics({"rtol": None, "n_nose": 24})
    assert num.n_nose == 24 and num.rtol == resolve_numerics(None).rtol
    with pytest.raises(InputError, match="unknown key 'rtoll'; did you mean 'rtol'"):
        resolve_numerics({"rtoll": 1e-6})


def test_velocity_grid():
    np.testing.assert_allclose(velocity_grid(100, 300, 3), [100, 200, 300])
    with pytest.raises(InputError, match="0 < min < max"):
        velocity_grid(300, 100, 3)
    with pytest.raises(InputError, match="0 < min < max"):
        velocity_grid(-1, 100, 3)


CASES = [
    {"name": "c3", "projectile": "concrete_crh3", "target": "concrete", "v_max": 500},
    {"name": "a05", "projectile": "al_sphere_var4340", "target": "aluminium"},
]


REPO = Path(__file__).resolve().parents[3]
SPHERE_SHOTS = REPO / "config" / "aluminium_sphere_shots.csv"


def test_fig5_ranges_and_shots():
    ds = fig5(CASES, [400.0, 800.0], shots=[SPHERE_SHOTS])
    assert np.isnan(float(ds["pencore_depth"].sel(case="c3", velocity=800.0)))
    assert ds["crh"].values.tolist() == [3.0, 0.5]
    assert ds["target_density"].values.tolist() == [1960.0, 2710.0]
    # every shot of the table is drawn, flagged as its authors flag it (none rigid)
    table = pd.read_csv(SPHERE_SHOTS, comment="#")
    assert ds.sizes["experiment"] == len(table) == 31
    assert ds["experiment_velocity"].values.tolist() == table["striking_velocity_m_s"].tolist()
    assert ds["experiment_depth"].values.tolist() == table["depth_m"].tolist()
    assert not ds["experiment_rigid"].values.any()


def test_fig5_cavity_form_is_the_tunnel_phase_from_impact():
    # the sources' Eq. 1: the full nose force from first contact, so shallower than the exact
    # nose entry by less than a nose length
    ds = fig5(CASES, [400.0, 800.0])
    sub = ds.sel(case="a05", velocity=800.0)
    cav, exact = float(sub["cavity_form_depth"]), float(sub["closedform_depth"])
    assert 0.0 < exact - cav < get_projectile("al_sphere_var4340").nose_length


def test_fig5_shot_of_no_case_is_refused(tmp_path):
    bad = tmp_path / "shots.csv"
    text = SPHERE_SHOTS.read_text().replace("al_sphere_var4340", "p2")
    bad.write_text(text)
    with pytest.raises(InputError, match=r"projectile\(s\) \['p2'\] match no case"):
        fig5(CASES, [400.0], shots=[bad])


def test_verification_against_closed_form():
    ds = verification(CASES, [300.0, 500.0])
    assert float(ds["max_abs_rel_diff"]) < 5e-3
    assert ds.attrs["max_abs_rel_diff_case"] in {"c3", "a05"}
