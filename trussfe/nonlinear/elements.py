# SPDX-License-Identifier: MIT
"""Co-rotational elements, vectorised over all elements.

Two kernels:

* :func:`truss_kinematics` / :func:`truss_matrices` — the co-rotational bar in 2-D or 3-D
  (axial force from the engineering strain of the chord, tangent = material + geometric part);
* :func:`beam2d_matrices` — Crisfield's co-rotational plane beam with a "shallow-arch" local
  element, whose tangent at the undeformed state equals the linear stiffness plus the consistent
  (Hermite) geometric stiffness ``K + Kg``.

Array axes are documented as ``# (element, ...)``; there is no Python loop over elements.
Each kernel returns element vectors/matrices in the element DOF order; :func:`assemble` scatters
them with one COO assembly.

Notation
--------
``L0`` reference length, ``l`` current length, ``e`` current unit vector, ``N`` axial force
(positive in tension), ``M1, M2`` end moments of a beam in its co-rotated frame.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from ..mechanics.geometry import member_vectors, unit_vectors


# ----------------------------------------------------------------------------------- bars
def truss_kinematics(x: np.ndarray, conn: np.ndarray, L0: np.ndarray):
    """Current length, unit vector and engineering strain of every bar.

    Parameters
    ----------
    x : ndarray, shape (point, dim)
        Current point positions.
    conn : ndarray of int, shape (element, 2)
    L0 : ndarray, shape (element,)
        Reference (stress-free) lengths.

    Returns
    -------
    l : ndarray, shape (element,)
    e : ndarray, shape (element, dim)
    strain : ndarray, shape (element,)
        ``(l - L0) / L0``.
    """
    e, l = unit_vectors(member_vectors(x, conn))            # (element, dim), (element,)
    return l, e, (l - L0) / L0


def truss_matrices(e: np.ndarray, l: np.ndarray, L0: np.ndarray, N: np.ndarray,
                   dNde: np.ndarray, tangent: bool = True):
    """Internal force vectors and tangent matrices of co-rotational bars.

    Parameters
    ----------
    e, l : ndarray, shapes (element, dim), (element,)
        Current unit vector and length.
    L0 : ndarray, shape (element,)
    N : ndarray, shape (element,)
        Axial force, positive in tension.
    dNde : ndarray, shape (element,)
        Tangent of the force–strain law, dN/dε (``EA`` while elastic).

    Returns
    -------
    f : ndarray, shape (element, 2*dim)
        ``N [-e, e]`` — the equilibrium matrix row of the bar times its force.
    k : ndarray, shape (element, 2*dim, 2*dim), or None when ``tangent`` is False

    Notes
    -----
    With ``ε = (l - L0)/L0`` and ``dl = eᵀ(du_b - du_a)``:

    .. math:: k = \\begin{bmatrix} k_0 & -k_0 \\\\ -k_0 & k_0\\end{bmatrix},\\quad
              k_0 = \\frac{N'}{L_0} e e^T + \\frac{N}{l}(I - e e^T)

    At the reference state the first term is the linear bar stiffness ``EA/L Bᵢᵀ Bᵢ``
    (Hortobágyi eq. 2 row times ``EA/L``) and the second the bar's geometric stiffness.
    """
    dim = e.shape[1]
    f = np.concatenate([-N[:, None] * e, N[:, None] * e], axis=1)    # (element, 2*dim)
    if not tangent:
        return f, None
    eet = e[:, :, None] * e[:, None, :]                               # (element, dim, dim)
    k0 = ((dNde / L0)[:, None, None] * eet
          + (N / l)[:, None, None] * (np.eye(dim)[None] - eet))       # (element, dim, dim)
    k = np.empty((len(l), 2 * dim, 2 * dim))
    k[:, :dim, :dim] = k0
    k[:, dim:, dim:] = k0
    k[:, :dim, dim:] = -k0
    k[:, dim:, :dim] = -k0
    return f, k


# ----------------------------------------------------------------------------- plane beams
def beam2d_local(x: np.ndarray, conn: np.ndarray, rot: np.ndarray, X: np.ndarray):
    """Co-rotated local deformations of plane beam elements.

    Parameters
    ----------
    x : ndarray, shape (point, 2)
        Current point positions.
    conn : ndarray of int, shape (element, 2)
        End points.
    rot : ndarray, shape (element, 2)
        Current total rotations of the element ends (rad, anticlockwise, 0 at reference).
    X : ndarray, shape (point, 2)
        Reference positions.

    Returns
    -------
    l, c, s : ndarray, shape (element,)
        Current length and direction cosines.
    L0 : ndarray, shape (element,)
    ul : ndarray, shape (element,)
        Local elongation ``(l² - L0²)/(l + L0)`` (the round-off safe ``l - L0``).
    th : ndarray, shape (element, 2)
        Local end rotations relative to the chord, ``θᵢ - α``.
    """
    d = member_vectors(x, conn)                     # (element, 2)
    D = member_vectors(X, conn)
    l = np.hypot(d[:, 0], d[:, 1])
    L0 = np.hypot(D[:, 0], D[:, 1])
    c, s = d[:, 0] / l, d[:, 1] / l
    c0, s0 = D[:, 0] / L0, D[:, 1] / L0
    # rigid rotation of the chord, robust for any angle: alpha = atan2(sin, cos)
    alpha = np.arctan2(c0 * s - s0 * c, c0 * c + s0 * s)
    th = rot - alpha[:, None]
    th = (th + np.pi) % (2.0 * np.pi) - np.pi
    ul = (l * l - L0 * L0) / (l + L0)
    return l, c, s, L0, ul, th


def beam2d_matrices(l, c, s, L0, ul, th, EA, EI, N_override=None):
    """Internal forces and tangents of Crisfield's co-rotational plane beam.

    Element DOF order: ``(u_a, v_a, θ_a, u_b, v_b, θ_b)``.

    Parameters
    ----------
    l, c, s, L0, ul, th
        From :func:`beam2d_local`.
    EA, EI : ndarray, shape (element,)
    N_override : ndarray, shape (element,), optional
        Use this axial force instead of the one from the local strain (for the prestressed
        reference tangent of a linear buckling analysis).

    Returns
    -------
    f : ndarray, shape (element, 6)
    k : ndarray, shape (element, 6, 6)
    N, M : ndarray, shapes (element,), (element, 2)
        Axial force and end moments (local).

    Notes
    -----
    Local shallow-arch element (Crisfield, *Non-linear Finite Element Analysis of Solids and
    Structures*, vol. 1, §7.4): with the Hermite transverse field of the local end rotations,

    .. math:: \\varepsilon = \\frac{u_l}{L_0} + \\frac{2\\theta_1^2 - \\theta_1\\theta_2
              + 2\\theta_2^2}{30},\\quad N = EA\\,\\varepsilon,\\quad
              M_i = \\frac{EI}{L_0}(4\\theta_i + 2\\theta_j) + \\frac{N L_0}{30}(4\\theta_i
              - \\theta_j)

    and the global forces are ``f = Bᵀ [N, M1, M2]`` with ``B`` the derivative of
    ``(u_l, θ1, θ2)``.  At the reference state the tangent is ``K + Kg`` with the consistent
    geometric stiffness ``N/(30L)[[36, 3L, ...]]`` of the Hermite beam.
    """
    ne = l.shape[0]
    t1, t2 = th[:, 0], th[:, 1]
    eps = ul / L0 + (2 * t1 * t1 - t1 * t2 + 2 * t2 * t2) / 30.0
    N = EA * eps if N_override is None else np.asarray(N_override, dtype=float)
    kb = EI / L0
    M1 = kb * (4 * t1 + 2 * t2) + N * L0 / 30.0 * (4 * t1 - t2)
    M2 = kb * (2 * t1 + 4 * t2) + N * L0 / 30.0 * (4 * t2 - t1)
    # local tangent D = EA L0 g gᵀ + N L0 H + bending, on q = (u_l, θ1, θ2)
    g = np.stack([1.0 / L0, (4 * t1 - t2) / 30.0, (4 * t2 - t1) / 30.0], axis=1)  # (el, 3)
    D = (EA * L0)[:, None, None] * g[:, :, None] * g[:, None, :]
    H = np.array([[0, 0, 0], [0, 4, -1], [0, -1, 4]]) / 30.0
    D = D + (N * L0)[:, None, None] * H[None]
    D[:, 1:, 1:] += kb[:, None, None] * np.array([[4.0, 2.0], [2.0, 4.0]])[None]
    # B: dq = B du   (element, 3, 6)
    zero = np.zeros(ne)
    one = np.ones(ne)
    r = np.stack([-c, -s, zero, c, s, zero], axis=1)            # (el, 6)  d l / d u
    z = np.stack([s, -c, zero, -s, c, zero], axis=1)            # (el, 6)
    dbeta = z / l[:, None]                                      # d β / d u
    B = np.empty((ne, 3, 6))
    B[:, 0] = r
    B[:, 1] = -dbeta
    B[:, 2] = -dbeta
    B[:, 1, 2] += one
    B[:, 2, 5] += one
    q = np.stack([N, M1, M2], axis=1)                           # (el, 3)
    f = np.einsum("eij,ei->ej", B, q)
    k = np.einsum("eij,eik,ekl->ejl", B, D, B)
    # geometric (frame) terms: N d²l/du² + (M1 + M2) d²(-β)/du²
    zz = z[:, :, None] * z[:, None, :]
    rz = r[:, :, None] * z[:, None, :]
    k += (N / l)[:, None, None] * zz
    k += ((M1 + M2) / (l * l))[:, None, None] * (rz + np.transpose(rz, (0, 2, 1)))
    return f, k, N, np.stack([M1, M2], axis=1)


# ----------------------------------------------------------------------------- assembly
def assemble(ndof: int, dofs: np.ndarray, f: np.ndarray, k: np.ndarray | None):
    """Scatter element vectors and matrices into a global vector and sparse matrix.

    Parameters
    ----------
    ndof : int
    dofs : ndarray of int, shape (element, nd)
        Global DOF of each element DOF.
    f : ndarray, shape (element, nd)
    k : ndarray, shape (element, nd, nd) or None

    Returns
    -------
    F : ndarray, shape (ndof,)
    K : scipy.sparse.csr_matrix or None

    Examples
    --------
    >>> F, K = assemble(3, np.array([[0, 1], [1, 2]]), np.ones((2, 2)),
    ...                 np.array([[[1., -1.], [-1., 1.]]] * 2))
    >>> F
    array([1., 2., 1.])
    >>> K.toarray()
    array([[ 1., -1.,  0.],
           [-1.,  2., -1.],
           [ 0., -1.,  1.]])
    """
    F = np.bincount(dofs.ravel(), weights=f.ravel(), minlength=ndof)
    if k is None:
        return F, None
    nd = dofs.shape[1]
    rows = np.repeat(dofs, nd, axis=1).ravel()
    cols = np.tile(dofs, (1, nd)).ravel()
    K = sp.coo_matrix((k.ravel(), (rows, cols)), shape=(ndof, ndof)).tocsr()
    return F, K
