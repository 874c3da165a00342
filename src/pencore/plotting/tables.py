"""CSV result tables as standalone HTML pages (for the Snakemake report).

The report shows a CSV only as a download; rendered HTML lets a reader see the table in
the browser. Cells are copied as text from the CSV (no re-rounding), so the page shows
exactly the numbers in the file.
"""

from __future__ import annotations

import html
import os

import pandas as pd

__all__ = ["csv_to_html"]

_CSS = """
body { font-family: sans-serif; font-size: 13px; margin: 1em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #ccc; padding: 3px 6px; text-align: left; vertical-align: top; }
th { background: #f0f0f0; position: sticky; top: 0; }
tr:nth-child(even) td { background: #fafafa; }
"""


def csv_to_html(csv_path: str | os.PathLike[str], title: str) -> str:
    """An HTML page with the CSV at ``csv_path`` as a table under the heading ``title``.

    Parameters
    ----------
    csv_path
        A comma-separated file with a header row.
    title
        Page title and heading (escaped).

    Returns
    -------
    str
        A complete HTML document.
    """
    df = pd.read_csv(csv_path, dtype=str, keep_default_na=False)
    table = df.to_html(index=False, border=0, escape=True)
    t = html.escape(title)
    return (
        "<!DOCTYPE html>\n<html><head><meta charset='utf-8'>"
        f"<title>{t}</title><style>{_CSS}</style></head>\n"
        f"<body><h2>{t}</h2>\n<p>{len(df)} rows; source: {html.escape(str(csv_path))}</p>\n"
        f"{table}\n</body></html>\n"
    )
