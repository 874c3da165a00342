"""Rule near_surface_figure: the map, ratio and ring-mesh check datasets -> pencore.plotting."""

from _common import start_log

from pencore import plotting
from pencore.io.netcdf import read_netcdf

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "near_surface_figure")

fig = plotting.plot_ballistic_map(
    read_netcdf(smk.input.map), read_netcdf(smk.input.cmp), read_netcdf(smk.input.mesh)
)
written = plotting.save_figure(fig, smk.output.png, smk.output.pdf)
log.info("wrote %s", ", ".join(map(str, written)))
