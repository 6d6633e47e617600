# SPDX-License-Identifier: MIT
"""Second-order unfolding directions of an assembly at a singular (e.g. folded) state.

At a state where B has more infinitesimal mechanisms than the assembly has finite degrees of
freedom (Hortobágyi section 6: a folded assembly, μ·j − ρ(B) = 4 with one finite freedom), the
first-order motions ``v = N a`` (N a basis of the null space of B) are not all the starts of
finite motions.  A finite motion ``d(h) = h v + h² w + …`` keeps every bar length to second
order when

    B w = −q(v) / 2,   q_i(v) = |v_k − v_h|² / l_i        (bar i from joint h to joint k),

which is solvable exactly when q(v) is orthogonal to every state of self-stress ω of B:

    ωᵀ q(v) = Σ_i ω_i |v_k − v_h|² / l_i = 0                 (one quadric per self-stress).

The real solution lines of these quadrics form the second-order tangent cone (Connelly and
Whiteley 1996, Hortobágyi's ref. [2]).  A simple real root is the tangent of a branch of the
finite motion leaving the singular state, so the lines are the *unfolding shapes*; no real root
means the state is second-order rigid (hence rigid: the eight-bar assembly of section 6).
Given a prescribed direction (Hortobágyi: "prescribe the vertical co-ordinate increments of the
four inner nodes"), :func:`project_to_cone` moves it onto the nearest line keeping the largest
increment, and :func:`second_order_prediction` adds ``h² w``, so the corrector starts O(h³)
from the branch instead of O(h²) — at a singular state the Jacobian's smallest singular value
is itself O(h), and only the second-order start puts Newton inside its convergence region.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..mechanics.geometry import member_lengths, member_vectors
from .compatibility import compatibility_matrix


@dataclass
class TangentCone:
    """Real second-order unfolding directions at a state.

    Attributes
    ----------
    directions : ndarray, shape (k, f)
        Unit first-order velocities (free coordinates), one per real line of the cone; the sign
        is chosen so that the entry of largest magnitude is positive (the opposite sense is the
        mirror motion).
    simple : ndarray of bool, shape (k,)
        The root is simple (its Jacobian has full rank): a branch of the finite motion leaves
        the state along it.
    mechanisms, self_stress_states : int
        Nullity of B and of Bᵀ at the state.
    """

    directions: np.ndarray
    simple: np.ndarray
    mechanisms: int
    self_stress_states: int


def _bases(coords, conn, free, rtol):
    B = compatibility_matrix(coords, conn, free).toarray()
    u, s, vt = np.linalg.svd(B, full_matrices=True)
    rank = int(np.sum(s > rtol * max(s.max(initial=0.0), 1e-300)))
    return B, vt[rank:].T, u[:, rank:]


def _quadric_terms(coords, conn, free, N, a):
    """q(N a) per bar and its derivative with respect to a, vectorised over bars."""
    n, dim = coords.shape
    fidx = np.flatnonzero(np.asarray(free, bool).ravel())
    Nf = np.zeros((n * dim, N.shape[1]))
    Nf[fidx] = N
    Nf = Nf.reshape(n, dim, -1)
    L = member_lengths(coords, conn)
    dN = Nf[conn[:, 1]] - Nf[conn[:, 0]]                   # (b, dim, m)
    dv = dN @ a                                            # (b, dim)
    q = np.einsum("bd,bd->b", dv, dv) / L
    dq = 2.0 * np.einsum("bd,bdm->bm", dv, dN) / L[:, None]
    return q, dq


def stress_quadrics(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                    N: np.ndarray, Om: np.ndarray) -> np.ndarray:
    """The quadrics ``ωᵀ q(N a) = aᵀ M_k a`` of the second-order condition (module notes).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
    connectivity : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
    N : ndarray, shape (f, m)
        First-order motions (a basis of the null space of B, free coordinates).
    Om : ndarray, shape (b, s)
        States of self-stress.

    Returns
    -------
    ndarray, shape (s, m, m)
        ``M_k = Σ_b ω_kb / l_b ΔN_bᵀ ΔN_b``.
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    n, dim = x.shape
    m = N.shape[1]
    fidx = np.flatnonzero(np.asarray(free, bool).ravel())
    Nf = np.zeros((n * dim, m))
    Nf[fidx] = N
    Nf = Nf.reshape(n, dim, m)
    L = member_lengths(x, conn)
    dN = Nf[conn[:, 1]] - Nf[conn[:, 0]]                   # (b, dim, m)
    W = np.einsum("bs,bdm->sbdm", Om / L[:, None], dN)      # stress-weighted, (s, b, dim, m)
    return np.einsum("sbdm,bdn->smn", W, dN)


