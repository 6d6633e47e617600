# SPDX-License-Identifier: MIT
"""Factorisation of the free-DOF stiffness, with mechanism detection.

A singular stiffness never reaches the user as a traceback or a NaN: the factorisation
(:func:`trussfe.linalg.factor`) is checked for negligible pivots, and when it is singular
the null space of the (diagonally scaled) stiffness
(:func:`trussfe.linalg.stiffness_null_space`) says how many independent mechanisms there
are and which nodes move in them.
"""
from __future__ import annotations

import dataclasses
import logging
import time

import numpy as np
import scipy.sparse as sp

from ..errors import UNITS_ADVICE, MechanismError
from ..linalg import SINGULAR_PIVOT, Factor, FreeBlock, factor, free_submatrix
from ..linalg.banded import band_layout_free, band_null_space
from ..linalg.factor import BANDED_MAX_BANDWIDTH, PARDISO_MIN_DOF, banded_limit
from ..linalg.ordering import Points
from ..linalg.rank import DENSE_LIMIT, NULL_TOLERANCE, stiffness_null_space
from ..mechanics.geometry import rotation_length

log = logging.getLogger(__name__)



def factorise(K: sp.spmatrix, free: np.ndarray, fe=None, item: str = "structure",
              backend: str = "auto") -> Factor:
    """Factorise K_ff (:func:`trussfe.linalg.factor`, ``kind="spd"``), raising
    :class:`MechanismError` when it is singular.

    Parameters
    ----------
    K : sparse matrix, shape (n_dof, n_dof)
    free : ndarray of int
        Free DOFs.
    fe : FEModel, optional
        Used to name the moving nodes in the error.
    item : str
        Item named in the error message (the model file).
    backend : {"auto", "banded", "superlu", "pardiso"}
        Linear-solver backend.

    Returns
    -------
    Factor
        Of K_ff: it solves for the free DOFs (see :func:`solve_free`).
    """
    K = sp.csr_matrix(K)
    if not K.has_canonical_format:
        K = K.copy()
        K.sum_duplicates()
    free = np.asarray(free, dtype=np.int64)
    block = FreeBlock(K, free)
    if block.shape[0] and np.any(block.diagonal() <= 0):     # a DOF nothing is attached to
        _raise_mechanism(block.tocsr(), free, fe, item, K)
    points = None
    if fe is not None and free.size >= PARDISO_MIN_DOF and joint_dofs_only(fe):
        # where the DOFs sit: PARDISO's Cholesky orders them by geometric nested dissection
        every = fe.dof_points()
        points = Points(every.of_unknown[free], every.coords)
    scale = rotation_scale(fe, free) if fe is not None else None
    if scale is None:
        fac = factor(block, "spd", backend, singular="flag", points=points)
    else:
        # the pivot test compares translational and rotational pivots: measure rotations in
        # a length of the model, so that its outcome does not depend on the unit of length
        fac = _scaled_factor(block.tocsr(), scale, backend, points)
    if fac.is_singular:
        _raise_mechanism(block.tocsr(), free, fe, item, K)
    log.debug("factorised %d free DOFs (%s)", free.size, fac.backend)
    return fac


def rotation_scale(fe, free: np.ndarray) -> np.ndarray | None:
    """Scale of the free DOFs that turns every rotation into a length: ``1/L`` on the
    rotations, 1 on the translations, with ``L`` the median member length rounded to a
    power of two.

    A stiffness holds translational entries (N/m) and rotational ones (N·m/rad), whose ratio
    changes with the unit of length as ``L²`` — in SI units the rotational pivots of a beam
    10 µm long are 1e-10 of its axial ones, in µm units 1e2 times them.  The relative pivot
    test of :mod:`trussfe.linalg.tolerance` therefore refused a sound micro-scale frame in
    SI units and accepted it in µm.  In ``S K S`` with this scale the ratio of a member's
    rotational to axial stiffness is its slenderness ``(r/L)²``, the same in every
    consistent unit system and for every geometrically similar structure (to the factor of
    at most 2 of the rounding of ``L``).

    Parameters
    ----------
    fe : FEModel
    free : ndarray of int
        Free DOFs.

    Returns
    -------
    ndarray, shape (free.size,), or None
        None when no free DOF is a rotation (a truss: every entry is N/m already).
    """
    rot = np.zeros(fe.n_dof, dtype=bool)
    dim = fe.structure.dim
    for dofs in (fe.node_dofs[:, dim:], fe.private_dofs, fe.interior_dofs[:, dim:]):
        rot[dofs[dofs >= 0]] = True
    rot = rot[free]
    if not rot.any():
        return None
    length = rotation_length(fe.structure.lengths())
    # a power of two: the scaling is exact in floating point, and a model whose members are
    # 0.7–1.4 units long (most SI models) is factorised exactly as without it
    return np.where(rot, 2.0 ** -np.round(np.log2(length)), 1.0)


