# SPDX-License-Identifier: MIT
"""Rank analysis of a pin-jointed assembly: mechanisms, rigid-body motions, self-stress states.

For ``b`` bars and ``f`` free joint coordinates the compatibility matrix B (b × f,
Hortobágyi eq. 2) has rank ρ.  Then (Hortobágyi section 2; Pellegrino & Calladine)

* ``f − ρ`` independent infinitesimal motions (the null space of B).  Those that are rigid-body
  motions of the whole assembly left free by insufficient supports are reported separately as
  ``rigid_body_motions``; the rest are internal ``mechanisms``;
* ``b − ρ`` independent states of self-stress (the null space of Bᵀ, the equilibrium matrix).

The assembly is statically determinate when it has no self-stress state and kinematically
determinate when it has no mechanism and no rigid-body motion.

Tolerance
---------
B holds direction cosines, so its singular values are dimensionless and independent of the
length unit; a singular value counts as zero when ``σ ≤ tolerance · σ_max``
(:func:`trussfe.linalg.matrix_rank`, shared with the post-critical hand-over).  The default
relative tolerance is ``max(b, f) · 1e3 · eps`` (about 2e-10 for a hundred bars) for the dense
SVD.  Near a singular position the gap matters: the result carries the smallest singular value
kept and the largest one dropped, so a reader can see how clear the decision was.  When the
geometry itself is only known to an accuracy δ (e.g. positions from a continuation converged to
a bar-length misfit δ·L), pass ``tolerance ≥ δ``: a rank decided below the geometric accuracy is
noise (the Bricard octahedron is the standard trap).

Large assemblies (more than ``dense_limit`` coordinates or bars) use a sparse
path: the nullity of ``K = BᵀB`` is the number of its eigenvalues σ² below the tolerance, counted
exactly by Sylvester's law of inertia from one symmetric sparse factorisation of
``K − σ_tol² I`` (:func:`trussfe.linalg.factor`, ``kind="symmetric"``; null vectors by inverse
iteration with that factorisation): MKL PARDISO's symmetric-indefinite LDLᵀ with
nested-dissection ordering for large systems when it is installed (it returns the inertia;
used only if no pivot was perturbed), else SuperLU with diagonal pivots.  The relative
tolerance is raised to at least 1e-6 (relative to the Gershgorin bound of σ_max) because σ² is
resolved only to round-off of K; self-stress states are counted as ``b − ρ`` without a basis,
and the decision margin is reported only when mechanisms are found.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

from ..errors import AnalysisError
from ..linalg.rank import RankError, matrix_rank
from .compatibility import compatibility_matrix

log = logging.getLogger(__name__)


@dataclass
class RankResult:
    """Outcome of :func:`rank_analysis`.

    Attributes
    ----------
    rank : int
        ρ(B).
    n_coordinates, n_bars : int
        Columns (free coordinates) and rows (bars) of B.
    mechanisms : int
        Internal infinitesimal mechanisms, ``f − ρ − rigid_body_motions``.
    rigid_body_motions : int
        Rigid-body motions the supports leave free.
    self_stress_states : int
        ``b − ρ``.
    mechanism_basis : ndarray, shape (f, mechanisms)
        Orthonormal basis of the internal mechanisms (orthogonal to the rigid-body motions),
        in free-coordinate order.
    rigid_body_basis : ndarray, shape (f, rigid_body_motions)
    self_stress_basis : ndarray, shape (b, self_stress_states) or None
        Bar tensions of each state (None on the sparse path).
    free : ndarray of bool, shape (n, dim)
        Free coordinates (columns of B in row-major order).
    tolerance : float
        Absolute singular-value threshold used.
    smallest_kept, largest_dropped : float
        Smallest singular value counted in the rank and largest one treated as zero
        (``nan`` if none): the margin of the rank decision.
    """

    rank: int
    n_coordinates: int
    n_bars: int
    mechanisms: int
    rigid_body_motions: int
    self_stress_states: int
    mechanism_basis: np.ndarray
    rigid_body_basis: np.ndarray
    self_stress_basis: np.ndarray | None
    free: np.ndarray
    tolerance: float
    smallest_kept: float = float("nan")
    largest_dropped: float = float("nan")
    extra: dict = field(default_factory=dict)

    @property
    def infinitesimal_motions(self) -> int:
        """``f − ρ``: every independent motion (Hortobágyi's μ·j − ρ(B))."""
        return self.n_coordinates - self.rank

    @property
    def statically_determinate(self) -> bool:
        """No state of self-stress."""
        return self.self_stress_states == 0

    @property
    def kinematically_determinate(self) -> bool:
        """No mechanism and no rigid-body motion."""
        return self.mechanisms == 0 and self.rigid_body_motions == 0

    @property
    def classification(self) -> str:
        """Pellegrino–Calladine type: I (s=0, m=0), II (s>0, m=0), III (s=0, m>0), IV."""
        m = self.mechanisms + self.rigid_body_motions
        s = self.self_stress_states
        return {(False, False): "I", (True, False): "II", (False, True): "III",
                (True, True): "IV"}[(s > 0, m > 0)]


def rigid_body_modes(coords: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the rigid-body displacement fields of a point set.

    Parameters
    ----------
    coords : ndarray, shape (n, dim)

    Returns
    -------
    ndarray, shape (n * dim, r)
        r = 3 in 2-D and 6 in 3-D, fewer for degenerate point sets (collinear points have no
        rotation about their own line).

    Examples
    --------
    >>> rigid_body_modes(np.array([[0., 0.], [1., 0.]])).shape
    (4, 3)
    >>> rigid_body_modes(np.array([[0., 0., 0.], [1., 0., 0.]])).shape
    (6, 5)
    """
    x = np.asarray(coords, dtype=float)
    n, dim = x.shape
    xc = x - x.mean(axis=0)
    cols = []
    for k in range(dim):                                   # translations
        t = np.zeros((n, dim))
        t[:, k] = 1.0
        cols.append(t.ravel())
    if dim == 2:                                           # rotation about z: (−y, x)
        cols.append(np.column_stack([-xc[:, 1], xc[:, 0]]).ravel())
    else:                                                  # rotations ω × x
        for k in range(3):
            w = np.zeros(3)
            w[k] = 1.0
            cols.append(np.cross(w, xc).ravel())
    R = np.column_stack(cols)
    u, s, _ = np.linalg.svd(R, full_matrices=False)
    keep = s > 1e-10 * max(s.max(), 1e-300)
    return u[:, keep]


def _free_rigid_modes(coords: np.ndarray, free: np.ndarray) -> np.ndarray:
    """Rigid-body motions with every fixed coordinate at zero, on the free coordinates."""
    R = rigid_body_modes(coords)                           # (n*dim, r)
    fixed_rows = ~free.ravel()
    if np.any(fixed_rows):
        ns = sla.null_space(R[fixed_rows], rcond=1e-10)    # (r, k) combinations fixing supports
        R = R @ ns
    if R.shape[1] == 0:
        return np.zeros((int(free.sum()), 0))
    Rf = R[free.ravel()]
    q, s, _ = np.linalg.svd(Rf, full_matrices=False)
    return q[:, s > 1e-10 * max(s.max(initial=0.0), 1e-300)]


def rank_analysis(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray, *,
                  tolerance: float | None = None, dense_limit: int = 1500,
                  sparse_backend: str = "auto") -> RankResult:
    """Rank, mechanisms, rigid-body motions and self-stress states of an assembly.

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
        Joint positions (the geometry decides the rank).
    connectivity : ndarray of int, shape (b, 2)
        Bars.
    free : ndarray of bool, shape (n, dim)
        Free coordinates (``~structure.translation_supports``).
    tolerance : float, optional
        Relative singular-value tolerance (σ ≤ tolerance·σ_max counts as zero).  Default
        ``1e3·eps·max(max(b, f), max|x|/l_min)`` — the round-off of the matrix and that of its
        direction cosines, computed from coordinates far from the origin against the
        shortest bar — on the dense path, and at least 1e-6 on the sparse one.
    dense_limit : int
        Above this many free coordinates the sparse path is used.
    sparse_backend : {"auto", "pardiso", "superlu"}
        Symmetric factorisation of the sparse path (see the module notes); ``auto`` follows
        the backend rule of :mod:`trussfe.linalg.factor`, and PARDISO's inertia is used only
        when it is reliable (SuperLU's otherwise).

    Returns
    -------
    RankResult

    Notes
    -----
    Hortobágyi section 2: infinitesimal mechanisms ``μ·j − ρ(B)``; self-stress ``b − ρ(B)``
    (the null space of the equilibrium matrix Bᵀ).

    Examples
    --------
    A triangle pinned at one corner and on a roller at another is rigid and determinate:

    >>> x = np.array([[0., 0.], [1., 0.], [0., 1.]])
    >>> free = np.array([[0, 0], [1, 0], [1, 1]], bool)
    >>> r = rank_analysis(x, np.array([[0, 1], [1, 2], [2, 0]]), free)
    >>> (r.rank, r.mechanisms, r.rigid_body_motions, r.self_stress_states)
    (3, 0, 0, 0)

    The same triangle with no support has three rigid-body motions and no mechanism:

    >>> r = rank_analysis(x, np.array([[0, 1], [1, 2], [2, 0]]), np.ones((3, 2), bool))
    >>> (r.mechanisms, r.rigid_body_motions)
    (0, 3)
    """
    x = np.asarray(coords, dtype=float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, dtype=bool).reshape(x.shape)
    B = compatibility_matrix(x, conn, free)
    b, f = B.shape
    rigid = _free_rigid_modes(x, free)
    if sparse_backend not in ("auto", "pardiso", "superlu"):
        raise AnalysisError("rank analysis", f"unknown sparse backend '{sparse_backend}' "
                                             "(auto, pardiso or superlu)")
    if tolerance is None and b and f:
        # the direction cosines of B come from coordinate differences, known to the
        # round-off of the coordinates themselves: ε·max|x| against the shortest bar (a
        # straight chain 1e5 m from the origin is straight only to 2e-11)
        lengths = np.linalg.norm(x[conn[:, 1]] - x[conn[:, 0]], axis=1)
        eps = np.finfo(float).eps
        geometry = eps * float(np.abs(x).max()) / max(float(lengths.min()), 1e-300)
        tolerance = 1e3 * max(max(b, f) * eps, geometry)
    try:
        r = matrix_rank(B, tolerance=tolerance, dense_limit=dense_limit,
                        backend=sparse_backend)
    except RankError as exc:
        raise AnalysisError("rank analysis", str(exc)) from None
    mech, rig = _split_rigid(r.null, rigid, 1e3 * r.tolerance)
    sparse = r.left_null is None
    return RankResult(rank=r.rank, n_coordinates=f, n_bars=b, mechanisms=mech.shape[1],
                      rigid_body_motions=rig.shape[1], self_stress_states=b - r.rank,
                      mechanism_basis=mech, rigid_body_basis=rig,
                      self_stress_basis=None if sparse else _sign_fix(r.left_null),
                      free=free, tolerance=r.tolerance, smallest_kept=r.smallest_kept,
                      largest_dropped=r.largest_dropped,
                      extra={"sparse_backend": r.backend} if sparse else {})


def _split_rigid(null: np.ndarray, rigid: np.ndarray, atol: float) -> tuple[np.ndarray, np.ndarray]:
    """Split a null-space basis into rigid-body motions and internal mechanisms."""
    if rigid.shape[1] == 0 or null.shape[1] == 0:
        return null, rigid[:, :0] if rigid.size else np.zeros((null.shape[0], 0))
    # rigid motions lie in the null space of B (they do not stretch bars); keep those that do
    coef = null.T @ rigid                                  # (k, r)
    resid = np.linalg.norm(rigid - null @ coef, axis=0)
    rig = rigid[:, resid <= max(atol, 1e-8)]
    if rig.shape[1] == 0:
        return null, rig
    proj = null - rig @ (rig.T @ null)                     # remove the rigid part
    u, s, _ = np.linalg.svd(proj, full_matrices=False)
    k = null.shape[1] - rig.shape[1]
    return u[:, :k], rig


def _sign_fix(v: np.ndarray) -> np.ndarray:
    """Make the largest entry of each column positive (deterministic output)."""
    if v.size == 0:
        return v
    idx = np.argmax(np.abs(v), axis=0)
    return v * np.sign(v[idx, np.arange(v.shape[1])])


def structure_rank(structure, **kwargs) -> RankResult:
    """:func:`rank_analysis` of a :class:`~trussfe.model.Structure` (its bars and supports).

    Beams are treated as pin-jointed bars: the rank analysis is that of the bar-and-joint
    assembly (Hortobágyi's setting).
    """
    return rank_analysis(structure.coords, structure.connectivity,
                         ~structure.translation_supports, **kwargs)
