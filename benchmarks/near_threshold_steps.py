"""What sets the step of a run near a ballistic limit: the ring mesh, the integrator or
the tolerance.

The cases are a search's slow kind of run (``benchmarks/search_cost.py``), each near a
ballistic limit of the near-surface map (projectile ``al_ogive_var4340``, aluminium
plates):

* ``none``: 45 deg into a plate 2 calibres thick on the half-space law, at 364 m/s: the
  body stops in the plate after about 0.5 ms;
* ``crater_2``: 60 deg into a plate 1.5 calibres thick with the 2-calibre crater of
  Forrestal et al. (1994), at 436 m/s, just above the map's limit (435.3 m/s). At 539 m/s,
  the limit with the crater factor of the tip's depth on the whole body, this run
  perforated, stopped, stopped on another path or exited as the rings went from 0.5x to
  4x, in up to 15 515 steps; with each element's own factor (and the closed-form
  Jacobian) it perforates on every mesh, in 2 405-2 513 steps (the ``none`` case near
  its limit takes about 2 100).

Each is run

* with the ring mesh scaled by 0.5, 1, 2 and 4 (``n_nose``, ``n_shank``): if the step were
  set by rings crossing the plate's faces one at a time, the steps would scale with the
  rings;
* with scipy's BDF (orders 1-5) beside pencore's Rosenbrock (2,3) at the default and a
  ten times looser ``rtol``: if a higher-order method needs as many steps, the step is
  set by the motion itself at that tolerance, not by the method.

Writes benchmarks/results/near_threshold_steps.csv (steps, rejected steps, right-hand
sides, wall s, the outcome and the path length) and prints it.
Run: python benchmarks/near_threshold_steps.py
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import pandas as pd

import pencore
from pencore.studies.perforation.slabs import slab_target

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from machine import machine  # noqa: E402

PROJECTILE = "al_ogive_var4340"
#: name: (plate thickness in calibres, crater depth in calibres (0: none), obliquity deg,
#: impact speed m/s)
PLATES = {"none": (2.0, 0.0, 45.0, 364.0), "crater_2": (1.5, 2.0, 60.0, 436.0)}
DEFAULT = pencore.Numerics()
NUMERICS = [
    *[("rosenbrock", DEFAULT.rtol, f) for f in (0.5, 1.0, 2.0, 4.0)],
    ("rosenbrock", 10 * DEFAULT.rtol, 1.0),
    ("BDF", DEFAULT.rtol, 1.0),
    ("BDF", 10 * DEFAULT.rtol, 1.0),
]


def main() -> None:
    d = pencore.get_projectile(PROJECTILE).diameter
    rows = []
    with warnings.catch_warnings():
        # plates 1.5-2 calibres thick: the plausibility warning is the point of the cases
        # (the map's thin plates), not a slip
        warnings.simplefilter("ignore", pencore.PlausibilityWarning)
        for plate, (t_over_d, crater, obliquity, velocity) in PLATES.items():
            target = slab_target("aluminium", t_over_d * d, crater_depth=crater)
            for method, rtol, mesh in NUMERICS:
                num = pencore.Numerics(
                    method=method,
                    rtol=rtol,
                    n_nose=round(mesh * DEFAULT.n_nose),
                    n_shank=round(mesh * DEFAULT.n_shank),
                )
                t0 = time.perf_counter()
                ds = pencore.simulate(PROJECTILE, target, velocity, obliquity, numerics=num)
                rows.append(
                    {
                        "plate": plate,
                        "t_over_d": t_over_d,
                        "obliquity_deg": obliquity,
                        "velocity_m_s": velocity,
                        "method": method,
                        "rtol": rtol,
                        "mesh_factor": mesh,
                        "outcome": ds.attrs["outcome"],
                        "n_steps": int(ds.attrs["n_steps"]),
                        "n_rejected": int(ds.attrs["n_rejected"]),
                        "n_rhs": int(ds.attrs["n_rhs"]),
                        "t_end_us": round(1e6 * float(ds["time"][-1]), 2),
                        "path_mm": round(1e3 * float(ds["path_length"]), 4),
                        "wall_s": round(time.perf_counter() - t0, 3),
                    }
                )
    m = machine()
    df = pd.DataFrame(rows).assign(
        cpu_model=m["cpu_model"], load_1min=m["load_1min"], measured_utc=m["measured_utc"],
        commit=m["commit"],
    )  # fmt: skip
    out = HERE / "results" / "near_threshold_steps.csv"
    df.to_csv(out, index=False)
    shown = df.drop(columns=["t_over_d", "obliquity_deg", "velocity_m_s", "cpu_model",
                             "measured_utc", "commit"])  # fmt: skip
    print(shown.to_string(index=False))


if __name__ == "__main__":
    main()
