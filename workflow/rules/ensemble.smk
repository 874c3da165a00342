# Ensemble (Monte Carlo) studies, pencore.studies.ensemble; config `ensemble`.
#   ensemble_chunk   one job per chunk: results/ensemble/<name>/parts/<k>.nc
#   ensemble_gather  results/ensemble/<name>.nc (sample dimension + statistics)
#   ensemble_figure  results/ensemble/<name>.{png,pdf}
# The chunks are the unit of parallelism (Snakemake schedules them, locally or on a
# cluster); no process pool inside a rule.
ENSEMBLES = {c["name"]: c for c in config["ensemble"]["cases"]}


rule ensemble_chunk:
    output:
        nc="results/ensemble/{name}/parts/{chunk}.nc",
    log:
        "results/logs/ensemble/{name}_{chunk}.log",
    benchmark:
        "results/benchmarks/ensemble/{name}_{chunk}.tsv"
    wildcard_constraints:
        name="|".join(ENSEMBLES) or "NONE",
        chunk=r"[0-9]+",
    conda:
        "../envs/pencore.yaml"
    params:
        case=lambda wc: canonical(ENSEMBLES[wc.name]),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/ensemble_chunk.py"


rule ensemble_gather:
    input:
        parts=lambda wc: [
            f"results/ensemble/{wc.name}/parts/{k}.nc"
            for k in range(ENSEMBLES[wc.name]["n_chunks"])
        ],
    output:
        nc="results/ensemble/{name}.nc",
    log:
        "results/logs/ensemble/{name}_gather.log",
    benchmark:
        "results/benchmarks/ensemble/{name}_gather.tsv"
    wildcard_constraints:
        name="|".join(ENSEMBLES) or "NONE",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        case=lambda wc: canonical(ENSEMBLES[wc.name]),
        code=PHYSICS_CODE,
    script:
        "../scripts/ensemble_gather.py"


rule ensemble_figure:
    input:
        nc="results/ensemble/{name}.nc",
    output:
        png=report(
            "results/ensemble/{name}.png",
            caption="../report/ensemble.rst",
            category="4 Beyond the paper",
            subcategory="Ensembles",
            labels={"name": "{name}", "type": "figure"},
        ),
        pdf="results/ensemble/{name}.pdf",
    log:
        "results/logs/ensemble/{name}_figure.log",
    benchmark:
        "results/benchmarks/ensemble/{name}_figure.tsv"
    wildcard_constraints:
        name="|".join(ENSEMBLES) or "NONE",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="ensemble",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


ALL_TARGETS.extend(
    f"results/ensemble/{name}.{ext}" for name in ENSEMBLES for ext in ("nc", "png", "pdf")
)
ARCHIVE_DATASETS.extend(f"results/ensemble/{name}.nc" for name in ENSEMBLES)
