"""Rule fig5 (paper Fig. 5): thin adapter to pencore.studies.validation.depth.fig5."""

from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation.depth import fig5, velocity_grid

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "fig5")

study = dict(smk.params.study)
shots = list(smk.input.shots)
body_shots = dict(study.get("body_shots", {}))
ds = fig5(
    study["cases"],
    velocity_grid(**study["velocities_m_s"]),
    smk.params.numerics,
    shots=shots,
    body_shots=body_shots,
)
log.info("%d measured shots from %s", ds.sizes["experiment"], ", ".join(shots) or "no file")
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        "validation.fig5": study,
        "numerics": dict(smk.params.numerics),
        "inputs": {f: file_sha256(f) for f in [*shots, *body_shots]},
    },
    study="validation/fig5",
)
log.info("pencore depth (m):\n%s", ds["pencore_depth"].to_pandas().to_string())
log.info("largest |pencore - closed form| / closed form = %.3e", float(abs(ds["rel_diff"]).max()))