def _scaled_factor(Kff: sp.csr_matrix, scale: np.ndarray, backend: str,
                   points: Points | None) -> Factor:
    """Factor of ``K_ff`` from the factorisation of ``S K_ff S`` (``S = diag(scale)``): its
    singularity test and inertia are those of the scaled matrix (a congruence keeps the
    inertia), its solves and their refinement those of ``K_ff`` (``x = S (S K S)⁻¹ S b``)."""
    S = sp.diags(scale)
    inner = factor((S @ Kff @ S).tocsr(), "spd", backend, singular="flag", points=points)
    if inner.is_singular:
        return inner
    col = scale[:, None]

    def solve(b):
        s = col if np.ndim(b) == 2 else scale
        return s * inner._solve(s * b)

    def solve_transposed(b):
        s = col if np.ndim(b) == 2 else scale
        return s * inner._solve_transposed(s * b)

    return dataclasses.replace(
        inner, matrix=Kff, _solve=solve, residuals=[],
        _solve_transposed=None if inner._solve_transposed is None else solve_transposed)


def joint_dofs_only(fe) -> bool:
    """Whether every DOF of the model is a joint's (no points inside subdivided members, no
    rotations a released member end owns): the models whose K_ff PARDISO's Cholesky takes in
    the geometric nested-dissection order of the DOFs' points.

    A member's own DOFs are coupled to that member only; eliminated first they fill nothing
    but the block between its two joints, which a graph ordering finds and a cut through
    the points does not (a 60 × 60 space grid of pinned beams: 7.0 GFlop in the geometric
    order against 0.5 GFlop in MKL's).
    """
    return fe.interior_dofs.size == 0 and not np.any(fe.private_dofs >= 0)


