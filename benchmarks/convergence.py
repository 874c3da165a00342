"""Convergence study that chose pencore's default numerics.

Each numerical parameter is varied alone around the defaults (pencore.Numerics) and the
reported quantities are recomputed:

* depth_280      normal-impact depth of p2 at 280 m/s (m), also against the exact 1-D
                 reference (pencore.closedform.depth);
* path_45_1000   tip path length of p2 at 45 deg, 1000 m/s (m);
* turn_45_1000   total turning angle d(theta)_12 of that run (deg, Eq. 12);
* dev_p4_1000    final deviation of p4, axis tilted 0.1 deg, 1000 m/s (deg, Fig. 13);
* vcr_p2_45      critical reverse velocity of p2 at 45 deg from (-1, 1) m (m/s, 1 m/s
                 bisection tolerance, Fig. 7).

Writes benchmarks/results/convergence.csv and prints the table with, for each
quantity, the change from the default run. Run: python benchmarks/convergence.py
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

import pandas as pd

import pencore
from pencore import analysis, closedform
from pencore.inputs.library import MEDIA, get_projectile
from pencore.run.impact import prepare
from pencore.search import critical

DEFAULT = pencore.Numerics()
SWEEPS: dict[str, list] = {
    "mesh_factor": [0.5, 1, 2, 4],
    "rtol": [1e-4, 1e-5, 1e-6, 1e-7],
    "max_travel": [0.25, 0.1, 0.05, 0.02],
    "eps": [1e-2, 1e-3, 1e-4],
}


def quantities(num: pencore.Numerics) -> dict[str, float]:
    p2 = prepare("p2", "soil", num)
    p4 = prepare("p4", "soil", num)
    d = pencore.simulate("p2", "soil", 280.0, prepared=p2)
    o = pencore.simulate("p2", "soil", 1000.0, obliquity=45.0, prepared=p2)
    y = pencore.simulate("p4", "soil", 1000.0, obliquity=0.1, yaw=-0.1, prepared=p4)
    v = critical.vcr(
        "p2", "soil", 45.0, lo=1300.0, hi=1900.0, tol=1.0, numerics=num, start=(-1.0, 1.0, 0.0)
    )
    return {
        "depth_280": float(d.penetration_depth),
        "path_45_1000": float(o.path_length),
        "turn_45_1000": float(analysis.turning_angle(o).delta_theta),
        "dev_p4_1000": float(analysis.final_deviation(y)),
        "vcr_p2_45": float(v.value),
    }


def main() -> None:
    ref_depth = closedform.depth(get_projectile("p2"), MEDIA["soil"], 280.0)
    rows = []
    for name, values in SWEEPS.items():
        for val in values:
            if name == "mesh_factor":
                num = dataclasses.replace(
                    DEFAULT, n_nose=int(DEFAULT.n_nose * val), n_shank=int(DEFAULT.n_shank * val)
                )
            else:
                num = dataclasses.replace(DEFAULT, **{name: val})
            t0 = time.perf_counter()
            q = quantities(num)
            q.update(
                parameter=name,
                value=val,
                seconds=time.perf_counter() - t0,
                depth_280_vs_exact=q["depth_280"] / ref_depth - 1.0,
            )
            rows.append(q)
            print(q, flush=True)
    df = pd.DataFrame(rows)
    cols = [
        "parameter",
        "value",
        "depth_280",
        "depth_280_vs_exact",
        "path_45_1000",
        "turn_45_1000",
        "dev_p4_1000",
        "vcr_p2_45",
        "seconds",
    ]
    df = df[cols]
    out = Path(__file__).parent / "results"
    out.mkdir(exist_ok=True)
    df.to_csv(out / "convergence.csv", index=False, float_format="%.6g")
    print(df.to_string(index=False, float_format=lambda x: f"{x:.6g}"))


if __name__ == "__main__":
    main()
