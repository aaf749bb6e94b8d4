"""Check the links of the built site: every relative link (href, src) must name a file that
exists and, with a #anchor into an HTML page, an id on that page.  Sphinx's own linkcheck
leaves anchors into the site unchecked.

    python docs/check_links.py docs/_build/html      (``make docs`` runs it last)
"""
from __future__ import annotations

import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote


class _Links(HTMLParser):
    """The ids of an HTML page and the links (href, src) it holds."""

    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        for key, value in attrs:
            if key == "id" and value:
                self.ids.add(value)
            elif key in ("href", "src") and value:
                self.links.append(value)


def _parsed(path, cache):
    if path not in cache:
        parser = _Links()
        parser.feed(path.read_text(encoding="utf-8", errors="replace"))
        cache[path] = parser
    return cache[path]


def broken_links(root: Path, skip=()) -> list:
    """Relative links of the built site under ``root`` whose file, or whose #anchor in an
    HTML file, does not exist; links starting with a prefix in ``skip`` are not followed."""
    cache, broken = {}, []
    for page in sorted(root.rglob("*.html")):
        if "_static" in page.relative_to(root).parts:       # theme templates, not pages
            continue
        for link in _parsed(page, cache).links:
            if link.startswith(("http://", "https://", "mailto:", "data:", "javascript:")):
                continue
            target, _, anchor = link.partition("#")
            target = target.partition("?")[0]
            if target.startswith(tuple(skip)):
                continue
            path = (page.parent / unquote(target)).resolve() if target else page
            if not path.exists():
                broken.append(f"{page.relative_to(root)}: {link}")
            elif anchor and path.suffix == ".html" and anchor not in _parsed(path, cache).ids:
                broken.append(f"{page.relative_to(root)}: {link} (no such anchor)")
    return broken


def main(argv=None) -> int:
    root = Path((argv or sys.argv[1:] or ["docs/_build/html"])[0])
    broken = broken_links(root)
    for line in broken:
        print(f"broken link: {line}")
    print(f"check_links: {len(broken)} broken link(s) in {root}")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
