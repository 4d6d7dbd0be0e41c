"""HTML of the reports: one self-contained page (inline CSS, figures as base64 PNG)."""

from __future__ import annotations

import base64
import html
import json
from pathlib import Path

import pandas as pd

CSS = """
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;max-width:1150px;
margin:1.5em auto;padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.6em;border-bottom:2px solid #333}h2{margin-top:1.8em;border-bottom:1px solid #aaa}
table{border-collapse:collapse;margin:.6em 0;font-size:.9em}
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:right}
th{background:#eee}td:first-child,th:first-child{text-align:left}
.table td:nth-child(2),.table th:nth-child(2){text-align:left}
figure{margin:1em 0}figure img{max-width:100%;height:auto;border:1px solid #ddd}
figcaption,.caption{font-size:.85em;color:#444}
.status{padding:.4em .8em;border-radius:4px;font-weight:600;display:inline-block}
.status-complete{background:#d9f0d3}.status-other{background:#fdd;border:1px solid #c00}
.note{background:#fff8e1;border-left:4px solid #f0b400;padding:.4em .8em}
.verdict{font-size:1.05em;background:#eef5ff;border-left:4px solid #2a6fdb;padding:.5em .8em}
.arg{white-space:nowrap}
pre{background:#f6f6f6;padding:.6em;overflow-x:auto;font-size:.8em;white-space:pre-wrap}
dl.kv{display:grid;grid-template-columns:max-content auto;gap:.1em 1em}dl.kv dt{font-weight:600}
dl.kv dd{margin:0}
table.kv{font-size:.8em}table.kv td,table.kv th{padding:.1em .5em;text-align:left}
table caption{font-weight:600;text-align:left;padding:.2em 0}
.tables{display:flex;flex-wrap:wrap;gap:0 1.5em;
align-items:flex-start}details{margin:.5em 0}summary{cursor:pointer;font-weight:600}
table.summary td,table.summary th{font-size:.95em}table.summary td.name{text-align:left}
table.summary td.num{text-align:right}.ok{color:#1a7f37}.bad{color:#b00}
@media print{body{max-width:none;margin:0;font-size:10pt}h2{page-break-after:avoid}
figure,table,.run-head{page-break-inside:avoid}pre{font-size:7pt}}
"""


def esc(value) -> str:
    return html.escape(str(value))


def png_data_uri(path: Path) -> str:
    return "data:image/png;base64," + base64.b64encode(Path(path).read_bytes()).decode("ascii")


def figure_html(path: Path, caption: str) -> str:
    return (f'<figure><img src="{png_data_uri(path)}" alt="{esc(caption)}">'
            f"<figcaption>{caption}</figcaption></figure>")


def table_html(df: pd.DataFrame, caption: str, digits: int = 2,
               formats: dict[str, str] | None = None) -> str:
    """An HTML table; floats with ``digits`` decimals unless ``formats`` gives a column's spec
    (seconds span six decades: ``{"time [s]": ".3g"}``)."""
    formats = {"time [s]": ".3g", "seconds_per_point": ".3g"} | (formats or {})
    df = df.map(lambda v: "—" if v is None else v)  # a column of only None is no exception
    formatters = {c: (lambda v, f=f: "—" if pd.isna(v) else format(v, f))
                  for c, f in formats.items() if c in df.columns}
    body = df.to_html(index=False, border=0, na_rep="—", escape=True, formatters=formatters,
                      float_format=lambda v: f"{v:.{digits}f}")
    return f'<div class="table">{body}<p class="caption">{caption}</p></div>'


def provenance_links(keys) -> str:
    return "Provenance: " + ", ".join(f'<a href="#prov-{esc(k)}">{esc(k)}</a>' for k in keys)


def provenance_details(entries: dict, filename: str, note: str = "") -> str:
    """Provenance folded in ``<details>``: one anchored block per entry (``#prov-KEY``, what
    :func:`provenance_links` point at), the full JSON being in ``filename`` beside the page."""
    if not all(isinstance(v, dict) for v in entries.values()) or not entries:
        entries = {"study": entries}
    blocks = "".join(f'<h3 id="prov-{esc(k)}">{esc(k)}</h3><pre>'
                     f"{esc(json.dumps(v, indent=1, default=str))}</pre>"
                     for k, v in entries.items())
    extra = f"; {esc(note)}" if note else ""
    return (f'<h2 id="provenance">Provenance</h2><details><summary>Models and their parameters, '
            f"data, software versions, command and machine (full JSON: "
            f'<a href="{esc(filename)}">{esc(filename)}</a>{extra})</summary>{blocks}</details>')


def html_page(title: str, body: str) -> str:
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">'
            f"<title>{esc(title)}</title><style>{CSS}</style></head>"
            f"<body><h1>{esc(title)}</h1>{body}</body></html>\n")


def mapping_table(mapping: dict, title: str, caption: str = "",
                  columns=("quantity", "value")) -> str:
    """A two-column table of nested metadata (``loadcell.capacity_N | 1961``) titled
    ``title``, numbers to 6 significant digits; lists are joined, empty values shown as —."""
    rows = []

    def walk(value, prefix):
        if isinstance(value, dict) and value:
            for k, v in value.items():
                walk(v, f"{prefix}{k}.")
            return
        if isinstance(value, float):
            text = f"{value:.6g}"
        elif isinstance(value, list | tuple):
            text = ", ".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in value)
        else:
            text = "—" if value in (None, "", {}) else str(value)
        rows.append((prefix[:-1], text))

    walk(mapping, "")
    body = "".join(f"<tr><td>{esc(k)}</td><td>{esc(v)}</td></tr>" for k, v in rows)
    head = "".join(f"<th>{esc(c)}</th>" for c in columns)
    note = f'<p class="caption">{caption}</p>' if caption else ""
    return (f'<div class="table"><table class="kv"><caption>{esc(title)}</caption>'
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>{note}</div>")


def kv_html(pairs: dict) -> str:
    return ('<dl class="kv">' + "".join(f"<dt>{esc(k)}</dt><dd>{esc(v)}</dd>"
                                        for k, v in pairs.items()) + "</dl>")
