"""A tiny document model for the validation report: one list of blocks, rendered both as
Markdown (``report.md``) and as a self-contained HTML page (``index.html``).

Blocks: headings, paragraphs, bullet lists, tables, images, preformatted text.  Inline markup
understood in text (both outputs): ``code``, **bold**, *italic*.  Nothing else is parsed, so
the two renderings carry exactly the same content.
"""
from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass, field
from pathlib import Path


@dataclass
class Block:
    kind: str                       # "h", "p", "ul", "table", "img", "pre"
    data: object
    level: int = 0
    caption: str = ""
    header: list = field(default_factory=list)


class Doc:
    def __init__(self, title):
        self.title = title
        self.blocks: list[Block] = []

    # -- building -------------------------------------------------------------------------
    def h(self, text, level=2):
        self.blocks.append(Block("h", text, level=level))

    def p(self, text):
        self.blocks.append(Block("p", text))

    def ul(self, items):
        self.blocks.append(Block("ul", list(items)))

    def table(self, header, rows, caption=""):
        rows = [[cell_text(c) for c in r] for r in rows]
        self.blocks.append(Block("table", rows, header=[str(h) for h in header], caption=caption))

    def img(self, path, caption):
        self.blocks.append(Block("img", str(path), caption=caption))

    def pre(self, text):
        self.blocks.append(Block("pre", text))

    # -- rendering ------------------------------------------------------------------------
    def markdown(self):
        out = [f"# {self.title}", ""]
        for b in self.blocks:
            if b.kind == "h":
                out += ["#" * b.level + " " + b.data, ""]
            elif b.kind == "p":
                out += [b.data, ""]
            elif b.kind == "ul":
                out += [f"* {it}" for it in b.data] + [""]
            elif b.kind == "table":
                if b.caption:
                    out += [b.caption, ""]
                out.append("| " + " | ".join(_md_cell(h) for h in b.header) + " |")
                out.append("|" + "---|" * len(b.header))
                for r in b.data:
                    out.append("| " + " | ".join(_md_cell(c) for c in r) + " |")
                out.append("")
            elif b.kind == "img":
                out += [f"![{b.caption}]({b.data})", "", f"*{b.caption}*", ""]
            elif b.kind == "pre":
                out += ["```", b.data.rstrip("\n"), "```", ""]
        return "\n".join(out).rstrip() + "\n"

    def html(self):
        body = [f"<h1>{_inline_html(self.title)}</h1>"]
        toc = []
        for i, b in enumerate(self.blocks):
            if b.kind == "h":
                anchor = f"s{i}"
                body.append(f'<h{b.level} id="{anchor}">{_inline_html(b.data)}</h{b.level}>')
                if b.level == 2:
                    toc.append(f'<li><a href="#{anchor}">{_inline_html(b.data)}</a></li>')
            elif b.kind == "p":
                body.append(f"<p>{_inline_html(b.data)}</p>")
            elif b.kind == "ul":
                body.append("<ul>" + "".join(f"<li>{_inline_html(t)}</li>" for t in b.data) + "</ul>")
            elif b.kind == "table":
                cap = f"<caption>{_inline_html(b.caption)}</caption>" if b.caption else ""
                head = "".join(f"<th>{_inline_html(h)}</th>" for h in b.header)
                rows = "".join("<tr>" + "".join(f"<td>{_inline_html(c)}</td>" for c in r) + "</tr>"
                               for r in b.data)
                body.append(f"<table>{cap}<thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>")
            elif b.kind == "img":
                body.append(f'<figure><img src="{html.escape(b.data)}" alt="{html.escape(b.caption)}">'
                            f"<figcaption>{_inline_html(b.caption)}</figcaption></figure>")
            elif b.kind == "pre":
                body.append(f"<pre>{html.escape(b.data)}</pre>")
        nav = f"<nav><ul>{''.join(toc)}</ul></nav>" if toc else ""
        body.insert(1, nav)
        return (
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{html.escape(self.title)}</title><style>{_CSS}</style></head>\n<body>\n"
            + "\n".join(body) + "\n</body></html>\n")

    def write(self, out: Path):
        out.mkdir(parents=True, exist_ok=True)
        (out / "report.md").write_text(self.markdown(), encoding="utf-8")
        (out / "index.html").write_text(self.html(), encoding="utf-8")


_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;max-width:1100px;
margin:2em auto;padding:0 1em;line-height:1.45;color:#222}
table{border-collapse:collapse;margin:.6em 0 1.2em;font-size:.86em}
th,td{border:1px solid #bbb;padding:.25em .5em;text-align:right;vertical-align:top}
th{background:#eee} td:first-child,th:first-child{text-align:left}
caption{caption-side:top;text-align:left;font-style:italic;padding:.3em 0}
code{background:#f3f3f3;padding:0 .2em} pre{background:#f6f6f6;padding:.6em;overflow-x:auto}
figure{margin:1em 0} img{max-width:100%;border:1px solid #ddd}
figcaption{font-style:italic;font-size:.9em} nav{background:#fafafa;border:1px solid #ddd;padding:.3em 1em}
"""


def cell_text(c):
    """Table cells: strings as they are, floats in a compact form."""
    if isinstance(c, str):
        return c
    if isinstance(c, bool) or c is None:
        return str(c)
    if isinstance(c, int):
        return str(c)
    if isinstance(c, float):
        return fmt_num(c)
    return str(c)


def fmt_num(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "n/a"
    if x == 0:
        return "0"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    ax = abs(x)
    if 1e-3 <= ax < 1e5:
        return f"{x:.{digits}g}"
    return f"{x:.{max(digits - 1, 1)}e}".replace("e-0", "e-").replace("e+0", "e").replace("e+", "e")


def fmt_err(x):
    """An error: one significant digit and a half, 0 shown as 0."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "n/a"
    if x == 0:
        return "0"
    return f"{x:.1e}".replace("e-0", "e-").replace("e+0", "e").replace("e+", "e")


def fmt_t(t):
    if t is None:
        return "n/a"
    if t < 1e-3:
        return f"{t * 1e6:.0f} µs"
    if t < 1:
        return f"{t * 1e3:.3g} ms"
    return f"{t:.3g} s"


def _md_cell(s):
    return str(s).replace("|", "\\|").replace("\n", " ")


_CODE = re.compile(r"`([^`]+)`")
_BOLD = re.compile(r"\*\*([^*]+)\*\*")
_ITAL = re.compile(r"(?<![\w*])\*([^*\s][^*]*?)\*(?![\w*])")


def _inline_html(text):
    parts = _CODE.split(str(text))
    out = []
    for i, part in enumerate(parts):
        if i % 2:
            out.append(f"<code>{html.escape(part)}</code>")
        else:
            s = html.escape(part, quote=False)
            s = _BOLD.sub(r"<b>\1</b>", s)
            s = _ITAL.sub(r"<i>\1</i>", s)
            out.append(s)
    return "".join(out)
