# SPDX-License-Identifier: MIT
"""Forward position of a pin-jointed assembly from its bar lengths.

Given the bar lengths (prescribed for active members, current for the others) find joint
positions that close every bar, by Newton iteration on the bar-length equations

.. math:: g_i(x) = \\lVert x_{b(i)} - x_{a(i)} \\rVert - L_i = 0 ,

whose Jacobian is the compatibility matrix B of the current iterate (Hortobágyi eq. 1–2).
Any topology: a square system is solved with a sparse LU factorisation, an over- or
under-determined one by (minimum-norm) least squares.  No closed form for one truss.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import AnalysisError
from ..linalg import factor
from ..mechanics.geometry import lengths as member_length_of, member_vectors
from .compatibility import compatibility_matrix


@dataclass
class AssemblyResult:
    """Outcome of :func:`solve_positions`.

    Attributes
    ----------
    coords : ndarray, shape (n, dim)
        Joint positions closing every bar.
    iterations : int
        Newton iterations used.
    residual : float
        Largest bar-length misfit at the solution, m.
    """

    coords: np.ndarray
    iterations: int
    residual: float


def solve_positions(
    coords0: np.ndarray,
    connectivity: np.ndarray,
    lengths: np.ndarray,
    fixed: np.ndarray,
    *,
    tolerance: float = 1e-12,
    max_iterations: int = 50,
    member_ids: list[str] | None = None,
    item: str = "assembly",
) -> AssemblyResult:
    """Joint positions of an assembly whose bars have the given lengths.

    Parameters
    ----------
    coords0 : ndarray, shape (n, dim)
        Starting guess (e.g. the previous time step); it also selects the branch.
    connectivity : ndarray of int, shape (b, 2)
        Bars.
    lengths : ndarray, shape (b,)
        Required bar lengths, m.
    fixed : ndarray of bool, shape (n, dim)
        Coordinates held at their ``coords0`` values (supports).
    tolerance : float
        Convergence tolerance on the bar-length misfit, relative to the largest length.
    max_iterations : int
        Newton iteration limit.
    member_ids : list of str, optional
        Names for error messages.
    item : str
        Item named in error messages (e.g. ``"motion: step 12"``).

    Returns
    -------
    AssemblyResult

    Raises
    ------
    AnalysisError
        When no assembly with these lengths exists near ``coords0`` (the misfit does not go to
        zero), naming the bars that cannot be closed; or when the Jacobian is singular (the
        assembly is at a singular position).

    Examples
    --------
    A triangle with a base of 2 m and sides of 2 m and 2.5 m:

    >>> x0 = np.array([[0., 0.], [2., 0.], [1., 1.]])
    >>> r = solve_positions(x0, np.array([[0, 1], [1, 2], [0, 2]]),
    ...                     np.array([2.0, 2.0, 2.5]), np.array([[1, 1], [1, 1], [0, 0]], bool))
    >>> np.round(r.coords[2], 4)
    array([1.5625, 1.9516])
    """
    x = np.array(coords0, dtype=float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    L = np.asarray(lengths, dtype=float)
    free = ~np.asarray(fixed, dtype=bool)
    free_flat = np.flatnonzero(free.ravel())
    if np.any(L <= 0) or not np.all(np.isfinite(L)):
        i = int(np.flatnonzero(~(L > 0) | ~np.isfinite(L))[0])
        name = member_ids[i] if member_ids else str(i)
        raise AnalysisError(item, f"member '{name}' has non-positive or non-finite length {L[i]}")
    scale = float(L.max())
    tol = tolerance * scale
    nb, nf = conn.shape[0], free_flat.size
    for it in range(max_iterations + 1):
        vec = member_vectors(x, conn)
        cur = member_length_of(vec)
        r = cur - L
        res = float(np.max(np.abs(r))) if nb else 0.0
        if res <= tol:
            return AssemblyResult(coords=x, iterations=it, residual=res)
        if it == max_iterations or not np.isfinite(res) or np.any(cur <= 1e-14 * scale):
            break
        B = compatibility_matrix(x, conn, free)
        dx = _newton_step(B, -r, nb, nf)
        if dx is None:
            raise AnalysisError(item, "the assembly is at a singular position (its "
                                      "compatibility matrix is rank deficient there); no "
                                      "unique forward position")
        # Damp steps longer than a tenth of the structure: keeps the iterate on its branch.
        step = float(np.max(np.abs(dx)))
        if step > 0.1 * scale:
            dx *= 0.1 * scale / step
        xf = x.ravel()
        xf[free_flat] += dx
        x = xf.reshape(x.shape)
    vec = member_vectors(x, conn)
    r = member_length_of(vec) - L
    worst = np.argsort(-np.abs(r))[:3]
    names = ", ".join(f"'{member_ids[i] if member_ids else i}'" for i in worst
                      if np.abs(r[i]) > tol)
    raise AnalysisError(item, f"no assembly exists for the prescribed lengths: member(s) "
                              f"{names} cannot be closed (misfit {np.max(np.abs(r)):.3g} m)")


def _newton_step(B: sp.csr_matrix, rhs: np.ndarray, nb: int, nf: int) -> np.ndarray | None:
    """Newton correction: solve B dx = rhs (square) or its least-squares / min-norm form."""
    if nb == nf:
        lu = factor(B, "general", singular="flag")
        return None if lu.is_singular else lu.solve(rhs, refine=False)
    if nf <= 3000:
        dx, *_ = np.linalg.lstsq(B.toarray(), rhs, rcond=1e-12)
        return dx
    sol = spla.lsmr(B, rhs, atol=1e-14, btol=1e-14, maxiter=20 * nf)
    return sol[0]


def solve_structure_positions(structure, lengths: np.ndarray, coords0: np.ndarray | None = None,
                              **kwargs) -> AssemblyResult:
    """:func:`solve_positions` for a :class:`~trussfe.model.Structure`.

    The structure's translational supports are the fixed coordinates; ``lengths`` gives every
    member's length (active members prescribed, passive members their current length).
    """
    x0 = structure.coords if coords0 is None else coords0
    return solve_positions(x0, structure.connectivity, lengths,
                           structure.translation_supports, member_ids=structure.member_ids,
                           **kwargs)
