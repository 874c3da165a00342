"""Rules s4_study and s4_part: one Section 4 study (or one part of a split study).

Thin adapter to pencore.studies.config.from_config; the study is params.kind, the
part (if any) comes from the output's `part` wildcard: `p2` or `p2_30` (projectile,
obliquity in degrees).
"""

import time

from _common import start_log

from pencore.io.netcdf import write_netcdf
from pencore.studies.config import from_config

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
kind = smk.params.kind
log = start_log(smk.log[0], f"section4_{kind}")

cfg = smk.params.config
part = {}
if "part" in smk.wildcards.keys():
    projectile, _, obliquity = smk.wildcards.part.partition("_")
    part["projectile"] = projectile
    if obliquity:
        part["obliquity"] = float(obliquity)
log.info("study %s %s; config %s", kind, part or "", cfg)
t0 = time.perf_counter()
ds = from_config(kind, cfg["study"], cfg["shared"], cfg["numerics"], **part)
log.info("computed in %.1f s: %s", time.perf_counter() - t0, dict(ds.sizes))
for name in ("status", "nose_direction"):
    if name in ds:
        log.info("%s:\n%s", name, ds[name].to_series().to_string())
for name in ("vcr", "vci", "omega_c", "final_deviation", "alpha", "delta_theta"):
    if name in ds:
        log.info(
            "%s (%s):\n%s", name, ds[name].attrs.get("units", ""), ds[name].to_series().to_string()
        )
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        f"section4.{kind}": cfg["study"],
        "section4 shared": cfg["shared"],
        "numerics": cfg["numerics"],
        "part": part,
    },
    study=f"section4/{kind}",
)
