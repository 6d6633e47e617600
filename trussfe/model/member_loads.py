# SPDX-License-Identifier: MIT
"""Loads applied along members: the data of the ``member_loads`` array of a model file.

A member load acts on one member, between its end nodes:

* ``uniform`` — a force per unit length ``q`` (N/m) constant along the member;
* ``trapezoidal`` — a force per unit length varying linearly from ``q_start`` at the start
  node to ``q_end`` at the end node;
* ``point`` — a force ``F`` (N) and optionally a couple ``M`` (N·m) at the fraction ``at`` of
  the length from the start node (``0 <= at <= 1``).

A distributed load covers the whole member unless ``span = [a, b]`` (fractions of the length
from the start node, ``0 <= a < b <= 1``) limits it to ``a L <= x <= b L``; a trapezoidal
load then varies from ``q_start`` at ``a L`` to ``q_end`` at ``b L``.

Vectors have ``dim`` components: in ``axes = "global"`` (the default) they are in the global
axes, in ``axes = "local"`` in the member axes (x along the member; y, z as in
:func:`trussfe.mechanics.geometry.local_axes`).  A couple has 1 component in 2-D (about z) and
3 in 3-D.  Intensities are per unit length *of the member* (not of its projection).

Model-file form (the key is a top-level array, like ``[loads]`` it is one load pattern)::

    member_loads = [
      { member = "AB", kind = "uniform", q = [0.0, 0.0, -800.0] },
      { member = "AB", kind = "trapezoidal", q_start = [0, 0, -200], q_end = [0, 0, -600],
        axes = "local" },
      { member = "AB", kind = "point", at = 0.25, F = [0.0, 0.0, -300.0] },
      { member = "AB", kind = "uniform", q = [0.0, 0.0, -500.0], span = [0.6, 1.0] },
    ]

The mechanics of these loads (equivalent end loads, section forces along the member) are in
:mod:`trussfe.mechanics.member_loads`.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np

#: Kinds of member load.
KINDS = ("uniform", "trapezoidal", "point")
#: Axes a member load's vectors may be given in.
AXES = ("global", "local")


@dataclass(frozen=True)
class MemberLoad:
    """One load along one member (see the module notes).

    Attributes
    ----------
    member : int
        Index of the loaded member in the structure.
    kind : str
        ``"uniform"``, ``"trapezoidal"`` or ``"point"``.
    q_start, q_end : tuple of float
        Force per unit length at the start and end of the span (by default the start and
        end node), N/m (equal for ``uniform``; empty for ``point``).
    at : float
        Position of a point load as a fraction of the length from the start node (``nan``
        for distributed loads).
    force : tuple of float
        Force of a point load, N (empty for distributed loads).
    moment : tuple of float
        Couple of a point load, N·m (empty when none: 1 component in 2-D, 3 in 3-D).
    axes : str
        ``"global"`` or ``"local"`` (member axes).
    span : tuple of float
        ``(a, b)``: a distributed load acts on ``a L <= x <= b L`` (fractions of the length
        from the start node; ``(0, 1)``, the whole member, by default).
    """

    member: int
    kind: str
    q_start: tuple[float, ...] = ()
    q_end: tuple[float, ...] = ()
    at: float = math.nan
    force: tuple[float, ...] = ()
    moment: tuple[float, ...] = ()
    axes: str = "global"
    span: tuple[float, float] = (0.0, 1.0)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown member-load kind {self.kind!r}; use one of "
                             + ", ".join(KINDS))
        if self.axes not in AXES:
            raise ValueError(f"unknown member-load axes {self.axes!r}; use global or local")
        for name in ("q_start", "q_end", "force", "moment"):
            object.__setattr__(self, name, tuple(float(v) for v in getattr(self, name)))
        if self.kind == "point":
            if not 0.0 <= self.at <= 1.0:
                raise ValueError(f"point load position at = {self.at!r} is outside [0, 1]")
            if not self.force and not self.moment:
                raise ValueError("a point load needs F (and/or M)")
        elif not self.q_start or len(self.q_start) != len(self.q_end):
            raise ValueError("a distributed load needs q_start and q_end of equal length")
        object.__setattr__(self, "span", tuple(float(v) for v in self.span))
        if len(self.span) != 2 or not 0.0 <= self.span[0] < self.span[1] <= 1.0:
            raise ValueError(f"span = {list(self.span)!r} is not [a, b] with "
                             "0 <= a < b <= 1 (fractions of the member length)")
        if self.kind == "point" and self.span != (0.0, 1.0):
            raise ValueError("a point load has a position (at), not a span")

    def scaled(self, factor: float) -> "MemberLoad":
        """The same load times ``factor`` (a load case in a combination).

        Examples
        --------
        >>> MemberLoad.uniform(0, (0.0, -2.0)).scaled(1.5).q_end
        (0.0, -3.0)
        """
        f = float(factor)
        return replace(self, **{k: tuple(f * v for v in getattr(self, k))
                                for k in ("q_start", "q_end", "force", "moment")})

    @classmethod
    def uniform(cls, member: int, q: Sequence[float], axes: str = "global",
                span: tuple[float, float] = (0.0, 1.0)) -> "MemberLoad":
        """A uniform load ``q`` (N/m) along member ``member`` (on the fractions ``span`` of
        its length)."""
        return cls(member, "uniform", tuple(q), tuple(q), axes=axes, span=span)


@dataclass(frozen=True, eq=False)
class MemberLoadArrays:
    """Member loads of a ``dim``-D model as arrays (one row per load), in member or global
    axes as given; :func:`load_arrays` makes them.

    Attributes
    ----------
    member : ndarray of int, shape (l,)
    point : ndarray of bool, shape (l,)
        Point loads (the others are distributed, linear from ``q1`` to ``q2``).
    local : ndarray of bool, shape (l,)
        Vectors given in member axes.
    q1, q2 : ndarray, shape (l, dim)
        Intensity at the start and end of the span, N/m (0 for point loads).
    span : ndarray, shape (l, 2)
        Span of a distributed load as fractions of the length (``(0, 1)``: the whole
        member; also for point loads).
    at : ndarray, shape (l,)
        Fraction of the length of a point load (0 for distributed loads).
    F : ndarray, shape (l, dim)
        Point force, N.
    C : ndarray, shape (l, 3)
        Point couple, N·m, components about x, y, z (2-D: about z only).
    """

    member: np.ndarray
    point: np.ndarray
    local: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    at: np.ndarray
    F: np.ndarray
    C: np.ndarray = field(repr=False)
    span: np.ndarray = field(repr=False)


def load_arrays(loads: Sequence[MemberLoad], dim: int) -> MemberLoadArrays:
    """The member loads as arrays (:class:`MemberLoadArrays`) of a ``dim``-D model.

    Raises
    ------
    ValueError
        A vector whose length is not ``dim`` (forces) or 1 / 3 (2-D / 3-D couples).
    """
    n = len(loads)
    q1, q2, F = (np.zeros((n, dim)) for _ in range(3))
    C = np.zeros((n, 3))
    ncouple = 1 if dim == 2 else 3
    for i, ld in enumerate(loads):
        for name, arr, size in (("q_start", q1, dim), ("q_end", q2, dim), ("force", F, dim)):
            v = getattr(ld, name)
            if v:
                if len(v) != size:
                    raise ValueError(f"{name} has {len(v)} components; a {dim}-D model "
                                     f"needs {size}")
                arr[i] = v
        if ld.moment:
            if len(ld.moment) != ncouple:
                raise ValueError(f"M has {len(ld.moment)} components; a {dim}-D model needs "
                                 f"{ncouple}")
            C[i, 3 - ncouple:] = ld.moment
    member = np.array([ld.member for ld in loads], dtype=np.int64)
    point = np.array([ld.kind == "point" for ld in loads], dtype=bool)
    local = np.array([ld.axes == "local" for ld in loads], dtype=bool)
    at = np.array([ld.at if ld.kind == "point" else 0.0 for ld in loads], dtype=float)
    span = np.array([ld.span for ld in loads], dtype=float).reshape(n, 2)
    return MemberLoadArrays(member=member, point=point, local=local, q1=q1, q2=q2, at=at,
                            F=F, C=C, span=span)
