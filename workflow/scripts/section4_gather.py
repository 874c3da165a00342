"""Rule s4_gather: join the per-job parts of a split Section 4 study into one dataset."""

from _common import start_log

from pencore.io.netcdf import read_netcdf, write_netcdf
from pencore.studies.config import gather

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
kind = smk.params.kind
log = start_log(smk, f"section4_{kind}_gather")

parts = [read_netcdf(p) for p in smk.input.parts]
ds = gather(kind, parts)
cfg = smk.params.config
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        f"section4.{kind}": cfg["study"],
        "section4 shared": cfg["shared"],
        "numerics": cfg["numerics"],
    },
    study=f"section4/{kind}",
)
log.info("%d parts -> %s %s", len(parts), smk.output.nc, dict(ds.sizes))
if "status" in ds:
    log.info("status:\n%s", ds["status"].to_series().to_string())
