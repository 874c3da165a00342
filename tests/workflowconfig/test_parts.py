"""pencore.workflowconfig.parts: the configuration's grids and ranges, and a split study's
job parts from its record."""

import numpy as np
import pytest

from pencore.errors import InputError
from pencore.workflowconfig.parts import grid, parts_of, round_robin, value_range, values
from pencore.workflowconfig.registry import STUDIES, split_studies


def test_grid_is_inclusive_and_rounded():
    np.testing.assert_allclose(grid(15, 75, 7.5), np.arange(15, 75.1, 7.5))
    assert grid(-4, 4, 1).tolist() == [-4, -3, -2, -1, 0, 1, 2, 3, 4]
    # 0.1 steps land on the decimal values, not on accumulated binary error
    assert grid(0.0, 0.3, 0.1).tolist() == [0.0, 0.1, 0.2, 0.3]
    for bad in ((1, 0, 1), (0, 1, 0), (0, float("nan"), 1)):
        with pytest.raises(InputError, match="grid needs"):
            grid(*bad)


def test_values_and_ranges():
    assert values([3, 1.5]) == [3.0, 1.5]
    assert values({"min": 1, "max": 2, "step": 0.5}) == [1.0, 1.5, 2.0]
    assert value_range({"min": 1, "max": 2}) == (1.0, 2.0)
    with pytest.raises(InputError, match="range needs min < max"):
        value_range({"min": 2, "max": 2})


@pytest.mark.parametrize("study", sorted(split_studies()))
def test_parts_follow_the_record(study):
    cfg = {"projectiles": ["p2", "p4"], "obliquity_deg": [30.0, 60.0]}
    parts = parts_of(study, cfg)
    if "obliquity" in split_studies()[study].split_by:
        assert parts == [
            {"projectile": p, "obliquity": o} for p in ("p2", "p4") for o in (30.0, 60.0)
        ]
    else:
        assert parts == [{"projectile": "p2"}, {"projectile": "p4"}]


def test_a_study_that_runs_whole_has_no_parts():
    whole = next(k for k in STUDIES if k not in split_studies())
    with pytest.raises(InputError, match="is not split into parts"):
        parts_of(whole, {"projectiles": ["p2"]})


def test_round_robin_deals_every_name_once_in_order():
    names = [f"s{i}" for i in range(7)]
    jobs = round_robin(names, 3)
    assert jobs == [["s0", "s3", "s6"], ["s1", "s4"], ["s2", "s5"]]
    assert sorted(n for job in jobs for n in job) == sorted(names)
    assert round_robin(names[:2], 5) == [["s0"], ["s1"]]  # no empty job
    assert round_robin(names, 1) == [names]


@pytest.mark.parametrize("bad", [0, -1, 1.5, True, "2"])
def test_round_robin_refuses_a_job_count_that_is_not_a_whole_number(bad):
    with pytest.raises(InputError, match="number of jobs must be a whole number >= 1"):
        round_robin(["a"], bad)
