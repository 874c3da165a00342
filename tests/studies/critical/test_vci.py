"""pencore.studies.critical.vci: Vci on (projectile, yaw, threshold): a larger deviation
threshold needs a faster impact; the primary threshold is one of the thresholds."""

import numpy as np
import pytest

from pencore.errors import InputError
from pencore.studies.critical.vci import vci_study


def test_vci_rises_with_the_threshold():
    ds = vci_study(["p4"], [1.0], [2.0, 5.0], lo=100.0, hi=2000.0, tol=100.0, scan=None)
    assert ds["vci"].dims == ("projectile", "yaw", "threshold")
    assert ds["vci"].attrs["units"] == "m s-1" and ds["threshold"].attrs["units"] == "degree"
    assert (ds["status"] == "ok").all()
    vci = ds["vci"].sel(projectile="p4", yaw=1.0).values
    assert np.all(np.diff(vci) > 0), vci
    assert ds.attrs["primary_threshold_deg"] == 2.0  # the middle (lower) of the two


def test_the_primary_threshold_must_be_one_of_them():
    with pytest.raises(InputError, match="primary threshold 3.0 is not one of"):
        vci_study(["p4"], [1.0], [2.0, 5.0], primary_threshold=3.0)
