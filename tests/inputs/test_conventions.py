"""pencore.inputs.conventions: the two readings of an obliquity and a yaw as simulate's
arguments."""

import pytest

from pencore.errors import InputError
from pencore.inputs.conventions import YAW_CONVENTIONS, impact_angles, normal_impact_angles


@pytest.mark.parametrize("convention", YAW_CONVENTIONS)
def test_at_zero_obliquity_it_is_the_normal_impact_with_yaw(convention):
    for yaw in (-3.0, 0.1, 7.5):
        assert impact_angles(0.0, yaw, convention) == normal_impact_angles(yaw, convention)


def test_axis_tilted_keeps_the_velocity_and_tilts_the_axis():
    """simulate's velocity angle is obliquity + yaw: the line of fire stays at the given
    obliquity; the axis is at obliquity + angle of attack."""
    obl, yaw = impact_angles(20.0, 4.0, "axis_tilted")
    assert (obl, yaw) == (24.0, -4.0) and obl + yaw == 20.0
    assert impact_angles(20.0, 4.0, "velocity_tilted") == (20.0, 4.0)


def test_an_unknown_reading_is_one_line():
    with pytest.raises(InputError, match="one of axis_tilted, velocity_tilted, got 'axis'"):
        impact_angles(0.0, 1.0, "axis")
