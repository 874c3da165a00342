"""
Your own projectile and a layered target from YAML
==================================================

Projectiles and targets are plain YAML files in SI units, the same files the command
line takes (``pencore simulate --projectile my.yaml --target layers.yaml ...``). This
example writes two such files, loads them with :func:`pencore.get_projectile` and
:func:`pencore.get_target` (the loaders behind the command line), and fires the
projectile into the layered target at two obliquities.
"""

# %%
# The projectile
# --------------
# A body of revolution: a nose (``ogive`` with its ``crh``, ``cone`` with its
# ``half_angle_deg``, or ``flat``) followed by cylindrical shank segments, each with its
# own density. Here a 50 mm steel cone-nosed penetrator with an aluminium tail, which
# moves the centre of mass forwards. Lengths in m, densities in kg/m3.

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import pencore

PROJECTILE_YAML = """\
name: cone-50mm
diameter: 0.050                                    # m
nose: {kind: cone, half_angle_deg: 20, density: 7850}
shank:
  - {length: 0.20, density: 7850}                  # steel body, m and kg/m3
  - {length: 0.15, density: 2700}                  # aluminium tail
source: example projectile of the pencore gallery
"""

# %%
# The target
# ----------
# Layers from the surface down: a 0.3 m slab of the shipped concrete, a 0.5 m air gap,
# 1 m of a user-defined crust, and the shipped soil below (no ``thickness``: the last
# layer is semi-infinite; give it a thickness to make a plate that can be perforated).
# A medium's ``coefficients`` ``[a0, a1, a2]`` are those of the normal stress
# ``sigma_n = a0 + a1 Vn + a2 Vn^2`` (Pa, Pa s/m, kg/m3) and ``friction`` is a
# Coulomb coefficient (or a table ``[[speed_m_s, mu], ...]``).

TARGET_YAML = """\
name: slab-gap-crust-soil
layers:
  - {medium: concrete, thickness: 0.3}             # m
  - {gap: 0.5}                                     # m of air
  - thickness: 1.0
    medium: {name: crust, coefficients: [30.0e6, 0.0, 5000.0], friction: 0.1}
  - medium: soil                                   # semi-infinite
"""

# %%
# Load the files
# --------------
# The files go to a temporary directory. Errors in a file (an unknown key, a value out
# of range, a missing number) raise :class:`pencore.InputError` with one line naming the
# file, the key and the value.

with tempfile.TemporaryDirectory() as tmp:
    projectile_file = Path(tmp) / "cone-50mm.yaml"
    target_file = Path(tmp) / "layers.yaml"
    projectile_file.write_text(PROJECTILE_YAML, encoding="utf-8")
    target_file.write_text(TARGET_YAML, encoding="utf-8")
    projectile = pencore.get_projectile(str(projectile_file))
    target = pencore.get_target(str(target_file))

mp = projectile.mass_properties()
print(f"{projectile.name}: mass {mp.mass:.3f} kg, length {mp.length:.3f} m")
print(f"  centre of mass {mp.lc:.3f} m behind the tip, Lc/L = {mp.lc_over_l:.3f} (dimensionless)")
print(f"  moments of inertia: axial {mp.i_axial:.3e} kg m2, transverse {mp.i_transverse:.3e} kg m2")
print(f"{target.name}: {len(target.layers)} layers, semi-infinite: {not target.finite}")
for layer in target.layers:
    what = "air gap" if layer.is_gap else layer.medium.name
    print(f"  {what:9s} thickness {layer.thickness:g} m")

# %%
# Run
# ---
# The objects go to :func:`pencore.simulate` like library names do. Two impacts at
# 700 m/s: a normal one and one at 30 degrees of obliquity.

runs = {
    obl: pencore.simulate(projectile, target, velocity=700.0, obliquity=obl) for obl in (0.0, 30.0)
}
for obl, ds in runs.items():
    print(
        f"obliquity {obl:4.1f} deg: {ds.attrs['outcome']}, depth "
        f"{float(ds['penetration_depth']):.3f} m, path {float(ds['path_length']):.3f} m, "
        f"final deviation {float(ds['final_deviation']):.2f} deg"
    )

# %%
# Plot
# ----
# Left: the nose-tip paths over the layers. Right: the speed of the centre of mass
# against the height of the nose tip. The rate at which the speed falls with depth
# changes at each interface, and the speed stays constant while the body crosses the air
# gap (the short drop just below the slab is the rest of the nose still in the concrete).

fig, (ax_path, ax_speed) = plt.subplots(1, 2, figsize=(11, 4.8), layout="constrained")
top, colours = 0.0, {"concrete": "0.6", "crust": "peru", "soil": "tan"}
deepest = max(float(ds["penetration_depth"]) for ds in runs.values()) + 0.5
for layer in target.layers:
    bottom = top - min(layer.thickness, deepest + top)
    if not layer.is_gap:
        name = layer.medium.name
        for ax in (ax_path, ax_speed):
            ax.axhspan(bottom, top, color=colours[name], alpha=0.4, lw=0)
        ax_path.text(
            0.98,
            (top + bottom) / 2,
            name,
            transform=ax_path.get_yaxis_transform(),
            ha="right",
            va="center",
        )
    top = bottom

for obl, ds in runs.items():
    label = f"obliquity {obl:g} deg"
    ax_path.plot(ds["tip_x"], ds["tip_y"], label=label)
    ax_speed.plot(ds["speed"], ds["tip_y"], label=label)
ax_path.set_xlabel("x, along the surface (m)")
ax_path.set_ylabel("y, height of the nose tip (m)")
ax_path.set_title(f"{projectile.name} into {target.name}, 700 m/s")
ax_path.legend(loc="lower left")
ax_speed.set_xlabel("speed of the centre of mass (m/s)")
ax_speed.set_ylabel("y, height of the nose tip (m)")
ax_speed.legend(loc="lower right")
plt.show()
