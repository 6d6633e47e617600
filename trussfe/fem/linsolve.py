# SPDX-License-Identifier: MIT
"""Sparse linear solvers: factorise once, solve many right-hand sides.

Backends
--------
``superlu``
    :func:`scipy.sparse.linalg.splu` (always available).  Its pivots reveal a singular
    (mechanism) stiffness matrix.
``pardiso``
    Intel MKL PARDISO through :mod:`pypardiso` (optional, x86-64).  An order of magnitude faster
    on large 3-D lattices (195k DOF: 0.2 s against 26 s for SuperLU on this kind of machine);
    perturbed pivots reveal singularity.
``banded``
    Banded Cholesky after reverse Cuthill–McKee reordering
    (:class:`trussfe.fem.banded.BandedCholesky`): the cheapest factorisation of long, narrow
    structures such as a chain of bays (half-bandwidth 17 whatever the length).  When
    round-off leaves a pivot of a badly conditioned chain non-positive, banded LU with
    partial pivoting (:class:`trussfe.fem.banded.BandedLU`, backend name ``banded-lu``) takes
    over.
``auto``
    Banded Cholesky when the system has at least ``BANDED_MIN_DOF`` unknowns and a reordered
    half-bandwidth of at most ``BANDED_MAX_BANDWIDTH``; otherwise PARDISO when it is installed
    and the system has at least ``PARDISO_MIN_DOF`` unknowns; SuperLU otherwise.  A matrix
    the banded Cholesky finds not positive definite goes to SuperLU, whose pivots tell a
    mechanism.

Each solve is followed by up to two steps of iterative refinement when the relative residual
exceeds ``1e-12`` (a further step only when the last one at least halved it, as LAPACK's
``xGERFS``), and the achieved residual is reported, because long chains are badly
conditioned (first frequency ~1e-6 Hz at 10,000 bays).
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .banded import banded_factor

log = logging.getLogger(__name__)

#: Systems at least this large use PARDISO under ``backend="auto"`` when it is installed.
PARDISO_MIN_DOF = 20_000
#: Systems at least this large try banded Cholesky under ``backend="auto"``.
BANDED_MIN_DOF = 5_000
#: Largest reordered half-bandwidth for which ``auto`` chooses banded Cholesky.
BANDED_MAX_BANDWIDTH = 64
#: Relative pivot size below which a factorisation is declared singular.
SINGULAR_PIVOT = 1e-11


_PARDISO_OK: bool | None = None


def pardiso_available() -> bool:
    """True when :mod:`pypardiso` can be imported and finds MKL."""
    global _PARDISO_OK
    if _PARDISO_OK is None:
        try:
            _locate_mkl()  # before the import: pypardiso builds a solver at import time
            import pypardiso  # noqa: F401
            _PARDISO_OK = True
        except Exception:  # ImportError, or MKL failing to load
            _PARDISO_OK = False
    return _PARDISO_OK


def _locate_mkl() -> None:
    """Point pypardiso at MKL once.

    Without it every ``PyPardisoSolver()`` searches the whole Python prefix for ``mkl_rt``
    (0.7 s per factorisation on this kind of machine).
    """
    import glob
    import os
    import sys

    if os.environ.get("PYPARDISO_MKL_RT"):
        return
    # pip puts MKL directly in <prefix>/lib: look there before walking the whole tree
    direct = sorted(glob.glob(f"{sys.prefix}/lib/libmkl_rt.so*"), key=len)
    if direct:
        os.environ["PYPARDISO_MKL_RT"] = direct[0]
        return
    for path in sorted(glob.glob(f"{sys.prefix}/[Ll]ib*/**/*mkl_rt*", recursive=True), key=len):
        os.environ["PYPARDISO_MKL_RT"] = path
        return


class SingularMatrixError(ValueError):
    """The matrix is (numerically) singular: the structure is a mechanism."""


@dataclass
class Factor:
    """A factorised sparse matrix.

    Attributes
    ----------
    backend : str
        "superlu" or "pardiso".
    n : int
        Order of the matrix.
    residuals : list of float
        Relative residual ‖A x − b‖/‖b‖ of every solve, for reporting.
    """

    matrix: sp.csr_matrix
    backend: str
    n: int
    _solve: object = field(repr=False)
    residuals: list = field(default_factory=list)

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Solve A x = b (b of shape (n,) or (n, k)), with iterative refinement."""
        b = np.asarray(b, dtype=float)
        x = self._solve(b)
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


