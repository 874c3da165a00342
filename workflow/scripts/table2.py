"""Rule table2 (paper Table 2, soil): thin adapter to pencore.studies.validation.table2 (the
runs and the selection, :func:`table2`; the candidates' table, :func:`selection_table`)."""

import pandas as pd
from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation.table2 import selection_table, table2

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "table2")

study = dict(smk.params.study)
rows = pd.read_csv(smk.input.rows, comment="#")
log.info(
    "%d tests from %s; candidates %s x %s",
    len(rows),
    smk.input.rows,
    study["projectiles"],
    study["depth_measures"],
)
table, ds = table2(
    rows,
    smk.params.numerics,
    projectiles=study["projectiles"],
    target=study["target"],
    measures=study["depth_measures"],
)

selection = selection_table(ds, study["depth_measures"])

atomic_write_text(
    smk.output.csv, table.to_csv(index=False, float_format="%.6g"), suffixes=(".csv",)
)
atomic_write_text(
    smk.output.selection, selection.to_csv(index=False, float_format="%.6g"), suffixes=(".csv",)
)
write_netcdf(
    ds,
    smk.output.nc,
    config_slice={
        "validation.table2": study,
        "numerics": dict(smk.params.numerics),
        "inputs": {smk.input.rows: file_sha256(smk.input.rows)},
    },
    study="validation/table2",
)
log.info("selected %s", ds.attrs["selection_rule"])
log.info(
    "-> projectile %s, depth measure %s (RMS relative difference %.4f)",
    ds.attrs["chosen_projectile"],
    ds.attrs["chosen_depth_measure"],
    ds.attrs["chosen_rms_rel_diff"],
)
log.info(
    "candidates (RMS relative difference from the paper's predicted column):\n%s",
    selection.to_string(index=False),
)
log.info("table:\n%s", table.to_string(index=False))
