"""Rule measurements_options: thin adapter to
pencore.studies.validation.measurements.statistics_by_option."""

from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation.measurements import statistics_by_option

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "measurements_options")

entries = [dict(e) for e in smk.params.study]
options = {k: dict(v) for k, v in dict(smk.params.options).items()}
ds = statistics_by_option(entries, options, smk.params.numerics)
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        "validation.measurements": entries,
        "validation.measurement_options": options,
        "numerics": dict(smk.params.numerics),
        "inputs": {f: file_sha256(f) for f in smk.input.csv},
    },
    study="validation/measurements_options",
)
for o in ds["option"].values:
    for g in ds["group"].values:
        s = {
            k[5:]: float(ds[k].sel(option=o, group=g))
            for k in ds.data_vars
            if k.startswith("stat_")
        }
        log.info("%s, %s: %s", o, g, ", ".join(f"{k} = {v:.4g}" for k, v in s.items()))
