"""Rule near_surface_map: thin adapter to pencore.studies.obliquity."""

from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.obliquity import (
    ballistic_map,
    compare_obliquity,
    load_oblique,
    obliquity_summary,
)

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk.log[0], "near_surface_map")

study = dict(smk.params.study)
bl_map = ballistic_map(
    study["projectile"],
    study["medium"],
    study["t_over_d"],
    study["obliquity_deg"],
    {k: dict(v) for k, v in dict(study["options"]).items()},
    lo=study["search_m_s"]["min"],
    hi=study["search_m_s"]["max"],
    tol=study["velocity_tol_m_s"],
    scan=study["scan_points"],
    numerics=smk.params.numerics,
)
cmp = compare_obliquity(load_oblique(smk.input.csv), bl_map)
config_slice = {
    "near_surface": study,
    "numerics": dict(smk.params.numerics),
    "inputs": {smk.input.csv: file_sha256(smk.input.csv)},
}
write_netcdf(bl_map, smk.output.map, config_slice=config_slice, study="near_surface/map")
write_netcdf(cmp, smk.output.cmp, config_slice=config_slice, study="near_surface/ratio")
log.info("obliquity ratio against measurements:\n%s", obliquity_summary(cmp))
