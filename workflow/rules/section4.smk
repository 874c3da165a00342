# Section 4 studies of the paper (Figs 7-18) and the comparison table.
#   s4_study             one dataset: results/<study>/<name>.nc (fig7, fig9, fig11, fig13,
#                        fig16 and its start-height study)
#   s4_part              the heavy searches split into independent jobs (both cores busy):
#                        fig8, fig15, fig18 per projectile; fig12 per (projectile, obliquity)
#   s4_gather            joins the parts: results/fig8/vcr.nc, results/fig12/vcr_yaw.nc,
#                        results/fig15/vci.nc, results/fig18/omega_c.nc
#   s4_<study>_figure    PNG + PDF from the dataset (restyling does not rerun the solver)
#   s4_paper_comparison  results/paper_comparison.csv: every claim of config/paper_claims.csv
#                        beside pencore's value
# Physics in pencore.studies.{config,comparison} (from_config, gather, paper_comparison); figures in
# pencore.plotting. Each rule gets only the config entries it reads (params), so
# editing one study reruns only that study.
include: "section4_common.smk"


# ----------------------------------------------------------------------------- datasets


rule s4_study:
    output:
        nc="results/{study}/{name}.nc",
    log:
        "results/logs/section4/{study}_{name}.log",
    benchmark:
        "results/benchmarks/section4/{study}_{name}.tsv"
    wildcard_constraints:
        study="fig7|fig9|fig11|fig13|fig16",
        name="trajectories|turning_angle|start_height",
    conda:
        "../envs/pencore.yaml"
    params:
        kind=lambda wc: "start_height" if wc.name == "start_height" else wc.study,
        config=lambda wc: s4_params("start_height" if wc.name == "start_height" else wc.study),
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_study.py"


rule s4_part:
    output:
        nc="results/{study}/parts/{part}.nc",
    log:
        "results/logs/section4/{study}_part_{part}.log",
    benchmark:
        "results/benchmarks/section4/{study}_part_{part}.tsv"
    wildcard_constraints:
        study="fig8|fig12|fig15|fig18",
        part=r"p[0-9]+(?:_[-0-9.]+)?",
    conda:
        "../envs/pencore.yaml"
    params:
        kind=lambda wc: wc.study,
        config=lambda wc: s4_params(wc.study),
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_study.py"


rule s4_gather:
    input:
        parts=lambda wc: s4_parts(wc.study),
    output:
        nc="results/{study}/{name}.nc",
    log:
        "results/logs/section4/{study}_{name}_gather.log",
    benchmark:
        "results/benchmarks/section4/{study}_{name}_gather.tsv"
    wildcard_constraints:
        study="fig8|fig12|fig15|fig18",
        name="vcr|vcr_yaw|vci|omega_c",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind=lambda wc: wc.study,
        config=lambda wc: s4_params(wc.study),
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_gather.py"


# ----------------------------------------------------------------------------- figures


for _kind, (_entry, _dataset) in S4_DATASETS.items():

    rule:
        name:
            f"s4_{_kind}_figure"
        input:
            nc=_dataset,
            # the paper's numbers drawn beside pencore's (pencore.paper.claims)
            claims="config/paper_claims.csv",
        output:
            png=report(
                s4_figure_path(_kind, "png"),
                caption=f"../report/section4_{_kind}.rst",
                category="2 Section 4 (Figs 7-18)",
                subcategory=S4_FIGURE_TITLES[_kind],
                labels={"name": S4_FIGURE_TITLES[_kind], "type": "figure"},
            ),
            pdf=s4_figure_path(_kind, "pdf"),
        log:
            f"results/logs/section4/{_kind}_figure.log",
        benchmark:
            f"results/benchmarks/section4/{_kind}_figure.tsv"
        localrule: True
        conda:
            "../envs/pencore.yaml"
        params:
            kind=_kind,
            code=PLOTTING_CODE,
        script:
            "../scripts/section4_figure.py"


# ----------------------------------------------------------------------------- comparison


rule s4_paper_comparison:
    input:
        **{kind: dataset for kind, (_, dataset) in S4_DATASETS.items()},
        table2="results/validation/table2.csv",
        claims="config/paper_claims.csv",
    output:
        csv="results/paper_comparison.csv",
    log:
        "results/logs/section4/paper_comparison.log",
    benchmark:
        "results/benchmarks/section4/paper_comparison.tsv"
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        yaw_convention=S4["yaw_convention"],
        vci_threshold=S4["fig15"]["threshold_deg"],
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_compare.py"


# the comparison table is versioned beside the archived datasets (rule `archive`)
rule s4_archive_comparison:
    input:
        "results/paper_comparison.csv",
    output:
        "results/archive/paper_comparison.csv",
    log:
        "results/logs/archive/paper_comparison.log",
    localrule: True
    conda:
        "../envs/pencore.yaml"
    shell:
        "cp {input} {output} > {log} 2>&1"


ALL_TARGETS.extend(
    [dataset for _, dataset in S4_DATASETS.values()]
    + [s4_figure_path(kind, ext) for kind in S4_DATASETS for ext in ("png", "pdf")]
    + ["results/paper_comparison.csv"]
)
ARCHIVE_DATASETS.extend(
    [dataset for _, dataset in S4_DATASETS.values()] + ["results/paper_comparison.csv"]
)
