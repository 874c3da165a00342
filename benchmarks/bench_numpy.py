"""pencore against the numpy form of the same force law, in one run (reported, never asserted).

The numpy form: the DAFL traction of :mod:`pencore.kernels.dynamics` (smoothed Heaviside
``clip((Vn + eps) / (2 eps), 0, 1)``, on the shank widened as
:func:`pencore.kernels.bands.band_eps` does, frictionless, one half-space layer) evaluated on
``n_phi`` points around every ring by vectorised numpy, and integrated with scipy's
``solve_ivp`` (BDF, a stiff method as the law needs); pencore evaluates each ring in
closed form in compiled code and integrates with its compiled Rosenbrock pair.

Printed: (1) both force evaluations on the benchmark state and their agreement,
(2) the time per force evaluation and (3) per trajectory (p2, soil, 45 deg, 1000 m/s,
rtol 1e-5) of each, and the ratios. Both trajectories are checked to reach the same
depth and path to within the numpy form's surface discretisation.

Run: python benchmarks/bench_numpy.py [--n-phi 64] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import time

import numpy as np
from scipy.integrate import solve_ivp

import pencore
from pencore.kernels.dynamics import contact_loads, quat_to_matrix
from pencore.run.impact import prepare
from pencore.run.initial import initial_state

CASE = dict(velocity=1000.0, obliquity=45.0)


def numpy_loads(y: np.ndarray, rings: np.ndarray, a: np.ndarray, eps: float, n_phi: int):
    """Force and moment (body frame, N and N m) of the DAFL on ``n_phi`` points per ring."""
    rot = quat_to_matrix(y[3:7])
    v = rot.T @ y[7:10]
    w = y[10:13]
    x1, r, na, nr, wt = (rings[:, k, None] for k in range(5))
    phi = (np.arange(n_phi) + 0.5) * (2.0 * math.pi / n_phi)
    c, s = np.cos(phi)[None, :], np.sin(phi)[None, :]
    # body-frame point and outward normal
    p = np.stack(np.broadcast_arrays(x1, r * c, r * s), -1)
    n = np.stack(np.broadcast_arrays(na, nr * c, nr * s), -1)
    u = v + np.cross(w, p)
    vn = np.einsum("ijk,ijk->ij", u, n)
    height = y[1] + p @ rot[1]
    sigma = a[0] + a[1] * vn + a[2] * vn * vn
    # the shank bands' step widened by the spread of Vn along them (pencore.kernels.bands.band_eps)
    spread = np.where(na == 0.0, 0.5 * wt / r * math.hypot(w[1], w[2]), 0.0)
    e = np.sqrt(eps * eps + spread * spread)
    h = np.clip((vn + e) / (2.0 * e), 0.0, 1.0) * (height <= 0.0)
    da = wt * (2.0 * math.pi / n_phi)
    traction = -(h * sigma * da)[..., None] * n
    return traction.sum((0, 1)), np.cross(p, traction).sum((0, 1))


def numpy_rhs(pr, n_phi: int):
    a = pr.coef[0]
    eps = pr.numerics.eps
    inertia = pr.inertia

    def f(t, y):
        yn = y.copy()
        yn[3:7] /= np.linalg.norm(yn[3:7])
        rot = quat_to_matrix(yn[3:7])
        fb, mb = numpy_loads(yn, pr.rings, a, eps, n_phi)
        qw, qx, qy, qz = yn[3:7]
        w1, w2, w3 = yn[10:13]
        dy = np.empty(14)
        dy[0:3] = yn[7:10]
        dy[3:7] = 0.5 * np.array(
            [-qx * w1 - qy * w2 - qz * w3, qw * w1 + qy * w3 - qz * w2,
             qw * w2 + qz * w1 - qx * w3, qw * w3 + qx * w2 - qy * w1]
        )  # fmt: skip
        dy[7:10] = rot @ fb / pr.mass
        i1, i2, i3 = inertia
        dy[10] = (mb[0] + (i2 - i3) * w2 * w3) / i1
        dy[11] = (mb[1] + (i3 - i1) * w3 * w1) / i2
        dy[12] = (mb[2] + (i1 - i2) * w1 * w2) / i3
        dy[13] = fb @ (rot.T @ yn[7:10]) + mb @ yn[10:13]
        return dy

    return f


def _median_time(fun, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fun()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n-phi", type=int, default=64, help="points around each ring (numpy)")
    ap.add_argument("--json", help="also write the figures to this JSON file")
    args = ap.parse_args()

    pr = prepare("p2", "soil")
    ds = pencore.simulate("p2", "soil", prepared=pr, **CASE)  # compiles or loads the cache
    # a state in mid-penetration: the benchmark trajectory at a third of its duration;
    # the motion stays in the x-y plane, so the attitude is a turn about z
    i = ds.sizes["time"] // 3
    y0 = initial_state(pr.projectile, pr.rings, CASE["velocity"], math.radians(45.0), 0.0,
                       0.0, None)  # fmt: skip
    state = np.zeros(14)
    state[0:3] = [ds[k].values[i] for k in ("cm_x", "cm_y", "cm_z")]
    state[7:10] = [ds[k].values[i] for k in ("vel_x", "vel_y", "vel_z")]
    th = math.atan2(ds.axis_y.values[i], ds.axis_x.values[i])
    state[3:7] = [math.cos(0.5 * th), 0.0, 0.0, math.sin(0.5 * th)]
    state[10:13] = [ds[k].values[i] for k in ("omega_1", "omega_2", "omega_3")]

    fb_c, mb_c, _ = contact_loads(state, pr.rings, pr.bounds, pr.coef, pr.fric, pr.numerics.eps, 0)
    fb_n, mb_n = numpy_loads(state, pr.rings, pr.coef[0], pr.numerics.eps, args.n_phi)
    t_c = _median_time(
        lambda: contact_loads(state, pr.rings, pr.bounds, pr.coef, pr.fric, pr.numerics.eps, 0),
        2000,
    )
    t_n = _median_time(
        lambda: numpy_loads(state, pr.rings, pr.coef[0], pr.numerics.eps, args.n_phi), 200
    )

    t_traj_c = _median_time(lambda: pencore.simulate("p2", "soil", prepared=pr, **CASE), 10)
    f = numpy_rhs(pr, args.n_phi)

    def stop(t, yy):
        return math.sqrt(float(yy[7:10] @ yy[7:10])) - pr.numerics.v_stop

    stop.terminal = True
    atol = np.append(
        1e-7 * np.array([pr.projectile.length] * 3 + [1.0] * 4 + [1e3] * 3 + [1e3] * 3), 1.0
    )
    t0 = time.perf_counter()
    sol = solve_ivp(f, (0.0, 1.0), y0, method="BDF", rtol=1e-5, atol=atol, events=stop,
                    max_step=0.1 / CASE["velocity"])  # fmt: skip
    t_traj_n = time.perf_counter() - t0
    tip = (
        sol.y[0:3]
        + pr.lc * np.array([quat_to_matrix(q / np.linalg.norm(q))[:, 0] for q in sol.y[3:7].T]).T
    )
    depth_n = float(-tip[1].min())

    out = {
        "case": "p2, soil, 45 deg, 1000 m/s, rtol 1e-5, frictionless",
        "n_phi_numpy": args.n_phi,
        "force_compiled_N": float(np.linalg.norm(fb_c)),
        "force_numpy_N": float(np.linalg.norm(fb_n)),
        "force_rel_diff": float(np.linalg.norm(fb_n - fb_c) / np.linalg.norm(fb_c)),
        "moment_rel_diff": float(np.linalg.norm(mb_n - mb_c) / max(np.linalg.norm(mb_c), 1e-30)),
        "force_eval_compiled_s": t_c,
        "force_eval_numpy_s": t_n,
        "force_eval_ratio_numpy_over_compiled": t_n / t_c,
        "trajectory_compiled_s": t_traj_c,
        "trajectory_numpy_scipy_s": t_traj_n,
        "trajectory_ratio_numpy_over_compiled": t_traj_n / t_traj_c,
        "rhs_calls_numpy_scipy": int(sol.nfev),
        "rhs_calls_compiled": int(ds.attrs["n_rhs"]),
        "depth_compiled_m": float(ds.penetration_depth),
        "depth_numpy_m": depth_n,
    }
    for k, v in out.items():
        print(f"{k:40s} {v:.4g}" if isinstance(v, float) else f"{k:40s} {v}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=2)


if __name__ == "__main__":
    main()
