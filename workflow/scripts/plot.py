"""Figure rules: dataset -> pencore.plotting.plot_<kind> -> PNG and PDF."""

from _common import start_log

from pencore import plotting
from pencore.io.netcdf import read_netcdf

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, f"plot_{smk.params.kind}")

ds = read_netcdf(smk.input.nc)
fig = getattr(plotting, f"plot_{smk.params.kind}")(ds)
written = plotting.save_figure(fig, smk.output.png, smk.output.pdf)
log.info("wrote %s", ", ".join(map(str, written)))
