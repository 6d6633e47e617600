# SPDX-License-Identifier: MIT
"""Sphinx configuration of the trussfe documentation.

Build: ``pip install -e ".[docs]" && sphinx-build -W -b html docs docs/_build``.  The user
guide is the Markdown pages of this folder (MyST), the API reference is built from the
numpydoc docstrings, and the gallery runs the scripts of ``examples/`` (sphinx-gallery).
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))           # document the source tree, not an installed copy
os.environ.setdefault("MPLBACKEND", "Agg")

import trussfe  # noqa: E402

project = "trussfe"
author = "trussfe authors"
copyright = "trussfe authors, MIT licence"
release = trussfe.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "derivations", "gallery/*.ipynb", "gallery/*.py",
                    "gallery/*.zip", "gallery/*.json", "gallery/*.codeobj.json"]

# MyST: the guide's pages link to each other as ``page.md#anchor``.
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

# autodoc and numpydoc: members in source order, no autosummary tables of class members
# (the classes list their attributes in their docstrings).
autodoc_member_order = "bysource"
autodoc_typehints = "none"
autosummary_generate = False
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# The gallery: every script of examples/ is run, its figure captured, and its text rendered.
# The scripts are the ones tests/test_gallery.py runs and checks.
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"/plot_",
    "ignore_pattern": r"paraview",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "reset_modules": ("matplotlib",),
    "plot_gallery": os.environ.get("TRUSSFE_DOCS_RUN_GALLERY", "True"),
    "abort_on_example_error": True,
    "show_memory": False,
    "min_reported_time": 3600,
}

html_theme = "alabaster"
html_title = f"trussfe {release}"
html_static_path: list[str] = []
html_theme_options = {"description": "Adaptive trusses and bar-and-joint mechanisms",
                      "page_width": "1100px", "sidebar_width": "240px"}
