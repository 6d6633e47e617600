# SPDX-License-Identifier: MIT
"""Co-rotational 3-D beam element, vectorised over all elements.

The element follows Battini & Pacoste (*Co-rotational beam elements with warping effects in
instability problems*, CMAME 191, 2002, §3) and Crisfield (*Non-linear Finite Element Analysis
of Solids and Structures*, vol. 2, ch. 17):

* the **element frame** ``R_r = [r1 r2 r3]`` follows the chord (``r1``) and the mean of the
  end triads' second axes (``q``): ``r3 = r1 × q / |r1 × q|``, ``r2 = r3 × r1``;
* the **local deformations** are the elongation ``ū = l − L0`` and the end rotations relative
  to the frame, ``θ̄ᵢ = log(R_rᵀ Rᵢ R_0)`` (``R_0`` the element's reference axes, ``Rᵢ`` the
  total rotation of end ``i``);
* the **local element** is the small-strain Euler–Bernoulli beam with axial force, torsion and
  bending in the two planes, enriched with the "shallow-arch" strain of the Hermite transverse
  fields so that its tangent at the reference state is ``K + K_g`` with the consistent
  geometric stiffness (the 3-D analogue of :func:`~trussfe.nonlinear.elements.beam2d_matrices`);
* the **global variations** are the translations and the *spatial spins* ``δwᵢ``
  (``δRᵢ = S(δwᵢ) Rᵢ``); rotations are updated multiplicatively (:func:`compose`).

Array axes are documented as ``# (element, ...)``; there is no Python loop over elements.
Element DOF order: ``(u_a, w_a, u_b, w_b)`` — 3 translations and 3 spin components per end,
global components.

Notation
--------
``S(v)`` skew matrix (``S(v) x = v × x``), ``Tₛ(θ)`` the tangent operator of the rotation
vector (``δw = Tₛ(θ) δθ``), ``N`` axial force (tension positive), ``m_a, m_b`` local end moments
conjugate to ``θ̄_a, θ̄_b``.
"""
from __future__ import annotations

import numpy as np

from ..mechanics.geometry import frame_rotations, member_vectors, unit_vectors

_EYE = np.eye(3)


# ------------------------------------------------------------------------- rotations
def skew(v: np.ndarray) -> np.ndarray:
    """Skew matrices ``S(v)`` with ``S(v) x = v × x``; ``v`` of shape (..., 3).

    >>> skew(np.array([1.0, 2.0, 3.0])) @ np.array([0.0, 0.0, 1.0])
    array([ 2., -1.,  0.])
    """
    v = np.asarray(v, dtype=float)
    S = np.zeros(v.shape[:-1] + (3, 3))
    S[..., 0, 1], S[..., 0, 2] = -v[..., 2], v[..., 1]
    S[..., 1, 0], S[..., 1, 2] = v[..., 2], -v[..., 0]
    S[..., 2, 0], S[..., 2, 1] = -v[..., 1], v[..., 0]
    return S


def expm_so3(psi: np.ndarray) -> np.ndarray:
    """Rotation matrices of rotation vectors (Rodrigues' formula), shape (..., 3, 3).

    .. math:: R = I + \\frac{\\sin\\alpha}{\\alpha} S + \\frac{1 - \\cos\\alpha}{\\alpha^2} S^2,
              \\quad \\alpha = |\\psi|

    (Crisfield vol. 2, eq. 16.15), with Taylor series below α = 1e-4.

    >>> R = expm_so3(np.array([0.0, 0.0, np.pi / 2]))
    >>> np.round(R @ np.array([1.0, 0.0, 0.0]), 12) + 0.0
    array([0., 1., 0.])
    """
    psi = np.asarray(psi, dtype=float)
    a2 = np.sum(psi * psi, axis=-1)
    a = np.sqrt(a2)
    small = a < 1e-4
    with np.errstate(divide="ignore", invalid="ignore"):
        c1 = np.where(small, 1.0 - a2 / 6.0 + a2 * a2 / 120.0, np.sin(a) / a)
        c2 = np.where(small, 0.5 - a2 / 24.0 + a2 * a2 / 720.0, (1.0 - np.cos(a)) / a2)
    S = skew(psi)
    return _EYE + c1[..., None, None] * S + c2[..., None, None] * (S @ S)


