# CSV tables rendered as HTML pages for the report (a CSV shows only as a download).
# name -> (csv, caption, category, subcategory, title)
REPORT_TABLES = {
    "table2": (
        "results/validation/table2.csv",
        "table2.rst",
        "1 Validation (paper Section 3)",
        "Table 2 (soil)",
        "Table 2: soil penetration",
    ),
    "table2_selection": (
        "results/validation/table2_selection.csv",
        "table2_selection.rst",
        "1 Validation (paper Section 3)",
        "Table 2 (soil)",
        "Table 2: candidate projectiles and depth measures",
    ),
    "validation_summary": (
        "results/validation/validation_summary.csv",
        "validation_summary.rst",
        "4 Beyond the paper",
        # its own subcategory: beside the measurements figure, one figure and one table
        # trip the report's figure/table toggle (see attribution_table below)
        "Validation summary",
        "Validation summary: every measurement, per data set, law and model",
    ),
    "paper_comparison": (
        "results/paper_comparison.csv",
        "paper_comparison.rst",
        "2 Section 4 (Figs 7-18)",
        "Comparison with the paper",
        "Comparison with the paper",
    ),
    "attribution_table": (
        "results/attribution/attribution_table.csv",
        "attribution_table.rst",
        "2 Section 4 (Figs 7-18)",
        # beside the comparison, not with the attribution figure: a subcategory of one
        # figure and one table makes Snakemake's report treat the label "type" as a
        # figure/table toggle, and its view then fails (TypeError reading 'mime_type')
        "Comparison with the paper",
        "Attribution: the closest reading of each paper number",
    ),
}


for _name, (_csv, _caption, _category, _subcategory, _title) in REPORT_TABLES.items():

    rule:
        name:
            f"{_name}_html"
        input:
            csv=_csv,
        output:
            html=report(
                _csv.replace(".csv", ".html"),
                caption=f"../report/{_caption}",
                category=_category,
                subcategory=_subcategory,
                labels={"name": _title, "type": "table"},
            ),
        log:
            f"results/logs/tables/{_name}.log",
        localrule: True
        conda:
            "../envs/pencore.yaml"
        params:
            title=_title,
            code=PLOTTING_CODE,
        script:
            "../scripts/table_html.py"

    ALL_TARGETS.append(_csv.replace(".csv", ".html"))
