# SPDX-License-Identifier: MIT
"""The documentation site builds without a single warning:
``sphinx-build -W -b html docs docs/_build`` (the ``docs`` extra: ``pip install -e ".[docs]"``).

The build runs the gallery scripts of ``examples/`` (their numbers are checked by
tests/test_gallery.py) and builds the API reference from the docstrings.  Skipped when the
documentation tools are not installed.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

for _tool in ("sphinx", "numpydoc", "myst_parser", "sphinx_gallery"):
    pytest.importorskip(_tool, reason="the docs extra is not installed")


def test_docs_build_without_warnings(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg"}
    r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b",
                        "html", "-d", str(tmp_path / "doctrees"), str(ROOT / "docs"),
                        str(tmp_path / "html")], cwd=ROOT, env=env, capture_output=True,
                       text=True, timeout=1800)
    problems = [line for line in r.stderr.splitlines()
                if "WARNING" in line or "ERROR" in line]
    assert r.returncode == 0 and not problems, "\n".join(problems) or r.stderr[-3000:]
    html = tmp_path / "html"
    for page in ("index.html", "cli.html", "api/analyses.html", "gallery/index.html",
                 "gallery/plot_01_static_truss.html"):
        assert (html / page).is_file(), page
    # the API reference is built from the docstrings, the gallery has its figures
    assert "Euler critical load" in (html / "api" / "mechanics.html").read_text("utf-8")
    figures = sorted((html / "_images").glob("sphx_glr_plot_*_001.png"))
    assert len(figures) == len(list((ROOT / "examples").glob("plot_*.py")))
