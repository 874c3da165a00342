"""pencore.studies.critical.vcr: Vcr on (projectile, obliquity, yaw) is a real bracket of
the turn-back (re-simulated on both sides), within the tolerance, with units."""

import pytest

import pencore
from pencore.errors import InputError
from pencore.studies.critical.vcr import vcr_obliquity_study, vcr_study

START = (-1.0, 1.0, 0.0)


def test_vcr_brackets_the_turn_back_of_p2_at_45_deg():
    ds = vcr_study(["p2"], [45.0], target="soil", lo=1000.0, hi=2500.0, tol=50.0, scan=None)
    cell = ds.sel(projectile="p2", obliquity=45.0, yaw=0.0)
    assert ds["vcr"].dims == ("projectile", "obliquity", "yaw")
    assert ds["vcr"].attrs["units"] == "m s-1" and ds["obliquity"].attrs["units"] == "degree"
    assert str(cell["status"].values) == "ok"
    lo, hi = float(cell["vcr_lo"]), float(cell["vcr_hi"])
    assert 0 < hi - lo <= 50.0  # the search's tolerance
    assert float(cell["vcr"]) == pytest.approx((lo + hi) / 2)
    runs = [pencore.simulate("p2", "soil", v, 45.0, start=START, stop_at_reversal=True)
            for v in (lo, hi)]  # fmt: skip
    assert [r.attrs["reversed"] for r in runs] == [0, 1]


def test_fig8_is_at_zero_yaw():
    with pytest.raises(InputError, match="vcr_obliquity_study is at zero yaw"):
        vcr_obliquity_study(["p2"], [45.0], yaws=(1.0,))
