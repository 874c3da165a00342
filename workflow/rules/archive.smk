# Archive: `snakemake --cores 2 archive` copies every aggregated dataset registered in
# ARCHIVE_DATASETS (results/<study>/<name>.nc) to results/archive/<study>/<name>.nc,
# with trajectories thinned (config archive.max_points) and compressed. Not part of
# `all`: the archive is committed and refreshed on request only.


rule archive:
    input:
        lambda wildcards: [
            path.replace("results/", "results/archive/", 1) for path in ARCHIVE_DATASETS
        ],


rule archive_dataset:
    input:
        "results/{dataset}.nc",
    output:
        "results/archive/{dataset}.nc",
    log:
        "results/logs/archive/{dataset}.log",
    wildcard_constraints:
        dataset=r"(?!archive/)[A-Za-z0-9_./-]+",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        max_points=config["archive"]["max_points"],
    script:
        "../scripts/archive.py"
