# SPDX-License-Identifier: MIT
"""Hand-over to finite-mechanism motion: rank of the compatibility matrix and the equilibrium
form of a kinematically indeterminate assembly under a load pattern.

When failed bars have left the lattice a mechanism (Hortobágyi §9: "the load cannot increase
when the structure will be mechanism"), its remaining bars are treated as rigid and the
assembly moves along its finite mechanism (Hortobágyi eq. 1) in the direction in which the
load does work, until it reaches a form in which the load is carried by bar forces alone:

.. math:: \\min_x V(x) = -\\lambda f^T x \\quad\\text{subject to}\\quad
          \\lVert x_{b_i} - x_{a_i}\\rVert = \\ell_i

Stationarity is ``Bᵀ t = λ f`` (equilibrium, ``t`` the bar tensions, the Lagrange
multipliers); a minimum needs the geometric stiffness ``Σ tᵢ/ℓᵢ (I − eᵢeᵢᵀ)`` positive on the
mechanism space (the null space of ``B``).
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np

from ..kinematics.compatibility import compatibility_matrix
from ..linalg import RankError, matrix_rank
from ..mechanics.geometry import member_lengths, member_vectors, unit_vectors

log = logging.getLogger(__name__)

#: Relative tolerance on singular values of B (scaled by the largest) for the rank.
RANK_TOLERANCE = 1e-9
#: Free coordinates up to which the rank comes from a dense SVD (exact); above, from the
#: inertia of the shifted Gram matrix (:func:`trussfe.linalg.matrix_rank`).
DENSE_RANK_LIMIT = 200


def mechanism_count(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                    tolerance: float = RANK_TOLERANCE) -> tuple[int, int]:
    """Number of independent infinitesimal mechanisms and the rank of B.

    Parameters
    ----------
    coords : ndarray, shape (node, dim)
    connectivity : ndarray of int, shape (bar, 2)
    free : ndarray of bool, shape (node, dim)
        Free joint coordinates.
    tolerance : float
        Singular values below ``tolerance · σ_max`` count as zero.

    Returns
    -------
    mechanisms : int
        ``μ·j − ρ(B)`` (Hortobágyi §2, eq. 2), rigid-body motions left free included.
    rank : int

    Notes
    -----
    The rank is that of :func:`trussfe.linalg.matrix_rank`: dense SVD up to
    :data:`DENSE_RANK_LIMIT` free coordinates, the inertia of the shifted Gram matrix ``BᵀB``
    above (the same routine as the rank analysis of :mod:`trussfe.kinematics.rank`).

    Examples
    --------
    A triangle pinned at one corner and on a roller at another is stiff; without its base it is
    a one-degree-of-freedom mechanism:

    >>> x = np.array([[0., 0.], [2., 0.], [1., 1.]])
    >>> free = np.array([[0, 0], [1, 0], [1, 1]], bool)
    >>> mechanism_count(x, np.array([[0, 1], [1, 2], [0, 2]]), free)
    (0, 3)
    >>> mechanism_count(x, np.array([[1, 2], [0, 2]]), free)
    (1, 2)
    """
    nf = int(np.sum(free))
    if len(connectivity) == 0:
        return nf, 0
    B = compatibility_matrix(np.asarray(coords, dtype=float),
                             np.asarray(connectivity, dtype=np.int64).reshape(-1, 2),
                             np.asarray(free, dtype=bool))
    try:
        rank = matrix_rank(B, tolerance=tolerance, dense_limit=DENSE_RANK_LIMIT).rank
    except RankError:        # nearly every direction free: the sparse path cannot tell
        rank = matrix_rank(B, tolerance=tolerance, dense_limit=max(B.shape)).rank
    return nf - rank, rank


def _null_space(B: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the mechanism space (null space of B) at :data:`RANK_TOLERANCE`."""
    return matrix_rank(B, tolerance=RANK_TOLERANCE, dense_limit=max(B.shape)).null


