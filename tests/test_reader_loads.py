# SPDX-License-Identifier: MIT
"""A large ``[loads]`` table (read in one vectorised step) gives the same loads as the
entry-by-entry reader, and bad entries in it are reported exactly as in a small table."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_array_equal

from trussfe import read_model
from trussfe.errors import InputError


def _model(tmp_path, loads: str, n: int = 100) -> str:
    nodes = "\n".join(f'{i} = [{float(i)}, {0.5 * (i % 2)}, 0.0]' for i in range(n))
    members = "\n".join(f'm{i} = {{ nodes = ["{i}", "{i + 1}"], section = "s", '
                        'material = "m" }' for i in range(n - 1))
    text = f"""[model]
dimension = 3
[materials.m]
E = 7.0e10
[sections.s]
area = 1.0e-4
[nodes]
{nodes}
[members]
{members}
[supports]
0 = ["x", "y", "z"]
[loads]
{loads}
"""
    path = tmp_path / "m.toml"
    path.write_text(text)
    return path


def test_large_table_equals_entries(tmp_path):
    """100 loads (fast path) against the values written (the independent source)."""
    rng = np.random.default_rng(2)
    want = rng.standard_normal((100, 3)).round(6)
    lines = "\n".join(f"{i} = {want[i].tolist()}" for i in range(100))
    s = read_model(_model(tmp_path, lines))
    assert_array_equal(s.loads[:, :3], want)
    assert not np.any(s.loads[:, 3:])


@pytest.mark.parametrize("bad, item", [("true", "loads.57[1]"), ('"x"', "loads.57[1]")])
def test_large_table_bad_entry(tmp_path, bad, item):
    lines = "\n".join(f"{i} = [0.0, {bad if i == 57 else 1.0}, 0.0]" for i in range(100))
    with pytest.raises(InputError) as err:
        read_model(_model(tmp_path, lines))
    assert item in str(err.value)


def test_large_table_unknown_node(tmp_path):
    lines = "\n".join(f"{i} = [0.0, 1.0, 0.0]" for i in range(99)) + "\nnine = [1.0, 0.0, 0.0]"
    with pytest.raises(InputError, match="loads.nine"):
        read_model(_model(tmp_path, lines))


def _mesh_model(tmp_path, loads: str, n: int = 100) -> str:
    """The same chain of bars with its nodes from a line mesh: nodes are named 0 … n − 1."""
    import meshio
    pts = np.column_stack([np.arange(n, dtype=float), 0.5 * (np.arange(n) % 2), np.zeros(n)])
    lines = np.column_stack([np.arange(n - 1), np.arange(1, n)])
    meshio.write(tmp_path / "m.vtu", meshio.Mesh(pts, [("line", lines)]))
    path = tmp_path / "m.toml"
    path.write_text(f"""[model]
dimension = 3
mesh = "m.vtu"
[materials.m]
E = 7.0e10
[sections.s]
area = 1.0e-4
[groups.default]
section = "s"
material = "m"
[supports]
0 = ["x", "y", "z"]
[loads]
{loads}
""")
    return path


def test_large_table_on_mesh_nodes(tmp_path):
    """A mesh model's nodes are found by number in one step: the loads written, in the order
    of the file (not of the nodes), and a node loaded twice sums."""
    rng = np.random.default_rng(3)
    want = rng.standard_normal((100, 3)).round(6)
    order = rng.permutation(100)
    lines = "\n".join(f"{i} = {want[i].tolist()}" for i in order)
    s = read_model(_mesh_model(tmp_path, lines))
    assert_array_equal(s.loads[:, :3], want)


@pytest.mark.parametrize("key", ["07", "100", "+7", "x7", "-1", "7_0", " 7"])
def test_large_table_on_mesh_nodes_bad_key(tmp_path, key):
    """Only the decimal number of a node names it ('07', '+7' do not; 100 is past the
    last of 100 nodes): the entry is reported as in a small table."""
    lines = "\n".join(f"{i} = [0.0, 1.0, 0.0]" for i in range(99) if i != 7)
    lines += f'\n"{key}" = [1.0, 0.0, 0.0]'
    with pytest.raises(InputError, match=f"loads.{key}"):
        read_model(_mesh_model(tmp_path, lines))
