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
