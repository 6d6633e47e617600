# SPDX-License-Identifier: MIT
"""One step of the finite motion of an inextensional bar-and-joint assembly (Hortobágyi 1999).

The motion is followed in steps; :mod:`trussfe.kinematics.trace` strings them together.  At
each step the compatibility matrix B is partitioned into ``[B11 B12]`` with the independent
coordinate(s) in ``B12`` (Hortobágyi eq. 3), a linear prediction is made (eq. 4) and the
dependent coordinates are corrected until the exact compatibility error of every bar (eq. 1 /
eq. 5) is below the tolerance (eq. 7).  This module holds that single-step machinery: the exact
error, the correctors, the pivoted partition, the tangent of ``[B; cᵀ]`` with its determinant
sign, the bifurcation test function, the re-tracing of one interval and the branch switch.

What recomputing the paper's section 4 showed, and how it is implemented here:

* The paper's B in section 4 is built at the start state *plus* the prescribed increment; at a
  bifurcation point that is what makes B11 invertible.  The first Jacobian here is likewise
  evaluated at the predicted state.
* Eq. (6) as printed, ``d1 = −B11⁻¹ B12 d2 − B11⁻¹ t``, has the linear prediction as its fixed
  point; the worked numbers follow the incremental form ``d1 ← d1 − B11⁻¹ t``, implemented here.
* Refreshing B11 at every iterate (Newton's method on eq. 1) converges in 4 iterations in the
  section-4 example where the frozen B11 of the paper needs 14 (see
  :func:`trussfe.studies.hortobagyi.hortobagyi_section4`).  ``newton=False`` keeps the
  paper's frozen matrix.
* Over-constrained assemblies (self-stress states, e.g. Bricard's octahedron) are corrected by
  least squares over all bars.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..linalg import SingularMatrixError, factor
from ..mechanics.geometry import member_vectors
from .compatibility import compatibility_matrix
from .unfolding import stress_quadrics

log = logging.getLogger(__name__)

#: Largest number of free coordinates for which the rank is computed by dense SVD each step.
DENSE_LIMIT = 200

DIVERGENCE_MESSAGE = ("the prescribed increment leaves the motion region, or the assembly is "
                      "not a finite mechanism")


# --------------------------------------------------------------------------- exact equation
def compatibility_error(coords: np.ndarray, connectivity: np.ndarray, lengths: np.ndarray,
                        increments: np.ndarray) -> np.ndarray:
    """Exact compatibility error t of every bar after finite increments (Hortobágyi eq. 1/5).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
        Joint positions r of the current state.
    connectivity : ndarray of int, shape (b, 2)
    lengths : ndarray, shape (b,)
        Bar lengths l_i.
    increments : ndarray, shape (n, dim)
        Finite coordinate increments δ.

    Returns
    -------
    ndarray, shape (b,)
        ``t_i = (|r_k + δ_k − r_h − δ_h|² − l_i²) / (2 l_i)``; for a compatible state r this is
        eq. (1), ``[(r_k − r_h)·(δ_k − δ_h) + |δ_k − δ_h|²/2] / l_i``.  Positive when the bar
        would have to lengthen.  Hortobágyi's printed t has the opposite sign (his B is minus
        ours); the correction ``−B11⁻¹ t`` is the same either way.

    Examples
    --------
    Hortobágyi section 4, bar 2 (node 3 at the origin to node 1 at (l, 0), l = 1) after
    δ1 = (−l/100, −l/10): the paper prints t₂ = l/202 with its sign convention.

    >>> t = compatibility_error(np.array([[0., 0.], [1., 0.]]), np.array([[0, 1]]),
    ...                         np.array([1.0]), np.array([[0., 0.], [-0.01, -0.1]]))
    >>> round(float(-1 / t[0]), 2)
    202.02
    """
    x = np.asarray(coords, float) + np.asarray(increments, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    vec = member_vectors(x, conn)
    L = np.asarray(lengths, float)
    return (np.einsum("ij,ij->i", vec, vec) - L * L) / (2.0 * L)


def _jacobian(x: np.ndarray, conn: np.ndarray, lengths: np.ndarray, free: np.ndarray):
    """∂t/∂δ of the exact error at positions x: row i = (x_k − x_h)/l_i at the free columns."""
    vec = member_vectors(x, conn)                    # (bar, dim)
    n, dim = x.shape
    b = conn.shape[0]
    g = vec / lengths[:, None]
    rows = np.repeat(np.arange(b), 2 * dim)
    cols = (conn[:, :, None] * dim + np.arange(dim)[None, None, :]).reshape(b, -1)
    vals = np.concatenate([-g, g], axis=1)
    J = sp.csr_matrix((vals.ravel(), (rows, cols.ravel())), shape=(b, n * dim))
    return J[:, np.flatnonzero(free.ravel())]


def _solve_dependent(J: sp.csr_matrix, rhs: np.ndarray) -> np.ndarray | None:
    """Solve ``J Δ = rhs``: sparse LU when square and regular, least squares over all bars
    otherwise — a square but singular J (as many bars as dependent coordinates, one of
    them a state of self-stress beside a finite mechanism elsewhere: a locked node's two bars
    and a four-bar) has the least-squares solution of smallest norm, which moves nothing
    along its null space."""
    b, f = J.shape
    if b == f:
        lu = factor(J, "general", singular="flag")
        if not lu.is_singular:
            return lu.solve(rhs, refine=False)
    if f <= 3000:
        A = J.toarray()
        sol, *_ = np.linalg.lstsq(A, rhs, rcond=1e-10)
        return sol
    return spla.lsqr(J, rhs, atol=1e-14, btol=1e-14, iter_lim=20 * f)[0]


@dataclass
class StepResult:
    """Outcome of one corrector (:func:`hortobagyi_step`).

    Attributes
    ----------
    increments : ndarray, shape (f,)
        Converged increments of the free coordinates d.
    iterations : int
        Corrector iterations used (eq. 5–6 cycles).
    residual : float
        Largest |t_i| at the end, m.
    converged : bool
    history : list of ndarray
        The compatibility error vector t⁽ⁿ⁾ of each iteration (``record=True`` only).
    iterates : list of ndarray
        The increments d⁽ⁿ⁾ after each update (``record=True`` only).
    """

    increments: np.ndarray
    iterations: int
    residual: float
    converged: bool
    history: list = field(default_factory=list)
    iterates: list = field(default_factory=list)


def hortobagyi_step(coords: np.ndarray, connectivity: np.ndarray, lengths: np.ndarray,
                    free: np.ndarray, independent: np.ndarray, prediction: np.ndarray, *,
                    tolerance: float = 1e-10, max_iterations: int = 30, newton: bool = True,
                    record: bool = False) -> StepResult:
    """Correct a predicted finite increment until every bar closes (Hortobágyi eq. 4–7).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
        Compatible start state r.
    connectivity : ndarray of int, shape (b, 2)
    lengths : ndarray, shape (b,)
        Bar lengths to keep.
    free : ndarray of bool, shape (n, dim)
        Free coordinates (the columns of B).
    independent : array of int
        Positions, among the free coordinates, of the prescribed (independent) increments d2.
    prediction : ndarray, shape (f,)
        Predicted increments; its independent entries are the prescribed d2 and are kept.
    tolerance : float
        Convergence when ``max|t| ≤ tolerance · max(l)`` (eq. 7).
    max_iterations : int
    newton : bool
        Refresh B11 at every iterate (Newton).  ``False`` keeps the matrix of the predicted
        state for all iterations, as the paper does.
    record : bool
        Keep the error vectors and iterates (for reproducing the paper's tables).

    Returns
    -------
    StepResult

    Notes
    -----
    Incremental form of eq. (6): ``d1 ← d1 − B11⁻¹ t(d)``, with B11 the dependent columns of
    ∂t/∂d evaluated at ``r + d`` (at ``r + prediction`` for the frozen variant).
    """
    x0 = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    L = np.asarray(lengths, float)
    free = np.asarray(free, bool)
    fidx = np.flatnonzero(free.ravel())
    f = fidx.size
    indep = np.atleast_1d(np.asarray(independent, dtype=np.int64))
    dep = np.setdiff1d(np.arange(f), indep)
    d = np.array(prediction, dtype=float)
    tol = tolerance * float(L.max())

    def full(dv):
        out = np.zeros(x0.size)
        out[fidx] = dv
        return out.reshape(x0.shape)

    out = StepResult(increments=d, iterations=0, residual=np.inf, converged=False)
    J = None
    t0 = None
    for it in range(max_iterations + 1):
        t = compatibility_error(x0, conn, L, full(d))
        res = float(np.max(np.abs(t))) if t.size else 0.0
        if record:
            out.history.append(t.copy())
        out.iterations, out.residual = it, res
        if not np.isfinite(res):
            break
        if res <= tol:
            out.converged = True
            break
        if t0 is None:
            t0 = res
        elif res > 1e3 * t0:                               # diverging: give up early
            break
        if it == max_iterations:
            break
        if J is None or newton:
            J = _jacobian(x0 + full(d), conn, L, free)[:, dep]
        delta = _solve_dependent(J, -t)
        if delta is None or not np.all(np.isfinite(delta)):
            break
        d = d.copy()
        d[dep] += delta
        out.increments = d
        if record:
            out.iterates.append(d.copy())
    out.increments = d
    return out


# --------------------------------------------------------------------------- partition
def pivoted_partition(B: np.ndarray, n_independent: int | None = None) -> tuple[np.ndarray,
                                                                                  np.ndarray]:
    """Split the columns of B into dependent (B11) and independent (B12) ones by pivoting.

    Column-pivoted QR picks the columns with the largest pivots for B11 (Hortobágyi section 3,
    step c: B11 the submatrix of largest determinant, found by pivoting); the remaining ones
    carry the independent coordinate increments.

    Parameters
    ----------
    B : ndarray, shape (b, f)
    n_independent : int, optional
        Number of independent coordinates (default ``f − rank``).

    Returns
    -------
    dependent, independent : ndarray of int

    Examples
    --------
    Hortobágyi section 4, B at the folded state plus δ12 = −l/10 (columns 11, 12, 21, 22):

    >>> B = np.array([[0.995037, 0.0995037, -0.995037, -0.0995037],
    ...               [-0.995037, 0.0995037, 0, 0], [0, 0, -1, 0]])
    >>> dep, ind = pivoted_partition(B)
    >>> ind.tolist()
    [3]

    The largest-determinant B11 (|det| = 0.198 against 0.099 for columns 11, 21, 22) leaves
    δ22 independent; the paper prescribes δ12 instead, which is allowed because its B11 is
    invertible too.
    """
    B = np.asarray(B, float)
    _, r, piv = sla.qr(B, mode="economic", pivoting=True)
    if n_independent is None:
        d = np.abs(np.diag(r))
        rank = int(np.sum(d > max(B.shape) * 1e3 * np.finfo(float).eps * max(d.max(), 1e-300)))
        n_independent = B.shape[1] - rank
    k = B.shape[1] - n_independent
    return np.sort(piv[:k]), np.sort(piv[k:])


# --------------------------------------------------------------------------- tangent, test function
def _augmented_tangent(B: sp.csr_matrix, c: np.ndarray, return_lu: bool = False):
    """Tangent τ with ``B τ = 0, cᵀ τ = 1`` and the sign of ``det [B; cᵀ]`` (sparse LU)."""
    A = sp.vstack([B, sp.csr_matrix(c[None, :])]).tocsr()
    # SuperLU's LU whatever the size: it gives the determinant sign and transposed solves
    lu = factor(A, "general", "superlu", singular="flag")
    if lu.is_singular:
        return None, 0
    rhs = np.zeros(A.shape[0])
    rhs[-1] = 1.0
    tau = lu.solve(rhs, refine=False)
    sign = lu.determinant_sign
    if return_lu:
        return tau, sign, lu
    return tau, sign


def _chord_corrector(x0, conn, L, fidx, pred, lu, p, tol, max_iterations) -> StepResult:
    """Corrector with the factorised ``[B(x0); e_pᵀ]`` kept (chord iteration): solves
    ``B Δ = −t, Δ_p = 0`` with one factorisation per step; for the small steps of a trace it
    converges in a few cheap solves (used above the dense limit)."""
    n, dim = x0.shape
    d = pred.copy()
    rhs = np.zeros(fidx.size)
    res = np.inf
    for it in range(max_iterations + 1):
        full = np.zeros(n * dim)
        full[fidx] = d
        t = compatibility_error(x0, conn, L, full.reshape(n, dim))
        res = float(np.max(np.abs(t)))
        if res <= tol or not np.isfinite(res) or it == max_iterations:
            break
        rhs[:-1] = -t
        d = d + lu.solve(rhs, refine=False)
    return StepResult(increments=d, iterations=it, residual=res,
                      converged=bool(res <= tol))


def _switch_branch(x_prev, x, conn, L, free, tau, h, branch, tolerance, max_iterations):
    """Leave the traced path at a bifurcation found between ``x_prev`` and ``x``.

    The bifurcation point is approximated (not located to machine precision) by interpolating
    the signed smallest singular value of ``[B; τᵀ]`` between the two states and correcting
    there.  The other branch's tangent lies in B's two-dimensional near-null space
    ``V = [v₁ v₂]``; it is the second root of the second-order compatibility condition
    ``ωᵀ q(V a) = aᵀ M_ω a = 0`` (:mod:`trussfe.kinematics.unfolding`, ω the states of
    self-stress at the point), of which the traced tangent t is one root
    (:func:`_other_root`).  It is in general *not* orthogonal to t: the change-point
    parallelogram's branches leave the flat state along (1, 1) and (1, −3) in the two
    transverse coordinates.  Odd ``branch`` steps along it, even ``branch`` against.
    Returns ``(x_b, prediction, independent)`` or None.
    """
    fidx = np.flatnonzero(free.ravel())
    n, dim = x.shape

    def smin(xx):
        A = np.vstack([compatibility_matrix(xx, conn, free).toarray(), tau])
        sv = np.linalg.svd(A, compute_uv=False)
        return sv[-1] * np.sign(np.linalg.slogdet(A)[0])

    s0, s1 = smin(x_prev), smin(x)
    theta = s0 / (s0 - s1) if s0 != s1 else 0.5
    d = (x - x_prev).ravel()[fidx] * theta
    p = int(np.argmax(np.abs(d)))
    res = hortobagyi_step(x_prev, conn, L, free, [p], d, tolerance=tolerance,
                          max_iterations=max_iterations)
    if not res.converged:
        return None
    xb = x_prev.copy().ravel()
    xb[fidx] += res.increments
    xb = xb.reshape(n, dim)
    ub, _, vt = np.linalg.svd(compatibility_matrix(xb, conn, free).toarray(), full_matrices=True)
    V2 = vt[-2:].T                                         # near-null space, (f, 2)
    # states of self-stress at the point: ρ(B) = f − 2 there, so the last b − f + 2 left
    # singular vectors (the one born at the bifurcation and any that persist along the path)
    Om = ub[:, max(0, fidx.size - 2):]
    w = V2 @ _other_root(stress_quadrics(xb, conn, free, V2, Om), V2.T @ tau)
    w /= np.linalg.norm(w)
    q = int(np.argmax(np.abs(w)))
    sgn = 1.0 if branch % 2 else -1.0
    return xb, sgn * h * w / abs(w[q]), q


def _other_root(M: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Second root line of the binary quadrics ``aᵀ M_k a = 0`` that share the root t.

    In the basis (t, t⊥), ``Q_k(α t + β t⊥) = α² Q_k(t) + 2αβ c_k + β² d_k`` with
    ``c_k = tᵀ M_k t⊥`` and ``d_k = t⊥ᵀ M_k t⊥``; with ``Q_k(t) = 0`` the other root is
    ``α/β = −d_k / (2 c_k)``, taken in the least-squares sense over the quadrics.  When every
    ``c_k`` vanishes t is a double root (no transversal branch is seen at second order) and
    t⊥ is returned.

    Parameters
    ----------
    M : ndarray, shape (s, 2, 2)
        The quadrics (:func:`trussfe.kinematics.unfolding.stress_quadrics`).
    t : ndarray, shape (2,)
        The known root (the traced tangent in the same basis).

    Returns
    -------
    ndarray, shape (2,)
        The other root, unit length.

    Examples
    --------
    ``Q(a) = (3a₀ + a₁)(a₀ − a₁)/2`` has the roots (1, 1) and (1, −3):

    >>> M = np.array([[[1.5, -0.5], [-0.5, -0.5]]])
    >>> a = _other_root(M, np.array([1.0, 1.0]))
    >>> np.round(a / a[0], 12).tolist()
    [1.0, -3.0]
    """
    t = np.asarray(t, float) / np.linalg.norm(t)
    tp = np.array([-t[1], t[0]])
    c = np.einsum("i,kij,j->k", t, M, tp)
    d = np.einsum("i,kij,j->k", tp, M, tp)
    cc = float(c @ c)
    if M.shape[0] == 0 or cc <= (1e-12 * max(float(np.abs(M).max(initial=0.0)), 1e-300)) ** 2:
        return tp
    a = -float(c @ d) / (2.0 * cc) * t + tp
    return a / np.linalg.norm(a)


#: A step whose middle state has the smallest singular value of ``[B; τᵀ]`` below this
#: fraction of its neighbours' (with no sign change of the determinant) is re-traced in
#: sub-steps: two bifurcations crossed in one step cancel in the sign test.
DIP_RATIO = 0.5
#: Sub-steps per step of the re-traced interval.
REFINE_SUBSTEPS = 8


def _test_function(x, conn, free, c, rows=None) -> float:
    """Signed smallest singular value of ``[B; ĉᵀ]`` (ĉ = c/|c|, c along the tangent).

    It vanishes where B loses rank on the path (a bifurcation) and, unlike det B11, not at
    a limit point.  Its sign is that of the determinant (by LU with the permutations' parity,
    never the determinant's value, which under- or overflows); the magnitude comes from an
    exact SVD up to the dense limit and from four steps of inverse iteration on ``AᵀA`` with
    the same LU above it.  Returns 0.0 when the matrix is singular
    (:mod:`trussfe.linalg.tolerance`) or not square.
    """
    B = compatibility_matrix(x, conn, free)
    if rows is not None and rows.size != B.shape[0]:
        B = B[rows]
    c = np.asarray(c, float) / np.linalg.norm(c)
    A = sp.vstack([B, sp.csr_matrix(c[None, :])]).tocsc()
    if A.shape[0] != A.shape[1]:
        return 0.0
    if A.shape[0] <= DENSE_LIMIT + 1:
        Ad = A.toarray()
        sign = np.linalg.slogdet(Ad)[0]
        return float(sign * np.linalg.svd(Ad, compute_uv=False)[-1])
    lu = factor(A.tocsr(), "general", "superlu", singular="flag")
    if lu.is_singular:                 # singular under trussfe.linalg.tolerance: the zero
        return 0.0
    return float(lu.determinant_sign * _lu_smallest_singular(lu))


def _lu_smallest_singular(lu) -> float:
    """Smallest singular value of a factorised matrix A (:class:`trussfe.linalg.Factor` with
    transposed solves), estimated by two steps of power iteration on ``(AᵀA)⁻¹`` (two solves
    each) from a fixed start: an estimate from above, within a small factor — enough to see
    the test function dip towards zero."""
    n = lu.n
    v = np.random.default_rng(0).normal(size=n)
    v /= np.linalg.norm(v)
    lam = 1.0
    for _ in range(2):
        try:
            z = lu.solve(lu.solve(v, refine=False, transpose=True), refine=False)
        except SingularMatrixError:                # an overflowing (non-finite) solution
            return 0.0
        lam = float(np.linalg.norm(z))
        if not np.isfinite(lam) or lam == 0.0:
            return 0.0
        v = z / lam
    return float(1.0 / np.sqrt(lam))


def _refine_interval(xa, xm, xb, conn, L, free, rows, tolerance, max_iterations,
                     sub: int = REFINE_SUBSTEPS) -> list[float] | None:
    """Re-trace the two steps ``xa → xm → xb`` in ``2·sub`` sub-steps and return where the
    sign of the test function changes (in steps from ``xa``), or None if a sub-step fails.

    The sub-states are corrected from ``xa`` along the quadratic through the three states with
    the coordinate of largest motion prescribed (Hortobágyi eq. 4–7); the test function's
    vector is the quadratic's derivative, which stays on the side of the true tangent.
    """
    fidx = np.flatnonzero(free.ravel())
    n, dim = xa.shape
    da = (xm - xa).ravel()[fidx]
    db = (xb - xa).ravel()[fidx]
    b2 = (db - 2.0 * da) / 2.0                             # q(s) = a s + b2 s², q(1)=da, q(2)=db
    a1 = da - b2
    p = int(np.argmax(np.abs(db)))
    svals = np.linspace(0.0, 2.0, 2 * sub + 1)
    phis = []
    for sv in svals:
        if sv == 0.0:
            x = xa
        else:
            res = hortobagyi_step(xa, conn, L, free, [p], a1 * sv + b2 * sv * sv,
                                  tolerance=tolerance, max_iterations=max_iterations)
            if not res.converged:
                return None
            u = np.zeros(n * dim)
            u[fidx] = res.increments
            x = xa + u.reshape(n, dim)
        phis.append(_test_function(x, conn, free, a1 + 2.0 * b2 * sv, rows))
    sg = np.sign(phis)
    return [float(svals[i]) for i in range(len(sg) - 1) if sg[i] and sg[i + 1]
            and sg[i] != sg[i + 1]]


def _check_double_crossing(phi, j, path, conn, L, free, rows, tolerance, max_iterations,
                           events) -> None:
    """If state ``j − 1`` is a sharp minimum of |test function| with no sign change around it,
    re-trace states ``j − 2 … j`` in sub-steps and report every sign change found as a
    bifurcation (two bifurcations crossed in one step cancel in the plain sign test)."""
    if not all(i in phi for i in (j - 2, j - 1, j)):
        return
    fa, fm, fb = phi[j - 2], phi[j - 1], phi[j]
    if not (fa and fm and fb) or len({np.sign(fa), np.sign(fm), np.sign(fb)}) != 1:
        return
    if abs(fm) >= DIP_RATIO * min(abs(fa), abs(fb)):
        return
    log.info("trace: sharp minimum of the test function at state %d; refining", j - 1)
    found = _refine_interval(path[j - 2], path[j - 1], path[j], conn, L, free, rows,
                             tolerance, max_iterations)
    if found is None:
        log.info("trace: step refinement near state %d did not converge", j - 1)
        return
    for sv in found:
        events.append({"step": j - 1 + int(sv), "kind": "bifurcation",
                       "detected_by": "step refinement (minimum of the smallest singular "
                                      "value of [B; tangent])"})
    phi.pop(j - 1)                                         # do not refine the same dip twice


def _dense_null(B: sp.csr_matrix, rtol: float):
    A = B.toarray()
    if A.shape[0] == 0:
        return A.shape[1] * 0, np.eye(A.shape[1]), np.zeros(0)
    _, s, vt = np.linalg.svd(A, full_matrices=True)
    tol = rtol * max(s.max(initial=0.0), 1e-300)
    rank = int(np.sum(s > tol))
    return rank, vt[rank:].T, s
