"""Rules s4_study and s4_part_<study>_<k>: one Section 4 study, or the parts of a split
study that one job runs (one output each).

Thin adapter to pencore.studies.config.from_config; the study is params.kind, the
parts (if any) are those of params.parts (every part of the study, by name: {"projectile":
"p2"} or with "obliquity" in deg) named by the job's outputs (results/<folder>/parts/<name>.nc).
"""

import time
from pathlib import Path

from _common import start_log

from pencore.io.netcdf import write_netcdf
from pencore.studies.config import from_config

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
kind = smk.params.kind
log = start_log(smk, f"section4_{kind}")

cfg = smk.params.config


def run(part, out):
    """Compute the study (or one part of it) and write it to ``out``."""
    log.info("study %s %s; config %s", kind, part or "", cfg)
    t0 = time.perf_counter()
    ds = from_config(kind, cfg["study"], cfg["shared"], cfg["numerics"], **part)
    log.info("computed in %.1f s: %s", time.perf_counter() - t0, dict(ds.sizes))
    for name in ("status", "nose_direction"):
        if name in ds:
            log.info("%s:\n%s", name, ds[name].to_series().to_string())
    for name in ("vcr", "vci", "omega_c", "final_deviation", "alpha", "delta_theta"):
        if name in ds:
            unit = ds[name].attrs.get("units", "")
            log.info("%s (%s):\n%s", name, unit, ds[name].to_series().to_string())
    write_netcdf(
        ds,
        out,
        config_slice={
            f"section4.{kind}": cfg["study"],
            "section4 shared": cfg["shared"],
            "numerics": cfg["numerics"],
            "part": part,
        },
        study=f"section4/{kind}",
    )


if "parts" in smk.params.keys():
    outputs = [smk.output.nc] if isinstance(smk.output.nc, str) else smk.output.nc
    for out in outputs:
        run(dict(smk.params.parts[Path(out).stem]), out)
else:
    run({}, smk.output.nc)
