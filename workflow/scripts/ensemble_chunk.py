"""Rule ensemble_chunk: thin adapter to pencore.studies.ensemble.run_chunk."""

import time

from _common import start_log

from pencore.inputs.numerics import resolve_numerics
from pencore.io.netcdf import write_netcdf
from pencore.studies.ensemble import run_chunk

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
case = dict(smk.params.case)
chunk = int(smk.wildcards.chunk)
log = start_log(smk, f"ensemble_{case['name']}_{chunk}")
t0 = time.perf_counter()
ds = run_chunk(case, chunk, resolve_numerics(smk.params.numerics))
log.info("chunk %d of %d: %d samples in %.1f s", chunk, case["n_chunks"], ds.sizes["sample"],
         time.perf_counter() - t0)  # fmt: skip
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={"ensemble.case": case, "numerics": dict(smk.params.numerics)},
    study=f"ensemble/{case['name']}",
)
