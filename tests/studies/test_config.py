"""pencore.studies.config: a study is run through its registry record, and bad requests
stop with one line before any run."""

import pytest

from pencore.errors import InputError
from pencore.studies.config import from_config
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
