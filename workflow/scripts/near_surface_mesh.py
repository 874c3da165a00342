"""Rule near_surface_mesh: thin adapter to pencore.studies.perforation.mesh_check (the map
against the same map on finer rings, cell by cell)."""

from _common import start_log

from pencore.io.netcdf import read_netcdf, write_netcdf
from pencore.studies.perforation.mesh_check import mesh_check
from pencore.studies.perforation.obliquity import combine_maps

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "near_surface_mesh")

study = dict(smk.params.study)
parts = {p.rsplit("/", 1)[-1].removesuffix(".nc"): p for p in smk.input.parts}
fine = combine_maps([read_netcdf(parts[name]) for name in study["options"]])
check = mesh_check(read_netcdf(smk.input.map), fine, float(study["mesh_factor"]))
config_slice = {"near_surface": study, "numerics": dict(smk.params.numerics)}
write_netcdf(check, smk.output[0], config_slice=config_slice, study="near_surface/mesh_check")
bad = check["reason"].to_series()
bad = bad[bad != ""]
log.info(
    "ring-mesh check: %d of %d cells converged on %gx the rings%s",
    check.attrs["n_converged"],
    check.attrs["n_cells"],
    check.attrs["mesh_factor"],
    "".join(f"\n  {k}: {v}" for k, v in bad.items()),
)
