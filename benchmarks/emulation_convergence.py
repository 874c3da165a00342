"""Convergence of the paper-emulation numerics and of the cavity shank model's limit.

pencore.inputs.models.Emulation emulates an explicit FE code (faceted panels with a point load
each, fixed-step central difference with the pure Heaviside). Refined, each must tend to
pencore's default solution of the same model; the cavity shank model must tend to the
DAFL as its wall stiffens (delta_ref -> 0). For projectile #2 in soil:

* ``depth`` / ``path``  tip depth and tip path length at 45 deg, 1000 m/s (m);
* ``dev``               final deviation of that run (deg);
* ``depth_280``         normal-impact depth at 280 m/s (m; Table 2, test 2).

Sweeps (each row is compared with the reference named in ``reference``):

* ``panels``            bands along the axis and around doubled together:
                        n_nose = 12 m, n_shank = 6 m, n_circumferential = 12 m;
                        reference: rings at n_nose 96, n_shank 48, rtol 1e-7;
* ``explicit``          fixed step dt on the default rings; reference: the adaptive
                        solver on the same rings at rtol 1e-8 (isolates the time error);
* ``panels+explicit``   both together (an FE model refined in space and time);
* ``cavity``            delta_ref from 20 mm to 0.01 mm; reference: the DAFL (default).

Writes benchmarks/results/emulation_convergence.csv and prints a markdown table.
Run: python benchmarks/emulation_convergence.py
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

import pencore
from pencore import analysis

OUT = Path(__file__).parent / "results" / "emulation_convergence.csv"
CASE = dict(velocity=1000.0, obliquity=45.0)


def quantities(**kw) -> dict[str, float]:
    t0 = time.perf_counter()
    o = pencore.simulate("p2", "soil", **CASE, **kw)
    n = pencore.simulate("p2", "soil", 280.0, **kw)
    return {
        "depth": float(o.penetration_depth),
        "path": float(o.path_length),
        "dev": float(analysis.final_deviation(o)),
        "depth_280": float(n.penetration_depth),
        "steps": int(o.attrs["n_rhs"]) if "explicit" in str(kw) else int(o.attrs["n_steps"]),
        "wall_s": time.perf_counter() - t0,
    }


def main() -> None:
    refs = {
        "fine rings": quantities(n_nose=96, n_shank=48, rtol=1e-7, max_travel=0.02),
        "same rings": quantities(rtol=1e-8, max_travel=0.01),
        "dafl": quantities(),
    }
    sweeps: list[tuple[str, str, str, dict]] = []
    for m in (1, 2, 4, 8):
        em = {"surface": "panels", "n_circumferential": 12 * m}
        sweeps.append(
            ("panels", f"{12 * m}/{6 * m}/{12 * m}", "fine rings",
             dict(n_nose=12 * m, n_shank=6 * m, emulation=em))
        )  # fmt: skip
    for dt in (8e-6, 4e-6, 2e-6, 1e-6, 5e-7, 2.5e-7):
        em = {"integrator": "explicit", "dt": dt}
        sweeps.append(("explicit", f"dt {dt:g} s", "same rings", dict(emulation=em)))
    for m, dt in ((1, 8e-6), (2, 4e-6), (4, 2e-6), (8, 1e-6)):
        em = {"surface": "panels", "n_circumferential": 12 * m, "integrator": "explicit", "dt": dt}
        sweeps.append(
            ("panels+explicit", f"{12 * m}/{6 * m}/{12 * m}, dt {dt:g} s", "fine rings",
             dict(n_nose=12 * m, n_shank=6 * m, emulation=em))
        )  # fmt: skip
    for d in (2e-2, 5e-3, 1e-3, 1e-4, 1e-5):
        shank = {"kind": "cavity", "delta_ref": d}
        sweeps.append(("cavity", f"delta_ref {d * 1e3:g} mm", "dafl", dict(shank=shank)))
    rows = []
    for name, setting, ref, kw in sweeps:
        q = quantities(**kw)
        r = refs[ref]
        rows.append(
            {
                "sweep": name,
                "setting": setting,
                "reference": ref,
                **{k: q[k] for k in ("depth", "path", "dev", "depth_280")},
                "err_depth": q["depth"] / r["depth"] - 1.0,
                "err_path": q["path"] / r["path"] - 1.0,
                "err_dev_deg": q["dev"] - r["dev"],
                "err_depth_280": q["depth_280"] / r["depth_280"] - 1.0,
                "steps": q["steps"],
                "wall_s": q["wall_s"],
            }
        )
        print(rows[-1], flush=True)
    for ref, r in refs.items():
        rows.append({"sweep": "reference", "setting": ref, "reference": "", **r})
    df = pd.DataFrame(rows)
    OUT.parent.mkdir(exist_ok=True)
    df.to_csv(OUT, index=False, float_format="%.8g")
    print()
    print("| sweep | setting | depth err | path err | dev err (deg) | depth 280 err | wall s |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        if r["sweep"] == "reference":
            continue
        print(
            f"| {r['sweep']} | {r['setting']} | {100 * r['err_depth']:+.3f} % | "
            f"{100 * r['err_path']:+.3f} % | {r['err_dev_deg']:+.3f} | "
            f"{100 * r['err_depth_280']:+.3f} % | {r['wall_s']:.1f} |"
        )


if __name__ == "__main__":
    main()
