# SPDX-License-Identifier: MIT
"""Node and member ids of mesh models without a string per item.

A model whose geometry comes from a mesh file names its nodes and members by their index in
the mesh: ``"0"``, ``"1"``, … .  :class:`IdRange` is that list of strings, made on demand,
and :class:`IdIndex` the matching id → index mapping; a million-member mesh then costs
nothing to name (the strings and the dictionary took ~0.1 s per million items).
"""
from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence

import numpy as np


class IdRange(Sequence):
    """The ids ``"0"``, ``"1"``, …, ``str(n − 1)``: a read-only list of str.

    Examples
    --------
    >>> ids = IdRange(4)
    >>> len(ids), ids[2], ids[-1], list(ids[1:3]), "3" in ids, "03" in ids, ids.index("2")
    (4, '2', '3', ['1', '2'], True, False, 2)
    >>> ids == ["0", "1", "2", "3"]
    True
    """

    __slots__ = ("_n",)

    def __init__(self, n: int):
        self._n = int(n)

    def __len__(self) -> int:
        return self._n

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [str(k) for k in range(self._n)[i]]
        return str(range(self._n)[i])

    def __iter__(self) -> Iterator[str]:
        return map(str, range(self._n))

    def position(self, key: object) -> int | None:
        """Index of id ``key``, or None when it is not one of the ids."""
        k = str(key)
        # only the canonical spelling names an item: "7", not "07", "+7" or " 7"
        if k.isdigit() and k.isascii() and (k == "0" or k[0] != "0"):
            i = int(k)
            if i < self._n:
                return i
        return None

    def __contains__(self, key: object) -> bool:
        return self.position(key) is not None

    def index(self, key, start: int = 0, stop: int | None = None) -> int:
        i = self.position(key)
        if i is None or i < start or (stop is not None and i >= stop):
            raise ValueError(f"{key!r} is not in the ids")
        return i

    def count(self, key) -> int:
        return int(key in self)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, IdRange):
            return self._n == other._n
        if isinstance(other, (list, tuple)):
            return len(other) == self._n and all(a == b for a, b in zip(self, other))
        return NotImplemented

    def __hash__(self) -> int:
        return hash(("IdRange", self._n))

    def __repr__(self) -> str:
        return f"IdRange({self._n})"

    def __add__(self, other) -> list[str]:
        return list(self) + list(other)

    def __radd__(self, other) -> list[str]:
        return list(other) + list(self)


class IdIndex(Mapping):
    """The mapping id → index of an :class:`IdRange`, without a dictionary.

    Examples
    --------
    >>> ix = IdIndex(IdRange(3))
    >>> ix["2"], "5" in ix, len(ix), list(ix)
    (2, False, 3, ['0', '1', '2'])
    """

    __slots__ = ("_ids",)

    def __init__(self, ids: IdRange):
        self._ids = ids

    def __getitem__(self, key) -> int:
        i = self._ids.position(key)
        if i is None:
            raise KeyError(key)
        return i

    def __contains__(self, key: object) -> bool:
        return key in self._ids

    def positions(self, keys: list) -> np.ndarray:
        """The indices of ids ``keys`` in one vectorised pass (a large table of a mesh
        model); KeyError naming the first key that is not an id.

        Examples
        --------
        >>> IdIndex(IdRange(5)).positions(["4", "0"]).tolist()
        [4, 0]
        """
        try:
            numbers = list(map(int, keys))
        except (ValueError, TypeError):
            numbers = None
        # the canonical spelling of position() only: int() also reads "07", "+7", " 7", "7_0"
        if numbers is not None and list(map(str, numbers)) == keys:
            rows = np.array(numbers, dtype=np.int64)
            if rows.size == 0 or (rows.min() >= 0 and rows.max() < len(self._ids)):
                return rows
        return np.array([self[k] for k in keys], dtype=np.int64)

    def __iter__(self) -> Iterator[str]:
        return iter(self._ids)

    def __len__(self) -> int:
        return len(self._ids)


def id_index(ids: Sequence[str]) -> Mapping[str, int]:
    """Mapping id → position for a list of ids (an :class:`IdIndex` for an :class:`IdRange`).

    Examples
    --------
    >>> id_index(["a", "b"])["b"], id_index(IdRange(5))["4"]
    (1, 4)
    """
    if isinstance(ids, IdRange):
        return IdIndex(ids)
    return {k: i for i, k in enumerate(ids)}