def tangent_cone(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray, *,
                 starts: int = 200, seed: int = 0, rtol: float = 1e-8) -> TangentCone:
    """Real lines of the second-order tangent cone (the unfolding directions) at a state.

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
    connectivity : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
    starts : int
        Random starts of Newton's method on the unit sphere of the null space; the lines are
        collected up to sign.  The cone of s quadrics in m unknowns has at most 2^(m−1) lines
        when s = m − 1 (Bézout), so a few hundred starts find every real one.
    seed : int
    rtol : float
        Relative singular-value tolerance of the rank of B.

    Returns
    -------
    TangentCone

    Examples
    --------
    Two collinear bars 0–1–2 with the ends fixed (a stretched chain): one vertical
    infinitesimal mechanism, one self-stress, and ``ω·q(v) = 2 v²`` has no real root — the
    stretched chain is second-order rigid.

    >>> x = np.array([[0., 0.], [1., 0.], [2., 0.]])
    >>> free = np.array([[0, 0], [1, 1], [0, 0]], bool)
    >>> c = tangent_cone(x, np.array([[0, 1], [1, 2]]), free)
    >>> c.mechanisms, c.self_stress_states, len(c.directions)
    (1, 1, 0)
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    B, N, Om = _bases(x, conn, free, rtol)
    m, s = N.shape[1], Om.shape[1]
    if m == 0:
        return TangentCone(np.zeros((0, B.shape[1])), np.zeros(0, bool), 0, s)
    if s == 0:
        return TangentCone(N.T.copy(), np.ones(m, bool), m, 0)
    rng = np.random.default_rng(seed)
    M = stress_quadrics(x, conn, free, N, Om)
    A = rng.normal(size=(starts, m))
    A /= np.linalg.norm(A, axis=1, keepdims=True)
    for _it in range(60):                                  # Newton on all starts at once
        MA = np.einsum("kmn,tn->tkm", M, A)                # (starts, s, m)
        F = np.concatenate([np.einsum("tkm,tm->tk", MA, A),
                            (np.einsum("tm,tm->t", A, A) - 1.0)[:, None]], axis=1)
        J = np.concatenate([2.0 * MA, 2.0 * A[:, None, :]], axis=1)
        A = A - np.einsum("tmk,tk->tm", np.linalg.pinv(J), F)
    MA = np.einsum("kmn,tn->tkm", M, A)
    res = np.abs(np.einsum("tkm,tm->tk", MA, A)).max(axis=1)
    scale = np.abs(M).max()
    found: list[np.ndarray] = []
    simple: list[bool] = []
    for t in np.flatnonzero(res <= 1e-10 * max(scale, 1e-300)):
        a = A[t] / np.linalg.norm(A[t])
        if any(abs(a @ b) > 1 - 1e-8 for b in found):
            continue
        J = np.vstack([2.0 * np.einsum("kmn,n->km", M, a), 2.0 * a])
        sv = np.linalg.svd(J, compute_uv=False)
        found.append(a)
        simple.append(bool(sv[-1] > 1e-6 * sv[0]) and J.shape[0] >= m)
    dirs = np.array([N @ a for a in found]).reshape(-1, N.shape[0])
    for k in range(dirs.shape[0]):
        if dirs[k, np.argmax(np.abs(dirs[k]))] < 0:
            dirs[k] = -dirs[k]
    order = np.lexsort(dirs.T[::-1]) if dirs.size else np.arange(0)
    return TangentCone(dirs[order], np.array(simple, bool)[order], m, s)


def project_to_cone(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                    prescribed: np.ndarray, keep: int, *, rtol: float = 1e-8,
                    max_iterations: int = 50) -> np.ndarray:
    """First-order velocity on the tangent cone nearest a prescribed one.

    Parameters
    ----------
    prescribed : ndarray, shape (f,)
        Prescribed increments (free coordinates), e.g. the null-space vector fitted to the
        drive increments.
    keep : int
        Free-coordinate position whose increment is kept (the independent coordinate: the
        largest prescribed increment, Hortobágyi section 6).

    Returns
    -------
    ndarray, shape (f,)
        ``v`` with ``B v = 0``, ``ωᵀ q(v) = 0`` for every self-stress ω and ``v[keep]`` equal to
        the prescribed value (Gauss–Newton from the prescription, minimum-norm steps).

    Raises
    ------
    AnalysisError
        No second-order motion near the prescribed increments.
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    _, N, Om = _bases(x, conn, free, rtol)
    v0 = np.asarray(prescribed, float)
    a = np.linalg.lstsq(N, v0, rcond=None)[0]
    target = v0[keep]
    scale = max(abs(target), 1e-300)
    for _ in range(max_iterations):
        q, dq = _quadric_terms(x, conn, free, N, a)
        F = np.concatenate([Om.T @ q / scale, [(N[keep] @ a - target) / scale]])
        J = np.vstack([Om.T @ dq / scale, N[keep][None, :] / scale])
        step = np.linalg.lstsq(J, -F, rcond=None)[0]
        a = a + step
        if np.linalg.norm(step) <= 1e-13 * max(np.linalg.norm(a), 1e-300):
            break
    q, _ = _quadric_terms(x, conn, free, N, a)
    if Om.shape[1] and np.abs(Om.T @ q).max() > 1e-9 * max(float(np.abs(q).max()), 1e-300):
        raise AnalysisError("trace", "the prescribed increments are not near a second-order "
                                     "motion of the assembly (no unfolding direction close to "
                                     "them); prescribe other increments")
    return N @ a


def second_order_prediction(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                            v: np.ndarray, keep: int) -> np.ndarray:
    """Predicted finite increment ``v + w`` with ``B w = −q(v)/2`` and ``w[keep] = 0``.

    ``v`` must lie on the tangent cone (:func:`project_to_cone`); ``w`` is the minimum-norm
    solution, so the prediction misses the bar lengths by O(|v|³) only.
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    B = compatibility_matrix(x, conn, free).toarray()
    n, dim = x.shape
    fidx = np.flatnonzero(np.asarray(free, bool).ravel())
    u = np.zeros(n * dim)
    u[fidx] = v
    u = u.reshape(n, dim)
    dv = member_vectors(u, conn)
    L = member_lengths(x, conn)
    q = np.einsum("bd,bd->b", dv, dv) / L
    A = np.vstack([B, np.eye(B.shape[1])[keep]])
    w = np.linalg.lstsq(A, np.concatenate([-0.5 * q, [0.0]]), rcond=None)[0]
    return np.asarray(v, float) + w
