"""Sphinx configuration of the sie-contact documentation (``make docs``)."""
from __future__ import annotations

import os
import sys
import warnings
from importlib import metadata

sys.path.insert(0, os.path.abspath(".."))

project = "sie-contact"
author = "the sie-contact developers"
copyright = "2026, " + author
try:
    release = metadata.version("sie-contact")
except metadata.PackageNotFoundError:   # a bare checkout on sys.path
    release = "unknown"
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    # MathJax 3 served from the built site instead of a CDN: the pages render offline (and
    # in the headless browser the docs are checked with)
    "sphinx-mathjax-offline",
]

exclude_patterns = ["_build", "**.ipynb_checkpoints", "examples"]
root_doc = "index"
nitpicky = False

# -- API reference -------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = True
# class pages document their public methods and properties (numpydoc then lists no
# second table of them)
autodoc_default_options = {"members": True, "inherited-members": False}
autodoc_typehints = "none"              # the numpydoc sections state the types
numpydoc_show_class_members = False     # attributes are in each class's own section
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# -- gallery -------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "image_scrapers": ("matplotlib",),
    "matplotlib_animations": False,
    "show_memory": False,
    "min_reported_time": 1,
}

# matplotlib without a display; its layout warnings are not ours to print
os.environ.setdefault("MPLBACKEND", "Agg")
warnings.filterwarnings("ignore", message=".*tight_layout.*")
warnings.filterwarnings("ignore", category=UserWarning, message="Matplotlib is currently using agg")

# -- HTML ----------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = "sie-contact"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
html_show_sourcelink = False
