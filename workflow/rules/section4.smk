# Section 4 studies of the paper (Figs 7-18) and the comparison table, one set of rules
# for every record of pencore.workflowconfig.registry.STUDIES:
#   s4_study             a study that runs as one job: its dataset results/<folder>/<name>.nc
#   s4_part_<study>_<k>  a study split into parts, per projectile or per (projectile,
#                        obliquity), dealt in turn into `section4.part_jobs` jobs (both cores
#                        busy; a part's runs take a few seconds, a job's start about one):
#                        results/<folder>/parts/<part>.nc
#   s4_gather            joins a split study's parts into its dataset
#   s4_<study>_figure    PNG + PDF from the dataset (restyling does not rerun the solver),
#                        captioned by workflow/report/section4_<study>.rst
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
        study=s4_alternatives(folder for folder, _ in S4_SINGLE),
        name=s4_alternatives(name for _, name in S4_SINGLE),
    conda:
        "../envs/pencore.yaml"
    params:
        kind=s4_study_of,
        config=lambda wc: s4_params(s4_study_of(wc)),
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_study.py"


for _kind, _study in STUDIES.items():
    if not _study.split_by:
        continue
    _folder = s4_folder_and_name(_study.dataset)[0]
    for _k, _names in enumerate(s4_part_jobs(_kind)):

        rule:
            name:
                f"s4_part_{_kind}_{_k}"
            output:
                nc=[s4_part_file(_kind, name) for name in _names],
            log:
                f"results/logs/section4/{_folder}_part_job{_k}.log",
            benchmark:
                f"results/benchmarks/section4/{_folder}_part_job{_k}.tsv"
            conda:
                "../envs/pencore.yaml"
            params:
                kind=_kind,
                # every part of the study, by name (the job's are its outputs' names), so
                # that regrouping them (part_jobs) is no reason to rerun
                parts=canonical(s4_parts_by_name(_kind)),
                config=s4_params(_kind),
                code=PHYSICS_CODE,
            script:
                "../scripts/section4_study.py"


rule s4_gather:
    input:
        parts=lambda wc: s4_parts(s4_study_of(wc)),
    output:
        nc="results/{study}/{name}.nc",
    log:
        "results/logs/section4/{study}_{name}_gather.log",
    benchmark:
        "results/benchmarks/section4/{study}_{name}_gather.tsv"
    wildcard_constraints:
        study=s4_alternatives(folder for folder, _ in S4_SPLIT),
        name=s4_alternatives(name for _, name in S4_SPLIT),
    localrule: True
    conda:
        "../envs/pencore.yaml"
    params:
        kind=s4_study_of,
        config=lambda wc: s4_params(s4_study_of(wc)),
        code=PHYSICS_CODE,
    script:
        "../scripts/section4_gather.py"


# ----------------------------------------------------------------------------- figures


for _kind, _study in STUDIES.items():

    rule:
        name:
            f"s4_{_kind}_figure"
        input:
            nc=_study.dataset,
            # the paper's numbers drawn beside pencore's (pencore.paper.claims)
            claims="config/paper_claims.csv",
        output:
            png=report(
                f"{_study.figure}.png",
                caption=f"../report/section4_{_kind}.rst",
                category="2 Section 4 (Figs 7-18)",
                subcategory=_study.title,
                labels={"name": _study.title, "type": "figure"},
            ),
            pdf=f"{_study.figure}.pdf",
        log:
            f"results/logs/section4/{_kind}_figure.log",
        benchmark:
            f"results/benchmarks/section4/{_kind}_figure.tsv"
        localrule: True
        conda:
            "../envs/pencore.yaml"
        params:
            kind=_kind,
            # the study's configuration entry, for its caption
            entry=canonical(S4[_study.entry]),
            code=PLOTTING_CODE,
        script:
            "../scripts/section4_figure.py"


# ----------------------------------------------------------------------------- comparison


rule s4_paper_comparison:
    input:
        **{kind: study.dataset for kind, study in STUDIES.items()},
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
    [study.dataset for study in STUDIES.values()]
    + [f"{study.figure}.{ext}" for study in STUDIES.values() for ext in ("png", "pdf")]
    + ["results/paper_comparison.csv"]
)
ARCHIVE_DATASETS.extend(
    [study.dataset for study in STUDIES.values()] + ["results/paper_comparison.csv"]
)
