#!/usr/bin/env python3
"""The report as a page to project: report/index.md (written by report.sh) turned into report/index.html beside it,
with its pictures and plots inline and its tables with named columns, numbers right-aligned (report_checks.py has
rounded them to four significant digits and turned the programs' console output into tables).

  report_html.py report/index.md        writes report/index.html

Only the Markdown that report.sh writes is read: headings (#, ##), paragraphs, <img> lines and ![](...) images,
and tables (| ... |). Only the Python 3 standard library is used.
"""

from __future__ import annotations

import html
import re
import sys
from pathlib import Path

NUMBER = re.compile(r"^[+−-]?(\d+\.?\d*|\.\d+)([eE][+−-]?\d+)?%?$")  # a number (− is U+2212, as lessons write it)


def inline(text: str) -> str:
    """Code spans, bold and images of one line of Markdown, the rest escaped."""
    out = html.escape(text, quote=False)
    out = re.sub(r"`([^`]+)`", r"<code>\1</code>", out)
    out = re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", out)
    out = re.sub(r"(?<![*\w])_([^_]+)_(?![\w])", r"<em>\1</em>", out)
    out = re.sub(r"!\[([^\]]*)\]\(([^)]+)\)", r'<img alt="\1" src="\2">', out)
    return out


def convert(markdown: str) -> str:
    lines = markdown.splitlines()
    body: list[str] = []
    paragraph: list[str] = []

    def flush() -> None:
        if paragraph:
            body.append("<p>" + " ".join(inline(line) for line in paragraph) + "</p>")
            paragraph.clear()

    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("#"):
            flush()
            level = len(line) - len(line.lstrip("#"))
            body.append(f"<h{level}>{inline(line[level:].strip())}</h{level}>")
        elif line.startswith("|"):
            flush()
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append([c.strip() for c in lines[i].strip().strip("|").split("|")])
                i += 1
            i -= 1
            header, data = rows[0], [r for r in rows[1:] if not all(re.match(r"^:?-+:?$", c) for c in r)]
            table = ["<table>", "<tr>" + "".join(f"<th>{inline(c.replace('_', ' '))}</th>" for c in header) + "</tr>"]
            for r in data:
                table.append("<tr>" + "".join(
                    f"<td class=\"{'n' if NUMBER.match(c) else 't'}\">{inline(c)}</td>" for c in r) + "</tr>")
            table.append("</table>")
            body.append("\n".join(table))
        elif line.lstrip().startswith("<img"):
            flush()
            body.append(f"<div class=\"pictures\">{line.strip()}</div>")
        elif not line.strip():
            flush()
        else:
            paragraph.append(line)
        i += 1
    flush()
    title = next((re.sub(r"<[^>]+>", "", b) for b in body if b.startswith("<h1>")), "Report")
    style = ("body{font-family:sans-serif;max-width:75em;margin:2em auto;font-size:18px;line-height:1.4}"
             "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:.25em .6em}"
             "th{background:#eee}td.n{text-align:right;font-variant-numeric:tabular-nums}"
             "img{max-width:100%;margin:.3em}code{background:#f4f4f4;padding:0 .2em}strong{color:#a00}")
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}</title>"
            f"<style>{style}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: report_html.py REPORT/index.md", file=sys.stderr)
        return 2
    source = Path(argv[0])
    target = source.with_suffix(".html")
    target.write_text(convert(source.read_text(encoding="utf-8")), encoding="utf-8")
    print(f"report: wrote {target}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
