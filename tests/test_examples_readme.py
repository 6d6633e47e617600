# SPDX-License-Identifier: MIT
"""The README's worked example and snippets are what the code does.

- its TOML listing is ``meshes/triangular_truss_static.toml`` (the apex written to full
  precision in the file);
- its ``trussfe static`` console block is what the command prints, line for line (the solve's
  residual, a rounding-level number, is compared as a pattern);
- its Python block runs from the repository root;
- its table of commands names every command of the ``trussfe`` parser.
"""
from __future__ import annotations

import re
import shlex
import tomllib
from pathlib import Path

import pytest

from trussfe.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
MODEL = ROOT / "meshes" / "triangular_truss_static.toml"


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", README, re.DOTALL)


def _static_block() -> tuple[list[str], list[str]]:
    """The command line and the printed lines of the README's ``trussfe static`` block."""
    block = next(b for b in _blocks("console") if b.startswith("$ trussfe static"))
    lines = block.rstrip("\n").split("\n")
    return shlex.split(lines[0][2:]), lines[1:]


def test_readme_toml_listing_is_the_shipped_model():
    (listing,) = [b for b in _blocks("toml") if "[model]" in b]
    shown = tomllib.loads(listing)
    shipped = tomllib.loads(MODEL.read_text(encoding="utf-8"))
    assert set(shown) == set(shipped)
    for table in shipped:
        if table == "nodes":
            assert set(shown["nodes"]) == set(shipped["nodes"])
            for nid, xy in shipped["nodes"].items():
                assert shown["nodes"][nid] == pytest.approx(xy, abs=5e-5), nid
        else:
            assert shown[table] == shipped[table], table


def test_readme_static_output(tmp_path, monkeypatch, capsys):
    argv, printed = _static_block()
    assert argv[:2] == ["trussfe", "static"] and argv[2] == "meshes/triangular_truss_static.toml"
    monkeypatch.chdir(tmp_path)                 # the command's --json and --vtk files go here
    assert main(["static", str(MODEL), *argv[3:]]) == 0
    out = capsys.readouterr().out.rstrip("\n").split("\n")
    assert (tmp_path / "out.json").is_file() and (tmp_path / "out.vtu").is_file()
    assert len(out) == len(printed), "\n".join(out)
    residual = re.compile(r"residual [0-9.e+-]+")
    for shown, actual in zip(printed, out):
        assert residual.sub("residual R", actual) == residual.sub("residual R", shown)


def test_readme_python_block_runs(monkeypatch):
    monkeypatch.chdir(ROOT)
    (block,) = [b for b in _blocks("python") if "import trussfe" in b]
    namespace: dict = {}
    exec(compile(block, "README.md python block", "exec"), namespace)
    assert namespace["m"].n_nodes == 3
    assert list(namespace["r"].member_ids) == ["follower", "active"]


def test_readme_lists_every_command():
    action = next(a for a in build_parser()._actions if a.dest == "command")
    listed = set(re.findall(r"^\| `trussfe (\w+)", README, re.MULTILINE))
    assert listed == set(action.choices)
