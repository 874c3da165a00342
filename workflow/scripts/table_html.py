"""Rules <table>_html: CSV -> pencore.plotting.tables.csv_to_html -> HTML page."""

from _common import start_log

from pencore.io.atomic import atomic_write_text
from pencore.io.outputs import TEXT_SUFFIXES
from pencore.plotting.tables import csv_to_html

smk = snakemake  # noqa: F821 -- injected by Snakemake's `script:` directive
log = start_log(smk, f"table_html_{smk.params.title}")

atomic_write_text(
    smk.output.html, csv_to_html(smk.input.csv, smk.params.title), suffixes=TEXT_SUFFIXES
)
log.info("wrote %s", smk.output.html)
