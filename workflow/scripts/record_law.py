"""Rule concrete_record_law: thin adapter to pencore.studies.validation.record.score_law."""

from _common import start_log

from pencore.io.netcdf import file_sha256, write_netcdf
from pencore.studies.validation.record import record_rows_to_score, score_law

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
law = smk.wildcards.law
log = start_log(smk, f"concrete_record_law_{law}")

study = dict(smk.params.study)
rows = record_rows_to_score(every=int(study["every"]))
ds = score_law(law, rows, smk.params.numerics, progress=log.info)
write_netcdf(
    ds,
    smk.output[0],
    config_slice={
        "concrete_record": study,
        "law": law,
        "numerics": dict(smk.params.numerics),
        "inputs": {smk.input.csv: file_sha256(smk.input.csv)},
    },
    study=f"validation/record/law_{law}",
)
log.info("%s: %d shots, outcomes %s", law, ds.sizes["shot"], sorted(set(ds["outcome"].values)))
