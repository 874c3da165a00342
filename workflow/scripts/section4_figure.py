"""Rules s4_<study>_figure: dataset -> pencore.plotting.PLOTS -> PNG and PDF."""

from _common import start_log

from pencore.io.netcdf import read_netcdf
from pencore.plotting import PLOTS
from pencore.plotting.style import save_figure

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, f"plot_{smk.params.kind}")

ds = read_netcdf(smk.input.nc)
fig = PLOTS[smk.params.kind](ds)
written = save_figure(fig, smk.output.png, smk.output.pdf)
log.info("wrote %s", ", ".join(map(str, written)))
