"""
An ensemble of impacts and its statistics
=========================================

Real impacts scatter: the speed, the obliquity, the yaw and the initial spin are known
only as distributions. An *ensemble* draws N impacts from stated distributions, runs
them, and reports outcome probabilities and the distributions of the results with
their uncertainties (:mod:`pencore.studies.ensemble`; the workflow's ``ensemble`` study
runs the same functions at a larger N, in parallel chunks).

Here projectile #2 strikes soil 128 times, with the speed, obliquity, yaw, spin and
azimuth drawn at random. The statistics come out of
:func:`~pencore.studies.ensemble.gather` as variables of an :class:`xarray.Dataset`.
"""

# %%
# The case
# --------
# The keys are those of a case in the workflow's configuration (``config/config.yaml``,
# section ``ensemble``); units are in the key names. A distribution is a number (fixed),
# ``{dist: uniform, min, max}`` or ``{dist: normal, mean, sd}`` with optional
# ``min``/``max`` (a truncated normal). All draws come from one seeded generator, and
# sample ``i`` is the same however the samples are split into chunks.

import warnings

import matplotlib.pyplot as plt
import numpy as np

from pencore.errors import RigidRegimeWarning
from pencore.search.critical import vcr
from pencore.studies.ensemble import gather, run_chunk, sample_conditions

# The fastest samples put more stress on the nose tip of #2 than pencore's
# declared rigid-regime bound; the paper treats the body as rigid, and so does this
# example (without the next line each such run says so once).
warnings.simplefilter("ignore", RigidRegimeWarning)

case = {
    "name": "gallery_p2_soil",
    "projectile": "p2",
    "target": "soil",
    "n_samples": 128,
    "n_chunks": 2,
    "seed": 2011,
    "velocity_m_s": {"dist": "normal", "mean": 1400, "sd": 150, "min": 800, "max": 2000},
    "obliquity_deg": {"dist": "uniform", "min": 30, "max": 60},
    "yaw_deg": {"dist": "normal", "mean": 0, "sd": 1.0},
    "omega_rad_s": {"dist": "normal", "mean": 0, "sd": 2.0},
    "azimuth_deg": {"dist": "uniform", "min": 0, "max": 360},
}
conditions = sample_conditions(case)
print(
    f"first impact: {conditions['velocity_m_s'][0]:.1f} m/s, "
    f"obliquity {conditions['obliquity_deg'][0]:.2f} deg, yaw {conditions['yaw_deg'][0]:.2f} deg, "
    f"omega {conditions['omega_rad_s'][0]:.2f} rad/s"
)

# %%
# Run and gather
# --------------
# :func:`~pencore.studies.ensemble.run_chunk` runs one chunk (a separate job in the
# workflow); :func:`~pencore.studies.ensemble.gather` joins the chunks and adds the
# statistics: probabilities with Wilson 95 % intervals, means with Student-t 95 %
# intervals, and quantiles with distribution-free 95 % intervals.

parts = [run_chunk(case, chunk) for chunk in range(case["n_chunks"])]
ens = gather(parts)
n = ens.attrs["n_samples"]
outcomes, counts = np.unique(ens["outcome"].values, return_counts=True)
print(f"{n} impacts: " + ", ".join(f"{c} {o}" for o, c in zip(outcomes, counts, strict=True)))

lo, hi = ens["p_reversed_ci95"].values
print(
    f"probability of turning back: {float(ens['p_reversed']):.3f} (dimensionless), "
    f"95 % interval [{lo:.3f}, {hi:.3f}]"
)

# %%
# The distribution of each result: its mean with a 95 % interval, and the 5 %, 50 % and
# 95 % quantiles, each with units read from the Dataset.

for name in ("penetration_depth", "path_length", "downrange", "final_deviation"):
    units = ens[name].attrs["units"]
    m_lo, m_hi = ens[f"{name}_mean_ci95"].values
    q = ens[f"{name}_quantile"].values
    print(f"{ens[name].attrs['long_name']} ({units}):")
    print(
        f"  mean {float(ens[f'{name}_mean']):.2f} {units}, "
        f"95 % interval [{m_lo:.2f}, {m_hi:.2f}] {units}"
    )
    print(
        f"  quantiles 5 %, 50 %, 95 %: {q[0]:.2f} {units}, {q[1]:.2f} {units}, {q[2]:.2f} {units}"
    )

