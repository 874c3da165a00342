"""Hash every data variable of twelve varied reference runs, to check that a change
keeps results bit-identical.

The twelve runs cover the paths a change can touch: normal, oblique, yawed and spinning
impact, soil and concrete, an off-surface start, the closed-form and finite-difference
Jacobians, scipy's reference integrator, the explicit (paper-emulation) integrator with
panels, the cavity shank model, a layered plate with a gap that is perforated, and the
crater and free-surface depth windows. Run it before and after a change on the same
machine: the digests must match (bits depend on the CPU's libm, so compare on one host).

Usage: ``python benchmarks/reference_runs.py [--out FILE] [--states-only]`` prints one line
per run and the combined digest; ``--states-only`` leaves out the loads on the body
(:data:`LOADS`, derived from each state after the run), to show that a change to how the
loads are computed leaves the trajectories themselves bit-identical.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys

import pencore

PLATE = {
    "name": "plate",
    "layers": [
        {"medium": "aluminium", "thickness": 0.01},
        {"gap": 0.02},
        {"medium": "aluminium", "thickness": 0.0254},
    ],
}
WINDOWS = {
    "name": "windows",
    "layers": [
        {"medium": "aluminium", "thickness": 0.05, "crater_depth": 2.0, "free_surface_depth": 1.0}
    ],
}

#: (label, projectile, target, keyword arguments of pencore.simulate)
CASES: list[tuple[str, str, object, dict]] = [
    ("normal", "p2", "soil", dict(velocity=280.0)),
    ("oblique", "p2", "soil", dict(velocity=1000.0, obliquity=45.0)),
    ("yawed", "p4", "soil", dict(velocity=500.0, yaw=2.0)),
    ("spinning", "p2", "soil", dict(velocity=1000.0, omega=20.0)),
    ("offset_start", "p2", "soil", dict(velocity=1700.0, obliquity=45.0, start=(-1.0, 1.0, 0.0))),
    ("concrete", "p1", "concrete", dict(velocity=800.0, obliquity=30.0, yaw=-1.0)),
    ("finite_difference", "p3", "soil",
     dict(velocity=900.0, obliquity=20.0, jacobian="finite_difference")),
    ("scipy_bdf", "p2", "soil", dict(velocity=600.0, obliquity=15.0, method="BDF")),
    ("explicit_panels", "p2", "soil",
     dict(velocity=500.0, obliquity=10.0,
          emulation={"surface": "panels", "integrator": "explicit"})),
    ("cavity_shank", "p4", "soil", dict(velocity=900.0, obliquity=30.0, shank="cavity")),
    ("plate_with_gap", "p2", PLATE, dict(velocity=900.0, obliquity=20.0)),
    ("windows", "p2", WINDOWS, dict(velocity=400.0, obliquity=5.0)),
]  # fmt: skip


#: The variables of the loads on the body (pencore.run.loads), left out by --states-only.
LOADS = ("axial_force", "lateral_force", "deceleration", "deceleration_g")


def digest(ds) -> str:
    """SHA-256 over every data variable's name and bytes and the time axis."""
    h = hashlib.sha256()
    for name in sorted(ds.data_vars):
        h.update(name.encode())
        h.update(ds[name].values.tobytes())
    h.update(ds.time.values.tobytes())
    return h.hexdigest()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", help="also write the digests as JSON to this file")
    ap.add_argument("--states-only", action="store_true", help="leave out the loads")
    args = ap.parse_args(argv)
    out: dict[str, str] = {}
    total = hashlib.sha256()
    for label, projectile, target, kw in CASES:
        ds = pencore.simulate(projectile, target, **kw)
        if args.states_only:
            ds = ds.drop_vars([v for v in LOADS if v in ds.data_vars])
        out[label] = digest(ds)
        total.update(out[label].encode())
        print(f"{label:18s} {out[label][:16]}  steps={ds.sizes['time']}  {ds.attrs['outcome']}")
    out["all"] = total.hexdigest()
    print(f"{'all':18s} {out['all']}")
    if args.out:
        with open(args.out, "w") as f:
            json.dump(out, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