@dataclass
class MechanismMotion:
    """Result of the mechanism hand-over.

    Attributes
    ----------
    positions : list of ndarray, each (node, dim)
        Joint positions along the mechanism motion, from the hand-over to the equilibrium form.
    potential : list of float
        Load potential ``−λ fᵀ(x − x_start)`` along the motion, J.
    converged : bool
        An equilibrium form was found.
    tensions : ndarray, shape (bar,)
        Bar forces at the equilibrium form (positive in tension).
    residual : float
        ``‖Bᵀt − λf‖ / ‖λf‖`` at the form.
    stable : bool
        Geometric stiffness positive definite on the mechanism space (a potential minimum).
    mechanisms : int
        Mechanisms of the assembly when it was handed over.
    reason : str
        Why the motion stopped.
    """

    positions: list = field(default_factory=list)
    potential: list = field(default_factory=list)
    converged: bool = False
    tensions: np.ndarray | None = None
    residual: float = np.nan
    stable: bool = False
    mechanisms: int = 0
    reason: str = ""


def _correct_lengths(x, conn, lengths, free, iters=30, tol=1e-12):
    """Return x moved (minimum norm, Newton) back onto the bar lengths (Hortobágyi eq. 1)."""
    fi = np.flatnonzero(free.ravel())
    scale = lengths.max()
    for _ in range(iters):
        err = lengths - member_lengths(x, conn)
        if np.abs(err).max() <= tol * scale:
            return x, True
        B = compatibility_matrix(x, conn, free).toarray()
        d = np.linalg.lstsq(B, err, rcond=None)[0]
        xr = x.ravel().copy()
        xr[fi] += d
        x = xr.reshape(x.shape)
    return x, False


def _geometric_stiffness(x, conn, t, free):
    dim = x.shape[1]
    n = x.shape[0]
    e, l = unit_vectors(member_vectors(x, conn))
    k0 = (t / l)[:, None, None] * (np.eye(dim)[None] - e[:, :, None] * e[:, None, :])
    K = np.zeros((n * dim, n * dim))
    for a_sign, b_sign, ca, cb in ((1, 1, 0, 0), (1, 1, 1, 1), (-1, -1, 0, 1), (-1, -1, 1, 0)):
        ia = (conn[:, ca, None] * dim + np.arange(dim))        # (bar, dim)
        ib = (conn[:, cb, None] * dim + np.arange(dim))
        np.add.at(K, (ia[:, :, None], ib[:, None, :]), a_sign * k0)
    fi = np.flatnonzero(free.ravel())
    return K[np.ix_(fi, fi)]


