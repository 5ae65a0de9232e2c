"""HTML of `dda report`: one self-contained page (styles inline, figures
as base64 PNG data), so that the file alone opens in any browser, offline,
and can be mailed or archived as it is."""

import base64
import html

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #444; }
.warning { background: #fff4e5; border-left: 4px solid #e66101; padding: 0.4em 0.8em; margin: 0.4em 0; }
pre { background: #f7f7f7; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }
"""


def esc(text):
    return html.escape(str(text), quote=True)


def key_value_table(rows, table_id):
    body = "".join(f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>" for k, v in rows)
    return f'<table id="table-{table_id}">{body}</table>'


def data_table(header, rows, table_id):
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f'<td class="{"num" if i else ""}">{esc(c)}</td>' for i, c in enumerate(row))
                   + "</tr>" for row in rows)
    return f'<table id="table-{table_id}"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'


def figure(png_bytes, kind, caption):
    data = base64.b64encode(png_bytes).decode("ascii")
    return (f'<figure id="figure-{esc(kind)}"><img alt="{esc(caption)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{esc(caption)}</figcaption></figure>")


def page(title, sections):
    """sections: (heading, html) pairs, in order."""
    parts = [f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
             f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
             f"<title>{esc(title)}</title><style>{STYLE}</style></head><body>",
             f"<h1>{esc(title)}</h1>"]
    for heading, content in sections:
        anchor = heading.lower().replace(" ", "-")
        parts.append(f'<section id="{esc(anchor)}"><h2>{esc(heading)}</h2>{content}</section>')
    parts.append("</body></html>\n")
    return "".join(parts)
