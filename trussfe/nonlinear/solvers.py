# SPDX-License-Identifier: MIT
"""Linear algebra of the path following: factorisation with inertia, Newton correctors.

The tangent stiffness is factorised once per Newton iteration as ``P K Pᵀ = L D Lᵀ`` (SuperLU
in symmetric mode with diagonal pivots only).  By Sylvester's law of inertia the number of
negative pivots in ``D`` equals the number of negative eigenvalues of ``K``; a change of that
count between two equilibrium states brackets a critical point (limit point or bifurcation).
No determinant value is ever formed.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.sparse.linalg import eigsh, splu


class SingularTangent(Exception):
    """The tangent stiffness is exactly singular (a zero pivot)."""


@dataclass
class Factor:
    """A factorised symmetric tangent.

    Attributes
    ----------
    negative : int
        Number of negative pivots = number of negative eigenvalues (inertia).
    """

    lu: object
    negative: int
    n: int

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Solve ``K x = b`` (b of shape (n,) or (n, k))."""
        x = self.lu.solve(np.asarray(b, dtype=float))
        if not np.all(np.isfinite(x)):
            raise SingularTangent("non-finite solution")
        return x


def factorize(K: sp.spmatrix) -> Factor:
    """LDLᵀ-type factorisation of a symmetric sparse matrix with its inertia.

    Parameters
    ----------
    K : sparse matrix, shape (n, n), symmetric

    Returns
    -------
    Factor

    Raises
    ------
    SingularTangent
        On an exactly zero pivot.

    Examples
    --------
    >>> f = factorize(sp.csr_matrix(np.diag([2.0, -1.0, 3.0])))
    >>> f.negative, f.solve(np.array([2.0, 1.0, 3.0]))
    (1, array([ 1., -1.,  1.]))
    """
    K = sp.csc_matrix(K)
    n = K.shape[0]
    if n == 0:
        raise SingularTangent("no free degree of freedom")
    try:
        lu = splu(K, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                  options=dict(SymmetricMode=True))
    except RuntimeError as exc:
        raise SingularTangent(str(exc)) from None
    d = lu.U.diagonal()
    if not np.array_equal(lu.perm_r, lu.perm_c) or not np.all(np.isfinite(d)):
        # off-diagonal pivoting happened: the pivots no longer give the inertia
        lu = splu(K)
        neg = int(np.sum(sla.eigvalsh(K.toarray()) < 0)) if n <= 2000 else -1
        return Factor(lu, neg, n)
    scale = np.abs(d).max()
    if scale == 0 or np.abs(d).min() <= 1e-14 * scale:
        raise SingularTangent("zero pivot")
    return Factor(lu, int(np.sum(d < 0)), n)


def critical_mode(K: sp.spmatrix) -> tuple[float, np.ndarray]:
    """Eigenvalue of ``K`` nearest zero and its unit eigenvector.

    Dense for small matrices, shift-invert Lanczos (``eigsh``, σ = 0) otherwise.
    """
    n = K.shape[0]
    if n <= 600:
        w, v = sla.eigh(K.toarray())
        i = int(np.argmin(np.abs(w)))
        return float(w[i]), v[:, i]
    w, v = eigsh(sp.csc_matrix(K), k=1, sigma=0.0, which="LM")
    return float(w[0]), v[:, 0] / np.linalg.norm(v[:, 0])
