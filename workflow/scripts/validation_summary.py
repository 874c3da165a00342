"""Rule validation_summary: thin adapter to
pencore.studies.validation.measurements.summary_table."""

from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import read_netcdf
from pencore.studies.validation.measurements import summary_table

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "validation_summary")

table = summary_table(read_netcdf(smk.input.measurements), read_netcdf(smk.input.ratios))
atomic_write_text(
    smk.output.csv, table.to_csv(index=False, float_format="%.6g"), suffixes=(".csv",)
)
log.info("validation summary:\n%s", table.to_string(index=False))
