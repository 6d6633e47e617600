# SPDX-License-Identifier: MIT
"""Dotted paths into nested data: the quantities of validation cases and the outputs of
parameter studies (into an analysis' JSON document, docs/json.md), and a study's parameters
(into a model or motion file's tables).

Syntax: keys separated by dots, list indices as ``.i`` or ``[i]`` (negative from the end), a
key with dots in double quotes (``nodes."b1.N7".displacement.2``).  A key that contains dots
is also found without quotes: the longest run of segments that is a key wins, so the node
``b50.N7`` of a chain is ``nodes.b50.N7``.  In an output, ``*`` stands for every key of a table
or every item of a list.

>>> get_values({"members": {"a": {"N": 1.0}, "b": {"N": -3.0}}}, "members.*.N")
[1.0, -3.0]
>>> d = {"loads": {"B": [0.0, -98.1]}}
>>> set_value(d, "loads.B.1", -196.2)
>>> d
{'loads': {'B': [0.0, -196.2]}}
"""
from __future__ import annotations

import math
import re
from typing import Any, Iterable

_TOKEN = re.compile(r'\s*(?:"([^"]*)"|([^.\[\]"]+)|\[\s*(-?\d+)\s*\])\s*(\.)?')
_INDEX = re.compile(r"-?\d+")

#: The reductions an output may name: each maps the numbers a path matched to one number.
REDUCTIONS = ("max", "min", "absmax", "mean", "sum", "first", "last", "count")


