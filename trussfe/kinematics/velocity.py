# SPDX-License-Identifier: MIT
"""Joint velocities and accelerations of a mechanism from its compatibility matrix.

Differentiating the bar-length condition ``|x_k − x_h|² = L²`` once and twice in time gives,
per bar (Hortobágyi eq. 2 is the first-order form)

.. math::

    B\\,v = \\dot L, \\qquad
    B\\,a = \\ddot L - \\frac{|v_k - v_h|^2 - \\dot L^2}{L},

exact relations (no finite differences).  With a mechanism the system is completed by the
prescribed velocity (acceleration) of the driven coordinates.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import AnalysisError
from ..linalg import factor
from ..mechanics.geometry import lengths, member_vectors
from .compatibility import compatibility_matrix


#: Largest residual of an over-determined system, relative to its right-hand side, for its
#: equations to count as consistent (round-off of the least-squares solution is ~1e-15).
CONSISTENCY_TOLERANCE = 1e-9


def _solve(A: sp.csr_matrix, rhs: np.ndarray, item: str) -> np.ndarray:
    """Solve the square system by sparse LU or a consistent over-determined one by lstsq.

    An over-determined system whose equations contradict one another (two prescribed rates
    of one crank pin that do not keep the crank's length) has no solution: it is refused,
    not answered by the least-squares compromise that keeps no equation."""
    if A.shape[0] == A.shape[1]:
        fac = factor(A, "general", singular="flag")
        if not fac.is_singular:
            return fac.solve(rhs, refine=False)
    dense = A.toarray()
    sol, _, rank, _ = np.linalg.lstsq(dense, rhs, rcond=1e-10)
    if rank < A.shape[1]:
        raise AnalysisError(item, "the prescribed motion does not determine every joint "
                                  "velocity (a singular position or too few drives)")
    scale = max(float(np.abs(rhs).max(initial=0.0)),
                float(np.abs(dense).max(initial=0.0) * np.abs(sol).max(initial=0.0)))
    if np.abs(dense @ sol - rhs).max(initial=0.0) > CONSISTENCY_TOLERANCE * scale:
        raise AnalysisError(item, "the prescribed rates contradict one another (more drives "
                                  "than degrees of freedom that the bars do not allow "
                                  "together): prescribe consistent rates or fewer of them")
    return sol


def mechanism_velocity(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                       prescribed: dict[int, float], length_rates: np.ndarray | None = None
                       ) -> np.ndarray:
    """Joint velocities of a mechanism from ``B v = L̇`` and the prescribed coordinate rates.

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
    connectivity : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
    prescribed : dict
        Flat coordinate index (``node * dim + axis``) → velocity, m/s.  More than the degrees of
        freedom may be given if they are consistent (e.g. both components of a crank pin).
    length_rates : ndarray, shape (b,), optional
        L̇ of each bar (active members); zero by default.

    Returns
    -------
    ndarray, shape (n, dim)
        Velocities (zero at fixed coordinates).

    Examples
    --------
    A crank of length 1 at 90° turning at 2 rad/s drives its pin at (−2, 0):

    >>> v = mechanism_velocity(np.array([[0., 0.], [0., 1.]]), np.array([[0, 1]]),
    ...                        np.array([[0, 0], [1, 1]], bool), {2: -2.0})
    >>> v[1].tolist()
    [-2.0, 0.0]
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, bool).reshape(x.shape)
    fidx = np.flatnonzero(free.ravel())
    col = -np.ones(x.size, dtype=np.int64)
    col[fidx] = np.arange(fidx.size)
    B = compatibility_matrix(x, conn, free)
    keys = np.array(list(prescribed), dtype=np.int64)
    if np.any(col[keys] < 0):
        raise AnalysisError("velocity", "a prescribed coordinate is fixed by a support")
    E = sp.csr_matrix((np.ones(keys.size), (np.arange(keys.size), col[keys])),
                      shape=(keys.size, fidx.size))
    ldot = np.zeros(conn.shape[0]) if length_rates is None else np.asarray(length_rates, float)
    rhs = np.concatenate([ldot, [prescribed[int(k)] for k in keys]])
    v = _solve(sp.vstack([B, E]).tocsr(), rhs, "velocity")
    out = np.zeros(x.size)
    out[fidx] = v
    return out.reshape(x.shape)


def mechanism_acceleration(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                           velocity: np.ndarray, prescribed: dict[int, float],
                           length_rates: np.ndarray | None = None,
                           length_accelerations: np.ndarray | None = None) -> np.ndarray:
    """Joint accelerations from ``B a = L̈ − (|v_rel|² − L̇²)/L`` and the prescribed ones.

    Parameters
    ----------
    velocity : ndarray, shape (n, dim)
        Joint velocities (from :func:`mechanism_velocity`).
    prescribed : dict
        Flat coordinate index → acceleration, m/s².
    length_rates, length_accelerations : ndarray, shape (b,), optional
        L̇ and L̈ of each bar; zero by default.

    Returns
    -------
    ndarray, shape (n, dim)

    Examples
    --------
    The crank pin of a crank of length 1 turning uniformly at 2 rad/s has the centripetal
    acceleration 4 m/s² towards the pivot:

    >>> x = np.array([[0., 0.], [0., 1.]]); c = np.array([[0, 1]])
    >>> f = np.array([[0, 0], [1, 1]], bool)
    >>> v = mechanism_velocity(x, c, f, {2: -2.0})
    >>> a = mechanism_acceleration(x, c, f, v, {2: 0.0})
    >>> np.round(a[1], 12).tolist()
    [0.0, -4.0]
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, bool).reshape(x.shape)
    fidx = np.flatnonzero(free.ravel())
    col = -np.ones(x.size, dtype=np.int64)
    col[fidx] = np.arange(fidx.size)
    v = np.asarray(velocity, float).reshape(x.shape)
    vec = member_vectors(x, conn)
    L = lengths(vec)
    vrel = member_vectors(v, conn)
    b = conn.shape[0]
    ldot = np.zeros(b) if length_rates is None else np.asarray(length_rates, float)
    lddot = np.zeros(b) if length_accelerations is None else np.asarray(length_accelerations,
                                                                         float)
    rhs_b = lddot - (np.einsum("ij,ij->i", vrel, vrel) - ldot ** 2) / L
    B = compatibility_matrix(x, conn, free)
    keys = np.array(list(prescribed), dtype=np.int64)
    if np.any(col[keys] < 0):
        raise AnalysisError("acceleration", "a prescribed coordinate is fixed by a support")
    E = sp.csr_matrix((np.ones(keys.size), (np.arange(keys.size), col[keys])),
                      shape=(keys.size, fidx.size))
    rhs = np.concatenate([rhs_b, [prescribed[int(k)] for k in keys]])
    a = _solve(sp.vstack([B, E]).tocsr(), rhs, "acceleration")
    out = np.zeros(x.size)
    out[fidx] = a
    return out.reshape(x.shape)


def bar_angular_velocity(coords: np.ndarray, connectivity: np.ndarray,
                         velocity: np.ndarray) -> np.ndarray:
    """Angular velocity of each bar of a planar assembly, ``ω = (e × v_rel)/L``, rad/s."""
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    vec = member_vectors(x, conn)
    vrel = member_vectors(velocity, conn)
    return (vec[:, 0] * vrel[:, 1] - vec[:, 1] * vrel[:, 0]) / np.einsum("ij,ij->i", vec, vec)
