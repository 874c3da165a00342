# Validation (paper Section 3) and verification studies.
#   table2        paper Table 2, soil (Forrestal & Luk 1992): selects projectile + measure
#   fig5          paper Fig. 5, concrete and aluminium, with the closed form
#   verification  pencore against pencore.closedform.depth, normal impact
#   measurements  pencore against published measurements (shipped data files with sources)
# Each study's rule gets its own config slice through params, so editing one study's
# entry reruns only that study (rerun trigger `params`).
import io

import pandas as pd

from pencore.errors import InputError
from pencore.workflowconfig.config_check import table_text

VALIDATION = config["validation"]

# Tabular inputs are checked at parse time, so a bad row fails before anything runs; a
# missing, empty or unreadable file is one line (pencore's file gate), not a traceback.
try:
    validate(
        pd.read_csv(
            io.StringIO(table_text(VALIDATION["table2"]["csv"], "validation.table2.csv")),
            comment="#",
        ),
        "../schemas/table2.schema.yaml",
    )
    for shot_table in VALIDATION["fig5"]["shots"]:
        validate(
            pd.read_csv(io.StringIO(table_text(shot_table, "validation.fig5.shots")), comment="#"),
            "../schemas/shot_table.schema.yaml",
        )
except InputError as exc:
    raise WorkflowError(str(exc)) from None


rule table2:
    input:
        rows=VALIDATION["table2"]["csv"],
    output:
        csv="results/validation/table2.csv",
        selection="results/validation/table2_selection.csv",
        nc="results/validation/table2.nc",
    log:
        "results/logs/validation/table2.log",
    benchmark:
        "results/benchmarks/validation/table2.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(VALIDATION["table2"]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/table2.py"


rule fig5:
    input:
        shots=VALIDATION["fig5"]["shots"],
        body_shots=list(VALIDATION["fig5"]["body_shots"]),
    output:
        nc="results/validation/fig5.nc",
    log:
        "results/logs/validation/fig5.log",
    benchmark:
        "results/benchmarks/validation/fig5.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(VALIDATION["fig5"]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/fig5.py"


rule verification:
    output:
        nc="results/validation/verification.nc",
        summary="results/validation/verification.txt",
    log:
        "results/logs/validation/verification.log",
    benchmark:
        "results/benchmarks/validation/verification.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(VALIDATION["verification"]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/verification.py"


rule measurements:
    input:
        csv=[entry["csv"] for entry in VALIDATION["measurements"]],
    output:
        nc="results/validation/measurements.nc",
    log:
        "results/logs/validation/measurements.log",
    benchmark:
        "results/benchmarks/validation/measurements.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(VALIDATION["measurements"]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/measurements.py"


rule measurements_options:
    input:
        csv=[entry["csv"] for entry in VALIDATION["measurements"]],
    output:
        nc="results/validation/measurements_options.nc",
    log:
        "results/logs/validation/measurements_options.log",
    benchmark:
        "results/benchmarks/validation/measurements_options.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(VALIDATION["measurements"]),
        options=canonical(VALIDATION["measurement_options"]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/measurements_options.py"


# Figures: separate rules, so restyling a plot does not rerun the solver.
rule table2_figure:
    input:
        nc="results/validation/table2.nc",
    output:
        png=report(
            "results/validation/table2.png",
            caption="../report/table2_figure.rst",
            category="1 Validation (paper Section 3)",
            subcategory="Table 2 (soil)",
            labels={"name": "Table 2", "type": "figure"},
        ),
        pdf="results/validation/table2.pdf",
    log:
        "results/logs/validation/table2_figure.log",
    benchmark:
        "results/benchmarks/validation/table2_figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="table2",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


rule fig5_figure:
    input:
        nc="results/validation/fig5.nc",
    output:
        png=report(
            "results/validation/fig5.png",
            caption="../report/fig5.rst",
            category="1 Validation (paper Section 3)",
            subcategory="Fig. 5 (concrete, aluminium)",
            labels={"name": "Fig. 5", "type": "figure"},
        ),
        pdf="results/validation/fig5.pdf",
    log:
        "results/logs/validation/fig5_figure.log",
    benchmark:
        "results/benchmarks/validation/fig5_figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="fig5",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


rule verification_figure:
    input:
        nc="results/validation/verification.nc",
    output:
        png=report(
            "results/validation/verification.png",
            caption="../report/verification.rst",
            category="3 Verification (closed form)",
            subcategory="Closed form, normal impact",
            labels={"name": "Verification", "type": "figure"},
        ),
        pdf="results/validation/verification.pdf",
    log:
        "results/logs/validation/verification_figure.log",
    benchmark:
        "results/benchmarks/validation/verification_figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="verification",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


ALL_TARGETS.extend(
    [
        "results/validation/table2.csv",
        "results/validation/table2_selection.csv",
        "results/validation/table2.nc",
        "results/validation/table2.png",
        "results/validation/table2.pdf",
        "results/validation/fig5.nc",
        "results/validation/fig5.png",
        "results/validation/fig5.pdf",
        "results/validation/verification.nc",
        "results/validation/verification.txt",
        "results/validation/verification.png",
        "results/validation/verification.pdf",
    ]
)
ARCHIVE_DATASETS.extend(
    [
        "results/validation/table2.nc",
        "results/validation/fig5.nc",
        "results/validation/verification.nc",
    ]
)


rule measurements_figure:
    input:
        nc="results/validation/measurements.nc",
    output:
        png=report(
            "results/validation/measurements.png",
            caption="../report/measurements.rst",
            category="4 Beyond the paper",
            subcategory="Validation against measurements",
            labels={"name": "measured vs predicted", "type": "figure"},
        ),
        pdf="results/validation/measurements.pdf",
    log:
        "results/logs/validation/measurements_figure.log",
    benchmark:
        "results/benchmarks/validation/measurements_figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="measurements",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


# One table over every measurement: the shots (per data set, law and model) and the
# plates' obliquity ratios of the near-surface study.
rule validation_summary:
    input:
        measurements="results/validation/measurements.nc",
        ratios="results/near_surface/obliquity_ratio.nc",
    output:
        csv="results/validation/validation_summary.csv",
    log:
        "results/logs/validation/validation_summary.log",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        code=PHYSICS_CODE,
    script:
        "../scripts/validation_summary.py"


ALL_TARGETS.extend(f"results/validation/measurements.{ext}" for ext in ("nc", "png", "pdf"))
ALL_TARGETS.append("results/validation/validation_summary.csv")
ALL_TARGETS.append("results/validation/measurements_options.nc")
ARCHIVE_DATASETS.extend(
    ["results/validation/measurements.nc", "results/validation/measurements_options.nc"]
)
