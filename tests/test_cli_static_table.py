# SPDX-License-Identifier: MIT
"""The ``trussfe static`` tables: spring reactions are printed with the support reactions,
and the envelope does not call a compressive force the largest tension.

The model: a bar AB (EA/L = 1e7 N/m) along x, held at A and by a spring of k = 1e7 N/m along
x at B, pushed at B by 1000 N (case ``push``) or 3000 N (case ``push2``).  Closed form, the
bar and the spring in parallel: u_B = −F/(EA/L + k) = −5e-5 m, the bar carries −500 N and the
spring +500 N on the structure (its reaction −k·u_B).
"""
from __future__ import annotations

import pytest

from trussfe.cli import main

MODEL = """
[model]
name = "bar on a spring"
dimension = 2

[materials.steel]
E = 2.0e11

[sections.bar]
area = 1.0e-4

[nodes]
A = [0.0, 0.0]
B = [2.0, 0.0]

[members]
AB = { nodes = ["A", "B"], section = "bar", material = "steel" }

[supports]
A = ["x", "y"]
B = ["y"]

[springs]
B = { x = 1.0e7 }

[load_cases.push]
loads = { B = [-1000.0, 0.0] }

[load_cases.push2]
loads = { B = [-3000.0, 0.0] }
"""


@pytest.fixture
def model(tmp_path):
    path = tmp_path / "spring.toml"
    path.write_text(MODEL, encoding="utf-8")
    return path


def test_spring_reaction_is_printed(model, capsys):
    assert main(["static", str(model), "--case", "push"]) == 0
    rows = {line.split()[0]: line.split() for line in capsys.readouterr().out.splitlines()
            if line.strip().startswith(("A ", "B "))}
    # id, ux, uy, Rx, Ry: B's spring reaction +500 N beside A's support reaction +500 N
    assert float(rows["B"][1]) == pytest.approx(-5e-5, rel=1e-12)
    assert float(rows["B"][3]) == pytest.approx(500.0, rel=1e-12)
    assert float(rows["A"][3]) == pytest.approx(500.0, rel=1e-12)


def test_envelope_of_compression_only(model, capsys):
    assert main(["static", str(model)]) == 0
    out = capsys.readouterr().out
    assert "no member in tension in any case" in out
    assert "largest compression -1500.0000 N in member AB (case push2)" in out
    assert "largest tension" not in out
