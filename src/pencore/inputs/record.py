"""What the measured record says of a concrete law: a depth band from comparable shots.

A law's answer is worth what the law scored on shots like the one asked about. The
workflow's concrete-record study (:mod:`pencore.studies.validation.record`) runs every clean
shot of the public concrete compilation (``config/concrete_compilation.csv``) with every
concrete law pencore ships and keeps, per law and shot, the ratio ``r = measured /
predicted`` of the depths with the shot's diameter, strength, speed and nose. Those scores
ship with the package (``inputs/data/concrete_record.csv``, generated from the archived
study and checked against it by a test), with each law's calibration
(``inputs/data/concrete_record_bands.yaml``).

*Comparable* shots (:func:`comparable`) are the scored shots of the same law within
:data:`WINDOWS` of the query: a diameter and a strength within a factor, a striking speed
within a factor, a CRH within a margin. With at least :data:`MIN_SHOTS` of them the depth
band (:func:`depth_band`) is the predicted depth times the quantiles of their ratios at
the law's *nominal* level, chosen by the study so that the band holds
:data:`STATED_LEVEL` (80 %) of shots it was not built from: every shot's band made from
the comparable shots of the *other* sources (one source left out at a time), the smallest
nominal level whose bands held at least 80 % of the shots
(:func:`pencore.analysis.record.calibrate_level`). The band's record says the stated level,
the nominal level, the held-out coverage it reached, the number of shots and sources and
the ranges they span. With fewer comparable shots there is no band, and
:func:`depth_band` says so (the run warns).

The comparable shots are normal impacts into half-spaces: for an oblique or yawed run the
band is that of the same shot at normal incidence, and it says so.

Examples
--------
>>> import numpy as np
>>> s = Scores("demo", np.array(["a"] * 6 + ["b"] * 6), np.full(12, 0.02), np.full(12, 40e6),
...            np.full(12, 500.0), np.full(12, 3.0), np.linspace(0.8, 1.3, 12), 0.8, 0.8)
>>> b = depth_band(s, 1.0, diameter=0.025, fc=45e6, velocity=450.0, crh=3.0, min_shots=10)
>>> print(f"{b.lo:.3f} to {b.hi:.3f} m from {b.n_shots} shots of {b.n_sources} sources")
0.850 to 1.250 m from 12 shots of 2 sources
"""

from __future__ import annotations

import csv
import functools
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pencore.errors import InputError, hint_keywords
from pencore.inputs.gate import read_yaml

__all__ = [
    "STATED_LEVEL",
    "MIN_SHOTS",
    "WINDOWS",
    "RECORD_LAWS",
    "DEFAULT_RECORD_LAW",
    "RECORD_COLUMNS",
    "RECORD_FILE",
    "BANDS_FILE",
    "Scores",
    "DepthBand",
    "comparable",
    "band_factors",
    "depth_band",
    "read_scores",
    "record_laws",
    "scores_of",
]

#: The coverage a band states: the share of comparable shots it held, one source left out.
STATED_LEVEL = 0.8

#: Fewest comparable shots a band is made from.
MIN_SHOTS = 10

#: What makes a scored shot comparable with a query: the largest factor between the two
#: diameters, strengths (fc) and striking speeds, and the largest difference of CRH. Wide
#: enough that most clean shots have ten neighbours, narrow enough that the scale effect
#: (the error changes by about 10 % per doubling of the diameter above 60 mm) and the speed
#: trend stay inside a band.
WINDOWS = {"diameter": 2.0, "fc": 1.6, "velocity": 1.4, "crh": 1.5}

#: The concrete laws the record scores: name -> the options of
#: :func:`pencore.inputs.laws.concrete_law` (``S`` from ``fc`` by the named form).
RECORD_LAWS: dict[str, dict[str, str]] = {
    "forrestal": {"s_model": "forrestal", "crater": "none", "size_term": "none"},
    "forrestal_crater": {"s_model": "forrestal", "crater": "forrestal", "size_term": "none"},
    "li_chen": {"s_model": "li_chen", "crater": "li_chen", "size_term": "none"},
    "forrestal_size": {"s_model": "forrestal", "crater": "none", "size_term": "fit"},
    "forrestal_crater_size": {"s_model": "forrestal", "crater": "forrestal", "size_term": "fit"},
    "li_chen_size": {"s_model": "li_chen", "crater": "li_chen", "size_term": "fit"},
}

