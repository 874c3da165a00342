"""The concrete record's prose (measurements page, user guide) types the constants of
pencore.inputs.record and the compilation's bound as the code holds them."""

from __future__ import annotations

from pathlib import Path

from pencore.inputs.record import MIN_SHOTS, STATED_LEVEL, WINDOWS
from pencore.measured.compilation import ERODING_SPEED_M_S

DOCS = Path(__file__).resolve().parents[2] / "docs"


def test_the_pages_type_the_windows_the_code_uses():
    windows = (
        f"within a factor {WINDOWS['diameter']:g} of the diameter, {WINDOWS['fc']:g}\n"
        f"of `fc` and {WINDOWS['velocity']:g} of the speed, CRH within {WINDOWS['crh']:g}; "
        f"at least {MIN_SHOTS} shots"
    )
    page = (DOCS / "results" / "measurements.md").read_text()
    assert windows in page
    assert f"held {100 * STATED_LEVEL:.0f} % of the shots" in page
    assert f"provisional bound of {ERODING_SPEED_M_S:g} m/s" in page
    guide = " ".join((DOCS / "user-guide" / "own-projectile-and-target.md").read_text().split())
    assert (
        f"within a factor {WINDOWS['diameter']:g} of its diameter, {WINDOWS['fc']:g} of its "
        f"`fc` and {WINDOWS['velocity']:g} of its striking speed, with a CRH within "
        f"{WINDOWS['crh']:g}. From at least {MIN_SHOTS} of them"
    ) in guide
    assert f"held {100 * STATED_LEVEL:.0f} % of the shots of sources left out" in guide
