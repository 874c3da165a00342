"""pencore.studies.config: every Section 4 study has one entry in the registry, and bad
requests stop with one line before any run."""

import pytest

from pencore.errors import InputError
from pencore.studies.config import REGISTRY, from_config
from pencore.studies.parts import SPLIT_STUDIES, STUDIES


def test_every_study_has_exactly_one_registry_entry():
    assert set(REGISTRY) == set(STUDIES)


def test_unknown_study_names_the_known_ones():
    with pytest.raises(InputError, match="unknown Section 4 study 'fig99'; known: fig7"):
        from_config("fig99", {}, {})


@pytest.mark.parametrize("study", sorted(SPLIT_STUDIES))
def test_split_study_needs_its_part(study):
    with pytest.raises(InputError, match="runs per projectile"):
        from_config(study, {}, {})


def test_fig12_needs_an_obliquity():
    with pytest.raises(InputError, match="give obliquity="):
        from_config("fig12", {"velocity_range_m_s": {"min": 1, "max": 2}}, {}, projectile="p2")