def equilibrium_form(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                     load: np.ndarray, *, max_steps: int = 400, step: float | None = None,
                     tolerance: float = 1e-9, travel_limit: float = 20.0) -> MechanismMotion:
    """Move a mechanism of rigid bars under a load until an equilibrium form is reached.

    Parameters
    ----------
    coords : ndarray, shape (node, dim)
        Joint positions at the hand-over.
    connectivity : ndarray of int, shape (bar, 2)
        Remaining bars (rigid, lengths = current lengths).
    free : ndarray of bool, shape (node, dim)
    load : ndarray, shape (node, dim)
        The load ``λ f`` at the hand-over (it stays constant: a dead load).
    max_steps : int
        Steps of the mechanism motion.
    step : float, optional
        Largest joint movement per step (default 1/20 of the assembly size).
    tolerance : float
        Equilibrium tolerance ``‖Bᵀt − λf‖ ≤ tolerance ‖λf‖``.
    travel_limit : float
        Stop (no equilibrium form) when the loaded joints travel more than this many assembly
        sizes: the load then does work without bound.

    Returns
    -------
    MechanismMotion

    Notes
    -----
    Steepest descent of the load potential along the mechanism — the load projected on the null
    space of B, followed by a minimum-norm return onto the bar lengths — then Newton on the
    stationarity conditions ``Bᵀt = λf``, ``ℓ(x) = ℓ₀`` (bordered with the geometric
    stiffness) for quadratic convergence near the form.
    """
    x = np.array(coords, dtype=float)
    conn = np.asarray(connectivity, dtype=np.int64)
    free = np.asarray(free, dtype=bool)
    fvec = np.asarray(load, dtype=float)
    fi = np.flatnonzero(free.ravel())
    f = fvec.ravel()[fi]
    fn = np.linalg.norm(f)
    lengths = member_lengths(x, conn)
    size = float(np.ptp(x, axis=0).max())
    h = step if step is not None else size / 20.0
    out = MechanismMotion(mechanisms=mechanism_count(x, conn, free)[0])
    x0 = x.copy()
    out.positions.append(x.copy())
    out.potential.append(0.0)
    if fn == 0:
        out.reason = "no load on the free joints"
        return out
    t = np.zeros(len(conn))
    for k in range(max_steps):
        B = compatibility_matrix(x, conn, free).toarray()
        t = np.linalg.lstsq(B.T, f, rcond=None)[0]
        p = f - B.T @ t                                   # load component on the mechanism
        pn = np.linalg.norm(p)
        if pn <= 1e-3 * fn:
            # stationary: a minimum, or an unstable form (compressed bars) to leave along the
            # mechanism direction of most negative curvature (branching on the eigenvector)
            ns = _null_space(B)
            if ns.shape[1] == 0:
                break
            w, v = np.linalg.eigh(ns.T @ _geometric_stiffness(x, conn, t, free) @ ns)
            if w[0] > 1e-9 * max(abs(w).max(), 1e-300):
                break
            d = ns @ v[:, 0]
            d = d if f @ d >= 0.0 else -d
            p, pn = d * fn, fn
        while True:
            xr = x.ravel().copy()
            xr[fi] += h * p / pn
            xn, ok = _correct_lengths(xr.reshape(x.shape), conn, lengths, free)
            dx = (xn - x).ravel()[fi]
            if ok and f @ dx > 0.0:                       # the load does positive work
                break
            h *= 0.5
            if h < 1e-8 * size:
                out.reason = "the mechanism motion stalled (no compatible step found)"
                return out
        x = xn
        out.positions.append(x.copy())
        out.potential.append(-float(fvec.ravel() @ (x - x0).ravel()))
        if np.abs(x - x0).max() > travel_limit * size:
            out.reason = ("no equilibrium form: the load drives the mechanism without bound "
                          f"(joints travelled more than {travel_limit:g} assembly sizes)")
            return out
        h = min(h * 1.5, size / 20.0 if step is None else step)
    # Newton on the stationarity conditions (KKT system)
    nb = len(conn)
    for _ in range(50):
        B = compatibility_matrix(x, conn, free).toarray()
        r = f - B.T @ t
        err = lengths - member_lengths(x, conn)
        if np.linalg.norm(r) <= tolerance * fn and np.abs(err).max() <= 1e-12 * size:
            break
        Kg = _geometric_stiffness(x, conn, t, free)
        # d(Bᵀt) = Kg(t) dx + Bᵀ dt and dℓ = B dx
        rhs = np.concatenate([r, err])
        sol = np.linalg.lstsq(np.block([[Kg, B.T], [B, np.zeros((nb, nb))]]), rhs,
                              rcond=None)[0]
        xr = x.ravel().copy()
        xr[fi] += sol[: len(fi)]
        x = xr.reshape(x.shape)
        t = t + sol[len(fi):]
    B = compatibility_matrix(x, conn, free).toarray()
    t = np.linalg.lstsq(B.T, f, rcond=None)[0]
    out.residual = float(np.linalg.norm(B.T @ t - f) / fn)
    out.tensions = t
    out.positions.append(x.copy())
    out.potential.append(-float(fvec.ravel() @ (x - x0).ravel()))
    out.converged = out.residual <= max(tolerance, 1e-8)
    # second-order check on the mechanism space (null space of B)
    ns = _null_space(B)
    if ns.shape[1] == 0:
        out.stable = True
    else:
        Kg = _geometric_stiffness(x, conn, t, free)
        out.stable = bool(np.linalg.eigvalsh(ns.T @ Kg @ ns).min() > 0.0)
    out.reason = ("equilibrium form reached" if out.converged else
                  f"equilibrium not reached (residual {out.residual:.2e})")
    return out