class PathError(KeyError):
    """A path that does not lead to a value; ``str()`` is the one-line reason."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else "bad path"


def tokens(path: str) -> list:
    """Split a path into keys (str) and list indices (int)."""
    out: list = []
    text = str(path).strip()
    if not text:
        raise PathError("empty path")
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise PathError(f"cannot read the path at '{text[pos:]}'")
        quoted, key, index, _dot = m.groups()
        if index is not None:
            out.append(int(index))
        else:
            out.append(quoted if quoted is not None else key.strip())
        pos = m.end()
    return out


def _have(obj: dict) -> str:
    keys = list(map(str, obj))
    return ", ".join(keys[:8]) + (", ..." if len(keys) > 8 else "")


def _key_run(obj: dict, toks: list, i: int) -> tuple[str, int] | None:
    """The longest run of string segments from ``i`` that is a key of ``obj``."""
    for j in range(len(toks), i, -1):
        run = toks[i:j]
        if all(isinstance(t, str) for t in run) and ".".join(run) in obj:
            return ".".join(run), j
    return None


def _list_index(obj: list, tok, done: str) -> int:
    if isinstance(tok, str) and _INDEX.fullmatch(tok):
        tok = int(tok)
    if not isinstance(tok, int):
        raise PathError(f"'{done}' is a list: expected an index, got '{tok}'")
    if not -len(obj) <= tok < len(obj):
        raise PathError(f"index {tok} is out of range of '{done}' ({len(obj)} items)")
    return tok


def _join(done: str, key) -> str:
    return f"{done}.{key}" if done else str(key)


def set_value(data: dict, path: str, value: Any, *, new_tables: Iterable[str] = ()) -> None:
    """Write ``value`` at ``path`` in ``data`` (in place).

    Every table on the way must exist; the last key may be new (the reader of the data then
    checks that it is a valid key), and a missing top-level table named in ``new_tables`` is
    created (``masses`` for a payload on a model without lumped masses).
    """
    toks = tokens(path)
    obj: Any = data
    done = ""
    i = 0
    while True:
        tok = toks[i]
        if isinstance(obj, dict):
            found = _key_run(obj, toks, i)
            if found is None:
                key = tok if isinstance(tok, str) else str(tok)
                last = i == len(toks) - 1
                if last:
                    obj[key] = value
                    return
                if not done and key in new_tables:
                    obj[key] = {}
                    found = (key, i + 1)
                else:
                    from ..io.suggest import suggest as _suggest
                    raise PathError(f"'{done or 'the file'}' has no '{key}'"
                                    f"{_suggest(key, list(obj))}")
            key, j = found
            if j == len(toks):
                obj[key] = value
                return
            obj, done, i = obj[key], _join(done, key), j
        elif isinstance(obj, list):
            k = _list_index(obj, tok, done)
            if i == len(toks) - 1:
                obj[k] = value
                return
            obj, done, i = obj[k], _join(done, k), i + 1
        else:
            raise PathError(f"'{done}' is a value, not a table: it has no '{tok}'")


def get_value(data: Any, path: str) -> Any:
    """The value at ``path`` (no wildcards)."""
    return _walk(data, tokens(path), 0, "")[0]


def _walk(obj: Any, toks: list, i: int, done: str) -> list:
    """Every value that ``toks[i:]`` reaches from ``obj``."""
    while i < len(toks):
        tok = toks[i]
        if tok == "*":
            if isinstance(obj, dict):
                items = [(k, v) for k, v in obj.items()]
            elif isinstance(obj, list):
                items = list(enumerate(obj))
            else:
                raise PathError(f"'{done}' is a value: '*' needs a table or a list")
            if i == len(toks) - 1:
                return [v for _, v in items]
            out: list = []
            misses = []
            for k, v in items:
                try:
                    out.extend(_walk(v, toks, i + 1, _join(done, k)))
                except PathError as err:
                    misses.append(err)
            if misses and len(misses) == len(items):
                raise misses[0]
            return out
        if isinstance(obj, dict):
            found = _key_run(obj, toks, i)
            if found is None:
                from ..io.suggest import suggest as _suggest
                raise PathError(f"'{done or 'the result'}' has no '{tok}'"
                                f"{_suggest(tok, list(obj))}")
            key, i = found
            obj, done = obj[key], _join(done, key)
        elif isinstance(obj, list):
            k = _list_index(obj, tok, done)
            obj, done, i = obj[k], _join(done, k), i + 1
        else:
            raise PathError(f"'{done}' is a value, not a table: it has no '{tok}'")
    return [obj]


def get_values(data: Any, path: str, where: dict | None = None) -> list:
    """Every value at ``path``; ``where`` keeps only the items matched by the first ``*``
    whose keys equal the given values (a list of values: any of them)."""
    toks = tokens(path)
    if where:
        if "*" not in toks:
            raise PathError("'where' needs a '*' in the path")
        star = toks.index("*")
        head = _walk(data, toks[:star], 0, "") if star else [data]
        out: list = []
        for container in head:
            items = container.values() if isinstance(container, dict) else container
            for item in items:
                if isinstance(item, dict) and all(
                        item.get(k) in (v if isinstance(v, list) else [v])
                        for k, v in where.items()):
                    if star == len(toks) - 1:
                        out.append(item)
                    else:
                        out.extend(_walk(item, toks, star + 1, "*"))
        return out
    return _walk(data, toks, 0, "")


def numbers(values: list) -> list[float]:
    """The numbers in matched values, nested lists flattened; ``None`` (a JSON null) is NaN.

    Raises :class:`PathError` for text or a table, which no reduction can take.
    """
    out: list[float] = []
    stack = list(reversed(values))
    while stack:
        v = stack.pop()
        if isinstance(v, list):
            stack.extend(reversed(v))
        elif v is None:
            out.append(math.nan)
        elif isinstance(v, bool):
            out.append(float(v))
        elif isinstance(v, (int, float)):
            out.append(float(v))
        elif isinstance(v, dict):
            raise PathError(f"leads to a table ({_have(v)}), not to numbers")
        else:
            raise PathError(f"leads to text ({str(v)[:40]!r}), not to a number")
    return out


def reduce(values: list[float], how: str | None) -> float:
    """One number from the matched ``values`` by the reduction ``how`` (one of
    :data:`REDUCTIONS`, or ``None`` when the path must lead to exactly one number).
    ``absmax`` is the largest magnitude (≥ 0).  An empty match is NaN (``count``: 0)."""
    import numpy as np

    if how is None:
        if len(values) != 1:
            raise PathError(f"leads to {len(values)} numbers: give reduce = "
                            f"{' | '.join(REDUCTIONS[:4])}")
        return values[0]
    if how == "count":
        return float(len(values))
    if not values:
        return math.nan
    a = np.asarray(values, dtype=float)
    if how == "first":
        return float(a[0])
    if how == "last":
        return float(a[-1])
    if np.isnan(a).all():
        return math.nan
    fn = {"max": np.nanmax, "min": np.nanmin, "mean": np.nanmean, "sum": np.nansum,
          "absmax": lambda x: np.nanmax(np.abs(x))}[how]
    return float(fn(a))
