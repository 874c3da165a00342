"""The paper's claims as data: every number and trend of Li & Flores-Johnson (2011) that
pencore computes, read from ``paper_claims.csv``, shipped with the package
(``pencore/paper/data/``; the repository's ``config/paper_claims.csv`` is a link to it, so
the workflow and an installed wheel read the one file).

One row per claim: ``id, kind, value, value_hi, units, at, where, provenance, study,
computed_by, note`` (the file's header explains each). The paper comparison table
(:func:`pencore.studies.comparison.paper_comparison`) makes its rows from these claims,
and :func:`paper_values` and :func:`disputed_values` key them as the studies use them, so
each of the paper's numbers is written once, in the file, with where in the paper it is
stated.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from pencore.errors import InputError
from pencore.paper.tables import read_csv

__all__ = [
    "DATA_DIR",
    "CLAIMS_FILE",
    "TABLE2_FILE",
    "KINDS",
    "load_claims",
    "claim",
    "at",
    "paper_values",
    "disputed_values",
]

#: The package's data: the paper's claims and tables (``config/`` of the repository links
#: its files here).
DATA_DIR = Path(__file__).resolve().parent / "data"
#: Default claims file, shipped with the package (environment variable
#: ``PENCORE_PAPER_CLAIMS`` overrides it).
CLAIMS_FILE = DATA_DIR / "paper_claims.csv"
#: The paper's Table 2 (shipped with the package; ``config/table2.csv`` of the repository):
#: the soil tests with the paper's predicted depths.
TABLE2_FILE = DATA_DIR / "table2.csv"
KINDS = ("value", "bracket", "verdict", "trend")
COLUMNS = (
    "id",
    "kind",
    "value",
    "value_hi",
    "units",
    "at",
    "where",
    "provenance",
    "study",
    "computed_by",
    "note",
)


def _path(path: str | os.PathLike | None) -> Path:
    if path is not None:
        return Path(path)
    return Path(os.environ.get("PENCORE_PAPER_CLAIMS", CLAIMS_FILE))


def at(text: Any) -> list[dict[str, float | str]]:
    """The ``at`` field as a list of condition dicts (``;`` separates ``key=value``
    pairs; a repeated key starts a new condition: ``velocity=1641;velocity=1650``)."""
    out: list[dict[str, float | str]] = []
    if not isinstance(text, str) or not text.strip():
        return [{}]
    cur: dict[str, float | str] = {}
    for part in text.split(";"):
        if "=" not in part:
            raise InputError(f"paper claims: 'at' entry {part!r} is not key=value")
        k, v = (s.strip() for s in part.split("=", 1))
        if k in cur:
            out.append(cur)
            cur = {}
        try:
            cur[k] = float(v)
        except ValueError:
            cur[k] = v
    out.append(cur)
    return out


@functools.lru_cache(maxsize=8)
def _load(path: Path, mtime: float) -> pd.DataFrame:
    df = read_csv(path, "paper claims", comment="#", dtype=str, keep_default_na=False)
    missing = [c for c in COLUMNS if c not in df.columns]
    if missing:
        raise InputError(f"paper claims: {path} lacks column(s) {missing}")
    if df.empty:
        raise InputError(f"paper claims: {path} has no claims")
    dup = df["id"][df["id"].duplicated()].tolist()
    if dup:
        raise InputError(f"paper claims: duplicate id(s) {dup} in {path}")
    for _, r in df.iterrows():
        where = f"paper claims: claim {r['id']!r}"
        if r["kind"] not in KINDS:
            raise InputError(f"{where}: kind must be one of {', '.join(KINDS)}, got {r['kind']!r}")
        if r["provenance"] not in ("paper", "derived"):
            raise InputError(f"{where}: provenance must be paper or derived")
        if not r["where"] or not r["computed_by"] or not r["study"]:
            raise InputError(f"{where}: where, study and computed_by are required")
        nums = [r["value"]] + ([r["value_hi"]] if r["kind"] == "bracket" else [])
        if r["kind"] in ("value", "bracket") and r["computed_by"] != "table2_rows":
            for v in nums:
                try:
                    float(v)
                except ValueError:
                    raise InputError(f"{where}: value {v!r} is not a number") from None
        if r["kind"] == "bracket" and not float(r["value"]) < float(r["value_hi"]):
            raise InputError(f"{where}: a bracket needs value < value_hi")
        if r["kind"] == "trend" and r["value"] not in ("rises", "falls"):
            raise InputError(f"{where}: a trend is rises or falls, got {r['value']!r}")
        at(r["at"])
    return df


def load_claims(path: str | os.PathLike | None = None) -> pd.DataFrame:
    """The claims file as a DataFrame of strings (checked; cached until the file changes).

    Raises
    ------
    InputError
        An unreadable file, a missing column, a duplicate id, an unknown kind, a number
        that is not one, a bracket with value >= value_hi, or a bad ``at`` entry.
    """
    p = _path(path)
    if not p.is_file():
        raise InputError(f"paper claims: no file {str(p)!r} (set PENCORE_PAPER_CLAIMS to its path)")
    return _load(p.resolve(), p.stat().st_mtime)


def claim(claim_id: str, claims: pd.DataFrame | None = None) -> Mapping[str, Any]:
    """One claim (a row of :func:`load_claims`) by its id."""
    df = load_claims() if claims is None else claims
    rows = df[df["id"] == claim_id]
    if rows.empty:
        raise InputError(f"paper claims: no claim {claim_id!r}")
    return rows.iloc[0].to_dict()


def _f(c: Mapping[str, Any]) -> float:
    return float(c["value"])


def paper_values(claims: pd.DataFrame | None = None) -> dict[str, Any]:
    """The paper's numbers keyed as the studies use them (the old in-code ``PAPER``).

    Keys: ``fig7_reverses`` {velocity: bool}, ``fig7_x_linear_m``, ``vcr_p2_45_bracket``
    (lo, hi), ``fig13_phi_deg`` {velocity: deg}, ``fig13_large_at`` (m/s),
    ``fig16_alpha_deg`` {omega: deg}, ``fig16_reverses_at`` (rad/s),
    ``omega_c_p2_1000_bracket`` (lo, hi), ``table3`` {projectile: (mass kg, Lc/L)}.
    """
    df = load_claims() if claims is None else claims
    by = {cb: df[df["computed_by"] == cb].to_dict("records") for cb in df["computed_by"].unique()}

    def one(cb: str) -> Mapping[str, Any]:
        if not by.get(cb):
            raise InputError(f"paper claims: no claim computed_by {cb!r}")
        return by[cb][0]

    def keyed(cb: str, key: str) -> dict[float, Any]:
        return {float(at(c["at"])[0][key]): c for c in by.get(cb, [])}

    vcr, om = one("vcr_p2_45"), one("omega_c_p2")
    mass = {at(c["at"])[0]["projectile"]: _f(c) for c in by.get("table3_mass", [])}
    lc = {at(c["at"])[0]["projectile"]: _f(c) for c in by.get("table3_lc", [])}
    reverses = keyed("fig7_reverses", "velocity")
    return {
        "fig7_reverses": {v: c["value"] == "yes" for v, c in reverses.items()},
        "fig7_x_linear_m": _f(one("fig7_x_linear")),
        "vcr_p2_45_bracket": (float(vcr["value"]), float(vcr["value_hi"])),
        "fig13_phi_deg": {v: _f(c) for v, c in keyed("fig13_phi", "velocity").items()},
        "fig13_large_at": float(at(one("fig13_large")["at"])[0]["velocity"]),
        "fig16_alpha_deg": {w: _f(c) for w, c in keyed("fig16_alpha", "omega").items()},
        "fig16_reverses_at": float(at(one("fig16_reverses")["at"])[0]["omega"]),
        "omega_c_p2_1000_bracket": (float(om["value"]), float(om["value_hi"])),
        "table3": {p: (mass[p], lc[p]) for p in mass},
    }


def disputed_values(claims: pd.DataFrame | None = None) -> dict[str, Any]:
    """The paper's values of the quantities the attribution study disputes
    (:func:`pencore.studies.attribution.disputed.disputed_quantities`), from the claims and, for the
    Table 2 depth, :data:`TABLE2_FILE`.

    Keys: ``alpha`` {omega rad/s: deg} (Sect. 4.3 text on Figs 16-17), ``turned_back``
    {omega rad/s: True} ("moves back to the surface"), ``vcr_bracket`` (lo, hi) m/s
    (Fig. 7 text: 1641 no, 1650 yes), ``depth_280`` (m, Table 2 test 2), ``phi_p4``
    {velocity m/s: deg} (Sect. 4.3 text on Figs 13-14), ``fig12_vcr_yaw`` (the Fig. 12
    trend, "falls").
    """
    pv = paper_values(claims)
    t2 = pd.read_csv(TABLE2_FILE, comment="#").set_index("test")
    return {
        "alpha": dict(pv["fig16_alpha_deg"]),
        "turned_back": {pv["fig16_reverses_at"]: True},
        "vcr_bracket": pv["vcr_p2_45_bracket"],
        "depth_280": float(t2.loc[2, "paper_predicted_depth_m"]),
        "phi_p4": dict(pv["fig13_phi_deg"]),
        "fig12_vcr_yaw": claim("fig12_vcr_yaw", claims)["value"],
    }
