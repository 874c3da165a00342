"""
Reading the archived results
============================

The workflow writes every study as a CF-convention netCDF file, and the repository
keeps a copy of the reference run under ``results/archive``. Each file is an
:class:`xarray.Dataset` with units and long names on every variable and its provenance
(git commit, configuration and its hash, creation time) in the attributes, so a result
can be read and plotted without running anything.

This example reads the paper's Fig. 8 study, the critical reverse velocity Vcr of the
four projectiles against obliquity, and sets it beside what the paper states, read from
``config/paper_claims.csv`` (the file that holds every number and trend of the paper
that pencore computes, each with where the paper states it).
"""

# %%
# Find the repository
# -------------------
# The archive is not part of the installed package; it lives in the repository. The
# script finds the repository's root by walking up from its own location (or, when run
# where ``__file__`` is not defined, from the working directory) to ``pyproject.toml``.

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import pencore
from pencore.io.netcdf import read_netcdf
from pencore.paper.claims import at, load_claims


def repository_root() -> Path:
    """The nearest folder above this script (or the working directory) that holds
    ``pyproject.toml``."""
    try:
        start = Path(__file__).resolve().parent
    except NameError:  # run interactively, e.g. as a notebook
        start = Path.cwd().resolve()
    for folder in (start, *start.parents):
        if (folder / "pyproject.toml").is_file():
            return folder
    raise FileNotFoundError(f"no pyproject.toml above {start}: run this inside the repository")


root = repository_root()
archive = root / "results" / "archive"
for path in sorted(archive.rglob("*.nc")):
    print(path.relative_to(archive))

# %%
# Read the Fig. 8 study
# ---------------------
# :func:`pencore.io.netcdf.read_netcdf` reads the file into memory and closes it. Vcr
# is on the dimensions ``(projectile, obliquity)``; ``vcr_lo`` and ``vcr_hi`` are the
# ends of each search's final bracket, ``status`` says whether the search converged and
# ``history`` holds every speed it evaluated.

vcr = read_netcdf(archive / "fig8" / "vcr.nc")
for name in ("vcr", "vcr_lo", "vcr_hi", "status"):
    var = vcr[name]
    print(f"{name:7s} {var.dims} [{var.attrs.get('units', '')}] {var.attrs.get('long_name', '')}")
print(f"target: {vcr.attrs['target']}; search tolerance {vcr.attrs['tolerance_m_s']:g} m/s")
print(
    f"written by pencore {vcr.attrs['pencore_version']} at git commit "
    f"{vcr.attrs['git_commit'][:10]} on {vcr.attrs['created_utc']}"
)
print("every search converged:", bool((vcr["status"] == "ok").all()))

# %%
# The values themselves, in m/s, one row per projectile with its centre-of-mass
# position ``Lc/L`` (dimensionless):

table = vcr["vcr"].to_pandas().round(1)
lc_over_l = vcr["lc_over_l"].values
table.index = [f"{p} (Lc/L {lc:.3f})" for p, lc in zip(table.index, lc_over_l, strict=True)]
table.columns = [f"{o:g} deg" for o in table.columns]
print(f"Vcr ({vcr['vcr'].attrs['units']}) against obliquity:")
print(table.to_string())

# %%
# What the paper states
# ---------------------
# The claims of the Fig. 8 study: a bracket for Vcr of #2 at 45 degrees (derived from
# two runs the paper reports, one that does not turn back and one that does) and two
# trends. The archived comparison table, ``results/archive/paper_comparison.csv``, holds
# pencore's verdict on each.

claims = load_claims(root / "config" / "paper_claims.csv")
fig8_claims = claims[claims["study"] == "fig8/vcr"]
comparison = pencore.read_table(archive / "paper_comparison.csv")  # pencore's CSV reader
for c in fig8_claims.to_dict("records"):
    rows = comparison[comparison["claim"] == c["id"]]
    for row in rows.to_dict("records"):
        units = f" {row['units']}" if isinstance(row["units"], str) else ""
        print(f"{row['quantity']} ({c['where']}):")
        print(f"  paper {row['paper_value']}{units}, pencore {row['pencore_value']}{units}")
        print(f"  {row['note']}")

# %%
# Plot
# ----
# Left: Vcr against obliquity for each projectile, with the paper's bracket for #2 at
# 45 degrees. Right: the same values against ``Lc/L`` at each obliquity, the paper's
# second trend. The search brackets (at most the search tolerance wide) are smaller
# than the markers.

fig, (ax_obl, ax_lc) = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
for p in vcr["projectile"].values:
    row = vcr.sel(projectile=p)
    err = np.array([row["vcr"] - row["vcr_lo"], row["vcr_hi"] - row["vcr"]])
    label = f"{p}, Lc/L = {float(row['lc_over_l']):.3f}"
    ax_obl.errorbar(row["obliquity"], row["vcr"], yerr=err, marker="o", ms=4, label=label)

for c in fig8_claims[fig8_claims["kind"] == "bracket"].to_dict("records"):
    where = at(c["at"])[0]
    lo, hi = float(c["value"]), float(c["value_hi"])
    ax_obl.errorbar(
        float(where["obliquity"]),
        (lo + hi) / 2,
        yerr=(hi - lo) / 2,
        fmt="none",
        ecolor="k",
        elinewidth=2,
        capsize=6,
        zorder=5,
        label=f"paper: {where['projectile']}, Vcr in ({lo:g}, {hi:g}] m/s",
    )
ax_obl.set_xlabel("obliquity (deg)")
ax_obl.set_ylabel("critical reverse velocity Vcr (m/s)")
ax_obl.set_title(f"Fig. 8: Vcr in {vcr.attrs['target']} (archived run)")
ax_obl.legend(fontsize="small")

colours = plt.cm.viridis(np.linspace(0.0, 0.9, vcr.sizes["obliquity"]))
for colour, obl in zip(colours, vcr["obliquity"].values, strict=True):
    col = vcr.sel(obliquity=obl)
    ax_lc.plot(col["lc_over_l"], col["vcr"], "o-", color=colour, ms=4, label=f"{obl:g} deg")
ax_lc.set_xlabel("centre of mass position Lc/L (dimensionless)")
ax_lc.set_ylabel("critical reverse velocity Vcr (m/s)")
ax_lc.set_title("Vcr against Lc/L, one line per obliquity")
ax_lc.legend(fontsize="small", ncols=3)
plt.show()
