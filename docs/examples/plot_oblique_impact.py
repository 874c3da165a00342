"""
An oblique impact and its trajectory
====================================

This example runs one steep oblique impact of the paper's projectile #2 into the soil
target (the speed and obliquity are in the first code cell), and reads the results from the
:class:`xarray.Dataset` that :func:`pencore.simulate` returns.

The conventions are those of :func:`pencore.simulate`: the target fills ``y <= 0``, the
projectile moves towards ``+x`` and ``-y``, and the obliquity is the angle between the
projectile axis and the target normal (``-y``). Inside pencore every quantity is in SI
units; angles are in degrees at the user-facing edges (the arguments and the Dataset).
"""

# %%
# Run the impact
# --------------
# The projectile and the target can be given by name (``pencore list`` prints the
# library), by the path of a YAML file, or as objects. ``simulate`` integrates the rigid
# body motion under the differential area force law until the projectile stops, turns
# back out of the target, or perforates a finite target.

import matplotlib.pyplot as plt
import numpy as np

import pencore

velocity, obliquity = 1200.0, 60.0  # m/s, deg
ds = pencore.simulate("p2", "soil", velocity=velocity, obliquity=obliquity)

# %%
# What the Dataset holds
# ----------------------
# The time histories live on the dimension ``time`` (s); the scalar results (depth, path
# length, final slope and deviation) are 0-d variables; the inputs and the run's
# bookkeeping are attributes. Every variable carries its ``units`` and ``long_name``.

for name, var in ds.data_vars.items():
    print(f"{name:18s} [{var.attrs.get('units', '')}] {var.attrs.get('long_name', '')}")

# %%
# The scalar results, printed with the units stored in the Dataset. The ``outcome`` is
# ``stopped``, ``exited`` (turned back out through the surface), ``reversed`` (only with
# ``stop_at_reversal=True``) or ``perforated``.


def show(name: str) -> None:
    """Print a 0-d variable of ``ds`` with its long name and units."""
    var = ds[name]
    print(f"{var.attrs['long_name']}: {float(var):.3f} {var.attrs['units']}")


print(f"outcome: {ds.attrs['outcome']}; turned back: {bool(ds.attrs['reversed'])}")
print(
    f"projectile {ds.attrs['projectile']}: mass {ds.attrs['mass_kg']:.2f} kg, "
    f"length {ds.attrs['length_m']:.3f} m, Lc/L {ds.attrs['lc_over_l']:.3f} (dimensionless)"
)
for name in ("penetration_depth", "path_length", "final_deviation"):
    show(name)
print(f"duration of the run: {float(ds['time'][-1]) * 1e3:.2f} ms ({ds.attrs['n_steps']} steps)")

# %%
# The final state is the last time sample. The centre of mass has almost stopped
# (the run ends below a small stopping speed), and the nose now points further from the
# normal than at impact: the trajectory has curved towards the surface.

last = ds.isel(time=-1)
print(f"final nose tip: x = {float(last['tip_x']):.3f} m, y = {float(last['tip_y']):.3f} m")
print(f"final speed: {float(last['speed']):.3f} {ds['speed'].attrs['units']}")
print(f"final axis angle from the normal: {float(last['theta']):.2f} {ds['theta'].attrs['units']}")

# %%
# Plot the trajectory
# -------------------
# Left: the paths of the nose tip and the centre of mass in the impact plane, with the
# projectile's axis drawn every 5 ms (from the tip back along ``axis_x``, ``axis_y`` over
# the body length). Middle: the speed of the centre of mass against time. Right: the
# axis angle ``theta`` and the velocity angle ``deviation`` from the normal, on a
# logarithmic time axis: the projectile turns while the nose enters, in the first few
# milliseconds, and then runs nearly straight until it stops.

length = ds.attrs["length_m"]
fig, (ax_path, ax_speed, ax_angle) = plt.subplots(1, 3, figsize=(13, 4.2), layout="constrained")

ax_path.axhspan(float(ds["tip_y"].min()) - 1.0, 0.0, color="tan", alpha=0.3, label="soil")
ax_path.plot(ds["tip_x"], ds["tip_y"], label="nose tip")
ax_path.plot(ds["cm_x"], ds["cm_y"], "--", label="centre of mass")
t = ds["time"].values
for t_mark in np.arange(0.0, t[-1], 5e-3):
    k = int(np.searchsorted(t, t_mark))
    tip = np.array([ds["tip_x"][k], ds["tip_y"][k]])
    axis = np.array([ds["axis_x"][k], ds["axis_y"][k]])
    tail = tip - length * axis
    ax_path.plot([tip[0], tail[0]], [tip[1], tail[1]], color="k", lw=3, solid_capstyle="butt")
ax_path.set_aspect("equal")
ax_path.set_xlabel("x, along the surface (m)")
ax_path.set_ylabel("y, height above the surface (m)")
ax_path.set_title(f"p2 into soil, {velocity:g} m/s, {obliquity:g} deg")
ax_path.legend(loc="lower left")

ax_speed.plot(ds["time"] * 1e3, ds["speed"])
ax_speed.set_xlabel("time (ms)")
ax_speed.set_ylabel("speed of the centre of mass (m/s)")

later = ds.isel(time=slice(1, None))  # t = 0 has no place on a log axis
ax_angle.semilogx(later["time"] * 1e3, later["theta"], label="axis, theta")
ax_angle.semilogx(later["time"] * 1e3, later["deviation"], "--", label="velocity")
ax_angle.set_xlabel("time (ms)")
ax_angle.set_ylabel("angle from the target normal (deg)")
ax_angle.legend()
plt.show()
