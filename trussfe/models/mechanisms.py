# SPDX-License-Identifier: MIT
"""Catalogue of named bar-and-joint assemblies with known rank and mechanism counts.

Each entry carries its geometry, supports, the counts a rank analysis must find (from the
source named in the entry, or from the construction) and a drive for tracing its motion.
Tests parametrise over :data:`CATALOGUE`; the shipped models ``meshes/mech_*.toml`` are written
from it by :func:`write_toml` (and a test checks they agree).

Hortobágyi's figures are missing from the 1999 paper's text; the assemblies of sections 6, 7, 8
and 9 are constructions that satisfy every property the text states, documented in their builders.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass
class MechanismEntry:
    """A reference assembly.

    Attributes
    ----------
    name : str
        Catalogue key and model name.
    title : str
    coords : ndarray, shape (n, dim)
    bars : ndarray of int, shape (b, 2)
    supports : dict
        Node index → fixed axes, e.g. ``"xy"``.
    expected : dict
        ``rank``, ``mechanisms``, ``rigid_body_motions``, ``self_stress_states``.
    source : str
        Where the expected numbers come from.
    drive : str
        ``"NODE:AXIS"`` suggested for ``trussfe trace`` (node ids are ``str(index + 1)``).
    step : float
        Suggested drive increment, m.
    removable : dict
        Names of bars whose removal gives another catalogue case (documentation).
    """

    name: str
    title: str
    coords: np.ndarray
    bars: np.ndarray
    supports: dict
    expected: dict
    source: str
    drive: str = ""
    step: float = 0.05
    notes: str = ""
    extra: dict = field(default_factory=dict)

    @property
    def dim(self) -> int:
        """Spatial dimension."""
        return self.coords.shape[1]

    @property
    def node_ids(self) -> list[str]:
        """Node ids: ``"1"``, ``"2"``, ... (Hortobágyi numbers joints from 1)."""
        return [str(i + 1) for i in range(self.coords.shape[0])]

    @property
    def free(self) -> np.ndarray:
        """Free coordinates, shape (n, dim)."""
        f = np.ones(self.coords.shape, dtype=bool)
        for i, axes in self.supports.items():
            for a in axes:
                f[i, "xyz".index(a)] = False
        return f

    def drive_index(self) -> int:
        """Flat coordinate index of :attr:`drive`."""
        node, axis = self.drive.split(":")
        return (int(node) - 1) * self.dim + "xyz".index(axis)

    def structure(self):
        """The entry as a :class:`~trussfe.model.Structure` (aluminium tube members)."""
        from trussfe.model.sections import Material, Section
        from trussfe.model.structure import build_structure
        return build_structure(self.coords, self.bars, section=Section.tube("tube", 0.02, 0.016),
                               material=Material("aluminium", E=70e9, G=26e9, density=2700.0),
                               supports={i: list(a) for i, a in self.supports.items()},
                               name=self.name, node_ids=self.node_ids,
                               member_ids=[f"b{k + 1}" for k in range(len(self.bars))])


def _entry(name, title, coords, bars, supports, expected, source, drive="", step=0.05,
           notes="") -> MechanismEntry:
    return MechanismEntry(name=name, title=title, coords=np.asarray(coords, float),
                          bars=np.asarray(bars, dtype=np.int64), supports=supports,
                          expected=dict(zip(("rank", "mechanisms", "rigid_body_motions",
                                             "self_stress_states"), expected)),
                          source=source, drive=drive, step=step, notes=notes)


def hortobagyi_section4() -> MechanismEntry:
    """Hortobágyi section 4 in the folded state (l = 1): joints 1, 2 free, 3 at the origin and
    4 at (l, 0) fixed; bars b1 = 1–2, b2 = 3–1, b3 = 4–2.  Joint 1 lies on top of joint 4.
    The paper: B is 3 × 4 with ρ(B) = 2 here (3 after a step)."""
    return _entry("mech_hortobagyi_sec4", "Hortobágyi (1999) section 4, folded state",
                  [[1, 0], [2, 0], [0, 0], [1, 0]], [[0, 1], [2, 0], [3, 1]],
                  {2: "xy", 3: "xy"}, (2, 2, 0, 1),
                  "Hortobágyi (1999) section 4: rho(B) = 2 at the folded state", "1:y", -0.1)


#: Crank-rocker four-bar (Grashof: 1 + 3.2 ≤ 2.6 + 3): ground 3, crank 1, coupler 3.2, rocker 2.6.
FOURBAR = {"ground": 3.0, "crank": 1.0, "coupler": 3.2, "rocker": 2.6}


def fourbar_position(theta: np.ndarray, a=1.0, b=3.2, c=2.6, d=3.0) -> tuple[np.ndarray, ...]:
    """Closed-form open-branch position of a four-bar: pin B and joint C for crank angle θ.

    Ground pivots A = (0, 0) and D = (d, 0); C is the intersection of the circles (B, b) and
    (D, c) on the left of B→D (above the ground for the open configuration).
    """
    th = np.asarray(theta, float)
    B = a * np.stack([np.cos(th), np.sin(th)], axis=-1)
    D = np.array([d, 0.0])
    w = D - B
    delta = np.linalg.norm(w, axis=-1)
    u = w / delta[..., None]
    along = (b * b - c * c + delta ** 2) / (2 * delta)
    h = np.sqrt(b * b - along ** 2)
    uperp = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    C = B + along[..., None] * u + h[..., None] * uperp
    return B, C


def fourbar(theta: float = 0.1) -> MechanismEntry:
    """Crank-rocker four-bar: ground 3, crank 1, coupler 3.2, rocker 2.6 (Grashof)."""
    B, C = fourbar_position(theta)
    return _entry("mech_fourbar", "Four-bar linkage (crank-rocker)",
                  [[0, 0], B, C, [3, 0]], [[0, 1], [1, 2], [3, 2]], {0: "xy", 3: "xy"},
                  (3, 1, 0, 0), "Gruebler: 2·2 − 3 = 1 degree of freedom", "2:y", 0.02)


def slider_crank(theta: float = 0.3) -> MechanismEntry:
    """Slider-crank as a bar assembly: crank 1, rod 3, slider joint on a roller (y fixed)."""
    x = np.cos(theta) + np.sqrt(9 - np.sin(theta) ** 2)
    return _entry("mech_slider_crank", "Slider-crank as a bar assembly",
                  [[0, 0], [np.cos(theta), np.sin(theta)], [x, 0]], [[0, 1], [1, 2]],
                  {0: "xy", 2: "y"}, (2, 1, 0, 0), "3 coordinates − 2 bars = 1", "2:y", 0.02)


def bricard_octahedron() -> MechanismEntry:
    """Bricard's flexible octahedron of type 1: opposite vertices (i, i + 3) symmetric about
    the z axis; 12 bars, 18 coordinates, six supports removing the rigid-body motions.  By
    Cauchy–Dehn counting it would be rigid (3·6 − 6 = 12 bars); it has one finite mechanism and
    one state of self-stress."""
    P = np.array([[1.0, 0.2, 0.3], [0.3, 1.1, -0.2], [-0.7, 0.5, 0.6]])
    X = np.vstack([P, P * np.array([-1.0, -1.0, 1.0])])
    bars = [(i, j) for i in range(6) for j in range(i + 1, 6) if j != i + 3]
    return _entry("mech_bricard", "Bricard's flexible octahedron (type 1, line-symmetric)",
                  X, bars, {0: "xyz", 1: "yz", 2: "z"}, (11, 1, 0, 1),
                  "Bricard (1897): flexible; rank 11 = 12 bars − 1 self-stress", "6:x", 0.02,
                  notes="over-constrained: traced by least squares over all bars")


def generic_octahedron() -> MechanismEntry:
    """A convex octahedron (Cauchy: rigid), same supports as the Bricard entry."""
    X = np.array([[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0.1, 0.1, 1], [0, 0.05, -1]],
                 float)
    opp = {(0, 2), (1, 3), (4, 5)}
    bars = [(i, j) for i in range(6) for j in range(i + 1, 6) if (i, j) not in opp]
    return _entry("mech_octahedron_rigid", "Convex octahedron (rigid)", X, bars,
                  {0: "xyz", 1: "yz", 2: "z"}, (12, 0, 0, 0),
                  "Cauchy (1813): convex polyhedra are rigid; 3·6 − 6 = 12 bars", "2:x", 0.02)


#: Section 6: inner joints P1..P4 (nodes 1–4) and ground joints G1..G4 (nodes 5–8), folded on
#: the x axis.
_SEC6_X = [[1, 0], [3, 0], [2, 0], [4, 0], [0, 0], [1.5, 0], [5, 0], [0.5, 0]]
#: Pi–Gi (bars 1–4), then the cycle P1–P2–P3–P4–P1 (bars 5–8).
_SEC6_BARS = [(0, 4), (1, 5), (2, 6), (3, 7), (0, 1), (1, 2), (2, 3), (3, 0)]


def section6_foldable(remove: int | None = None) -> MechanismEntry:
    """Hortobágyi section 6 (Figs. 4–8), a construction.

    Four inner joints P1..P4 at x = 1, 3, 2, 4 and ground joints G1..G4 at x = 0, 1.5, 5, 0.5,
    all on the x axis (the folded state); eight bars: Pi–Gi (bars 1–4) and the cycle
    P1–P2–P3–P4–P1 (bars 5–8).

    Why this topology: in a folded state every triangle of bars (or a joint tied to two ground
    joints) is a flat triangle whose lengths satisfy a + b = c — rigid, it never leaves the
    line.  With four inner joints, eight bars and no such triangle, the only graph is a
    4-cycle with each joint tied once to the ground.  Properties stated by the text, all
    checked by tests and the validation case:

    * eight bars, four inner joints: an infinitesimal mechanism (ρ(B) = 4, four vertical
      infinitesimal mechanisms, four self-stress states) that cannot move: no real
      second-order unfolding direction (:func:`trussfe.kinematics.unfolding.tangent_cone`),
      so it is second-order rigid, hence rigid;
    * removing a bar (P1–G1, "Fig. 5", ``remove=0``; or P3–G3, "Fig. 7", ``remove=2``):
      μ·j − ρ(B) = 8 − 4 = 4; after the prescribed vertical increments of the four inner
      joints the assembly is a one-degree-of-freedom finite mechanism, B of full row rank 7;
    * four different unfolding shapes: prescribing the four vertical increments along the
      unfolding direction nearest the vertical mechanism of joint Pi (i = 1..4), the largest
      being the independent coordinate, gives four distinct traced shapes.

    Found by computing: the second-order cone of this construction has eight real lines per
    removed bar (each with its mirror image y → −y).  With a ground bar removed the assembly is
    a flat four-bar (two branches) carrying two flat dyads, each of which opens both ways or not
    at all, so 0 or 8 lines: in a sweep of 150 random folded states of this graph
    (:func:`trussfe.studies.hortobagyi.section6_direction_counts`, 598 counted
    cases) the count was 0 in 444 cases and 8 in 153 (once 7, a root the multi-start missed),
    never 2 — the paper's "two shapes, symmetrical pairs of these are the other two", read as
    all the unfolding shapes, cannot hold together with the other properties here.  The four
    shapes traced are the four that the four independent coordinates select, as section 6
    controls them.
    """
    bars = list(_SEC6_BARS)
    name, title, exp = "mech_sec6_foldable", "Hortobágyi section 6: foldable assembly", \
        (4, 4, 0, 4)
    if remove is not None:
        del bars[remove]
        fig = {0: 5, 2: 7}.get(remove, "")
        name = f"mech_sec6_foldable_minus{remove + 1}"
        title = f"Hortobágyi section 6, Fig. {fig}: foldable assembly with bar {remove + 1} removed"
        exp = (4, 4, 0, 3)
    e = _entry(name, title, _SEC6_X, bars, {i: "xy" for i in range(4, 8)}, exp,
               "Hortobágyi (1999) section 6: mu*j - rho(B) = 4 with a bar removed", "1:y", 0.05)
    if remove is not None:
        # four prescribed vertical increments near the unfolding direction led by P1
        e.extra["trace"] = ("--drive 1:y --step 0.05 --drive 2:y --step 0.008 --drive 3:y "
                            "--step 0.0015 --drive 4:y --step 0.0003 --steps 12")
    return e


def section8_compound(flip: bool = False) -> MechanismEntry:
    """Hortobágyi section 8 (Fig. 10), a construction: two Watt linkages joined by a bar.

    Each side is a Watt straight-line linkage (rockers 1, coupler 1) whose coupler is a plate of
    joints C1, M, C2 and E, triangulated by five bars (Vlase's construction I); the coupler
    midpoint M traces a curve with an inflection and a vertical tangent at the symmetric state.
    The two midpoints are joined by the horizontal connecting bar.  8 inner joints, 15 bars.
    At the symmetric state each M moves vertically, so the connecting bar adds no first-order
    constraint: ρ(B) = 14, μ·j − ρ(B) = 2, b − ρ(B) = 1 (as the text states); one end can move
    down with the other fixed to first order.  To second order the connecting bar needs
    ``(y_L − y_R)² = 4a β (y_L³ + y_R³)`` (β the cubic coefficient of the midpoint curve),
    which has real solutions only for y ≤ 0 with this orientation: the assembly can move only
    downward (``flip=True`` mirrors it upside down).
    """
    s = 1.0 if flip else -1.0
    left = np.array([[-3, 0.5], [-2, 0.5], [-2, -0.5], [-1, -0.5], [-2, 0], [-2.3, 0]], float)
    right = left * np.array([-1.0, 1.0])
    left[:, 1] *= s
    right[:, 1] *= s
    # joints: A, C1, C2, D, M, E per side; A and D are ground
    X = np.vstack([left, right])
    side = [(0, 1), (2, 3), (1, 4), (4, 2), (1, 5), (5, 2), (4, 5)]
    bars = side + [(a + 6, b + 6) for a, b in side] + [(4, 10)]
    return _entry("mech_sec8_compound", "Hortobágyi section 8: compound mechanism", X, bars,
                  {0: "xy", 3: "xy", 6: "xy", 9: "xy"}, (14, 2, 0, 1),
                  "Hortobágyi (1999) section 8: mu*j - rho(B) = 2, b - rho(B) = 1", "5:y",
                  -0.02)


def section9_space(seed: int = 3) -> MechanismEntry:
    """Hortobágyi section 9 (Figs. 12–14), a construction: 17 inner joints, 50 bars in space.

    A change-point four-bar (ground 3, crank 1, coupler 2.5, rocker 1.5) in the plane z = 0 is
    built from bars: each of its two moving joints P, Q is tied to two ground joints on the
    pivot's axis (z = ±1), so it moves on a circle, and P–Q is the coupler — 2 joints, 5 bars.
    Fifteen more joints follow, each tied by three bars to joints of the crank or the rocker
    body (Henneberg steps, full row rank): 17 joints, 5 + 45 = 50 bars,
    μ·j − ρ(B) = 51 − 50 = 1.  At the four-bar's
    flat position all bars meeting at P (and at Q) are coplanar — the bifurcation the text
    describes; the start state is the four-bar at crank angle 150°.
    """
    rng = np.random.default_rng(seed)
    theta = np.deg2rad(150.0)
    P = np.array([np.cos(theta), np.sin(theta), 0.0])
    D = np.array([3.0, 0.0, 0.0])
    # Q: |Q − P| = 2.5, |Q − D| = 1.5, in the plane z = 0, on the branch through Q = (1.5, 0)
    w = D - P
    dist = np.linalg.norm(w)
    u = w / dist
    along = (2.5 ** 2 - 1.5 ** 2 + dist ** 2) / (2 * dist)
    h = np.sqrt(2.5 ** 2 - along ** 2)
    Q = P + along * u - h * np.array([-u[1], u[0], 0.0])
    ground = np.array([[0, 0, 1], [0, 0, -1], [3, 0, 1], [3, 0, -1],
                       [-1.5, 2.0, 0.0], [4.5, 2.0, 0.3], [1.5, -2.5, 0.2]], float)
    # node order: P, Q, ground (7), then 15 new joints: 8 on the crank body {P, axis joints},
    # 7 on the rocker body {Q, axis joints}; each is tied by three bars to joints of its body
    # (Henneberg steps), so it turns rigidly with the crank or the rocker and never makes its
    # own bars coplanar.
    pts = [P, Q] + list(ground)
    bodies = [[0, 2, 3], [1, 4, 5]]
    centres = [np.zeros(3), np.array([3.0, 0.0, 0.0])]
    new_bars = []
    for k in range(15):
        body = bodies[0] if k < 8 else bodies[1]
        c = centres[0] if k < 8 else centres[1]
        pick = rng.choice(np.array(body), 3, replace=False)
        ref = pts[body[0]] - c                              # towards the moving joint
        pts.append(c + ref * rng.uniform(0.3, 0.9) + rng.normal(0, 0.25, 3))
        new_bars += [(int(i), len(pts) - 1) for i in pick]
        body.append(len(pts) - 1)
    X = np.array(pts)
    bars = [(0, 2), (0, 3), (1, 4), (1, 5), (0, 1)] + new_bars
    ground_idx = range(2, 9)
    return _entry("mech_sec9_space", "Hortobágyi section 9: spatial assembly, 17 joints, 50 bars",
                  X, bars, {i: "xyz" for i in ground_idx}, (50, 1, 0, 0),
                  "Hortobágyi (1999) section 9: 3*17 - 50 = 1, full row rank", "1:y", -0.05)


def section7_chain(n: int, remove: bool = False,
                   lengths: list[tuple[float, float]] | None = None) -> MechanismEntry:
    """Hortobágyi section 7 (Fig. 9, Tarnai 1989), a construction: n straight bar pairs in a
    chain whose infinitesimal mechanism has order 2ⁿ − 1.

    Pair j (j = 1 … n) is two collinear bars ``A_j–X_j–X_{j+1}`` of lengths a_j, b_j (default
    1 m each; ``lengths`` gives the n pairs (a_j, b_j)) along the unit vector e_j, with A_j
    fixed; the end X_{j+1} of pair j is the middle joint of pair j + 1, whose axis e_{j+1} is
    perpendicular to e_j (e_j alternates between x and y: a staircase).  The last end X_{n+1} is fixed.  Joints X_1 … X_n are free: 2n coordinates,
    2n bars.  Node ids: X_1 … X_{n+1} are "1" … "n+1", A_1 … A_n are "n+2" … "2n+1".

    Why the order is 2ⁿ − 1.  To first order only X_1 moves, across its pair (ρ(B) = 2n − 1,
    one mechanism, one state of self-stress: the last pair in tension).  A middle joint moved
    across its pair by y pulls the pair's end along the axis by ``y²(a + b)/(2ab)`` (a, b the
    two bar lengths; ``y²/l`` for equal bars), and that end is the middle joint of the next
    pair, moved across it.  So if X_j first moves at order v_j with coefficient c_j,

        v_{j+1} = 2 v_j,   c_{j+1} = −c_j² (a_j + b_j) / (2 a_j b_j),   v_1 = 1,

    i.e. v_j = 2^(j−1).  The last pair has both ends fixed: its bars' lengths need
    ``|X_n(t) − X_n|² = 0`` at every order, and the first non-zero term of that sum, c_n²,
    appears at order 2 v_n = 2ⁿ — the compatibility equations are solvable up to order 2ⁿ − 1
    and not beyond (:mod:`trussfe.kinematics.order`).  n = 1 is the straight two-bar chain
    (order 1); n = 14 gives the paper's 2¹⁴ − 1 = 16383
    (:func:`trussfe.studies.hortobagyi.section7_recursion` carries the recursion exactly).

    ``remove=True`` removes the bar A_n–X_n: the last pair is no longer straight, B has full row
    rank (2n − 1 bars, 2n coordinates) and the assembly is a one-degree-of-freedom finite
    mechanism, X_n turning about X_{n+1} (the paper: "removing one bar we obtain a
    one-degree-of-freedom finite mechanism").
    """
    ab = [(1.0, 1.0)] * n if lengths is None else [tuple(map(float, p)) for p in lengths]
    if len(ab) != n:
        raise ValueError(f"give {n} pairs of bar lengths, got {len(ab)}")
    e = (np.array([1.0, 0.0]), np.array([0.0, 1.0]))
    X = [np.array([ab[0][0], 0.0])]
    A = []
    for j in range(n):
        A.append(X[j] - ab[j][0] * e[j % 2])
        X.append(X[j] + ab[j][1] * e[j % 2])
    coords = np.array(X + A)
    bars = []
    for j in range(n):
        bars += [(n + 1 + j, j), (j, j + 1)]
    supports = {i: "xy" for i in range(n, 2 * n + 1)}
    name = f"mech_sec7_chain_{n}"
    title = f"Hortobágyi section 7: {n} straight bar pair(s), order 2^{n} - 1 = {2 ** n - 1}"
    exp = (2 * n - 1, 1, 0, 1)
    source = (f"construction (Tarnai 1989): order 2^{n} - 1; rank 2n - 1, one mechanism, "
              "one self-stress")
    if remove:
        del bars[2 * n - 2]
        name += "_minus1"
        title = (f"Hortobágyi section 7: {n} bar pairs with bar A{n}-X{n} removed, a "
                 "one-degree-of-freedom finite mechanism")
        exp = (2 * n - 1, 1, 0, 0)
        source = "Hortobágyi (1999) section 7: removing one bar gives a 1-dof finite mechanism"
    return _entry(name, title, coords, bars, supports, exp, source, "1:y", 0.05)


def square_frame() -> MechanismEntry:
    """A pinned square of four bars on two supports: one mechanism (sway)."""
    return _entry("mech_square", "Square frame, no diagonal (sway mechanism)",
                  [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 3], [3, 2], [2, 1]],
                  {0: "xy", 1: "xy"}, (3, 1, 0, 0), "4 coordinates − 3 independent bars", "3:x",
                  0.05)


def triangle_free() -> MechanismEntry:
    """An unsupported triangle: three rigid-body motions, no mechanism."""
    return _entry("mech_triangle_free", "Unsupported triangle", [[0, 0], [1, 0], [0, 1]],
                  [[0, 1], [1, 2], [2, 0]], {}, (3, 0, 3, 0), "3·2 − 3 bars = 3 rigid-body "
                  "motions in the plane")


def _build() -> dict[str, MechanismEntry]:
    entries = [hortobagyi_section4(), fourbar(), slider_crank(), bricard_octahedron(),
               generic_octahedron(), section6_foldable(), section6_foldable(0),
               section6_foldable(2), section7_chain(1), section7_chain(2), section7_chain(3),
               section7_chain(4), section7_chain(14), section7_chain(14, remove=True),
               section8_compound(), section9_space(), square_frame(), triangle_free()]
    return {e.name: e for e in entries}


#: Named reference assemblies.
CATALOGUE: dict[str, MechanismEntry] = _build()


def to_toml(entry: MechanismEntry) -> str:
    """The entry as a trussfe model file (docs/model-format.md)."""
    fmt = "{:.15g}".format
    lines = [f"# {entry.title}", f"# expected: {entry.expected}; source: {entry.source}"]
    if entry.extra.get("trace"):
        lines.append(f"# trace: trussfe trace {entry.name}.toml {entry.extra['trace']}")
    elif entry.drive:
        lines.append(f"# trace: trussfe trace {entry.name}.toml --drive {entry.drive} "
                     f"--step {entry.step:g} --steps 20")
    lines += ["", "[model]", f'name = "{entry.name}"', f"dimension = {entry.dim}", "",
              "[materials.aluminium]", "E = 70.0e9", "G = 26.0e9", "density = 2700.0", "",
              "[sections.tube]", "outer_diameter = 0.02", "inner_diameter = 0.016", "",
              "[nodes]"]
    for nid, x in zip(entry.node_ids, entry.coords):
        lines.append(f'"{nid}" = [{", ".join(fmt(v) for v in x)}]')
    lines += ["", "[members]"]
    for k, (a, b) in enumerate(entry.bars):
        lines.append(f'b{k + 1} = {{ nodes = ["{a + 1}", "{b + 1}"], section = "tube", '
                     'material = "aluminium" }')
    if entry.supports:
        lines += ["", "[supports]"]
        for i, axes in entry.supports.items():
            quoted = ", ".join(f'"{a}"' for a in axes)
            lines.append(f'"{i + 1}" = [{quoted}]')
    return "\n".join(lines) + "\n"


def write_toml(directory: str | Path) -> list[Path]:
    """Write every catalogue entry as ``<directory>/<name>.toml``; returns the paths."""
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    out = []
    for e in CATALOGUE.values():
        p = d / f"{e.name}.toml"
        p.write_text(to_toml(e))
        out.append(p)
    return out
