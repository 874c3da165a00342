"""Rule near_surface_map: thin adapter to pencore.studies.perforation.obliquity (the option
sets' maps joined, and the measured obliquity ratios against them)."""

from _common import start_log

from pencore.io.netcdf import file_sha256, read_netcdf, write_netcdf
from pencore.studies.perforation.obliquity import (
    combine_maps,
    compare_obliquity,
    load_oblique,
    obliquity_summary,
)

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "near_surface_map")

study = dict(smk.params.study)
# in the configured order of the option sets
parts = {p.rsplit("/", 1)[-1].removesuffix(".nc"): p for p in smk.input.parts}
bl_map = combine_maps([read_netcdf(parts[name]) for name in study["options"]])
cmp = compare_obliquity(load_oblique(smk.input.csv), bl_map)
config_slice = {
    "near_surface": study,
    "numerics": dict(smk.params.numerics),
    "inputs": {smk.input.csv: file_sha256(smk.input.csv)},
}
write_netcdf(bl_map, smk.output.map, config_slice=config_slice, study="near_surface/map")
write_netcdf(cmp, smk.output.cmp, config_slice=config_slice, study="near_surface/ratio")
log.info("obliquity ratio against measurements:\n%s", obliquity_summary(cmp))