#: The law ``law: concrete`` gives by default (:func:`pencore.inputs.laws.concrete_law`
#: with ``s`` not given): the record law with the smallest median ``|e|`` on the sources no
#: law was fitted to (the archived ``concrete_record_stats.nc``'s ``best_law``; a test
#: checks the two agree).
DEFAULT_RECORD_LAW = "forrestal_size"

_DATA = Path(__file__).parent / "data"
#: The scored shots: one row per law and clean shot of the compilation.
RECORD_FILE = _DATA / "concrete_record.csv"
#: Each law's calibration: nominal level and held-out coverage.
BANDS_FILE = _DATA / "concrete_record_bands.yaml"

#: Columns of :data:`RECORD_FILE`.
RECORD_COLUMNS = ("law", "row", "source", "diameter_m", "fc_pa", "velocity_m_s", "crh", "ratio")


@dataclass(frozen=True)
class Scores:
    """One law's scored shots.

    Attributes
    ----------
    law : str
        The law's name in the record.
    source : ndarray of str
        Each shot's source (the compilation's reference key).
    diameter, fc, velocity, crh : ndarray of float
        Each shot's projectile diameter (m), target strength (Pa), striking speed (m/s)
        and nose CRH.
    ratio : ndarray of float
        Measured over predicted depth.
    nominal_level : float
        The quantile level whose bands held :data:`STATED_LEVEL` of held-out shots.
    held_out_coverage : float
        The share of shots their held-out band at ``nominal_level`` held.
    """

    law: str
    source: np.ndarray
    diameter: np.ndarray
    fc: np.ndarray
    velocity: np.ndarray
    crh: np.ndarray
    ratio: np.ndarray
    nominal_level: float
    held_out_coverage: float


@dataclass(frozen=True)
class DepthBand:
    """A depth band from comparable shots (see the module notes).

    Attributes
    ----------
    lo, hi : float
        The band (m): the predicted depth times the comparable shots' ratio quantiles.
    level : float
        The coverage the band states (:data:`STATED_LEVEL`).
    nominal_level : float
        The quantile level used (calibrated one source left out at a time).
    held_out_coverage : float
        The share of held-out shots such bands held for this law.
    n_shots, n_sources : int
        Comparable shots and their sources.
    ranges : dict
        ``{quantity: (min, max)}`` of the comparable shots: ``diameter`` (m), ``fc`` (Pa),
        ``velocity`` (m/s), ``crh``.
    law : str
        The law's name in the record.
    """

    lo: float
    hi: float
    level: float
    nominal_level: float
    held_out_coverage: float
    n_shots: int
    n_sources: int
    ranges: dict[str, tuple[float, float]]
    law: str

    def describe(self) -> str:
        """One line: the band, its coverage, the shots and their ranges."""
        r = self.ranges
        return (
            f"{self.lo:.4g} to {self.hi:.4g} m ({self.level:.0%} band of law {self.law!r}, "
            f"held {self.held_out_coverage:.0%} of shots of left-out sources; "
            f"{self.n_shots} comparable shots from {self.n_sources} sources: "
            f"d {r['diameter'][0] * 1e3:.3g}-{r['diameter'][1] * 1e3:.3g} mm, "
            f"fc {r['fc'][0] / 1e6:.3g}-{r['fc'][1] / 1e6:.3g} MPa, "
            f"V {r['velocity'][0]:.0f}-{r['velocity'][1]:.0f} m/s, "
            f"CRH {r['crh'][0]:.3g}-{r['crh'][1]:.3g})"
        )


def comparable(
    scores: Scores,
    diameter: float,
    fc: float,
    velocity: float,
    crh: float,
    windows: dict[str, float] | None = None,
) -> np.ndarray:
    """Which of a law's scored shots are comparable with a query (:data:`WINDOWS`).

    Parameters
    ----------
    scores : Scores
        The law's shots.
    diameter, fc, velocity : float
        The query's diameter (m), strength (Pa) and striking speed (m/s).
    crh : float
        The query's nose CRH (NaN: a nose that is no ogive, which no shot matches).
    windows : dict, optional
        Overrides of :data:`WINDOWS`.

    Returns
    -------
    ndarray of bool
        One entry per shot.
    """
    w = {**WINDOWS, **(windows or {})}

    def within(x: np.ndarray, q: float, factor: float) -> np.ndarray:
        return np.abs(np.log(x / q)) <= math.log(factor) * (1 + 1e-12)

    return (
        within(scores.diameter, diameter, w["diameter"])
        & within(scores.fc, fc, w["fc"])
        & within(scores.velocity, velocity, w["velocity"])
        & (np.abs(scores.crh - crh) <= w["crh"] * (1 + 1e-12))
    )


