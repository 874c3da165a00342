"""pencore.run.band: the depth band a run into a scored concrete law carries."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import pencore
from pencore.errors import PlausibilityWarning
from pencore.inputs.record import comparable, scores_of


def _rod(d: float = 0.0129, crh: float = 3.0) -> pencore.Projectile:
    return pencore.Projectile(
        "rod", d, pencore.OgiveNose(crh, 7850.0), (pencore.Cylinder(5 * d, 7850.0),)
    )


def test_a_run_carries_the_band_of_its_comparable_shots():
    c35 = pencore.concrete_law(35e6, 2300.0)
    rod = _rod()
    ds = pencore.simulate(rod, c35, 600.0)
    s = scores_of(c35.record_law)
    m = comparable(s, rod.diameter, 35e6, 600.0, 3.0)
    lo, hi = np.quantile(s.ratio[m], [(1 - s.nominal_level) / 2, (1 + s.nominal_level) / 2])
    path = float(ds["path_length"])
    assert ds["depth_band"].values.tolist() == pytest.approx([lo * path, hi * path], rel=1e-12)
    assert ds["depth_band"].attrs["units"] == "m"
    assert ds.attrs["depth_band_n_shots"] == int(m.sum())
    assert ds.attrs["depth_band_law"] == c35.record_law == "forrestal_size"
    assert ds.attrs["depth_band"].startswith(f"{lo * path:.4g} to {hi * path:.4g} m")


def test_no_comparable_shot_warns_and_says_why():
    c35 = pencore.concrete_law(35e6, 2300.0)
    with pytest.warns(PlausibilityWarning, match="no measured error for this answer"):
        ds = pencore.simulate(_rod(crh=8.0), c35, 300.0)  # no scored nose that sharp
    assert "depth_band" not in ds and ds.attrs["depth_band"].startswith("none: fewer than")


def test_laws_the_record_did_not_score_carry_no_band():
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        given = pencore.simulate(_rod(), pencore.concrete_law(35e6, 2300.0, s=12.0), 600.0)
        paper = pencore.simulate(_rod(), "concrete", 600.0)
    assert "depth_band" not in given.attrs and "depth_band" not in paper.attrs
    windowed = pencore.Target.half_space(pencore.concrete_law(35e6, 2300.0))
    windowed = windowed.with_windows(free_surface_depth=1.0)
    assert windowed.layers[0].medium.record_law == ""
    same = pencore.Target.half_space(pencore.concrete_law(35e6, 2300.0)).with_windows(
        crater_depth=0.0
    )
    assert same.layers[0].medium.record_law == "forrestal_size"  # nothing changed


def test_an_oblique_run_says_its_band_is_from_normal_impacts():
    ds = pencore.simulate(_rod(), pencore.concrete_law(35e6, 2300.0), 600.0, obliquity=10.0)
    assert ds.attrs["depth_band"].endswith("the shots are normal impacts")
