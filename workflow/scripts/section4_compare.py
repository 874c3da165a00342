"""Rule s4_paper_comparison: the paper's numbers and trends beside pencore's (CSV)."""

import pandas as pd
from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.netcdf import read_netcdf
from pencore.paper.claims import load_claims
from pencore.studies.comparison import paper_comparison

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, "paper_comparison")

datasets = {k: read_netcdf(v) for k, v in smk.input.items() if k not in ("table2", "claims")}
table2 = pd.read_csv(smk.input.table2)
claims = load_claims(smk.input.claims)
log.info("%d claims from %s", len(claims), smk.input.claims)
df = paper_comparison(
    datasets=datasets,
    claims=claims,
    table2=table2,
    yaw_convention=smk.params.yaw_convention,
)
atomic_write_text(smk.output.csv, df.to_csv(index=False, float_format="%.6g"), suffixes=(".csv",))
with pd.option_context("display.width", 200, "display.max_colwidth", 90):
    log.info("comparison with the paper:\n%s", df.to_string(index=False))