def banded_limit(backend: str, n: int) -> int | None:
    """Largest half-bandwidth a banded factorisation may have under ``backend`` for ``n``
    unknowns, or None when ``backend`` does not try one (``auto``: from
    :data:`BANDED_MIN_DOF` unknowns, up to :data:`BANDED_MAX_BANDWIDTH`; ``banded``: always)."""
    if backend == "banded":
        return max(n - 1, 0)
    if backend == "auto" and n >= BANDED_MIN_DOF:
        return BANDED_MAX_BANDWIDTH
    return None


def general_backend(n: int) -> str:
    """The sparse backend ``auto`` uses when no banded factorisation applies."""
    return "pardiso" if n >= PARDISO_MIN_DOF and pardiso_available() else "superlu"


def factorize(A: sp.spmatrix, backend: str = "auto", anchored: np.ndarray | None = None,
              symmetric: bool = False) -> Factor:
    """Factorise a sparse square matrix.

    Parameters
    ----------
    A : sparse matrix, shape (n, n)
    backend : {"auto", "superlu", "pardiso", "banded"}
    anchored : ndarray of bool, shape (n,), optional
        Rows coupled to a support: the banded factorisation orders them last.
    symmetric : bool
        ``A`` is symmetric (a stiffness, ``K − σM``): PARDISO then factorises its upper
        triangle as LDLᵀ instead of a general LU.

    Returns
    -------
    Factor

    Raises
    ------
    SingularMatrixError
        When a pivot is zero or below ``SINGULAR_PIVOT`` relative to the largest one.

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> f = factorize(sp.csr_matrix([[2.0, -1.0], [-1.0, 2.0]]), backend="superlu")
    >>> f.solve(np.array([1.0, 1.0]))
    array([1., 1.])
    """
    A = sp.csr_matrix(A)
    n = A.shape[0]
    if backend in ("auto", "banded"):
        limit = banded_limit(backend, n)
        if limit is not None:
            band = banded_factor(A, max_bandwidth=limit, anchored=anchored)
            if band is not None:
                return Factor(matrix=A, backend=band.kind, n=n, _solve=band.solve)
        backend = general_backend(n)
    if backend == "pardiso":
        return _pardiso(A, symmetric=symmetric)
    if backend != "superlu":
        raise ValueError(f"unknown linear-solver backend '{backend}'")
    try:
        lu = spla.splu(A.tocsc())
    except RuntimeError as exc:  # "Factor is exactly singular"
        raise SingularMatrixError(str(exc)) from None
    piv = np.abs(lu.U.diagonal())
    if n and piv.min() <= SINGULAR_PIVOT * piv.max():
        raise SingularMatrixError(f"pivot {piv.min():.3g} against {piv.max():.3g}")
    return Factor(matrix=A, backend="superlu", n=n, _solve=lu.solve)


def _pardiso(A: sp.csr_matrix, symmetric: bool = False) -> Factor:
    import pypardiso

    _locate_mkl()
    A = A.sorted_indices() if not A.has_sorted_indices else A
    if symmetric:
        # real symmetric indefinite (PARDISO mtype -2, LDLᵀ with Bunch–Kaufman pivoting) on the
        # upper triangle: about half the work of the general LU (195k-DOF space grid here:
        # 2.6 s against 4.5 s), and it still reports perturbed pivots of a singular matrix
        M = sp.triu(A, format="csr")
        M.sort_indices()
        solver = pypardiso.PyPardisoSolver(mtype=-2)
    else:
        M = A
        solver = pypardiso.PyPardisoSolver()
    solver.set_iparm(8, 2)  # two steps of PARDISO's own iterative refinement
    try:
        solver.factorize(M)
    except ValueError as exc:  # pypardiso refuses empty rows/columns as singular
        raise SingularMatrixError(str(exc)) from None
    # iparm(14) (1-based): number of perturbed pivots -> numerically singular matrix
    perturbed = int(solver.get_iparm(14))
    if perturbed > 0:
        solver.free_memory(everything=True)
        raise SingularMatrixError(f"{perturbed} perturbed pivot(s)")

    def solve(b):
        return solver.solve(M, b)

    return Factor(matrix=A, backend="pardiso", n=A.shape[0], _solve=solve)


def solve(A: sp.spmatrix, b: np.ndarray, backend: str = "auto") -> np.ndarray:
    """Solve A x = b once (see :func:`factorize`)."""
    return factorize(A, backend).solve(b)
