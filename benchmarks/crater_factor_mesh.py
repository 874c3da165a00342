"""The crater factor at a shallow tip against the ring mesh.

With a crater region (:mod:`pencore.kernels.crater`) each element's DAFL stress is
multiplied by the factor of the normal-entry state that puts it at its own depth,
``g(z_e / k d) F_full / R_q(z_e)``, with ``F_full`` the exact nose's and ``R_q`` the rings'
own quadrature of the normal-entry resistance. This prints and writes, in normal entry
of the near-surface map's projectile into its aluminium at tip depths from 0.001 to 1
calibre, on the ring mesh scaled by 0.5, 1, 2 and 4:

* ``load_over_cz``: the crater load over Forrestal's ``c z`` (1 on every mesh);
* ``lam``: the crater load over the exact profile's resistance at the same depth
  (:func:`pencore.kernels.crater.nose_resistance`), the factor Forrestal's law puts on
  the DAFL: the same on every mesh;
* ``lam_rings``: the crater load over the rings' own load (the multiplier on each ring):
  it carries the rings' error at the tip, which the multiplier cancels, and it applies
  only to elements that are themselves that shallow (it applied to the whole body at the
  tip's depth before: 4.4 / 8.6 / 17.1 / 23.2 at 0.01 calibre on these meshes).

Writes benchmarks/results/crater_factor_mesh.csv. Run: python benchmarks/crater_factor_mesh.py
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import pandas as pd

import pencore
from pencore.inputs.library import get_projectile, get_target
from pencore.inputs.target import Target
from pencore.kernels.crater import crater_shape, nose_resistance
from pencore.kernels.dynamics import quat_to_matrix
from pencore.kernels.forces import default_model, model_loads
from pencore.run.initial import initial_state

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

OUT = HERE / "results" / "crater_factor_mesh.csv"
PROJECTILE = "al_ogive_var4340"
MEDIUM = "aluminium"
CRATER = 2.0  # calibres, as the map's option crater_2
SPEED = 500.0  # m/s
DEPTHS = (0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0)  # tip depth, calibres
FACTORS = (0.5, 1.0, 2.0, 4.0)


def axial_load(p, target: Target, z: float, n_nose: int, n_shank: int) -> float:
    """Body-frame axial load (N) of ``target`` on ``p`` in normal entry at ``SPEED`` with
    the nose tip ``z`` (m) below the face."""
    rings = p.rings(n_nose, n_shank, pencore.Numerics().n_face).as_array()
    mp = p.mass_properties()
    bounds, coef, fric = target.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc, p.nose)
    y = initial_state(p, rings, SPEED, 0.0, 0.0, 0.0, None, 0.0, "cm")
    y[1] -= y[1] + quat_to_matrix(y[3:7])[1, 0] * mp.lc + z  # the tip z below the face
    eps = pencore.Numerics().eps
    return float(model_loads(y, rings, bounds, coef, fric, eps, 0, default_model())[0][0])


def main() -> None:
    p = get_projectile(PROJECTILE)
    medium = get_target(MEDIUM).layers[0].medium
    with_crater = Target.half_space(replace(medium, crater_depth=CRATER))
    without = Target.half_space(medium)
    mp = p.mass_properties()
    bounds, coef, _ = with_crater.kernel_arrays(p.diameter, mp.mass, p.nose_length, mp.lc, p.nose)
    a, a0, a2 = p.radius, medium.coefficients[0], medium.coefficients[2]
    kd = CRATER * p.diameter
    beta = 3.141592653589793 * a * a * p.nose_factor() * a2 * kd / mp.mass
    full = 3.141592653589793 * a * a * (a0 + p.nose_factor() * a2 * SPEED**2)
    default = pencore.Numerics()
    rows = []
    for zd in DEPTHS:
        z = zd * p.diameter
        exact = nose_resistance(z, SPEED, bounds, coef, 0)
        cz = crater_shape(z / kd, beta) * full
        for f in FACTORS:
            nn, ns = round(f * default.n_nose), round(f * default.n_shank)
            crater = -axial_load(p, with_crater, z, nn, ns)
            plain = -axial_load(p, without, z, nn, ns)
            rows.append(
                {
                    "tip_depth_calibres": zd,
                    "mesh_factor": f,
                    "n_nose": nn,
                    "load_over_cz": crater / cz,
                    "lam": crater / exact,
                    "lam_rings": crater / plain,
                }
            )
    df = pd.DataFrame(rows)
    m = machine()
    df["commit"] = m["commit"]
    df["measured_utc"] = m["measured_utc"]
    df.to_csv(OUT, index=False, float_format="%.10g")
    for col in ("load_over_cz", "lam", "lam_rings"):
        print(col)
        print(df.pivot(index="tip_depth_calibres", columns="mesh_factor", values=col).round(6))


if __name__ == "__main__":
    main()
