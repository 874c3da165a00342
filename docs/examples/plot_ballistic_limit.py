"""
A plate's ballistic limit and residual velocity
===============================================

A target whose last layer has a finite thickness is a plate that can be perforated. The
*ballistic limit* ``v_bl`` is the lowest impact speed that perforates it; above it, the
projectile leaves the rear face with a *residual velocity* ``v_r``.

This example finds the ballistic limit of a 1 m concrete slab against projectile #2 at
normal incidence and at 30 degrees of obliquity
(:func:`pencore.search.perforation.ballistic_limit`), computes residual velocities over
a range of impact speeds, and fits the Recht-Ipson curve

.. math:: v_r = a \\left(v^p - v_{bl}^p\\right)^{1/p}, \\qquad v > v_{bl},

(:func:`pencore.search.perforation.fit_recht_ipson`). For a rigid projectile whose
resisting work does not depend on the impact speed, ``a = 1`` and ``p = 2``. The
concrete law of the paper has a velocity-squared term: a resisting force ``F0 + B v^2``
acting over a fixed path ``h`` gives ``v_r^2 = exp(-2 B h / m) (v^2 - v_bl^2)``, still
``p = 2`` but ``a < 1``, which is what the fit finds. These are model predictions: no
measurement is compared here.
"""

# %%
# The slab
# --------
# A target of one finite layer of the shipped concrete medium, built from the objects
# (a YAML file with ``layers: [{medium: concrete, thickness: 1.0}]`` is the same).

import matplotlib.pyplot as plt
import numpy as np

import pencore
from pencore.search.perforation import (
    ballistic_limit,
    fit_recht_ipson,
    recht_ipson,
    residual_velocity,
)

concrete = pencore.get_target("concrete").medium
slab = pencore.Target("concrete slab 1 m", (pencore.Layer(concrete, 1.0),))
print(f"{slab.name}: rear face at y = {slab.rear_face:g} m, finite: {slab.finite}")

# %%
# The ballistic limit
# -------------------
# The same threshold search as Vcr (:func:`pencore.search.critical.vcr`), with the
# verdict "the run ends ``perforated``". The result is a
# :class:`~pencore.search.threshold.CriticalResult`: the slowest speed evaluated that
# perforated is ``hi``, the fastest that did not is ``lo``.

obliquities = (0.0, 30.0)
limits = {}
for obl in obliquities:
    limits[obl] = ballistic_limit("p2", slab, obliquity=obl, lo=50.0, hi=3000.0, tol=2.0)
    r = limits[obl]
    print(
        f"obliquity {obl:4.1f} deg: v_bl = {r.value:.1f} m/s, in ({r.lo:.2f} m/s, "
        f"{r.hi:.2f} m/s], {r.n_evals} runs, status {r.status}"
    )

# %%
# Residual velocities
# -------------------
# One full run per impact speed. :func:`~pencore.search.perforation.residual_velocity`
# reads the residual speed of a perforating run from the Dataset (it is 0 when the run
# stopped in the slab or ricocheted). :func:`pencore.prepare` resolves the inputs once
# for the loop.

speeds = np.linspace(300.0, 1500.0, 17)
residual = {}
for obl in obliquities:
    prepared = pencore.prepare("p2", slab)
    runs = [pencore.simulate("p2", slab, v, obl, prepared=prepared) for v in speeds]
    residual[obl] = np.array([residual_velocity(ds) for ds in runs])
    outcomes = sorted({ds.attrs["outcome"] for ds in runs})
    print(f"obliquity {obl:4.1f} deg: outcomes {outcomes}")

# %%
# The Recht-Ipson fit
# -------------------
# ``v_bl`` is held at the searched value and ``a`` and ``p`` are fitted to the
# perforating runs; the RMS residual of the fit is compared with that of the rigid-body
# curve ``a = 1``, ``p = 2``.

fits = {}
for obl in obliquities:
    v_bl = limits[obl].value
    fits[obl] = fit = fit_recht_ipson(speeds, residual[obl], v_bl=v_bl)
    perforating = residual[obl] > 0.0
    rigid = recht_ipson(speeds[perforating], v_bl)
    rms_rigid = np.sqrt(np.mean((rigid - residual[obl][perforating]) ** 2))
    print(
        f"obliquity {obl:4.1f} deg: a = {fit['a']:.3f} (dimensionless), "
        f"p = {fit['p']:.3f} (dimensionless), RMS {fit['rms']:.2f} m/s; "
        f"rigid a = 1, p = 2: RMS {rms_rigid:.1f} m/s"
    )

# %%
# Plot
# ----
# Residual against impact speed: the runs (dots), the fitted curve (line) and the
# rigid-body curve (dashed), with the ballistic limit of each obliquity marked.

fig, ax = plt.subplots(figsize=(7, 5), layout="constrained")
v_fine = np.linspace(speeds[0], speeds[-1], 400)
for k, obl in enumerate(obliquities):
    colour, fit, v_bl = f"C{k}", fits[obl], limits[obl].value
    ax.plot(speeds, residual[obl], "o", color=colour, label=f"pencore runs, {obl:g} deg")
    ax.plot(
        v_fine,
        recht_ipson(v_fine, v_bl, fit["a"], fit["p"]),
        color=colour,
        label=f"Recht-Ipson fit, a = {fit['a']:.2f}, p = {fit['p']:.2f}",
    )
    ax.plot(
        v_fine,
        recht_ipson(v_fine, v_bl),
        "--",
        color=colour,
        lw=1,
        label="rigid-body curve, a = 1, p = 2",
    )
    ax.axvline(v_bl, color=colour, ls=":", lw=1)
    ax.annotate(
        f"v_bl = {v_bl:.0f} m/s",
        (v_bl, 0.95 - 0.06 * k),
        xycoords=("data", "axes fraction"),
        xytext=(4, 0),
        textcoords="offset points",
        ha="left",
        color=colour,
    )
ax.set_xlabel("impact speed v (m/s)")
ax.set_ylabel("residual speed v_r (m/s)")
ax.set_title("p2 against a 1 m concrete slab")
ax.legend(fontsize="small")
plt.show()
