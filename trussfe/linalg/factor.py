# SPDX-License-Identifier: MIT
"""Sparse factorisation: one entry, :func:`factor`, and one result type, :class:`Factor`.

Kinds
-----
``"spd"``
    Symmetric, expected positive definite (a supported stiffness, ``K − σM`` below the
    spectrum).  Long, narrow systems go to a banded Cholesky factorisation
    (:mod:`trussfe.linalg.banded`; banded LU when round-off made the stored matrix indefinite
    in its softest direction); otherwise PARDISO's Cholesky ``LLᵀ`` (its ``LDLᵀ`` when a
    pivot is not positive) or SuperLU's LU.
``"symmetric"``
    Symmetric, possibly indefinite (a tangent stiffness, a shifted Gram matrix): a
    factorisation that reveals the inertia — SuperLU in symmetric mode with diagonal pivots
    (minimum-degree ordering of ``A + Aᵀ``) or PARDISO's ``LDLᵀ``.
``"general"``
    Any square matrix: SuperLU's or PARDISO's LU.

Backend selection (the one rule)
--------------------------------
``backend="auto"``: for ``kind="spd"`` with at least :data:`BANDED_MIN_DOF` unknowns, the
banded factorisation when the reordered half-bandwidth is at most
:data:`BANDED_MAX_BANDWIDTH`; otherwise PARDISO when it is installed and the system has at
least :data:`PARDISO_MIN_DOF` unknowns; SuperLU otherwise.  Whether a band is narrow
enough is first bounded from one breadth-first search
(:func:`~trussfe.linalg.banded.bandwidth_lower_bound`): a wide lattice (a square space grid)
goes to the general backend without a reordering.  Only direct factorisations are chosen:
the long chains are so badly conditioned (first frequency ~1e-6 Hz at 10,000 bays; a 410 ×
410 space grid supported at its corners leaves a relative residual of ~1e-6 after a
backward-stable solve) that an iterative solver would need thousands of iterations, and
smoothed-aggregation multigrid with the rigid-body modes as near-null space did not reach
1e-8 in 1,000 conjugate-gradient iterations on a 60 × 60 grid.  ``"banded"`` tries the band
whatever the size and bandwidth (then ``auto``'s general backend); ``"superlu"`` and
``"pardiso"`` are taken as asked.

Ordering
--------
PARDISO orders a matrix itself (MKL's parallel nested dissection of the matrix's graph).
When the caller says where the unknowns sit (``points``: a structure's joints and the points
inside its members), the Cholesky factorisation takes the geometric nested dissection of
:func:`~trussfe.linalg.ordering.nested_dissection` instead: on the space grids it is 4–5×
faster to compute and gives a factor as sparse or sparser (180 × 180 cells: 7.8 against 8.0
GFlop; 410 × 410: 91 against 106 GFlop).  The ordering declines, and PARDISO orders, when
its first cut's separator is larger than a cut through a two-dimensional mesh gives
(:data:`~trussfe.linalg.ordering.SEPARATOR_FACTOR`: a three-dimensional lattice, members
joining far-apart points).  The ordering changes the round-off of the solution only.

Singularity
-----------
One policy for every backend (:mod:`trussfe.linalg.tolerance`).  A singular matrix gives a
:class:`Factor` with ``is_singular`` set (``singular="flag"``) or :class:`SingularMatrixError`
(``singular="raise"``, the default); a singular factor never solves.

Inertia
-------
``Factor.inertia`` is the number of negative pivots, which by Sylvester's law of inertia is
the number of negative eigenvalues, when the factorisation reveals it: banded Cholesky (0),
SuperLU in symmetric mode (when it kept diagonal pivots), PARDISO ``LDLᵀ`` (no perturbed
pivot), PARDISO's Cholesky (0).  Otherwise it is ``None``: unknown, never a number standing for "unknown".

Refinement
----------
:meth:`Factor.solve` follows each solve by up to two steps of iterative refinement when the
relative residual exceeds ``1e-12`` (a further step only when the last one at least halved
it, as LAPACK's ``xGERFS``), and records the achieved residual, because long chains are badly
conditioned (first frequency ~1e-6 Hz at 10,000 bays).  ``refine=False`` gives the plain
solve (inside an eigen-solver or a Newton iteration, whose own iteration corrects it).
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from . import pardiso
from .banded import BandLayout, band_layout, band_layout_free, banded_factor
from .ordering import Points
from .sparse import FreeBlock
from .tolerance import SINGULAR_PIVOT

log = logging.getLogger(__name__)

#: Systems at least this large use PARDISO under ``backend="auto"`` when it is installed.
PARDISO_MIN_DOF = 20_000
#: Systems at least this large try the banded factorisation under ``backend="auto"`` (below,
#: a general sparse factorisation takes milliseconds too).
BANDED_MIN_DOF = 5_000
#: Largest reordered half-bandwidth for which ``auto`` chooses the banded factorisation: a
#: chain of double-octahedral bays has 17; a square space grid of 180 × 180 cells is far
#: wider, and SuperLU or PARDISO factorise it faster.
BANDED_MAX_BANDWIDTH = 64
#: Order up to which the inertia is counted from dense eigenvalues when SuperLU had to leave
#: the diagonal while pivoting (the pivots then no longer give it).
INERTIA_DENSE_LIMIT = 2000

KINDS = ("general", "symmetric", "spd")
BACKENDS = ("auto", "banded", "superlu", "pardiso")


class SingularMatrixError(ValueError):
    """The matrix is (numerically) singular (:mod:`trussfe.linalg.tolerance`)."""


@dataclass(eq=False)
class Factor:
    """A factorised square matrix.

    Attributes
    ----------
    matrix : sparse matrix or operator
        The matrix (products ``matrix @ x`` for the refinement).
    backend : str
        "banded", "banded-lu", "superlu" or "pardiso".
    kind : str
        "general", "symmetric" or "spd".
    n : int
        Order.
    inertia : int or None
        Number of negative pivots (= negative eigenvalues); None when the factorisation does
        not reveal it.
    pivot_ratio : float
        Smallest over largest pivot magnitude (NaN for PARDISO, which does not return them).
    is_singular : bool
        Singular under :data:`~trussfe.linalg.tolerance.SINGULAR_PIVOT`; :meth:`solve` then
        raises.
    determinant_sign : int or None
        Sign of ``det A`` (+1 or −1; 0 when singular) where the factorisation gives it — from
        the pivots and the parity of the permutations, never from the determinant's value,
        which under- or overflows — else None.
    residuals : list of float
        Relative residual ‖A x − b‖/‖b‖ of every refined solve, for reporting.
    smallest_pivot : float
        Magnitude of the smallest pivot (NaN where the backend does not return pivots).
    smallest_pivot_column : int or None
        The column of ``A`` whose elimination gave that pivot (SuperLU's LU), so that a
        caller can name the unknown — or the block of a block-diagonal matrix — that is
        singular; None where unknown.
    ordering : str
        How the unknowns were ordered for PARDISO's Cholesky: ``"geometric"``
        (:func:`~trussfe.linalg.ordering.nested_dissection`) or ``"pardiso"`` (its own);
        ``""`` for the other factorisations.
    """

    matrix: object
    backend: str
    kind: str
    n: int
    inertia: int | None
    pivot_ratio: float
    is_singular: bool
    _solve: Callable | None = field(repr=False, default=None)
    residuals: list = field(default_factory=list)
    reason: str = ""
    determinant_sign: int | None = None
    _solve_transposed: Callable | None = field(repr=False, default=None)
    smallest_pivot: float = float("nan")
    smallest_pivot_column: int | None = None
    ordering: str = ""

    def solve(self, b: np.ndarray, refine: bool = True, transpose: bool = False) -> np.ndarray:
        """Solve ``A x = b`` (b of shape (n,) or (n, k)); ``Aᵀ x = b`` with ``transpose``
        (without refinement; the symmetric kinds and SuperLU's LU).

        Raises
        ------
        SingularMatrixError
            The factor is singular, or the solution is not finite.
        """
        if self.is_singular:
            raise SingularMatrixError(self.reason or "singular matrix")
        b = np.asarray(b, dtype=float)
        if transpose and self.kind == "general":
            if self._solve_transposed is None:
                raise ValueError(f"no transposed solve with the {self.backend} backend")
            x = self._solve_transposed(b)
            if not np.all(np.isfinite(x)):
                raise SingularMatrixError("non-finite solution")
            return x
        x = self._solve(b)
        if refine:
            x = self._refine(b, x)
        if not np.all(np.isfinite(x)):
            raise SingularMatrixError("non-finite solution")
        return x

    def _refine(self, b: np.ndarray, x: np.ndarray) -> np.ndarray:
        nb = np.linalg.norm(b)
        if nb == 0.0:
            self.residuals.append(0.0)
            return x
        r = b - self.matrix @ x
        rel = np.linalg.norm(r) / nb
        for _ in range(2):
            if rel <= 1e-12:
                break
            x_new = x + self._solve(r)
            r_new = b - self.matrix @ x_new
            rel_new = np.linalg.norm(r_new) / nb
            halved = rel_new <= 0.5 * rel
            if rel_new < rel:           # keep the better solution
                x, r, rel = x_new, r_new, rel_new
            if not halved:              # at the conditioning floor (LAPACK's xGERFS rule)
                break
        self.residuals.append(float(rel))
        return x


def banded_limit(backend: str, n: int, kind: str = "spd") -> int | None:
    """Largest half-bandwidth a banded factorisation may have, or None when none is tried
    (see the module notes: the backend-selection rule)."""
    if kind != "spd":
        return None
    if backend == "banded":
        return max(n - 1, 0)
    if backend == "auto" and n >= BANDED_MIN_DOF:
        return BANDED_MAX_BANDWIDTH
    return None


def general_backend(backend: str, n: int) -> str:
    """The sparse backend when no banded factorisation applies."""
    if backend in ("auto", "banded"):
        return "pardiso" if n >= PARDISO_MIN_DOF and pardiso.available() else "superlu"
    if backend not in BACKENDS:
        raise ValueError(f"unknown linear-solver backend '{backend}'")
    return backend


def factor(A, kind: str = "general", backend: str = "auto", *,
           anchored: np.ndarray | None = None, layout: BandLayout | None = None,
           singular: str = "raise", points: Points | None = None) -> Factor:
    """Factorise a sparse square matrix.

    Parameters
    ----------
    A : sparse matrix, :class:`~trussfe.linalg.sparse.FreeBlock` or operator, shape (n, n)
        A FreeBlock (the free rows and columns of a global matrix) is laid out for the band
        without forming the submatrix; an operator needs ``layout`` or ``tocsr()``.
    kind : {"general", "symmetric", "spd"}
    backend : {"auto", "banded", "superlu", "pardiso"}
        See the module notes.
    anchored : ndarray of bool, shape (n,), optional
        Rows coupled to a support: the banded factorisation orders them last.
    layout : BandLayout, optional
        The band layout of ``A``, already made (the banded path then does not look at ``A``
        except for products).
    singular : {"raise", "flag"}
        On a singular matrix raise :class:`SingularMatrixError`, or return a Factor with
        ``is_singular`` set.
    points : Points, optional
        Where the unknowns sit (:class:`~trussfe.linalg.ordering.Points`): PARDISO's
        Cholesky then factorises in the geometric nested-dissection order
        (:func:`~trussfe.linalg.ordering.nested_dissection`) instead of ordering the matrix
        itself (see the module notes).

    Returns
    -------
    Factor

    Examples
    --------
    >>> f = factor(sp.csr_matrix([[2.0, -1.0], [-1.0, 2.0]]), "spd")
    >>> f.solve(np.array([1.0, 1.0])), f.backend
    (array([1., 1.]), 'superlu')
    >>> f = factor(sp.csr_matrix(np.diag([2.0, -1.0, 3.0])), "symmetric")
    >>> f.inertia, f.solve(np.array([2.0, 1.0, 3.0]))
    (1, array([ 1., -1.,  1.]))
    >>> factor(sp.csr_matrix([[1.0, 1.0], [1.0, 1.0]]), "spd", singular="flag").is_singular
    True
    """
    if kind not in KINDS:
        raise ValueError(f"unknown matrix kind '{kind}' ({', '.join(KINDS)})")
    if backend not in BACKENDS:
        raise ValueError(f"unknown linear-solver backend '{backend}'")
    n = A.shape[0]
    if n == 0:                          # nothing to solve for: every solution is empty
        return Factor(matrix=A, backend="none", kind=kind, n=0, inertia=0, pivot_ratio=1.0,
                      is_singular=False, _solve=lambda b: np.zeros(b.shape))
    limit = banded_limit(backend, n, kind)
    if limit is not None:
        if layout is None:
            if isinstance(A, FreeBlock) and A.K is not None:
                layout = band_layout_free(A.K, A.free, limit, submatrix=A.tocsr)
            else:
                layout = band_layout(_csr(A), limit, anchored)
        elif layout.bandwidth > limit:
            layout = None
        band = banded_factor(layout=layout) if layout is not None else None
        if band is not None:
            log.debug("factorised %d unknowns (%s)", n, band.kind)
            chol = band.kind == "banded"               # positive definite: det > 0
            return Factor(matrix=A, backend=band.kind, kind=kind, n=n,
                          inertia=0 if chol else None, pivot_ratio=band.pivot_ratio,
                          is_singular=False, _solve=band.solve,
                          determinant_sign=1 if chol else None)
    used = general_backend(backend, n)
    M = _csr(A)
    if used == "pardiso":
        out = _pardiso(M, kind, points)
    elif kind == "symmetric":
        out = _superlu_symmetric(M)
    else:
        out = _superlu(M, kind)
    if out.is_singular and singular == "raise":
        raise SingularMatrixError(out.reason)
    return out


def _csr(A) -> sp.csr_matrix:
    if sp.issparse(A):
        return A.tocsr() if A.format != "csr" else A
    if hasattr(A, "tocsr"):
        return A.tocsr()
    return sp.csr_matrix(A)


def _singular(M, backend: str, kind: str, reason: str, ratio: float = 0.0,
              **pivot) -> Factor:
    return Factor(matrix=M, backend=backend, kind=kind, n=M.shape[0], inertia=None,
                  pivot_ratio=ratio, is_singular=True, reason=reason, determinant_sign=0,
                  **pivot)


def _smallest_pivot(lu, d: np.ndarray) -> dict:
    """The smallest |pivot| of SuperLU's ``Pr A Pc = L U`` and the column of A it eliminates."""
    if d.size == 0:
        return {}
    j = int(np.argmin(np.abs(d)))
    column = int(lu.perm_c[j]) if lu.perm_c is not None else j
    return {"smallest_pivot": float(abs(d[j])), "smallest_pivot_column": column}


def permutation_parity(perm: np.ndarray) -> int:
    """Parity (0 even, 1 odd) of a permutation, vectorised by pointer doubling.

    Examples
    --------
    >>> permutation_parity(np.array([1, 0, 2])), permutation_parity(np.array([1, 2, 0]))
    (1, 0)
    """
    n = perm.size
    lab = np.arange(n)
    p = perm.copy()
    for _ in range(max(1, int(np.ceil(np.log2(max(n, 2)))) + 1)):
        lab = np.minimum(lab, lab[p])
        p = p[p]
    cycles = int(np.sum(lab == np.arange(n)))
    return (n - cycles) % 2


def _lu_sign(lu, d: np.ndarray) -> int:
    """Sign of det A from SuperLU's ``Pr A Pc = L U`` (unit L)."""
    sign = int(np.prod(np.sign(d)))
    return sign * (-1) ** (permutation_parity(lu.perm_r) + permutation_parity(lu.perm_c))


def _ratio(d: np.ndarray) -> float:
    a = np.abs(d)
    if a.size == 0:
        return 1.0
    if not np.all(np.isfinite(a)) or a.max() == 0.0:
        return 0.0
    return float(a.min() / a.max())


def _superlu(M: sp.csr_matrix, kind: str) -> Factor:
    n = M.shape[0]
    try:
        lu = spla.splu(M.tocsc())
    except RuntimeError as exc:  # "Factor is exactly singular"
        return _singular(M, "superlu", kind, str(exc))
    d = lu.U.diagonal()
    ratio = _ratio(d)
    pivot = _smallest_pivot(lu, d)
    if n and ratio <= SINGULAR_PIVOT:
        a = np.abs(d)
        return _singular(M, "superlu", kind, f"pivot {a.min():.3g} against {a.max():.3g}",
                         ratio, **pivot)
    return Factor(matrix=M, backend="superlu", kind=kind, n=n, inertia=None,
                  pivot_ratio=ratio, is_singular=False, _solve=lu.solve,
                  determinant_sign=_lu_sign(lu, d),
                  _solve_transposed=lambda b: lu.solve(b, trans="T"), **pivot)


def _superlu_symmetric(M: sp.csr_matrix) -> Factor:
    """SuperLU in symmetric mode with diagonal pivots only: ``P A Pᵀ = L U`` with ``U``'s
    diagonal the ``D`` of ``LDLᵀ``, whose negative entries give the inertia.

    Diagonal pivoting can break down on an indefinite matrix: a pivot at round-off level
    although the matrix is regular, or off-diagonal pivots where a diagonal one vanished.
    Neither decides anything: LU with partial pivoting (:func:`_superlu`) then factorises the
    matrix and applies the singularity rule to its own pivots, and the inertia is counted
    from dense eigenvalues up to :data:`INERTIA_DENSE_LIMIT` unknowns (else None)."""
    n = M.shape[0]
    K = M.tocsc()
    if n == 0:
        return _singular(M, "superlu", "symmetric", "no unknown")
    try:
        lu = spla.splu(K, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                       options=dict(SymmetricMode=True))
    except RuntimeError as exc:
        return _singular(M, "superlu", "symmetric", str(exc))
    d = lu.U.diagonal()
    diagonal = np.array_equal(lu.perm_r, lu.perm_c) and bool(np.all(np.isfinite(d)))
    ratio = _ratio(d)
    if diagonal and ratio > SINGULAR_PIVOT:
        neg = int(np.sum(d < 0))
        return Factor(matrix=M, backend="superlu", kind="symmetric", n=n, inertia=neg,
                      pivot_ratio=ratio, is_singular=False, _solve=lu.solve,
                      determinant_sign=(-1) ** neg)
    # off-diagonal pivoting, or a diagonal pivot at round-off: the pivots no longer give the
    # inertia, and only partial pivoting tells a breakdown from a singular matrix
    out = _superlu(M, "symmetric")
    if not out.is_singular and n <= INERTIA_DENSE_LIMIT and _symmetric(K):
        out.inertia = int(np.sum(sla.eigvalsh(K.toarray()) < 0))
    return out


def _symmetric(K: sp.spmatrix) -> bool:
    """Whether ``K`` is symmetric to round-off (1e-12 of its largest entry): only then do the
    eigenvalues of one triangle give its inertia.  An unsymmetric matrix given as
    ``"symmetric"`` (the tangent of a 3-D beam under a moment of fixed direction, slightly
    unsymmetric) keeps its inertia unknown."""
    scale = abs(K).max() if K.nnz else 0.0
    return scale == 0.0 or abs(K - K.T).max() <= 1e-12 * scale


def _pardiso(M: sp.csr_matrix, kind: str, points: Points | None = None) -> Factor:
    if not pardiso.available():
        raise ValueError("the PARDISO backend is not available (pypardiso with MKL)")
    if kind == "spd":
        chol = _pardiso_cholesky(M, points)
        if chol is not None:
            return chol
    try:
        solve, negative, perturbed = pardiso.factorise(M, symmetric=kind != "general")
    except ValueError as exc:  # pypardiso refuses empty rows/columns as singular
        return _singular(M, "pardiso", kind, str(exc))
    if perturbed > 0:
        return _singular(M, "pardiso", kind, f"{perturbed} perturbed pivot(s)", float("nan"))
    return Factor(matrix=M, backend="pardiso", kind=kind, n=M.shape[0], inertia=negative,
                  pivot_ratio=float("nan"), is_singular=False, _solve=solve,
                  determinant_sign=None if negative is None else (-1) ** negative)


def _pardiso_cholesky(M: sp.csr_matrix, points: Points | None = None) -> Factor | None:
    """PARDISO's Cholesky factorisation (:func:`trussfe.linalg.pardiso.cholesky`), its
    pivots under the one singularity policy; None when a pivot is not positive (the caller
    then takes the ``LDLᵀ``, which reports the inertia or the perturbed pivots)."""
    try:
        solve, pivots, ordering = pardiso.cholesky(M, points)
    except pardiso.NotPositiveDefinite:
        return None
    except ValueError as exc:           # an empty row or column
        return _singular(M, "pardiso", "spd", str(exc))
    ratio, pivot = float("nan"), {}
    if pivots is not None and pivots.size:
        ratio = _ratio(pivots)
        j = int(np.argmin(np.abs(pivots)))
        pivot = {"smallest_pivot": float(abs(pivots[j]))}
        if ratio <= SINGULAR_PIVOT:
            a = np.abs(pivots)
            return _singular(M, "pardiso", "spd", f"pivot {a.min():.3g} against {a.max():.3g}",
                             ratio, **pivot)
    return Factor(matrix=M, backend="pardiso", kind="spd", n=M.shape[0], inertia=0,
                  pivot_ratio=ratio, is_singular=False, _solve=solve, determinant_sign=1,
                  ordering=ordering, **pivot)
