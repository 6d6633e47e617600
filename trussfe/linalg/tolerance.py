# SPDX-License-Identifier: MIT
"""The singularity policy of every factorisation in :mod:`trussfe.linalg`.

One rule for all backends: a factorisation is singular when a pivot is zero or not finite,
or when the smallest pivot in magnitude is at most :data:`SINGULAR_PIVOT` times the largest.
"Pivot" means the diagonal of ``D`` in ``P A Pᵀ = L D Lᵀ``, the diagonal of ``U`` in
``P A Q = L U``, and the *square* of the diagonal of a Cholesky factor (the Cholesky factor
holds square roots of the ``LDLᵀ`` pivots; PARDISO's Cholesky returns the ``LDLᵀ`` pivots
themselves).  PARDISO's ``LDLᵀ`` does not return its pivots; it replaces a pivot below its own
threshold by a perturbed one and reports how many it replaced, and a perturbed pivot counts
as singular.
"""
from __future__ import annotations

#: Smallest accepted ratio of the smallest to the largest pivot magnitude.
#:
#: Why 1e-14: an exact mechanism leaves pivots at round-off of the largest one, ε·growth with
#: ε ≈ 2.2e-16 and a growth of at most a few tens in the factorisations used here, so ≲ 1e-15;
#: the stiffness of a long cantilever chain of double-octahedral bays, a regular but badly
#: conditioned matrix, has a pivot ratio of ~5e-14 at 10,000 bays and ~3e-13 at 100,000 bays
#: under banded LU (measured), which must be accepted.  Between the two, a ratio of 1e-14 is
#: ~50 ε: what is below it is round-off, what is above it is a stiffness.  Whether a regular
#: but ill-conditioned system is *solved* well enough is a separate question, answered by the
#: residual of every solve (:attr:`trussfe.linalg.factor.Factor.residuals`).
SINGULAR_PIVOT = 1e-14