def logm_so3(R: np.ndarray) -> np.ndarray:
    """Rotation vectors (|ψ| ≤ π) of rotation matrices, shape (..., 3).

    Through the unit quaternion (Spurrier's algorithm: the largest of the trace and the
    diagonal picks the stable formula), ``ψ = 2 atan2(|v|, w) v/|v|`` — accurate near 0 and π.

    >>> psi = np.array([0.3, -1.2, 2.0])
    >>> bool(np.allclose(logm_so3(expm_so3(psi)), psi, rtol=1e-14, atol=1e-14))
    True
    """
    R = np.asarray(R, dtype=float)
    tr = np.trace(R, axis1=-2, axis2=-1)
    diag = np.stack([R[..., 0, 0], R[..., 1, 1], R[..., 2, 2]], axis=-1)
    which = np.argmax(np.concatenate([tr[..., None], diag], axis=-1), axis=-1)
    q = np.empty(R.shape[:-2] + (4,))                  # (..., [w, x, y, z])
    # trace largest
    w = 0.5 * np.sqrt(np.maximum(1.0 + tr, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = np.stack([w, (R[..., 2, 1] - R[..., 1, 2]) / (4 * w),
                       (R[..., 0, 2] - R[..., 2, 0]) / (4 * w),
                       (R[..., 1, 0] - R[..., 0, 1]) / (4 * w)], axis=-1)
        q[:] = t0
        for i in range(3):                              # three formulas, not a loop over data
            j, k = (i + 1) % 3, (i + 2) % 3
            qi = 0.5 * np.sqrt(np.maximum(1.0 + 2.0 * R[..., i, i] - tr, 0.0))
            qq = np.empty_like(q)
            qq[..., 0] = (R[..., k, j] - R[..., j, k]) / (4 * qi)
            qq[..., 1 + i] = qi
            qq[..., 1 + j] = (R[..., j, i] + R[..., i, j]) / (4 * qi)
            qq[..., 1 + k] = (R[..., k, i] + R[..., i, k]) / (4 * qi)
            sel = which == i + 1
            q[sel] = qq[sel]
    # w ≥ 0 picks the rotation angle in [0, π]
    q *= np.where(q[..., :1] < 0, -1.0, 1.0)
    v = q[..., 1:]
    s = np.linalg.norm(v, axis=-1)
    ang = 2.0 * np.arctan2(s, q[..., 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(s < 1e-12, 2.0, ang / s)
    return f[..., None] * v


def unwrap_rotation(psi: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """Among the rotation vectors ``e(α + 2πk)`` of the rotation ``psi``, the one nearest
    ``ref`` — so that stored total rotations stay continuous beyond |ψ| = π.

    >>> round(float(unwrap_rotation(np.array([0.0, 0.0, -3.0]), np.array([0.0, 0.0, 3.1]))[2]), 6)
    3.283185
    """
    a = np.linalg.norm(psi, axis=-1)
    ar = np.linalg.norm(ref, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        e = np.where((a > 1e-12)[..., None], psi / a[..., None],
                     np.where((ar > 1e-12)[..., None], ref / ar[..., None], 0.0))
    k = np.round((np.sum(ref * e, axis=-1) - a) / (2.0 * np.pi))
    return e * (a + 2.0 * np.pi * k)[..., None]


def compose(psi: np.ndarray, spin: np.ndarray) -> np.ndarray:
    """Multiplicative update of total rotations: ``exp(ψ') = exp(S(δw)) exp(ψ)``.

    Parameters
    ----------
    psi : ndarray, shape (..., 3)
        Total rotation vectors.
    spin : ndarray, shape (..., 3)
        Spatial spin increments δw (global components).

    Returns
    -------
    ndarray, shape (..., 3)
        The new total rotation vectors, continuous with ``psi``.

    >>> p = compose(np.array([0.0, 0.0, 3.0]), np.array([0.0, 0.0, 0.5]))
    >>> round(float(p[2]), 12)
    3.5
    """
    R = expm_so3(spin) @ expm_so3(psi)
    return unwrap_rotation(logm_so3(R), psi)


def _eta_mu(a: np.ndarray):
    """Coefficients of ``Tₛ⁻¹(θ) = I − S/2 + η S²`` and ``μ = η'(α)/α`` (Battini 2002)."""
    a2 = a * a
    small = a < 0.05
    with np.errstate(divide="ignore", invalid="ignore"):
        h = 0.5 * a
        eta = np.where(small, 1.0 / 12.0 + a2 / 720.0 + a2 * a2 / 30240.0,
                       (1.0 - h / np.tan(h)) / a2)
        s2 = np.sin(h) ** 2
        mu = np.where(small, 1.0 / 360.0 + a2 / 7560.0 + a2 * a2 / 201600.0,
                      (a * (a + np.sin(a)) - 8.0 * s2) / (4.0 * a2 * a2 * s2))
    return eta, mu


def inverse_tangent(theta: np.ndarray) -> np.ndarray:
    """``Tₛ⁻¹(θ) = I − ½S(θ) + η S(θ)²`` (so that ``δθ = Tₛ⁻¹ δw``), shape (..., 3, 3).

    >>> bool(np.allclose(inverse_tangent(np.zeros(3)), np.eye(3)))
    True
    """
    a = np.linalg.norm(theta, axis=-1)
    eta, _ = _eta_mu(a)
    S = skew(theta)
    return _EYE - 0.5 * S + eta[..., None, None] * (S @ S)


def tangent_operator(psi: np.ndarray) -> np.ndarray:
    """``Tₛ(ψ) = I + c₁ S(ψ) + c₂ S(ψ)²`` with ``c₁ = (1 − cos α)/α²``, ``c₂ = (α − sin α)/α³``:
    the spin of an additive increment of the rotation vector, ``δw = Tₛ(ψ) δψ``
    (Crisfield vol. 2 eq. 16.39; Battini 2002 eq. 7), shape (..., 3, 3).

    >>> bool(np.allclose(tangent_operator(np.array([0.2, 0.1, -0.4]))
    ...                  @ inverse_tangent(np.array([0.2, 0.1, -0.4])), np.eye(3)))
    True
    """
    c1, c2, _, _ = _c12(np.linalg.norm(psi, axis=-1))
    S = skew(psi)
    return _EYE + c1[..., None, None] * S + c2[..., None, None] * (S @ S)


def _c12(a: np.ndarray):
    """``c₁, c₂`` of :func:`tangent_operator` and ``c₁'/α, c₂'/α`` (series below α = 0.05)."""
    a2 = a * a
    small = a < 0.05
    with np.errstate(divide="ignore", invalid="ignore"):
        s, c = np.sin(a), np.cos(a)
        c1 = np.where(small, 0.5 - a2 / 24.0 + a2 * a2 / 720.0, (1.0 - c) / a2)
        c2 = np.where(small, 1.0 / 6.0 - a2 / 120.0 + a2 * a2 / 5040.0, (a - s) / (a2 * a))
        d1 = np.where(small, -1.0 / 12.0 + a2 / 180.0 - a2 * a2 / 6720.0,
                      (s / a2 - 2.0 * (1.0 - c) / (a2 * a)) / a)
        d2 = np.where(small, -1.0 / 60.0 + a2 / 1260.0 - a2 * a2 / 60480.0,
                      ((1.0 - c) / (a2 * a) - 3.0 * (a - s) / (a2 * a2)) / a)
    return c1, c2, d1, d2


def tangent_operator_derivative(psi: np.ndarray, m: np.ndarray) -> np.ndarray:
    """``∂(Tₛ(ψ)ᵀ m)/∂ψ`` with ``m`` held, shape (..., 3, 3).

    ``Tₛᵀ m = m − c₁ ψ×m + c₂[(ψ·m)ψ − α² m]``, differentiated with ``∇cᵢ = (cᵢ'/α) ψ``.
    """
    a = np.linalg.norm(psi, axis=-1)
    c1, c2, d1, d2 = _c12(a)
    pm = np.sum(psi * m, axis=-1)
    outer = lambda x, y: x[..., :, None] * y[..., None, :]
    S2m = pm[..., None] * psi - (a * a)[..., None] * m
    return (c1[..., None, None] * skew(m) - d1[..., None, None] * outer(np.cross(psi, m), psi)
            + c2[..., None, None] * (outer(psi, m) + pm[..., None, None] * _EYE
                                     - 2.0 * outer(m, psi))
            + d2[..., None, None] * outer(S2m, psi))


def _kh(theta: np.ndarray, m: np.ndarray, Tinv: np.ndarray) -> np.ndarray:
    """``∂(Tₛ⁻ᵀ(θ) m)/∂θ · Tₛ⁻¹(θ)`` with ``m`` held (Battini 2002, the matrix K_h).

    ``Tₛ⁻ᵀ m = m + ½ θ×m + η[(θ·m)θ − α² m]``, differentiated with ``∇η = μ θ``.
    """
    a = np.linalg.norm(theta, axis=-1)
    eta, mu = _eta_mu(a)
    tm = np.sum(theta * m, axis=-1)
    S2m = tm[..., None] * theta - (a * a)[..., None] * m           # S(θ)² m
    outer = lambda x, y: x[..., :, None] * y[..., None, :]
    D = (eta[..., None, None] * (outer(theta, m) - 2.0 * outer(m, theta)
                                 + tm[..., None, None] * _EYE)
         + mu[..., None, None] * outer(S2m, theta) - 0.5 * skew(m))
    return D @ Tinv


# ----------------------------------------------------------------------------- frames
def reference_frames(X: np.ndarray, conn: np.ndarray, orientation: np.ndarray) -> np.ndarray:
    """Reference axes of the elements as columns ``[e1 e2 e3]``, shape (element, 3, 3).

    ``e1`` along the chord; ``e2`` from the member's orientation vector, else global z (or
    global x for an element along z) — :func:`trussfe.mechanics.geometry.frame_rotations`, so
    that ``Iy``/``Iz`` refer to the same axes in the linear and the nonlinear analysis.

    Parameters
    ----------
    X : ndarray, shape (point, 3)
    conn : ndarray of int, shape (element, 2)
    orientation : ndarray, shape (element, 3)
        A vector in the local x–y plane; ``nan`` rows take the default.
    """
    e1, _ = unit_vectors(member_vectors(X, conn))
    return np.swapaxes(frame_rotations(e1, orientation), -1, -2)


# ----------------------------------------------------------------------------- element
def beam3d_matrices(x: np.ndarray, conn: np.ndarray, Ra: np.ndarray, Rb: np.ndarray,
                    R0: np.ndarray, L0: np.ndarray, EA, GJ, EIy, EIz,
                    N_override=None, tangent: bool = True):
    """Internal forces and consistent tangents of co-rotational 3-D beams.

    Parameters
    ----------
    x : ndarray, shape (point, 3)
        Current point positions.
    conn : ndarray of int, shape (element, 2)
    Ra, Rb : ndarray, shape (element, 3, 3)
        Total rotations of the element ends (identity at the reference state).
    R0 : ndarray, shape (element, 3, 3)
        Reference element axes as columns (:func:`reference_frames`).
    L0 : ndarray, shape (element,)
    EA, GJ, EIy, EIz : ndarray, shape (element,)
    N_override : ndarray, shape (element,), optional
        Axial force to use instead of the one of the local strain (prestressed reference
        tangent of a linear buckling analysis).
    tangent : bool

    Returns
    -------
    f : ndarray, shape (element, 12)
        Global internal forces, order ``(u_a, w_a, u_b, w_b)``.
    k : ndarray, shape (element, 12, 12) or None
        Consistent tangent ``∂f/∂(u, w)`` (spin variations; not symmetric away from
        equilibrium).
    N : ndarray, shape (element,)
    m : ndarray, shape (element, 2, 3)
        Local end moments (twist, about y, about z) conjugate to ``θ̄_a, θ̄_b``.

    Notes
    -----
    Local element on ``p = (ū, θ̄_a, θ̄_b)``:

    .. math:: \\varepsilon = \\frac{\\bar u}{L_0} + \\sum_{y,z}
              \\frac{2\\bar\\theta_a^2 - \\bar\\theta_a\\bar\\theta_b + 2\\bar\\theta_b^2}{30},
              \\quad N = EA\\,\\varepsilon,\\quad T = \\frac{GJ}{L_0}
              (\\bar\\theta_{bx} - \\bar\\theta_{ax}),

    .. math:: m_{a} = \\frac{EI}{L_0}(4\\bar\\theta_a + 2\\bar\\theta_b)
              + \\frac{N L_0}{30}(4\\bar\\theta_a - \\bar\\theta_b)\\ \\text{(each plane)}.

    Variations (Battini & Pacoste 2002, eqs. 13–30): ``δū = r1·(δu_b − δu_a)``; local spins
    ``δw̄ᵢ = R_rᵀ(δwᵢ − δw_r)`` with the frame spin ``δw_r = Σ r_k ω_k``,

    .. math:: \\omega_2 = -\\frac{r_3\\cdot\\Delta\\delta u}{l},\\quad
              \\omega_3 = \\frac{r_2\\cdot\\Delta\\delta u}{l},\\quad
              \\omega_1 = \\frac{q_1}{q_2}\\omega_2
              + \\sum_i \\frac{(q_i\\times r_3)\\cdot\\delta w_i}{2 q_2}

    (from ``r3 · q = 0``), and ``δθ̄ᵢ = Tₛ⁻¹(θ̄ᵢ) δw̄ᵢ``.  Then ``f = Bᵀ f_a`` with
    ``f_a = (N, Tₛ⁻ᵀm_a, Tₛ⁻ᵀm_b)`` and ``k = Bᵀ K_a B + K_σ``: ``K_a`` the local tangent
    mapped by ``Tₛ⁻¹`` plus ``K_h``, ``K_σ`` the derivative of ``Bᵀ`` at fixed ``f_a`` (the
    chord term ``N/l (I − r1r1ᵀ)``, the rotation of the end moments with the frame, and the
    second derivatives of the frame spin).
    """
    ne = len(conn)
    EA, GJ, EIy, EIz = (np.broadcast_to(np.asarray(v, dtype=float), (ne,))
                        for v in (EA, GJ, EIy, EIz))
    r1, l = unit_vectors(member_vectors(x, conn))                   # (el, 3), (el,)
    Ta = Ra @ R0                                                    # (el, 3, 3) end triads
    Tb = Rb @ R0
    qa, qb = Ta[:, :, 1], Tb[:, :, 1]
    q = 0.5 * (qa + qb)
    r3 = np.cross(r1, q)
    r3 /= np.linalg.norm(r3, axis=1)[:, None]
    r2 = np.cross(r3, r1)
    Rr = np.stack([r1, r2, r3], axis=2)                             # (el, 3, 3) columns
    RrT = np.transpose(Rr, (0, 2, 1))
    tha = logm_so3(RrT @ Ta)                                        # (el, 3) local rotations
    thb = logm_so3(RrT @ Tb)
    ul = (l * l - L0 * L0) / (l + L0)                               # l − L0, round-off safe

    # ---- local element on p = (ū, θ̄a, θ̄b)
    ay, az, by, bz = tha[:, 1], tha[:, 2], thb[:, 1], thb[:, 2]
    eps = (ul / L0 + (2 * ay * ay - ay * by + 2 * by * by) / 30.0
           + (2 * az * az - az * bz + 2 * bz * bz) / 30.0)
    N = EA * eps if N_override is None else np.asarray(N_override, dtype=float)
    NL = N * L0 / 30.0
    ky, kz, kt = EIy / L0, EIz / L0, GJ / L0
    tors = kt * (thb[:, 0] - tha[:, 0])
    ma = np.stack([-tors, ky * (4 * ay + 2 * by) + NL * (4 * ay - by),
                   kz * (4 * az + 2 * bz) + NL * (4 * az - bz)], axis=1)
    mb = np.stack([tors, ky * (2 * ay + 4 * by) + NL * (4 * by - ay),
                   kz * (2 * az + 4 * bz) + NL * (4 * bz - az)], axis=1)
    Tia = inverse_tangent(tha)                                      # (el, 3, 3)
    Tib = inverse_tangent(thb)
    mta = np.einsum("eji,ej->ei", Tia, ma)                          # Tₛ⁻ᵀ m (local spin)
    mtb = np.einsum("eji,ej->ei", Tib, mb)

    # ---- gradients (el, 12) of l and of the frame spin components ω_k
    z3 = np.zeros((ne, 3))
    gl = np.concatenate([-r1, z3, r1, z3], axis=1)
    Om2 = np.concatenate([r3, z3, -r3, z3], axis=1) / l[:, None]
    Om3 = np.concatenate([-r2, z3, r2, z3], axis=1) / l[:, None]
    q1 = np.sum(q * r1, axis=1)
    q2 = np.sum(q * r2, axis=1)
    eq = q1 / q2
    ca = np.cross(qa, r3) / (2 * q2)[:, None]
    cb = np.cross(qb, r3) / (2 * q2)[:, None]
    Om1 = eq[:, None] * Om2 + np.concatenate([z3, ca, z3, cb], axis=1)
    Om = np.stack([Om1, Om2, Om3], axis=1)                          # (el, 3, 12)
    # B (el, 7, 12): rows ū, local spins of end a (3), of end b (3)
    B = np.zeros((ne, 7, 12))
    B[:, 0] = gl
    B[:, 1:4, 3:6] = RrT
    B[:, 4:7, 9:12] = RrT
    B[:, 1:4] -= Om
    B[:, 4:7] -= Om
    fa = np.concatenate([N[:, None], mta, mtb], axis=1)             # (el, 7)
    f = np.einsum("eij,ei->ej", B, fa)
    m = np.stack([ma, mb], axis=1)
    if not tangent:
        return f, None, N, m

    # ---- local tangent D (el, 7, 7) on p, then K_a on (ū, local spins)
    g = np.zeros((ne, 7))
    g[:, 0] = 1.0 / L0
    g[:, 2], g[:, 5] = (4 * ay - by) / 30.0, (4 * by - ay) / 30.0
    g[:, 3], g[:, 6] = (4 * az - bz) / 30.0, (4 * bz - az) / 30.0
    D = (EA * L0)[:, None, None] * g[:, :, None] * g[:, None, :]
    for (i, j), kk in (((2, 5), ky), ((3, 6), kz)):                 # two bending planes
        D[:, i, i] += 4 * kk + 4 * NL
        D[:, j, j] += 4 * kk + 4 * NL
        D[:, i, j] += 2 * kk - NL
        D[:, j, i] += 2 * kk - NL
    D[:, 1, 1] += kt
    D[:, 4, 4] += kt
    D[:, 1, 4] -= kt
    D[:, 4, 1] -= kt
    Bt = np.zeros((ne, 7, 7))
    Bt[:, 0, 0] = 1.0
    Bt[:, 1:4, 1:4] = Tia
    Bt[:, 4:7, 4:7] = Tib
    Ka = np.einsum("eji,ejk,ekl->eil", Bt, D, Bt)
    Ka[:, 1:4, 1:4] += _kh(tha, ma, Tia)
    Ka[:, 4:7, 4:7] += _kh(thb, mb, Tib)
    k = np.einsum("eji,ejk,ekl->eil", B, Ka, B)

    # ---- K_σ: derivative of Bᵀ at fixed f_a
    outer = lambda a, b: a[:, :, None] * b[:, None, :]
    A = _EYE[None] - outer(r1, r1)
    NA = (N / l)[:, None, None] * A
    for (i, j), s in (((0, 0), 1.0), ((0, 6), -1.0), ((6, 0), -1.0), ((6, 6), 1.0)):
        k[:, i:i + 3, j:j + 3] += s * NA
    # end moments turn with the frame: δ(R_r m̃ᵢ) = δw_r × Mᵢ = −S(Mᵢ) R_r Ω δd
    dwr = np.einsum("eik,ekj->eij", Rr, Om)                         # (el, 3, 12) δw_r
    for sl, mt in ((3, mta), (9, mtb)):
        M = np.einsum("eij,ej->ei", Rr, mt)
        k[:, sl:sl + 3, :] -= np.einsum("eij,ejk->eik", skew(M), dwr)
    # frame-spin second derivatives: −Σ m̄_k δΩ_k, m̄ = m̃a + m̃b
    mbar = mta + mtb
    sel = np.concatenate([-_EYE, np.zeros((3, 3)), _EYE, np.zeros((3, 3))])   # (12, 3)
    dr2 = (outer(r3, Om1) - outer(r1, Om3)) / l[:, None, None] \
        - outer(r2, gl) / (l * l)[:, None, None]                    # δ(r2/l), (el, 3, 12)
    dr3 = (outer(r1, Om2) - outer(r2, Om1)) / l[:, None, None] \
        - outer(r3, gl) / (l * l)[:, None, None]                    # δ(r3/l)
    dOm3 = np.einsum("ai,eij->eaj", sel, dr2)
    dOm2 = -np.einsum("ai,eij->eaj", sel, dr3)
    # δq = Jq δd, Jq = [0, −½S(qa), 0, −½S(qb)]
    Jq = np.zeros((ne, 3, 12))
    Jq[:, :, 3:6] = -0.5 * skew(qa)
    Jq[:, :, 9:12] = -0.5 * skew(qb)
    dq1 = np.einsum("ei,eij->ej", r1, Jq) + q2[:, None] * Om3
    dq2 = np.einsum("ei,eij->ej", r2, Jq) - q1[:, None] * Om3
    deq = dq1 / q2[:, None] - (q1 / (q2 * q2))[:, None] * dq2
    dr3v = outer(r1, Om2) - outer(r2, Om1)                          # δr3, (el, 3, 12)
    dOm1 = outer(Om2, deq) + eq[:, None, None] * dOm2
    for sl, qi, ci in ((3, qa, ca), (9, qb, cb)):
        Ei = np.zeros((ne, 3, 12))
        Ei[:, :, sl:sl + 3] = -skew(qi)                             # δqᵢ = −S(qᵢ) Eᵢ δd
        dci = (np.einsum("eij,ejk->eik", -skew(r3), Ei)             # δqᵢ × r3 = −S(r3) δqᵢ
               + np.einsum("eij,ejk->eik", skew(qi), dr3v)) / (2 * q2)[:, None, None] \
            - outer(ci, dq2) / q2[:, None, None]
        dOm1[:, sl:sl + 3, :] += dci
    k -= (mbar[:, 0, None, None] * dOm1 + mbar[:, 1, None, None] * dOm2
          + mbar[:, 2, None, None] * dOm3)
    return f, k, N, m