# %%
# Which impacts turn back?
# ------------------------
# Without yaw and spin, an impact turns back when its speed exceeds the critical reverse
# velocity Vcr at its obliquity (see the Vcr search example). We search Vcr at a few
# obliquities over the ensemble's range and interpolate it to each impact, to compare
# each impact's speed with it.

vcr_obliquities = np.linspace(30.0, 60.0, 7)
vcr_values = np.array([vcr("p2", "soil", obliquity=o, tol=5.0).value for o in vcr_obliquities])
for o, v in zip(vcr_obliquities, vcr_values, strict=True):
    print(f"Vcr at {o:4.1f} deg: {v:.1f} m/s")
speed_ratio = ens["velocity"].values / np.interp(
    ens["obliquity"].values, vcr_obliquities, vcr_values
)
turned = ens["reversed"].values == 1
below = turned & (speed_ratio < 1.0)
print(f"{int(turned.sum())} impacts turned back, {int(below.sum())} of them slower than Vcr")
yaw_below = ens["yaw"].values[below]
print(f"yaw of those: {yaw_below.min():.2f} deg to {yaw_below.max():.2f} deg")

# %%
# Many impacts turn back below Vcr, and their yaw is negative: the velocity is closer
# to the normal than the axis (the yaw is the velocity angle minus the axis angle), so
# the axis leans further towards the surface than the path does. A positive yaw works
# the other way, and some impacts faster than Vcr do not turn back. A yaw of one degree
# moves the threshold by hundreds of m/s: the workflow's Fig. 12 study
# (``results/archive/fig12/vcr_yaw.nc``) maps Vcr against yaw.

# %%
# Plot
# ----
# Left: the histogram of the penetration depth, split by outcome, with its quantiles.
# Middle: each impact's speed relative to Vcr against its yaw. Right: the running estimate of the
# probability of turning back against the number of impacts used, with its 95 %
# interval; it narrows like one over the square root of N.

fig, (ax_hist, ax_map, ax_run) = plt.subplots(1, 3, figsize=(14, 4.3), layout="constrained")
depth = ens["penetration_depth"].values
bins = np.linspace(0.0, depth.max() * 1.05, 25)
ax_hist.hist(
    [depth[~turned], depth[turned]], bins=bins, stacked=True, label=["no reversal", "turned back"]
)
for q, value in zip(ens["quantile"].values, ens["penetration_depth_quantile"].values, strict=True):
    ax_hist.axvline(value, color="k", ls=":", lw=1)
    ax_hist.annotate(
        f"{q:.0%}",
        (value, 1.0),
        xycoords=("data", "axes fraction"),
        xytext=(2, -12),
        textcoords="offset points",
        fontsize="small",
    )
ax_hist.set_xlabel("penetration depth of the nose tip (m)")
ax_hist.set_ylabel("number of impacts")
ax_hist.legend(loc="center left")

yaw = ens["yaw"].values
ax_map.scatter(yaw[~turned], speed_ratio[~turned], s=12, label="no reversal")
ax_map.scatter(yaw[turned], speed_ratio[turned], s=12, label="turned back")
ax_map.axhline(1.0, color="k", lw=1, label="Vcr (no yaw, no spin)")
ax_map.set_xlabel("yaw (deg)")
ax_map.set_ylabel("impact speed / Vcr at its obliquity (dimensionless)")
ax_map.legend(fontsize="small")

ci = ens["running_p_reversed_ci95"].values
ax_run.fill_between(ens["n_used"], ci[:, 0], ci[:, 1], alpha=0.3, label="Wilson 95 % interval")
ax_run.plot(ens["n_used"], ens["running_p_reversed"], "o-", label="estimate")
ax_run.set_xscale("log", base=2)
ax_run.set_xlabel("number of impacts used, N")
ax_run.set_ylabel("probability of turning back (dimensionless)")
ax_run.legend()
plt.show()
