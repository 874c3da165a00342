"""Rule near_surface_mesh_part: thin adapter to
pencore.studies.perforation.obliquity.ballistic_map for one option set on the finer ring
mesh of the map's check (pencore.studies.perforation.mesh_check.finer_rings)."""

from _common import start_log

from pencore.io.netcdf import write_netcdf
from pencore.studies.perforation.mesh_check import finer_rings
from pencore.studies.perforation.obliquity import ballistic_map

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, f"near_surface_mesh_part {smk.wildcards.option}")

study = dict(smk.params.study)
numerics = finer_rings(dict(smk.params.numerics), float(study["mesh_factor"]))
part = ballistic_map(
    study["projectile"],
    study["medium"],
    study["t_over_d"],
    study["obliquity_deg"],
    {k: dict(v) for k, v in dict(study["options"]).items()},
    lo=study["search_m_s"]["min"],
    hi=study["search_m_s"]["max"],
    tol=study["velocity_tol_m_s"],
    scan=study["scan_points"],
    numerics=numerics,
)
config_slice = {"near_surface": study, "numerics": dict(smk.params.numerics)}
write_netcdf(part, smk.output[0], config_slice=config_slice, study="near_surface/mesh_part")
