"""pencore.studies.config: a study is run through its registry record, and bad requests
stop with one line before any run."""

import numpy as np
import pytest
import xarray as xr
from helpers import search_results

from pencore.errors import InputError
from pencore.studies.common import projectile_coords, search_variables
from pencore.studies.config import from_config, gather
from pencore.workflowconfig.registry import split_studies


def test_unknown_study_names_the_known_ones():
    with pytest.raises(InputError, match="unknown Section 4 study 'fig99'; known: fig7"):
        from_config("fig99", {}, {})


@pytest.mark.parametrize("study", sorted(split_studies()))
def test_split_study_needs_its_part(study):
    with pytest.raises(InputError, match="runs per projectile"):
        from_config(study, {}, {})


@pytest.mark.parametrize("study", [k for k, s in split_studies().items() if len(s.split_by) > 1])
def test_a_study_split_by_obliquity_needs_an_obliquity(study):
    with pytest.raises(InputError, match="give obliquity="):
        from_config(study, {"velocity_range_m_s": {"min": 1, "max": 2}}, {}, projectile="p2")


def test_gather_joins_parts_in_any_order():
    def part(p, o):
        data = search_variables(
            search_results(np.array([[[1000.0 + o]]])),
            "vcr",
            "m s-1",
            "Vcr",
            ("projectile", "obliquity", "yaw"),
        )
        return xr.Dataset(
            data,
            coords={
                **projectile_coords([p]),
                "obliquity": ("obliquity", [o]),
                "yaw": ("yaw", [0.0]),
            },
        )

    ds = gather("fig12", [part("p4", 60.0), part("p2", 60.0), part("p4", 30.0), part("p2", 30.0)])
    assert ds["vcr"].dims == ("projectile", "obliquity", "yaw")
    assert ds["projectile"].values.tolist() == ["p4", "p2"]
    assert ds["obliquity"].values.tolist() == [30.0, 60.0]
    assert ds["vcr"].sel(projectile="p2", obliquity=60.0).item() == 1060.0
    np.testing.assert_allclose(ds["lc_over_l"], [0.5708, 0.5246], atol=1e-3)
