"""Rule measurements: thin adapter to
pencore.studies.validation.measurements.measured_vs_predicted."""

from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation.measurements import measured_vs_predicted

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "measurements")

entries = [dict(e) for e in smk.params.study]
ds = measured_vs_predicted(entries, smk.params.numerics)
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        "validation.measurements": entries,
        "numerics": dict(smk.params.numerics),
        "inputs": {f: file_sha256(f) for f in smk.input.csv},
    },
    study="validation/measurements",
)
log.info(
    "measured vs predicted:\n%s",
    ds[["measured", "predicted", "rel_error", "outcome"]].to_dataframe().to_string(),
)
for q in ds["quantity"].values:
    s = {k[5:]: float(ds[k].sel(quantity=q)) for k in ds.data_vars if k.startswith("stat_")}
    log.info("%s: %s", q, ", ".join(f"{k} = {v:.4g}" for k, v in s.items()))
