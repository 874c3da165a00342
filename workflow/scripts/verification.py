"""Rule verification: thin adapter to pencore.studies.validation.depth.verification."""

from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import write_netcdf
from pencore.io.outputs import TEXT_SUFFIXES
from pencore.studies.validation.depth import velocity_grid, verification, verification_summary

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "verification")

study = dict(smk.params.study)
ds = verification(study["cases"], velocity_grid(**study["velocities_m_s"]), smk.params.numerics)
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={"validation.verification": study, "numerics": dict(smk.params.numerics)},
    study="validation/verification",
)
summary = verification_summary(ds)
atomic_write_text(smk.output.summary, summary + "\n", suffixes=TEXT_SUFFIXES)
print(summary)
log.info("pencore against the closed form:\n%s", summary)
