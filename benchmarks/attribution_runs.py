"""The attribution table of the docs (results, "Why the numbers differ"): the paper's
disputed quantities, setting by setting (pencore.studies.attribution.disputed.disputed_quantities),
run one at a time.

Writes benchmarks/results/attribution.csv (one row per setting: the quantities, their
differences from the paper, wall times) and prints a markdown table.
Run: python benchmarks/attribution_runs.py
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import pandas as pd

from pencore.studies.attribution.disputed import disputed_quantities, relative_differences

OUT = Path(__file__).parent / "results" / "attribution.csv"
FE_COARSE = {"n_nose": 16, "n_shank": 16}
FE_MEDIUM = {"n_nose": 24, "n_shank": 24}

SETTINGS: dict[str, dict] = {
    "dafl (default)": {},
    "factor 0.7": {"shank": {"kind": "factor", "factor": 0.7}},
    "factor 0.5": {"shank": {"kind": "factor", "factor": 0.5}},
    "factor 0.45": {"shank": {"kind": "factor", "factor": 0.45}},
    "cavity 1 mm": {"shank": {"kind": "cavity", "delta_ref": 1e-3}},
    "cavity 5 mm": {"shank": {"kind": "cavity", "delta_ref": 5e-3}},
    "cavity 20 mm": {"shank": {"kind": "cavity", "delta_ref": 2e-2}},
    "cavity 0.1 mm (rigid-wall limit)": {"shank": {"kind": "cavity", "delta_ref": 1e-4}},
    "cavity 1 mm, shoulder path": {
        "shank": {"kind": "cavity", "delta_ref": 1e-3, "axis": "shoulder"}
    },
    "cavity 5 mm, shoulder path": {
        "shank": {"kind": "cavity", "delta_ref": 5e-3, "axis": "shoulder"}
    },
    "FE coarse: panels 16x16, explicit 1e-5 s": {
        "numerics": FE_COARSE,
        "emulation": {"surface": "panels", "n_circumferential": 16,
                      "integrator": "explicit", "dt": 1e-5},
    },
    "FE medium: panels 24x24, explicit 1e-6 s": {
        "numerics": FE_MEDIUM,
        "emulation": {"surface": "panels", "n_circumferential": 24,
                      "integrator": "explicit", "dt": 1e-6},
    },
    "cavity 5 mm + FE coarse": {
        "shank": {"kind": "cavity", "delta_ref": 5e-3},
        "numerics": FE_COARSE,
        "emulation": {"surface": "panels", "n_circumferential": 16,
                      "integrator": "explicit", "dt": 1e-5},
    },
    "spin about the tip": {"spin_about": "tip"},
    "start 0.5 m above": {"start_height": 0.5},
    "velocity tilted (yaw reading)": {"yaw_reading": "velocity_tilted"},
    "friction 0.1": {"friction": 0.1},
}  # fmt: skip


def main() -> None:
    rows = []
    for label, choices in SETTINGS.items():
        t0 = time.perf_counter()
        ds = disputed_quantities(choices)
        wall = time.perf_counter() - t0
        rel = relative_differences(ds)
        row = {
            "setting": label,
            "choices": json.dumps(choices),
            **{f"alpha_{w:g}": float(ds.alpha.sel(omega=w)) for w in ds.omega.values},
            **{f"back_{w:g}": bool(ds.turned_back.sel(omega=w)) for w in ds.omega.values},
            "vcr": float(ds.vcr),
            "vcr_lo": float(ds.vcr_lo),
            "vcr_hi": float(ds.vcr_hi),
            "vcr_status": ds.attrs["vcr_status"],
            "depth_280": float(ds.depth_280),
            **{
                f"phi_p4_{v:g}": float(ds.phi_p4.sel(phi_velocity=v))
                for v in ds.phi_velocity.values
            },
            **{f"rel_{k}": v for k, v in rel.items()},
            "within_3pct_all": all(
                abs(v) <= 0.03 for k, v in rel.items() if not k.startswith("turn")
            )
            and rel["turn_back_25_agrees"] == 1.0,
            "wall_s": wall,
        }
        rows.append(row)
        print(json.dumps(row), flush=True)
    df = pd.DataFrame(rows)
    OUT.parent.mkdir(exist_ok=True)
    df.to_csv(OUT, index=False, float_format="%.6g")
    print()
    print(
        "| setting | alpha 5 (0.14) | alpha 20 (2.86) | alpha 25 | back at 25 (yes) | "
        "Vcr (1641-1650) | depth 280 (4.25) | phi #4 280 (0.16) | phi #4 1000 (0.24) | s |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(
            f"| {r['setting']} | {r['alpha_5']:.3g} | {r['alpha_20']:.3g} | {r['alpha_25']:.3g} | "
            f"{'yes' if r['back_25'] else 'no'} | {r['vcr']:.0f} | {r['depth_280']:.3f} | "
            f"{r['phi_p4_280']:.3f} | {r['phi_p4_1000']:.3f} | {r['wall_s']:.0f} |"
        )


if __name__ == "__main__":
    main()
