# Attribution study: the paper's disputed numbers under each reading of what
# the paper leaves open. pencore.studies.attribution.settings; settings in config `attribution`.
#   attribution_settings_<k>  job k of `jobs`: its settings (dealt in turn, config order),
#                             results/attribution/parts/<setting>.nc each
#   attribution_gather        results/attribution/attribution.nc and attribution_table.csv
#   attribution_figure        results/attribution/attribution.{png,pdf}
# A setting's runs take about a second: one job per setting paid more for its process
# start and kernel load than for them. Each setting carries its own numerics (the global
# `numerics` does not apply here).
ATTRIBUTION_SETTINGS = {s["name"]: s for s in config["attribution"]["settings"]}
ATTRIBUTION_JOBS = round_robin(list(ATTRIBUTION_SETTINGS), config["attribution"]["jobs"])


for _k, _names in enumerate(ATTRIBUTION_JOBS):

    rule:
        name:
            f"attribution_settings_{_k}"
        output:
            nc=[f"results/attribution/parts/{name}.nc" for name in _names],
        log:
            f"results/logs/attribution/settings_{_k}.log",
        benchmark:
            f"results/benchmarks/attribution/settings_{_k}.tsv"
        # among the longest jobs: started first (as near_surface_part), not left to the end
        priority: 1
        conda:
            "../envs/pencore.yaml"
        params:
            settings=canonical([ATTRIBUTION_SETTINGS[name] for name in _names]),
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
