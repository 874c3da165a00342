"""The near-surface ballistic-limit map against the ring mesh: which cells are converged.

The workflow's map (config block ``near_surface``, rule ``near_surface_part``) runs every
search on the default ring mesh (``n_nose``, ``n_shank`` of :class:`pencore.Numerics`).
This runs the same map, with the same searches (range, tolerance, scan), on the mesh
scaled by each factor given (default 0.5 and 2: half and twice the rings) and writes
benchmarks/results/near_surface_mesh.csv: one row per option set, thickness and
obliquity, with ``v_bl`` (m/s) and ``status`` on each mesh, the default one included
(factor 1, run here too, so that the file stands on its own).

A cell counts as converged in the mesh when its ``v_bl`` on twice the rings is within the
search's tolerance of the default's (:func:`pencore.studies.perforation.mesh_check.mesh_check`,
the rule the workflow's own check, rule ``near_surface_mesh``, applies and archives; the
docs' map marks the others from the archive); ``reason`` says why for the others.
Run (about 10 min on one core): python benchmarks/near_surface_mesh.py [--factors 0.5 1 2]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import pandas as pd
import xarray as xr
import yaml

from pencore.studies.perforation.mesh_check import finer_rings, mesh_check
from pencore.studies.perforation.obliquity import ballistic_map

HERE = Path(__file__).parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

OUT = HERE / "results" / "near_surface_mesh.csv"


def mesh_map(study: dict, factor: float) -> xr.Dataset:
    """The map of ``study`` (the config's ``near_surface`` block) on the ring mesh scaled
    by ``factor``."""
    numerics = finer_rings(None, factor)
    return ballistic_map(
        study["projectile"],
        study["medium"],
        study["t_over_d"],
        study["obliquity_deg"],
        {k: dict(v) for k, v in study["options"].items()},
        lo=study["search_m_s"]["min"],
        hi=study["search_m_s"]["max"],
        tol=study["velocity_tol_m_s"],
        scan=study["scan_points"],
        numerics=numerics,
    )


def as_table(ds: xr.Dataset) -> pd.DataFrame:
    """option, t_over_d, obliquity, v_bl (m/s), status of a map."""
    df = ds[["v_bl", "status"]].to_dataframe().reset_index()
    return df[["option", "t_over_d", "obliquity", "v_bl", "status"]]


def label(factor: float) -> str:
    """The column suffix of a mesh factor: ``mesh1``, ``mesh2``, ``mesh0p5``."""
    return f"mesh{factor:g}".replace(".", "p")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--factors", type=float, nargs="+", default=[0.5, 1.0, 2.0])
    ap.add_argument("--csv", default=str(OUT))
    args = ap.parse_args()
    if not {1.0, 2.0} <= set(args.factors):
        raise SystemExit("near_surface_mesh: --factors must include 1 and 2 (the verdict)")
    study = yaml.safe_load((REPO / "config" / "config.yaml").read_text())["near_surface"]
    table = None
    maps = {}
    keys = ["option", "t_over_d", "obliquity"]
    for f in args.factors:
        t0 = time.perf_counter()
        maps[f] = mesh_map(study, f)
        print(f"mesh x{f:g}: {time.perf_counter() - t0:.1f} s", flush=True)
        df = as_table(maps[f])
        df = df.rename(columns={"v_bl": f"v_bl_{label(f)}", "status": f"status_{label(f)}"})
        table = df if table is None else table.merge(df, on=keys)
    check = mesh_check(maps[1.0], maps[2.0], 2.0)
    verdict = check[["converged", "reason"]].to_dataframe().reset_index()
    table = table.merge(verdict, on=keys)
    table["converged"] = table["converged"].astype(bool)
    m = machine()
    table["tol_m_s"] = float(study["velocity_tol_m_s"])
    table["commit"] = m["commit"]
    table["measured_utc"] = m["measured_utc"]
    table.round(3).to_csv(args.csv, index=False)
    bad = table[~table["converged"]]
    print(f"{len(bad)} of {len(table)} cells not converged in the mesh:")
    print(bad.drop(columns=["commit", "measured_utc"]).to_string(index=False))


if __name__ == "__main__":
    main()
