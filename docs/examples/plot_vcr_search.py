"""
Searching the critical reverse velocity Vcr
===========================================

At a given obliquity, a slow projectile stops in the target, while a fast one turns
back towards the surface (it *reverses*). The critical reverse velocity Vcr is the lowest
impact speed at which it turns back (paper Section 4.2, Figs 7-8).

:func:`pencore.search.critical.vcr` finds it as the threshold of a yes/no verdict: it
checks both ends of the speed range, scans it coarsely to detect a verdict that is not
monotone, and then bisects until the bracket is narrower than ``tol``. Here we search Vcr
of projectile #2 in soil at 45 degrees, look at the search's evidence, and compare the
trajectories just below and just above the threshold.
"""

# %%
# Run the search
# --------------
# The search runs each trajectory only up to the first reversal (``stop_at_reversal``),
# since the verdict needs nothing more. The arguments are the projectile, the target and
# the obliquity (deg); ``lo`` and ``hi`` bound the speeds searched and ``tol`` is the
# final bracket width (all in m/s).

import warnings

import matplotlib.pyplot as plt

import pencore
from pencore.search.critical import vcr

# Near Vcr the paper's soil law puts about 10 GPa on the nose tip, more than pencore's
# declared rigid-regime bound (5.5 times the projectile's yield strength, 1720 MPa assumed
# for #2): a real nose would deform. The paper treats the body as rigid, and so does this
# example; without the next line each search and run near Vcr says so once.
warnings.simplefilter("ignore", pencore.RigidRegimeWarning)

result = vcr("p2", "soil", obliquity=45.0, lo=100.0, hi=4000.0, tol=5.0)
print(result.message)

# %%
# The result
# ----------
# :class:`~pencore.search.threshold.CriticalResult` holds the bracket: ``lo`` is the
# fastest speed evaluated that did not turn back and ``hi`` the slowest that did, so
# ``lo < Vcr <= hi``; ``value`` is its midpoint. ``status`` says whether the search
# converged (``ok``), and ``monotone`` whether the coarse scan saw the verdict switch
# only once. ``history`` lists every speed evaluated and its verdict, in order.

print(f"status: {result.status}, converged: {result.converged}, monotone: {result.monotone}")
print(f"Vcr = {result.value:.1f} m/s, bracket ({result.lo:.2f} m/s, {result.hi:.2f} m/s]")
print(f"bracket width {result.hi - result.lo:.2f} m/s (asked for at most {result.tol:g} m/s)")
print(f"{result.n_evals} trajectories evaluated:")
for k, (speed, turned_back) in enumerate(result.history):
    print(f"  {k:2d}: {speed:8.2f} m/s -> {'turns back' if turned_back else 'stops'}")

# %%
# Trajectories on either side of Vcr
# ----------------------------------
# Full runs (to the end, not stopped at the reversal) at the two ends of the final
# bracket, and at 10 % below and above Vcr. Below Vcr the nose tip runs on into the
# soil and stops (``reversed = 0``). Above it the path bends back upwards
# (``reversed = 1``): just above Vcr the projectile may have too little speed left to reach
# the surface and stop inside all the same, while faster ones leave through the surface
# (outcome ``exited``).

speeds = [0.9 * result.value, result.lo, result.hi, 1.1 * result.value]
runs = [pencore.simulate("p2", "soil", v, 45.0) for v in speeds]
for v, ds in zip(speeds, runs, strict=True):
    print(
        f"{v:8.2f} m/s: {ds.attrs['outcome']:8s} reversed = {ds.attrs['reversed']}, "
        f"depth {float(ds['penetration_depth']):.2f} m, "
        f"final deviation {float(ds['final_deviation']):.1f} deg"
    )

# %%
# Plot
# ----
# Left: the speeds the search evaluated, in order, coloured by their verdict; the
# shaded band is the final bracket. Right: the nose-tip paths of the four runs.

fig, (ax_hist, ax_path) = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
for k, (speed, turned_back) in enumerate(result.history):
    ax_hist.plot(k, speed, "o", color="C3" if turned_back else "C0")
ax_hist.plot([], [], "o", color="C0", label="stops (no reversal)")
ax_hist.plot([], [], "o", color="C3", label="turns back")
ax_hist.axhspan(result.lo, result.hi, color="0.8", label="final bracket")
ax_hist.set_xlabel("evaluation number")
ax_hist.set_ylabel("impact speed (m/s)")
ax_hist.set_title(f"Vcr search: p2, soil, 45 deg; Vcr = {result.value:.0f} m/s")
ax_hist.legend()

ax_path.axhspan(-12.0, 0.0, color="tan", alpha=0.3)
for v, ds in zip(speeds, runs, strict=True):
    style = "-" if ds.attrs["reversed"] else "--"
    ax_path.plot(ds["tip_x"], ds["tip_y"], style, label=f"{v:.1f} m/s, {ds.attrs['outcome']}")
ax_path.set_aspect("equal")
ax_path.set_xlabel("x, along the surface (m)")
ax_path.set_ylabel("y, height above the surface (m)")
ax_path.set_title("nose-tip paths")
ax_path.legend(loc="lower left", fontsize="small")
plt.show()
