# SPDX-License-Identifier: MIT
"""Small named structures with hand solutions, for tests and examples."""
from __future__ import annotations

import numpy as np

from ..errors import AnalysisError, InputError
from ..model.sections import Section
from ..model.structure import Structure, build_structure
from .materials import ALUMINIUM, triangular_tube


def two_bar(span: float = 2.0, height: float = 1.0, load: float = 1000.0) -> Structure:
    """Symmetric two-bar truss: supports ``A`` (−span/2, 0) and ``C`` (span/2, 0), apex ``B``
    (0, height) loaded by ``load`` downward.

    Hand solution: each bar carries N = −P / (2 sin θ), sin θ = height / bar length; each
    support reacts P/2 upward.

    Examples
    --------
    >>> s = two_bar()
    >>> s.member_ids, s.loads[1, :2].tolist()
    (('AB', 'BC'), [0.0, -1000.0])
    """
    if span <= 0 or height <= 0:
        raise InputError("two_bar", "span and height must be positive")
    return build_structure(
        [[-span / 2, 0.0], [0.0, height], [span / 2, 0.0]], [[0, 1], [1, 2]],
        section=triangular_tube(), material=ALUMINIUM, supports={0: "xy", 2: "xy"},
        loads={1: [0.0, -load]}, name="two-bar truss", node_ids=["A", "B", "C"],
        member_ids=["AB", "BC"])


def three_bar(width: float = 1.0, height: float = 1.0, load: tuple[float, float] = (0.0, -1000.0),
              areas: tuple[float, float, float] = (1e-4, 1e-4, 1e-4)) -> Structure:
    """The classical statically indeterminate three-bar truss.

    Supports ``A`` (−width, height), ``B`` (0, height), ``C`` (width, height); the loaded
    node ``D`` at (0, 0); bars ``AD``, ``BD``, ``CD`` with the given areas (explicit
    sections, aluminium).

    Hand solution for a vertical load P (symmetric areas A1 = A3): with c = cos α of the
    inclined bars, N_BD = P / (1 + 2 c³ A1/A2), N_AD = N_CD = N_BD c² A1/A2 (tension for P
    downward, since the bars hang above D).
    """
    if width <= 0 or height <= 0:
        raise InputError("three_bar", "width and height must be positive")
    s = build_structure(
        [[-width, height], [0.0, height], [width, height], [0.0, 0.0]],
        [[0, 3], [1, 3], [2, 3]], section=Section(name="bar", area=areas[0]),
        material=ALUMINIUM, supports={0: "xy", 1: "xy", 2: "xy"}, loads={3: list(load)},
        name="three-bar truss", node_ids=["A", "B", "C", "D"], member_ids=["AD", "BD", "CD"])
    return s.with_sections([Section(name=f"bar{i + 1}", area=a) for i, a in enumerate(areas)])


def four_bar_linkage(crank_angle: float = np.pi / 3, ground: float = 4.0, crank: float = 1.0,
                     coupler: float = 3.5, rocker: float = 3.0) -> Structure:
    """Planar four-bar linkage: a finite mechanism with one degree of freedom.

    Ground pivots ``A`` (0, 0) and ``D`` (ground, 0) are pinned (the ground link is not a
    member); ``crank`` AB at ``crank_angle`` from the x axis, ``coupler`` BC, ``rocker`` CD,
    with C in the upper (open) assembly.  The default lengths satisfy Grashof's condition
    (s + l = 1 + 4 ≤ p + q = 3.5 + 3): the crank turns fully.

    Returns
    -------
    Structure
        Rank of B is 3 with 4 free coordinates: one internal mechanism.

    Examples
    --------
    >>> s = four_bar_linkage()
    >>> np.allclose(s.lengths(), [1.0, 3.5, 3.0])
    True
    """
    b = crank * np.array([np.cos(crank_angle), np.sin(crank_angle)])
    d = np.array([ground, 0.0])
    # C on the intersection of the circles |C − B| = coupler and |C − D| = rocker.
    bd = d - b
    dist = float(np.linalg.norm(bd))
    if dist > coupler + rocker or dist < abs(coupler - rocker):
        raise AnalysisError("four_bar_linkage", f"the linkage cannot be assembled at crank "
                                                f"angle {crank_angle!r}")
    along = (coupler**2 - rocker**2 + dist**2) / (2 * dist)
    h = np.sqrt(max(coupler**2 - along**2, 0.0))
    e = bd / dist
    c = b + along * e + h * np.array([-e[1], e[0]])
    if c[1] < 0:  # take the open (upper) branch
        c = b + along * e - h * np.array([-e[1], e[0]])
    return build_structure(
        [[0.0, 0.0], b, c, d], [[0, 1], [1, 2], [2, 3]], section=triangular_tube(),
        material=ALUMINIUM, supports={0: "xy", 3: "xy"}, name="four-bar linkage",
        node_ids=["A", "B", "C", "D"], member_ids=["crank", "coupler", "rocker"])