def band_factors(ratios: np.ndarray, level: float) -> tuple[float, float]:
    """The central ``level`` quantile interval of ``ratios`` (numpy's linear quantiles;
    ``level`` 1 gives the smallest and largest)."""
    r = np.asarray(ratios, dtype=float)
    lo, hi = np.quantile(r, [(1 - level) / 2, (1 + level) / 2])
    return float(lo), float(hi)


def depth_band(
    scores: Scores,
    depth: float,
    *,
    diameter: float,
    fc: float,
    velocity: float,
    crh: float,
    min_shots: int = MIN_SHOTS,
) -> DepthBand | None:
    """The depth band of a predicted ``depth`` (m) from the law's comparable shots.

    Returns
    -------
    DepthBand or None
        None where fewer than ``min_shots`` scored shots are comparable.
    """
    m = comparable(scores, diameter, fc, velocity, crh)
    n = int(m.sum())
    if n < min_shots:
        return None
    lo, hi = band_factors(scores.ratio[m], scores.nominal_level)

    def span(x: np.ndarray) -> tuple[float, float]:
        return float(x[m].min()), float(x[m].max())

    return DepthBand(
        lo=lo * depth,
        hi=hi * depth,
        level=STATED_LEVEL,
        nominal_level=scores.nominal_level,
        held_out_coverage=scores.held_out_coverage,
        n_shots=n,
        n_sources=len(set(scores.source[m].tolist())),
        ranges={
            "diameter": span(scores.diameter),
            "fc": span(scores.fc),
            "velocity": span(scores.velocity),
            "crh": span(scores.crh),
        },
        law=scores.law,
    )


def read_scores(path: Path | str = RECORD_FILE, bands: Path | str = BANDS_FILE) -> dict:
    """Every law's :class:`Scores` from the shipped record and its calibration.

    Returns
    -------
    dict
        ``{law: Scores}``; empty when the record is not shipped.

    Raises
    ------
    InputError
        A record whose columns, numbers or laws do not match its calibration file.
    """
    path, bands = Path(path), Path(bands)
    if not path.is_file():
        return {}
    with path.open(newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows or tuple(rows[0]) != RECORD_COLUMNS:
        raise InputError(f"{path}: columns must be {', '.join(RECORD_COLUMNS)}")
    cal = read_yaml(bands, "concrete record bands")
    if not isinstance(cal, dict) or not isinstance(cal.get("laws"), dict):
        raise InputError(f"{bands}: needs a mapping 'laws: {{law: {{nominal_level, ...}}}}'")
    out = {}
    for law in dict.fromkeys(r["law"] for r in rows):
        if law not in cal["laws"]:
            raise InputError(f"{bands}: no calibration of law {law!r} of {path.name}")
        sel = [r for r in rows if r["law"] == law]
        try:

            def col(k: str, sel: list = sel) -> np.ndarray:
                return np.array([float(r[k]) for r in sel])

            c = cal["laws"][law]
            out[law] = Scores(
                law=law,
                source=np.array([r["source"] for r in sel]),
                diameter=col("diameter_m"),
                fc=col("fc_pa"),
                velocity=col("velocity_m_s"),
                crh=col("crh"),
                ratio=col("ratio"),
                nominal_level=float(c["nominal_level"]),
                held_out_coverage=float(c["held_out_coverage"]),
            )
        except (KeyError, TypeError, ValueError) as err:
            raise InputError(f"{path}: law {law!r}: a value is not a number ({err})") from None
    return out


@functools.cache
def _shipped() -> dict:
    return read_scores()


def record_laws() -> tuple[str, ...]:
    """The laws the shipped record scores."""
    return tuple(_shipped())


def scores_of(law: str) -> Scores | None:
    """The shipped record of one law (None: the record does not score it)."""
    return _shipped().get(law)


hint_keywords(globals())  # a misspelt keyword of a public function: one line with a hint