def solve_free(fac: Factor, free: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Solve K u = f with a factor of K_ff (:func:`factorise`): ``f`` of shape (n_dof,) or
    (n_dof, r) over all DOFs; the fixed DOFs of ``u`` are 0."""
    f = np.asarray(f, dtype=float)
    u = np.zeros(f.shape)
    u[free] = fac.solve(np.ascontiguousarray(f[free]))
    return u


def factorise_truss(fe, backend: str = "auto") -> tuple[Factor, dict] | None:
    """Banded factorisation of K_ff of a plain truss straight from its bars, without the
    global sparse K (:mod:`trussfe.fem.truss_band`); None where that path does not apply (not
    a truss of single bars, too few DOFs for ``auto``, a DOF order that is not narrow, or
    both band factorisations refuse the matrix) — :func:`factorise` then takes over and, for
    a singular K, names the mechanism.

    Returns
    -------
    (Factor, dict) or None
        The factor of K_ff and the seconds spent gathering the bars' node blocks
        (``assemble``) and filling the band and factorising (``factorise``).
    """
    from .truss_band import TrussStiffness, is_plain_truss, truss_band_layout

    n = fe.free.size
    limit = banded_limit(backend, n, "spd")
    if limit is None or n == 0 or not is_plain_truss(fe):
        return None
    t0 = time.perf_counter()
    layout = truss_band_layout(fe, limit)
    t1 = time.perf_counter()
    if layout is None:
        return None
    fac = factor(TrussStiffness(fe), "spd", "banded", layout=layout, singular="flag")
    if fac.backend not in ("banded", "banded-lu"):
        return None
    log.debug("factorised %d free DOFs of a truss from its bars (%s)", n, fac.backend)
    # the bars' node blocks gathered for the band ("assemble"); band fill + LAPACK
    return fac, {"assemble": t1 - t0, "factorise": time.perf_counter() - t1}


#: Largest number of mechanisms the banded search of :func:`_null_space` resolves one by one.
BAND_NULL_VECTORS = 64


def _null_space(Kff, free, K) -> tuple[np.ndarray, bool]:
    """Mechanism modes of K_ff and whether they are all of them.

    A K_ff of narrow band (a chain of bays) is searched by its banded Cholesky factorisation
    in the order that eliminates a cantilever from its free end
    (:func:`~trussfe.linalg.banded.band_null_space`): its vanishing pivots are the exact
    mechanisms only, each vector local to its mechanism.  The smallest eigenvalues of a long
    chain's scaled stiffness are its bending modes, ~N⁻⁴ for N bays, below the null tolerance
    from ~160 double-octahedral bays: an eigen-solver counts them as mechanisms (and the
    shift-invert iteration stalls on thousands of them beyond a few thousand bays).  Other
    matrices: :func:`~trussfe.linalg.stiffness_null_space`.
    """
    if Kff.shape[0] > 2:
        # (band_layout_free brings K to canonical form itself)
        layout = band_layout_free(K, np.asarray(free, dtype=np.int64),
                                  max_bandwidth=BANDED_MAX_BANDWIDTH, submatrix=lambda: Kff)
        if layout is not None:
            return band_null_space(layout, NULL_TOLERANCE, BAND_NULL_VECTORS)
    V = stiffness_null_space(Kff)
    return V, not (Kff.shape[0] > DENSE_LIMIT and V.shape[1] >= 12)


def _raise_mechanism(Kff, free, fe, item, K):
    V, complete = _null_space(Kff, free, K)
    r = V.shape[1]
    if r == 0:
        # pivots collapsed without an exact null space: ill-conditioned beyond double
        # precision; say so rather than return meaningless numbers
        raise MechanismError(item, "the stiffness matrix is numerically singular (a pivot "
                             f"below {SINGULAR_PIVOT:g} of the largest) although no exact "
                             "mechanism was found: the structure is too flexible for a "
                             "reliable linear solution, or its numbers are out of range; "
                             f"{UNITS_ADVICE}; add supports or members",
                             mechanisms=0, moving_nodes=[])
    moving = _moving_nodes(V, free, fe)
    shown = ", ".join(moving[:20]) + (" ..." if len(moving) > 20 else "")
    more = "" if complete else "at least "
    raise MechanismError(
        item, f"the structure is a mechanism: {more}{r} independent mechanism"
        f"{'s' if r != 1 else ''} (rigid-body motions included); moving nodes: "
        f"{shown or 'none (only member-internal DOFs)'}; add supports or members, or run "
        "'trussfe mechanism' for the rank analysis", mechanisms=r, moving_nodes=moving)


def raise_mechanism(K: sp.spmatrix, fe, item: str):
    """Raise the :class:`MechanismError` that names the mechanisms of K_ff (for a factor that
    passed its pivot test but does not solve the system)."""
    _raise_mechanism(free_submatrix(K, fe.free), fe.free, fe, item, K)


def _moving_nodes(V: np.ndarray, free: np.ndarray, fe) -> list[str]:
    if fe is None:
        return []
    full = np.zeros((fe.n_dof, V.shape[1]))
    full[free] = V
    amp = np.abs(full).max(axis=1)                   # (n_dof,)
    dofs = fe.node_dofs
    node_amp = np.where(dofs >= 0, amp[np.maximum(dofs, 0)], 0.0).max(axis=1)
    ids = fe.structure.node_ids
    moving = [ids[i] for i in np.flatnonzero(node_amp > 1e-6)]
    if not moving:
        pts = fe.interior_dofs
        pt_amp = np.where(pts >= 0, amp[np.maximum(pts, 0)], 0.0).max(axis=1) if pts.size \
            else np.zeros(0)
        mem = np.unique(fe.interior_member[pt_amp > 1e-6])
        moving = [f"member {fe.structure.member_ids[i]}" for i in mem]
    return moving
