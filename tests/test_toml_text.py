# SPDX-License-Identifier: MIT
"""TOML parsing (trussfe.io.toml_text): the compiled parser for large documents, used inside
``compiled_parser()`` (the command line), changes nothing that tomllib decides."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from trussfe.io import toml_text


def _big_loads(n: int = 20_000) -> str:
    lines = ["[model]", 'name = "big"', "", "[loads]"]
    lines += [f'"{i}" = [{0.5 * i!r}, -{1e3 + i!r}, 0.0]' for i in range(n)]
    return "\n".join(lines) + "\n"


def test_large_document_same_as_tomllib():
    """Above the size threshold the result is tomllib's dictionary, key for key."""
    pytest.importorskip("rtoml")
    text = _big_loads()
    assert len(text) >= toml_text.FAST_MIN_BYTES
    with toml_text.compiled_parser():
        assert toml_text.loads(text) == tomllib.loads(text)


def test_library_default_is_tomllib(monkeypatch):
    """Outside the command line's context the compiled parser is never asked (a stand-in
    that would fail if it were)."""
    import sys
    import types

    fake = types.ModuleType("rtoml")
    fake.loads = lambda text: {"not": "tomllib"}
    monkeypatch.setitem(sys.modules, "rtoml", fake)
    text = _big_loads()
    assert toml_text.loads(text) == tomllib.loads(text)
    with toml_text.compiled_parser():
        assert toml_text.loads(text) == {"not": "tomllib"}


def test_what_the_compiled_parser_refuses_tomllib_decides():
    """1e400 overflows in rtoml but is inf for tomllib: the answer is tomllib's."""
    text = _big_loads() + "[extra]\nbig = 1e400\n"
    with toml_text.compiled_parser():
        assert math.isinf(toml_text.loads(text)["extra"]["big"])


def test_malformed_large_document_raises_tomllib_error():
    """A duplicate key in a large document: tomllib's error and message."""
    text = _big_loads() + '[loads]\n"0" = [1.0, 2.0, 3.0]\n'
    with pytest.raises(tomllib.TOMLDecodeError) as ours, toml_text.compiled_parser():
        toml_text.loads(text)
    with pytest.raises(tomllib.TOMLDecodeError) as ref:
        tomllib.loads(text)
    assert str(ours.value) == str(ref.value)


def test_large_model_file_reads_the_same(tmp_path):
    """A 4,000-node line model with a load on every node: read through the
    compiled parser and through tomllib alone, the same loads and geometry."""
    pytest.importorskip("rtoml")
    from trussfe import read_model

    n = 4000
    lines = ["[model]", 'name = "line"', "dimension = 2", "",
             "[materials.s]", "E = 2.1e11", "G = 8.1e10", "",
             "[sections.a]", "area = 1e-4", "", "[nodes]"]
    lines += [f'n{i} = [{float(i)!r}, 0.0]' for i in range(n)]
    lines += ["", "[members]"]
    lines += [f'm{i} = {{ nodes = ["n{i}", "n{i + 1}"], section = "a", material = "s" }}'
              for i in range(n - 1)]
    lines += ["", "[supports]", 'n0 = ["x", "y"]', "", "[loads]"]
    lines += [f'n{i} = [{1.0 + i!r}, {-2.0 * i!r}]' for i in range(1, n)]
    path = tmp_path / "line.toml"
    path.write_text("\n".join(lines) + "\n")
    assert path.stat().st_size >= toml_text.FAST_MIN_BYTES
    with toml_text.compiled_parser():
        fast = read_model(path)
    slow = read_model(path)
    np.testing.assert_array_equal(fast.loads, slow.loads)
    np.testing.assert_array_equal(fast.coords, slow.coords)
    np.testing.assert_array_equal(fast.connectivity, slow.connectivity)
    assert fast.node_ids == slow.node_ids and fast.member_ids == slow.member_ids
