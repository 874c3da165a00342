"""Rules <table>_html: CSV -> pencore.plotting.tables.csv_to_html -> HTML page."""

from pathlib import Path

from _common import start_log

from pencore.plotting.tables import csv_to_html

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk.log[0], f"table_html_{smk.params.title}")

Path(smk.output.html).write_text(csv_to_html(smk.input.csv, smk.params.title))
log.info("wrote %s", smk.output.html)
