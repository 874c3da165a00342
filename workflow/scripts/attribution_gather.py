"""Rule attribution_gather: thin adapter to pencore.studies.attribution.settings.gather/table."""

import pandas as pd
from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import read_netcdf, write_netcdf
from pencore.studies.attribution.settings import attribution_table, gather

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "attribution_gather")

ds = gather([read_netcdf(p) for p in smk.input.parts])
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={"attribution.settings": list(smk.params.settings)},
    study="attribution",
)
table = attribution_table(ds)
atomic_write_text(smk.output.csv, table.to_csv(index=False), suffixes=(".csv",))
with pd.option_context("display.width", 250, "display.max_colwidth", 60):
    log.info("attribution:\n%s", table.to_string(index=False))
