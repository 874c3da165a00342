"""Rule fig5 (paper Fig. 5): thin adapter to pencore.studies.validation.fig5."""

import pandas as pd
from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation import fig5, velocity_grid

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk.log[0], "fig5")

study = dict(smk.params.study)
experiments = pd.read_csv(smk.input.experiments, comment="#")
log.info("%d experimental points in %s", len(experiments), smk.input.experiments)
if experiments.empty:
    log.warning("no experimental points: Fig. 5 shows pencore and the closed form only")
ds = fig5(
    study["cases"],
    velocity_grid(**study["velocities_m_s"]),
    smk.params.numerics,
    experiments=experiments,
)
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        "validation.fig5": study,
        "numerics": dict(smk.params.numerics),
        "inputs": {smk.input.experiments: file_sha256(smk.input.experiments)},
    },
    study="validation/fig5",
)
log.info("pencore depth (m):\n%s", ds["pencore_depth"].to_pandas().to_string())
log.info("largest |pencore - closed form| / closed form = %.3e", float(abs(ds["rel_diff"]).max()))
