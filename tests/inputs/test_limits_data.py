"""The ranges are data: ``inputs/data/limits.yaml`` (one entry a quantity) is what the
number gate applies and what the docs' tables show. Each entry's valid range is checked
at both its bounds through :func:`~pencore.inputs.limits.number` (or ``integer``), each
plausible range by the warning a value just outside it gives; a malformed file is
refused naming the entry."""

from __future__ import annotations

import math
import shutil
import warnings

import pytest

from pencore.errors import InputError, PlausibilityWarning
from pencore.inputs import limits
from pencore.inputs.limits import LIMITS, LIMITS_FILE, PLAUSIBLE, integer, load_limits, number


def _quiet(call):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)
        return call()


def _beyond(x: float, up: bool) -> float:
    if isinstance(x, int):
        return x + 1 if up else x - 1
    return math.nextafter(x, math.inf if up else -math.inf)


@pytest.mark.parametrize("key", list(LIMITS))
def test_each_valid_range_of_the_file_is_the_gates(key):
    """A bound is admitted exactly when the file's interval closes it, the value just
    beyond it is refused, and the refusal is the file's words: label, interval, unit."""
    lim = LIMITS[key]
    check = integer if isinstance(lim.lo, int) and isinstance(lim.hi, int) else number
    for bound, is_open, up in ((lim.lo, lim.lo_open, False), (lim.hi, lim.hi_open, True)):
        if math.isinf(bound):
            if bound > 0:  # an infinite upper bound admits inf
                assert _quiet(lambda b=bound: check(b, key)) == bound
            continue
        if is_open:
            with pytest.raises(InputError, match="must be in"):
                _quiet(lambda b=bound: check(b, key))
        else:
            assert _quiet(lambda b=bound: check(b, key)) == bound
        with pytest.raises(InputError) as info:
            _quiet(lambda b=bound, u=up: check(_beyond(b, u), key))
        assert f"{lim.label} must be {lim.describe()}" in str(info.value)
        if lim.unit and lim.unit != "SI":
            assert lim.describe().endswith(f" {lim.unit}")


RANGES = [k for k, p in PLAUSIBLE.items() if p.rule == "range"]


@pytest.mark.parametrize("key", RANGES)
def test_each_plausible_range_of_the_file_warns_with_its_slip(key):
    p = PLAUSIBLE[key]
    inside = [x for x in (p.lo, p.hi) if x > 0 and math.isfinite(x)]
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        for x in inside:
            assert limits.plausible(x, key)
    for x, slip in ((0.5 * p.lo, p.below), (2.0 * p.hi, p.above)):
        if x == 0.0 or not math.isfinite(x):
            continue
        with pytest.warns(PlausibilityWarning) as record:
            assert not limits.plausible(x, key)
        text = str(record[0].message)
        assert f"{p.label} {x:g}" in text and p.describe() in text
        assert slip in text


@pytest.mark.parametrize("key", [k for k, p in PLAUSIBLE.items() if p.rule == "radians"])
def test_each_angle_in_radians_warns(key):
    with pytest.warns(PlausibilityWarning, match=r"radians\? \(30.0 deg"):
        limits.plausible(math.radians(30.0), key)


def test_the_loaded_table_is_the_files_and_feeds_the_docs():
    assert load_limits(LIMITS_FILE) == (LIMITS, PLAUSIBLE)
    core = limits.limits_markdown("core").splitlines()
    models = limits.limits_markdown("models").splitlines()
    assert len(core) - 2 + len(models) - 2 == len(LIMITS)
    for key, lim in LIMITS.items():
        assert f"| `{key}` | {lim.describe()[3:]} | {lim.kind} | {lim.why} |" in (core + models)
    assert len(limits.plausible_markdown().splitlines()) == len(PLAUSIBLE) + 2
    assert LIMITS_FILE.parent.name == "data" and LIMITS_FILE.suffix == ".yaml"


def test_an_edited_file_changes_the_gate(tmp_path):
    """The ranges come from the file, not from code: an edited copy gives other ranges."""
    edited = tmp_path / "limits.yaml"
    text = LIMITS_FILE.read_text().replace('valid: "(0.0, 10000.0]"', 'valid: "(0.0, 20000.0]"', 1)
    edited.write_text(text)
    new, _ = load_limits(edited)
    assert new["velocity"].hi == 20000.0 and LIMITS["velocity"].hi == 10000.0


@pytest.mark.parametrize(
    ("old", "new", "words"),
    [
        ('valid: "(0.0, 10000.0]"', 'valid: "0 to 1e4"', "must be an interval"),
        ('valid: "(0.0, 10000.0]"', 'valid: "(10000.0, 0.0]"', "is empty"),
        ('valid: "(0.0, 10000.0]"', 'valid: "(0.0, 1_0]"', "bound must be a number"),
        ("  kind: physical / guard\n", "  knd: physical / guard\n", "did you mean 'kind'"),
        ('label: "velocity"', "label: 5", "label must be text"),
    ],
)
def test_a_malformed_file_is_refused_naming_the_entry(tmp_path, old, new, words):
    bad = tmp_path / "limits.yaml"
    shutil.copyfile(LIMITS_FILE, bad)
    bad.write_text(bad.read_text().replace(old, new, 1))
    with pytest.raises(InputError, match=words) as info:
        load_limits(bad)
    assert "limits.yaml" in str(info.value) and "\n" not in str(info.value)
