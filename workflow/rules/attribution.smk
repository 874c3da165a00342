# Attribution study: the paper's disputed numbers under each reading of what
# the paper leaves open. pencore.studies.attribution.settings; settings in config `attribution`.
#   attribution_setting  one job per setting: results/attribution/parts/<setting>.nc
#   attribution_gather   results/attribution/attribution.nc and attribution_table.csv
#   attribution_figure   results/attribution/attribution.{png,pdf}
# Each setting carries its own numerics (the global `numerics` does not apply here).
ATTRIBUTION_SETTINGS = {s["name"]: s for s in config["attribution"]["settings"]}


rule attribution_setting:
    output:
        nc="results/attribution/parts/{setting}.nc",
    log:
        "results/logs/attribution/{setting}.log",
    benchmark:
        "results/benchmarks/attribution/{setting}.tsv"
    wildcard_constraints:
        setting="|".join(ATTRIBUTION_SETTINGS),
    conda:
        "../envs/pencore.yaml"
    params:
        setting=lambda wc: canonical(ATTRIBUTION_SETTINGS[wc.setting]),
        code=PHYSICS_CODE,
    script:
        "../scripts/attribution.py"


rule attribution_gather:
    input:
        parts=[f"results/attribution/parts/{name}.nc" for name in ATTRIBUTION_SETTINGS],
    output:
        nc="results/attribution/attribution.nc",
        csv="results/attribution/attribution_table.csv",
    log:
        "results/logs/attribution/gather.log",
    benchmark:
        "results/benchmarks/attribution/gather.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        settings=canonical(config["attribution"]["settings"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/attribution_gather.py"


rule attribution_figure:
    input:
        nc="results/attribution/attribution.nc",
    output:
        png=report(
            "results/attribution/attribution.png",
            caption="../report/attribution.rst",
            category="2 Section 4 (Figs 7-18)",
            subcategory="Why the numbers differ",
            labels={"name": "attribution", "type": "figure"},
        ),
        pdf="results/attribution/attribution.pdf",
    log:
        "results/logs/attribution/figure.log",
    benchmark:
        "results/benchmarks/attribution/figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind="attribution",
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


ALL_TARGETS.extend(
    [
        "results/attribution/attribution.nc",
        "results/attribution/attribution_table.csv",
        "results/attribution/attribution.png",
        "results/attribution/attribution.pdf",
    ]
)
ARCHIVE_DATASETS.append("results/attribution/attribution.nc")
