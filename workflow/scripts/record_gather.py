"""Rule concrete_record: thin adapter to pencore.studies.validation.record (gather_record,
record_statistics, statistics_table)."""

from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import file_sha256, read_netcdf, write_netcdf
from pencore.studies.validation.record import (
    gather_record,
    record_rows_to_score,
    record_statistics,
    statistics_table,
)

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "concrete_record")

study = dict(smk.params.study)
rows = record_rows_to_score(every=int(study["every"]))
ds = gather_record([read_netcdf(p) for p in smk.input.parts], rows)
stats = record_statistics(ds)
provenance = {
    "concrete_record": study,
    "inputs": {f: file_sha256(f) for f in [smk.input.csv, *smk.input.parts]},
}
write_netcdf(ds, smk.output.nc, config_slice=provenance, study="validation/concrete_record")
write_netcdf(
    stats, smk.output.stats, config_slice=provenance, study="validation/concrete_record_stats"
)
atomic_write_text(
    smk.output.csv,
    statistics_table(stats).to_csv(index=False, float_format="%.6g"),
    suffixes=(".csv",),
)
log.info("best law on held-out sources: %s", stats.attrs["best_law"])
log.info("it loses in: %s", stats.attrs["best_law_loses"] or "no bin")
