"""The documentation builds: Sphinx with warnings as errors (gallery not executed here; ``make
docs`` executes it), every public name has its API page, and the examples in the pages run."""
from __future__ import annotations

import doctest
import importlib.util
import inspect
import py_compile
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import contact
import contact.scene
import sie

DOCS = Path(__file__).resolve().parents[2] / "docs"
sys.path.insert(0, str(DOCS))
from check_links import broken_links  # noqa: E402  (docs/check_links.py, also run by make docs)


def _build_site(root):
    """The site built from a copy of docs/ below ``root`` (the build writes generated pages
    beside its sources), with the gallery's scripts listed but not run: (the html folder,
    the finished Sphinx process)."""
    src = root / "docs"
    shutil.copytree(DOCS, src, ignore=shutil.ignore_patterns("_build", "auto_examples",
                                                            "generated"))
    out = src / "_build" / "html"
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b",
                           "html", "-D", "plot_gallery=0", str(src), str(out)],
                          capture_output=True, text=True)
    return out, proc


#: the fixture ``built`` is what tests/conftest.py starts early (the build, ~30 s, runs while
#: the tests before these run)
BACKGROUND_FOR = ("built",)
_STARTED = {}


def start_in_background(background):
    if importlib.util.find_spec("sphinx") is not None:
        _STARTED["site"] = background.submit(_build_site, background.mkdtemp("docs"))


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """The strict build of the site (warnings are errors): its html folder."""
    pytest.importorskip("sphinx")
    started = _STARTED.pop("site", None)
    out, proc = started.result() if started else _build_site(tmp_path_factory.mktemp("docs"))
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-6000:]
    return out


@pytest.mark.slow
def test_every_public_name_has_an_api_page(built):
    pages = {sie: "sie.html", contact: "contact.html", contact.scene: "scene.html"}
    missing = [f"{mod.__name__}.{name}" for mod, page in pages.items() for name in mod.__all__
               if not (built / "api" / "generated" / f"{mod.__name__}.{name}.html").exists()
               and f'id="{mod.__name__}.{name}"' not in
               (built / "api" / page).read_text(encoding="utf-8")]
    assert missing == []


@pytest.mark.slow
def test_theory_and_gallery_pages_exist(built):
    for page in ("index.html", "theory/sie.html", "theory/contact.html", "theory/errata.html",
                 "auto_examples/index.html", "validation.html"):
        assert (built / page).is_file(), page
    sie_page = (built / "theory" / "sie.html").read_text(encoding="utf-8")
    assert "P_{k-\\kappa}^{(-\\alpha,-\\beta)}" in sie_page      # the equations reach MathJax
    assert (built / "_static" / "mathjax").is_dir()          # served with the site (offline)


def test_gallery_scripts_compile():
    scripts = sorted((DOCS / "examples").glob("plot_*.py"))
    assert len(scripts) >= 9
    for path in scripts:
        py_compile.compile(str(path), doraise=True)


@pytest.mark.slow
def test_examples_in_the_pages_run():
    for page in sorted(DOCS.rglob("*.rst")):
        if "_build" in page.parts or "generated" in page.parts:
            continue
        failed, _ = doctest.testfile(str(page), module_relative=False,
                                     optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
        assert failed == 0, page


@pytest.mark.slow
def test_no_broken_internal_links(built):
    assert broken_links(built, skip=("report/",)) == []   # the report is written by make docs


def test_the_link_check_finds_broken_links(tmp_path):
    (tmp_path / "a.html").write_text('<p id="here"><a href="b.html#there">b</a>'
                                     '<a href="#here">self</a><img src="missing.png"></p>')
    (tmp_path / "b.html").write_text('<p id="elsewhere"></p>')
    assert broken_links(tmp_path) == ["a.html: b.html#there (no such anchor)",
                                      "a.html: missing.png"]


def _sections_missing(obj) -> list:
    """The numpydoc sections a public name must have and lacks: Examples everywhere;
    References (the paper or equation it implements) except on exceptions and warnings;
    Parameters and Returns on functions; Attributes or Parameters on classes."""
    from numpydoc.docscrape import ClassDoc, FunctionDoc
    error = inspect.isclass(obj) and issubclass(obj, (Exception, Warning))
    doc = ClassDoc(obj) if inspect.isclass(obj) else FunctionDoc(obj)
    missing = [] if doc["Examples"] else ["Examples"]
    if not error and not doc["References"]:
        missing.append("References")
    if inspect.isfunction(obj):
        if inspect.signature(obj).parameters and not doc["Parameters"]:
            missing.append("Parameters")
        if not doc["Returns"]:
            missing.append("Returns")
    elif not error and not (doc["Attributes"] or doc["Parameters"]):
        missing.append("Attributes or Parameters")
    return missing


@pytest.mark.parametrize("name", [f"{m.__name__}.{n}" for m in (sie, contact) for n in m.__all__
                                  if callable(getattr(m, n))])
def test_public_docstrings_have_their_sections(name):
    pytest.importorskip("numpydoc")
    module, _, attr = name.partition(".")
    obj = getattr({"sie": sie, "contact": contact}[module], attr)
    assert _sections_missing(obj) == []
