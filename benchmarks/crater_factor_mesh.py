"""The crater factor at a shallow tip against the ring mesh.

With a crater region (:mod:`pencore.kernels.crater`) every element's DAFL stress is
scaled by ``lam = g(s) F_full / R_ref(z)``: Forrestal's linear crater force over the
DAFL's axial resistance of the same body in normal entry at tip depth ``z``. For a
pointed nose ``g`` is proportional to ``z`` and ``R_ref`` to about ``z^2`` at a shallow
tip, so ``lam`` grows like ``1/z``, and ``R_ref`` there comes from the few rings below the
face. This prints and writes ``lam`` in normal entry (crater load over the same state's
load without the crater) of the near-surface map's projectile into its aluminium, at tip
depths from 0.01 to 1 calibre, on the ring mesh scaled by 0.5, 1, 2 and 4.

Writes benchmarks/results/crater_factor_mesh.csv. Run: python benchmarks/crater_factor_mesh.py
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pandas as pd

import pencore
from pencore.inputs.library import get_projectile, get_target
from pencore.inputs.target import Target
from pencore.kernels.forces import default_model, model_loads
from pencore.run.initial import initial_state

OUT = Path(__file__).parent / "results" / "crater_factor_mesh.csv"
PROJECTILE = "al_ogive_var4340"
MEDIUM = "aluminium"
CRATER = 2.0  # calibres, as the map's option crater_2
SPEED = 500.0  # m/s
DEPTHS = (0.01, 0.03, 0.1, 0.3, 1.0)  # tip depth, calibres
FACTORS = (0.5, 1.0, 2.0, 4.0)


def axial_load(p, target: Target, z: float, n_nose: int, n_shank: int) -> float:
    """Body-frame axial load (N) of ``target`` on ``p`` in normal entry at ``SPEED`` with
    the tip ``z`` (m) below the face."""
    rings = p.rings(n_nose, n_shank, pencore.Numerics().n_face).as_array()
    mp = p.mass_properties()
    bounds, coef, fric = target.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc)
    y = initial_state(p, rings, SPEED, 0.0, 0.0, 0.0, None, 0.0, "cm")
    y[1] -= z
    eps = pencore.Numerics().eps
    return float(model_loads(y, rings, bounds, coef, fric, eps, 0, default_model())[0][0])


def main() -> None:
    p = get_projectile(PROJECTILE)
    medium = get_target(MEDIUM).layers[0].medium
    with_crater = Target.half_space(replace(medium, crater_depth=CRATER))
    without = Target.half_space(medium)
    default = pencore.Numerics()
    rows = []
    for zd in DEPTHS:
        for f in FACTORS:
            nn, ns = round(f * default.n_nose), round(f * default.n_shank)
            z = zd * p.diameter
            lam = axial_load(p, with_crater, z, nn, ns) / axial_load(p, without, z, nn, ns)
            rows.append({"tip_depth_calibres": zd, "mesh_factor": f, "n_nose": nn, "lam": lam})
    df = pd.DataFrame(rows)
    df.round(4).to_csv(OUT, index=False)
    print(df.pivot(index="tip_depth_calibres", columns="mesh_factor", values="lam").round(3))


if __name__ == "__main__":
    main()
