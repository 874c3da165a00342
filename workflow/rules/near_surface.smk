# Near-surface options against measured oblique ballistic limits (beyond the paper),
# pencore.studies.perforation.obliquity.
#   near_surface_part    ballistic-limit map (t/d x obliquity) of one option set
#   near_surface_map     the parts joined (option x t/d x obliquity) with the
#                        line-of-sight rule, and the measured obliquity ratios against it
#   near_surface_mesh_part  the map of one option set on mesh_factor times the rings
#   near_surface_mesh    the ring-mesh check: each cell of the map against the finer
#                        map, converged or why not (archived beside the map)
#   near_surface_figure  the map and the ratio figure, unconverged cells marked
NEAR_SURFACE = config["near_surface"]


rule near_surface_part:
    input:
        csv=NEAR_SURFACE["csv"],
    output:
        "results/near_surface/parts/{option}.nc",
    log:
        "results/logs/near_surface/part_{option}.log",
    benchmark:
        "results/benchmarks/near_surface/part_{option}.tsv"
    wildcard_constraints:
        option="|".join(NEAR_SURFACE["options"]),
    # one job per option set, so the map's searches run in parallel; among the longest
    # jobs, started first so that the short ones fill the cores at the end (priority)
    priority: 1
    conda:
        "../envs/pencore.yaml"
    params:
        study=lambda wc: canonical(
            {**NEAR_SURFACE, "options": {wc.option: NEAR_SURFACE["options"][wc.option]}}
        ),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/near_surface_part.py"


rule near_surface_map:
    input:
        csv=NEAR_SURFACE["csv"],
        parts=expand("results/near_surface/parts/{option}.nc", option=NEAR_SURFACE["options"]),
    output:
        map="results/near_surface/ballistic_map.nc",
        cmp="results/near_surface/obliquity_ratio.nc",
    log:
        "results/logs/near_surface/map.log",
    benchmark:
        "results/benchmarks/near_surface/map.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(NEAR_SURFACE),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/near_surface.py"


rule near_surface_mesh_part:
    input:
        csv=NEAR_SURFACE["csv"],
    output:
        "results/near_surface/mesh/{option}.nc",
    log:
        "results/logs/near_surface/mesh_{option}.log",
    benchmark:
        "results/benchmarks/near_surface/mesh_{option}.tsv"
    wildcard_constraints:
        option="|".join(NEAR_SURFACE["options"]),
    # the finer map's searches take twice the default's: started first (priority)
    priority: 1
    conda:
        "../envs/pencore.yaml"
    params:
        study=lambda wc: canonical(
            {**NEAR_SURFACE, "options": {wc.option: NEAR_SURFACE["options"][wc.option]}}
        ),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/near_surface_mesh_part.py"


rule near_surface_mesh:
    input:
        map="results/near_surface/ballistic_map.nc",
        parts=expand("results/near_surface/mesh/{option}.nc", option=NEAR_SURFACE["options"]),
    output:
        "results/near_surface/mesh_check.nc",
    log:
        "results/logs/near_surface/mesh_check.log",
    benchmark:
        "results/benchmarks/near_surface/mesh_check.tsv"
    conda:
        "../envs/pencore.yaml"
    params:
        study=canonical(NEAR_SURFACE),
        numerics=canonical(config["numerics"]),
        code=PHYSICS_CODE,
    script:
        "../scripts/near_surface_mesh.py"


rule near_surface_figure:
    input:
        map="results/near_surface/ballistic_map.nc",
        cmp="results/near_surface/obliquity_ratio.nc",
        mesh="results/near_surface/mesh_check.nc",
    output:
        png=report(
            "results/near_surface/ballistic_map.png",
            caption="../report/near_surface.rst",
            category="4 Beyond the paper",
            subcategory="Near-surface options",
            labels={"name": "ballistic-limit map", "type": "figure"},
        ),
        pdf="results/near_surface/ballistic_map.pdf",
    log:
        "results/logs/near_surface/figure.log",
    benchmark:
        "results/benchmarks/near_surface/figure.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        code=PLOTTING_CODE,
    script:
        "../scripts/near_surface_figure.py"


ALL_TARGETS.extend(
    [
        "results/near_surface/ballistic_map.nc",
        "results/near_surface/obliquity_ratio.nc",
        "results/near_surface/mesh_check.nc",
        "results/near_surface/ballistic_map.png",
        "results/near_surface/ballistic_map.pdf",
    ]
)
ARCHIVE_DATASETS.extend(
    [
        "results/near_surface/ballistic_map.nc",
        "results/near_surface/obliquity_ratio.nc",
        "results/near_surface/mesh_check.nc",
    ]
)
