# The concrete record (beyond the paper): every clean shot of the public concrete
# compilation run by pencore under each concrete law it ships,
# pencore.studies.validation.record.
#   concrete_record_law     one law over every scored row (a job per law)
#   concrete_record         the laws side by side, the closed forms beside, the
#                           held-out statistics and the depth band's calibration
#   concrete_record_figure  measured against predicted, the error against diameter and speed
RECORD = config["concrete_record"]


rule concrete_record_law:
    input:
        csv="config/concrete_compilation.csv",
    output:
        "results/validation/record/law_{law}.nc",
    log:
        "results/logs/validation/record_law_{law}.log",
    benchmark:
        "results/benchmarks/validation/record_law_{law}.tsv"
    wildcard_constraints:
        law="|".join(RECORD["laws"]),
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(RECORD),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/record_law.py"


rule concrete_record:
    input:
        csv="config/concrete_compilation.csv",
        parts=expand("results/validation/record/law_{law}.nc", law=RECORD["laws"]),
    output:
        nc="results/validation/concrete_record.nc",
        stats="results/validation/concrete_record_stats.nc",
        csv="results/validation/concrete_record_stats.csv",
    log:
        "results/logs/validation/concrete_record.log",
    benchmark:
        "results/benchmarks/validation/concrete_record.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(RECORD),
        code=PHYSICS_CODE,
    script:
        "../scripts/record_gather.py"


rule concrete_record_figure:
    input:
        nc="results/validation/concrete_record.nc",
    output:
        png=report(
            "results/validation/concrete_record.png",
            caption="../report/concrete_record.rst",
            category="4 Beyond the paper",
            subcategory="Validation against measurements",
            labels={"name": "concrete record", "type": "figure"},
        ),
        pdf="results/validation/concrete_record.pdf",
    log:
        "results/logs/validation/concrete_record_figure.log",
    benchmark:
        "results/benchmarks/validation/concrete_record_figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="concrete_record",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


ALL_TARGETS.extend(
    [
        "results/validation/concrete_record.nc",
        "results/validation/concrete_record_stats.nc",
        "results/validation/concrete_record_stats.csv",
        "results/validation/concrete_record.png",
        "results/validation/concrete_record.pdf",
    ]
)
ARCHIVE_DATASETS.extend(
    ["results/validation/concrete_record.nc", "results/validation/concrete_record_stats.nc"]
)
