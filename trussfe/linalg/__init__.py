# SPDX-License-Identifier: MIT
"""Linear algebra shared by every solver: factorisation, band storage, rank and null spaces,
eigen-solvers.

The package sits below the mechanics and the solvers and imports nothing from them.

* :mod:`~trussfe.linalg.factor` — :func:`factor` and :class:`Factor` (the one factorisation
  entry, the one backend-selection rule, inertia);
* :mod:`~trussfe.linalg.tolerance` — the singularity policy of all backends;
* :mod:`~trussfe.linalg.banded` — band layouts and banded Cholesky / LU;
* :mod:`~trussfe.linalg.pardiso` — MKL PARDISO (optional);
* :mod:`~trussfe.linalg.sparse` — free rows and columns of a sparse matrix;
* :mod:`~trussfe.linalg.rank` — rank, mechanisms and self-stress of a matrix, the null space
  of a stiffness;
* :mod:`~trussfe.linalg.eigen` — shift-invert Lanczos, the eigenpair nearest zero.
"""
from .factor import Factor, SingularMatrixError, factor
from .rank import Rank, RankError, matrix_rank, stiffness_null_space
from .sparse import FreeBlock, free_submatrix
from .tolerance import SINGULAR_PIVOT

__all__ = ["Factor", "SingularMatrixError", "factor", "Rank", "RankError", "matrix_rank",
           "stiffness_null_space", "FreeBlock", "free_submatrix", "SINGULAR_PIVOT"]
