"""Rule ensemble_gather: thin adapter to pencore.studies.ensemble.gather."""

from _common import start_log

from pencore.io.netcdf import read_netcdf, write_netcdf
from pencore.studies.ensemble import RESULTS, gather

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
case = dict(smk.params.case)
log = start_log(smk, f"ensemble_{case['name']}_gather")
ds = gather([read_netcdf(p) for p in smk.input.parts])
write_netcdf(
    ds, smk.output.nc, config_slice={"ensemble.case": case}, study=f"ensemble/{case['name']}"
)
lo, hi = ds["p_reversed_ci95"].values
log.info("N = %d; P(turns back) = %.4f [%.4f, %.4f]", ds.sizes["sample"],
         float(ds["p_reversed"]), lo, hi)  # fmt: skip
for name, units, _ in RESULTS:
    m = ds[f"{name}_mean_ci95"].values
    log.info("%s: mean %.4g %s [%.4g, %.4g]", name, float(ds[f"{name}_mean"]), units, *m)
