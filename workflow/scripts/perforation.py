"""Rules perforation_*: thin adapter to pencore.studies.perforation.slabs."""

from _common import start_log

from pencore.io.netcdf import write_netcdf
from pencore.studies.perforation.slabs import ballistic_limit_map, residual_velocity_curve
from pencore.studies.validation.depth import velocity_grid

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
kind = smk.params.kind
log = start_log(smk, f"perforation_{kind}")

study = dict(smk.params.study)
common = dict(
    crater_depth=study["crater_depth"],
    free_surface_depth=study["free_surface_depth"],
    lo=study["search_m_s"]["min"],
    hi=study["search_m_s"]["max"],
    tol=study["velocity_tol_m_s"],
    numerics=smk.params.numerics,
)
if kind == "ballistic_limit":
    grid = study["ballistic_limit"]
    ds = ballistic_limit_map(
        study["projectile"],
        study["medium"],
        grid["thickness_m"],
        grid["obliquity_deg"],
        scan=study["scan_points"],
        **common,
    )
else:
    rv = study["residual_velocity"]
    ds = residual_velocity_curve(
        study["projectile"],
        study["medium"],
        rv["thickness_m"],
        velocity_grid(**rv["velocities_m_s"]),
        obliquity=rv["obliquity_deg"],
        **common,
    )
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={"perforation": study, "numerics": dict(smk.params.numerics)},
    study=f"perforation/{kind}",
)
log.info("wrote %s", smk.output.nc)
