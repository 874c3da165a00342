"""Validation against published measurements (pencore.studies.validation.measurements): data-file
checks, error statistics, predictions that are the solver's own results."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pencore import simulate
from pencore.analysis.errors import error_statistics
from pencore.errors import InputError
from pencore.inputs.library import get_target
from pencore.inputs.target import Layer, Target
from pencore.studies.validation.measurements import (
    load_measurements,
    measured_vs_predicted,
    statistics_by_option,
)

HEADER = "test,velocity_m_s,obliquity_deg,yaw_deg,measured_depth_m,source\n"


def _csv(tmp_path, text, name="m.csv"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def _entry(path, **kw):
    return {"name": "t", "csv": path, "projectile": "p2", "target": "soil", **kw}


@pytest.mark.parametrize(
    "text, needle",
    [
        ("test,velocity_m_s,obliquity_deg,yaw_deg,source\n1,300,0,0,x\n", "exactly one"),
        (HEADER, "no rows"),
        (HEADER + "1,300,0,0,4.0,\n", "no source"),
        (HEADER + "1,-300,0,0,4.0,src\n", "velocity must be > 0"),
        (HEADER + "1,abc,0,0,4.0,src\n", "velocity_m_s must be a finite number"),
        ("test,velocity_m_s,obliquity_deg,source\n1,300,0,src\n", "lacks column"),
        (
            "test,velocity_m_s,obliquity_deg,yaw_deg,measured_residual_velocity_m_s,source\n"
            "1,300,0,0,100,src\n",
            "thickness_m > 0",
        ),
    ],
)
def test_bad_files_one_line(tmp_path, text, needle):
    with pytest.raises(InputError, match=needle) as e:
        load_measurements(_entry(_csv(tmp_path, text)))
    assert "\n" not in str(e.value)


def test_bad_entries(tmp_path):
    path = _csv(tmp_path, HEADER + "1,300,0,0,4.0,src\n")
    with pytest.raises(InputError, match="did you mean"):
        load_measurements({**_entry(path), "projectil": "p2"})
    with pytest.raises(InputError, match="no such file"):
        load_measurements(_entry(str(tmp_path / "missing.csv")))
    with pytest.raises(InputError, match="depth_measure"):
        load_measurements(_entry(path, depth_measure="depth"))
    with pytest.raises(InputError, match="no projectile/target"):
        load_measurements({"name": "t", "csv": path})
    with pytest.raises(InputError, match="duplicate shots"):
        measured_vs_predicted([_entry(path), _entry(path)])


def test_predictions_are_the_solver_results(tmp_path):
    """A depth row predicts exactly the path length (or vertical depth) of the same run;
    a residual-velocity row on a slab thinner than the depth predicts the run's residual
    velocity, and one thicker than the depth predicts 0 (no perforation)."""
    depth_csv = _csv(tmp_path, HEADER + "a,300,20,1,4.0,src\n", "d.csv")
    rv_csv = _csv(
        tmp_path,
        "test,velocity_m_s,obliquity_deg,yaw_deg,thickness_m,"
        "measured_residual_velocity_m_s,source\nthin,300,0,0,1.0,100,src\n"
        "thick,300,0,0,20.0,0,src\n",
        "r.csv",
    )
    ds = measured_vs_predicted(
        [
            _entry(depth_csv, name="d"),
            _entry(depth_csv, name="v", depth_measure="vertical_depth"),
            _entry(rv_csv, name="r"),
        ]
    )
    run = simulate("p2", "soil", 300.0, 20.0, 1.0)
    assert float(ds.predicted.sel(shot="d:a")) == float(run.path_length)
    assert float(ds.predicted.sel(shot="v:a")) == float(run.penetration_depth)
    medium = get_target("soil").layers[0].medium
    thin = simulate("p2", Target("slab", (Layer(medium, 1.0),)), 300.0)
    assert thin.attrs["outcome"] == "perforated"
    assert float(ds.predicted.sel(shot="r:thin")) == float(thin.attrs["residual_velocity"])
    assert float(ds.predicted.sel(shot="r:thick")) == 0.0
    assert str(ds.outcome.sel(shot="r:thick").values) != "perforated"
    # the statistics are those of the rows of each quantity
    sel = ds.quantity_of_shot.values == "penetration_depth"
    expect = error_statistics(ds.measured.values[sel], ds.predicted.values[sel])
    got = float(ds.stat_rms_rel_error.sel(quantity="penetration_depth"))
    assert got == pytest.approx(expect["rms_rel_error"], rel=1e-15)
    assert np.allclose(ds.rel_error, ds.predicted / ds.measured - 1.0, equal_nan=True)


def test_statistics_by_option_on_the_soil_shots():
    from pencore.studies.validation.measurements import statistics_by_option

    csv = Path(__file__).resolve().parents[3] / "config" / "table2.csv"
    entry = {"name": "soil", "csv": str(csv), "projectile": "p2", "target": "soil"}
    ds = statistics_by_option([entry], {"none": {}, "crater_2": {"crater_depth": 2.0}})
    assert list(ds["group"].values) == ["soil/penetration_depth"]
    plain = measured_vs_predicted([entry])
    # the paper's model is the measurements study, shot by shot
    np.testing.assert_array_equal(
        ds["predicted"].sel(option="none").values, plain["predicted"].values
    )
    # a crater takes less work near the surface: every shot goes deeper
    assert np.all(ds["predicted"].sel(option="crater_2") > ds["predicted"].sel(option="none"))
    assert float(ds["stat_n"].sel(option="none", group="soil/penetration_depth")) == 5
    with pytest.raises(InputError, match="unknown key"):
        statistics_by_option([entry], {"x": {"crater": 2.0}})


# ----------------------------------------------------------------------------- shot tables

REPO = Path(__file__).resolve().parents[3]
OGIVE = str(REPO / "config" / "aluminium_ogive_shots.csv")


def test_targets_and_target_are_exclusive(tmp_path):
    e = {"name": "a", "csv": OGIVE, "target": "aluminium", "targets": ["aluminium"]}
    with pytest.raises(InputError, match="target or targets, not both"):
        load_measurements(e)
    with pytest.raises(InputError, match="distinct target names"):
        load_measurements({"name": "a", "csv": OGIVE, "targets": ["aluminium", "aluminium"]})


@pytest.fixture(scope="module")
def aluminium():
    return measured_vs_predicted(
        [
            {
                "name": "ogive",
                "csv": OGIVE,
                "targets": ["aluminium", "aluminium_3term"],
                "depth_measure": "vertical_depth",
            }
        ]
    )


def test_every_shot_run_once_per_law(aluminium):
    assert aluminium.sizes["shot"] == 2 * 34
    assert list(aluminium["group"].values) == ["ogive/aluminium", "ogive/aluminium_3term"]
    assert aluminium["summary_n_not_rigid"].values.tolist() == [20.0, 20.0]
    n = aluminium["summary_n"].sel(model="predicted")
    # 14 rigid shots by the authors' limits; 31 of the 34 have a printed depth
    assert n.sel(subset="rigid").values.tolist() == [14.0, 14.0]
    assert n.sel(subset="all").values.tolist() == [31.0, 31.0]


def test_summary_statistics_are_those_of_the_rigid_shots(aluminium):
    sel = (aluminium["target"] == "aluminium_3term") & (aluminium["rigid"] == 1)
    e = aluminium["rel_error"].values[sel.values]
    s = aluminium.sel(group="ogive/aluminium_3term", model="predicted", subset="rigid")
    assert float(s["summary_mean_abs_rel_error"]) == pytest.approx(np.mean(np.abs(e)))
    assert float(s["summary_bias"]) == pytest.approx(np.mean(e))
    assert abs(float(s["summary_worst_rel_error"])) == pytest.approx(np.max(np.abs(e)))


def test_three_dimensional_runs_meet_the_exact_closed_form(aluminium):
    # a shot with no measured angle is a normal, zero-yaw impact: pencore is the closed form
    # to its step control (the verification study's 5e-3)
    straight = aluminium["obliquity"].values == 0.0
    assert straight.any()
    got = aluminium["predicted"].values[straight]
    exact = aluminium["closedform_depth"].values[straight]
    np.testing.assert_allclose(got, exact, rtol=5e-3)
    # the full-nose-force form is shallower than the exact entry, by less than a nose
    gap = aluminium["closedform_depth"] - aluminium["cavity_form_depth"]
    assert (gap > 0).all() and (gap < 0.0118).all()


def test_three_term_law_is_shallower_than_the_table1_law(aluminium):
    # same shot, same rod: the source's law resists more at every speed above ~0 (its a1 V
    # term outweighs the smaller a2), so every 3-term depth is shallower
    t1 = aluminium["predicted"].where(aluminium["target"] == "aluminium", drop=True).values
    t3 = aluminium["predicted"].where(aluminium["target"] == "aluminium_3term", drop=True).values
    assert (t3 < t1).all()


def test_a_data_set_with_no_rigid_shot_has_no_statistic():
    # Forrestal & Piekutowski (2000): every rod deformed; the shots are run and kept, and
    # the statistics say n = 0 instead of failing (the rule measurements_options met this)
    sphere = {
        "name": "sphere",
        "csv": str(REPO / "config" / "aluminium_sphere_shots.csv"),
        "targets": ["aluminium"],
        "depth_measure": "vertical_depth",
    }
    ds = measured_vs_predicted([sphere])
    assert ds.sizes["shot"] == 31 and not ds["rigid"].values.any()
    assert float(ds["stat_n"].item()) == 0.0 and np.isnan(ds["stat_mean_rel_error"].item())
    opt = statistics_by_option([sphere], {"none": {}})
    assert float(opt["stat_n"].item()) == 0.0
