"""Rule archive_dataset: thinned, compressed copy of a study dataset for results/archive/."""

import json

from _common import start_log

from pencore.io.netcdf import downsample, read_netcdf, write_netcdf

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "archive")

ds = read_netcdf(smk.input[0])
study = ds.attrs.get("study", "unknown")
# keep the provenance of the run that made the dataset; write_netcdf records the archive
# step's own on top, so the original configuration travels under `source_*`.
source = {
    k: ds.attrs.get(k, "")
    for k in ("config_json", "config_sha256", "git_commit", "git_dirty", "created_utc")
}
thin = downsample(ds, smk.params.max_points)
thin.attrs.update({f"source_{k}": v for k, v in source.items()})
write_netcdf(
    thin,
    smk.output[0],
    config_slice=json.loads(source["config_json"] or "{}"),
    study=study,
)
log.info("%s -> %s (%s)", smk.input[0], smk.output[0], dict(thin.sizes))
