# Perforation of finite slabs (beyond the paper), pencore.studies.perforation.slabs.
#   perforation_ballistic_limit    ballistic limit against slab thickness and obliquity
#   perforation_residual_velocity  residual against impact velocity, Recht-Ipson fit
PERFORATION = config["perforation"]
PERFORATION_KINDS = ["ballistic_limit", "residual_velocity"]


rule perforation_study:
    output:
        nc="results/perforation/{kind}.nc",
    log:
        "results/logs/perforation/{kind}.log",
    benchmark:
        "results/benchmarks/perforation/{kind}.tsv"
    wildcard_constraints:
        kind="|".join(PERFORATION_KINDS),
    conda:
        "../envs/pencore.yaml"
    params:
        kind=lambda wc: wc.kind,
        study=canonical(PERFORATION),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/perforation.py"


rule perforation_figure:
    input:
        nc="results/perforation/{kind}.nc",
    output:
        png=report(
            "results/perforation/{kind}.png",
            caption="../report/perforation.rst",
            category="4 Beyond the paper",
            subcategory="Perforation",
            labels={"name": "{kind}", "type": "figure"},
        ),
        pdf="results/perforation/{kind}.pdf",
    log:
        "results/logs/perforation/{kind}_figure.log",
    benchmark:
        "results/benchmarks/perforation/{kind}_figure.tsv"
    wildcard_constraints:
        kind="|".join(PERFORATION_KINDS),
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind=lambda wc: wc.kind,
        code=PLOTTING_CODE,
    script:
        "../scripts/plot.py"


ALL_TARGETS.extend(
    f"results/perforation/{kind}.{ext}"
    for kind in PERFORATION_KINDS
    for ext in ("nc", "png", "pdf")
)
ARCHIVE_DATASETS.extend(f"results/perforation/{kind}.nc" for kind in PERFORATION_KINDS)
