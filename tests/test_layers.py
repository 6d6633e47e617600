# SPDX-License-Identifier: MIT
"""The package's import layers (pyproject.toml, ``[tool.importlinter]``): no import runs
upwards and no two packages import each other; docs/architecture.md draws the layers."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_import_layers_hold(capsys):
    cli = pytest.importorskip("importlinter.cli")
    status = cli.lint_imports(config_filename=str(ROOT / "pyproject.toml"), no_cache=True)
    out = capsys.readouterr().out
    assert status == 0, out
    assert "0 broken" in out


def test_a_contract_that_cannot_hold_is_reported_broken(tmp_path, capsys):
    """The check can fail: the layers turned upside down are reported broken."""
    cli = pytest.importorskip("importlinter.cli")
    cfg = tmp_path / "upside_down.toml"
    cfg.write_text('[tool.importlinter]\nroot_package = "trussfe"\n'
                   '[[tool.importlinter.contracts]]\nname = "upside down"\ntype = "layers"\n'
                   'layers = ["trussfe.model", "trussfe.api"]\n')
    status = cli.lint_imports(config_filename=str(cfg), no_cache=True)
    assert status != 0, capsys.readouterr().out
