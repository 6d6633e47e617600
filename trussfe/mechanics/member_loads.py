# SPDX-License-Identifier: MIT
r"""Loads along a member: equivalent end loads (fixed-end forces) and section forces along it.

One home for the member-load mechanics of every analysis.  A member (or a sub-element of a
subdivided member) of length ``h`` lies on its local axis ``0 <= x <= h``, ``ξ = x/h``.

Shape functions
---------------
Axial displacement, twist and — for a pin-ended bar — the transverse displacements are linear
(P1): ``N = [1 − ξ, ξ]``.  The end loads of a load on a P1 field are those of a simply
supported member: the statically equivalent reactions.

Bending deflection (with DOFs ``[v_a, ψ_a, v_b, ψ_b]``: end deflections and section
rotations, ``ψ = v'`` for ``Φ = 0``) uses the shape functions of the two-node
shear-deformable (Timoshenko) beam with shear parameter
``Φ = 12 EI / (κGA h²)`` (Friedman & Kosmatka 1993, "An improved two-node Timoshenko beam
finite element", Computers & Structures 47); ``Φ = 0`` gives the cubic Hermite
functions of the Euler–Bernoulli beam:

.. math::

   N_1 = \frac{1 − 3ξ² + 2ξ³ + Φ(1 − ξ)}{1 + Φ}, \quad
   N_2 = h\,\frac{ξ − 2ξ² + ξ³ + \tfrac{Φ}{2}(ξ − ξ²)}{1 + Φ}, \\
   N_3 = \frac{3ξ² − 2ξ³ + Φξ}{1 + Φ}, \quad
   N_4 = h\,\frac{−ξ² + ξ³ − \tfrac{Φ}{2}(ξ − ξ²)}{1 + Φ}.

These are the exact deflections of a beam loaded only at its ends, so the element is exact
for end loads and its equivalent end loads ``∫ q N dx`` are the fixed-end forces of the beam
(Betti's theorem): the nodal displacements of a member cut into any number of sub-elements
are exact.  The section rotation is ``ψ = v' + (Φh²/12) v'''`` (the shear strain is
``v' − ψ = −EI ψ''/(κGA)``); a couple acting at a point does work on ``ψ``.

Fixed-end forces
----------------
A load varying linearly from ``q_a`` to ``q_b`` over the whole element:

.. math::

   F_a = h\,\frac{(21 + 20Φ) q_a + (9 + 10Φ) q_b}{60(1 + Φ)}, \quad
   M_a = h²\,\frac{(6 + 5Φ) q_a + (4 + 5Φ) q_b}{120(1 + Φ)}, \\
   F_b = h\,\frac{(9 + 10Φ) q_a + (21 + 20Φ) q_b}{60(1 + Φ)}, \quad
   M_b = −h²\,\frac{(4 + 5Φ) q_a + (6 + 5Φ) q_b}{120(1 + Φ)};

for ``Φ = 0`` and ``q_a = q_b = q``: ``qh/2`` and ``±qh²/12``; for a triangular load
``(q_a, q_b) = (0, q)``: ``3qh/20, qh²/30, 7qh/20, −qh²/20`` (Roark's Formulas for Stress and
Strain, 7th ed., Table 8.1 case 2).  A load on part of an element only, from ``ξ₀`` to ``ξ₁``, gives
``∫ q N_i dx`` over that part: a three-point Gauss–Legendre rule on it is exact (a linear
load times a cubic shape function).  A point force ``P`` at ``ξ``: ``P N_i(ξ)`` — for
``Φ = 0`` the end moments ``Pab²/h²`` and ``−Pa²b/h²`` with ``a = ξh``, ``b = h − a`` (Roark
Table 8.1 case 1).  A couple ``C`` at ``ξ``: ``C ψ_i(ξ)``.  On a P1 field: ``h(2q_a + q_b)/6``,
``h(q_a + 2q_b)/6``; ``P(1 − ξ), Pξ``; a couple on the slope of a transverse P1 field (a
pin-ended bar) ``∓C/h``, while a torque is a load on the twist field itself,
``T(1 − ξ), Tξ``.  ``M`` here is the load on the rotation DOF ``ψ``
of the x–y plane (the rotation about z; in the x–z plane the rotation about y is ``−ψ``, so
the sign changes).

Section forces along a member
-----------------------------
``[N, Vy, Vz, T, My, Mz]`` at a station ``x`` (the resultant on the part before ``x`` exerted
by the part after it, member axes) follows by statics from the section forces ``S₀`` at
``x = 0`` and the loads on ``[0, x]``: with ``Q(x) = ∫₀ˣ q`` and ``Q₁(x) = ∫₀ˣ (x − s) q(s) ds``,

.. math::

   N = N₀ − Q_x, \quad V_y = V_{y0} − Q_y, \quad V_z = V_{z0} − Q_z, \quad T = T₀ − C_x, \\
   M_y = M_{y0} + x V_{z0} − Q_{1z} − C_y, \quad M_z = M_{z0} − x V_{y0} + Q_{1y} − C_z,

where ``Q = q₁y + k y²/2``, ``Q₁ = q₁y²/2 + k y³/6 + (x − c − y) Q`` with
``y = min(max(x, c), d) − c`` and ``k = (q₂ − q₁)/(d − c)`` for a load varying from ``q₁`` at
``c`` to ``q₂`` at ``d`` (``Q = q₁x + (q₂ − q₁)x²/(2L)``, ``Q₁ = q₁x²/2 + (q₂ − q₁)x³/(6L)``
over the whole length, ``c = 0``, ``d = L``); a point load at ``a`` adds ``F`` to ``Q``,
``(x − a)F`` to ``Q₁`` and its couple ``C`` beyond ``a``.  A point load at a station counts as before it
(the section just after the load) except at the end ``x = L``.  For a pin-ended bar
(``M₀ = 0``, ``V₀`` the support reaction) this is the simply supported beam; for a simply
supported beam under ``q``, ``M_z(L/2) = qL²/8``.
"""
from __future__ import annotations

import numpy as np

#: Relative tolerance (of the member length) within which a point load sits at a station.
AT_STATION = 1e-12


def shear_parameter(EI: np.ndarray, GA_shear: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Φ = 12 EI / (κGA h²) of a shear-deformable beam element; 0 where ``GA_shear`` is
    ``nan`` or infinite (an Euler–Bernoulli beam).

    Parameters
    ----------
    EI : ndarray
        Bending stiffness, N·m².
    GA_shear : ndarray
        Shear stiffness κGA = G·A_s (A_s the shear area), N.
    h : ndarray
        Element length, m.

    Examples
    --------
    >>> float(shear_parameter(np.array(2.0), np.array(3.0), np.array(2.0)))
    2.0
    >>> float(shear_parameter(np.array(2.0), np.array(np.nan), np.array(2.0)))
    0.0
    """
    GA = np.asarray(GA_shear, dtype=float)
    ok = np.isfinite(GA) & (GA > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(ok, 12.0 * np.asarray(EI, float) / (np.where(ok, GA, 1.0)
                                                             * np.asarray(h, float) ** 2), 0.0)


def deflection_shapes(xi: np.ndarray, h: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Bending shape functions ``[N₁, N₂, N₃, N₄]`` at ``ξ`` (module notes), shape (..., 4)."""
    x, h, p = (np.asarray(a, dtype=float) for a in (xi, h, phi))
    d = 1.0 + p
    return np.stack([(1 - 3 * x**2 + 2 * x**3 + p * (1 - x)) / d,
                     h * (x - 2 * x**2 + x**3 + 0.5 * p * (x - x**2)) / d,
                     (3 * x**2 - 2 * x**3 + p * x) / d,
                     h * (-x**2 + x**3 - 0.5 * p * (x - x**2)) / d], axis=-1)


def slope_shapes(xi: np.ndarray, h: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Slope ``dN/dx`` of each bending shape function at ``ξ`` (the derivative of
    :func:`deflection_shapes` along the element: the deflection's total slope, bending and
    shear), shape (..., 4).

    Examples
    --------
    >>> xi, h, phi = 0.3, 2.0, 0.4
    >>> fd = (deflection_shapes(xi + 1e-6, h, phi) - deflection_shapes(xi - 1e-6, h, phi))
    >>> bool(np.allclose(slope_shapes(xi, h, phi), fd / (2e-6 * h)))
    True
    """
    x, h, p = (np.asarray(a, dtype=float) for a in (xi, h, phi))
    d = 1.0 + p
    return np.stack([(-6 * x + 6 * x**2 - p) / (h * d),
                     (1 - 4 * x + 3 * x**2 + 0.5 * p * (1 - 2 * x)) / d,
                     (6 * x - 6 * x**2 + p) / (h * d),
                     (-2 * x + 3 * x**2 - 0.5 * p * (1 - 2 * x)) / d], axis=-1)


def rotation_shapes(xi: np.ndarray, h: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Section rotation ``ψ = N' + (Φh²/12) N'''`` of each bending shape function at ``ξ``,
    shape (..., 4): ``[ψ₁, ψ₂, ψ₃, ψ₄]``, which are 0, 1, 0, 0 at ``ξ = 0`` and 0, 0, 0, 1
    at ``ξ = 1``."""
    x, h, p = (np.asarray(a, dtype=float) for a in (xi, h, phi))
    d = 1.0 + p
    return np.stack([6 * (x**2 - x) / (h * d),
                     (1 - 4 * x + 3 * x**2 + p * (1 - x)) / d,
                     6 * (x - x**2) / (h * d),
                     (-2 * x + 3 * x**2 + p * x) / d], axis=-1)


def linear_load_bending(h: np.ndarray, phi: np.ndarray, qa: np.ndarray, qb: np.ndarray
                        ) -> np.ndarray:
    """Fixed-end forces ``[F_a, M_a, F_b, M_b]`` of a load varying linearly from ``qa`` to
    ``qb`` over a bending element (module notes, closed form), shape (..., 4)."""
    h, p, qa, qb = (np.asarray(a, dtype=float) for a in (h, phi, qa, qb))
    d = 1.0 + p
    return np.stack([h * ((21 + 20 * p) * qa + (9 + 10 * p) * qb) / (60 * d),
                     h**2 * ((6 + 5 * p) * qa + (4 + 5 * p) * qb) / (120 * d),
                     h * ((9 + 10 * p) * qa + (21 + 20 * p) * qb) / (60 * d),
                     -h**2 * ((4 + 5 * p) * qa + (6 + 5 * p) * qb) / (120 * d)], axis=-1)


def linear_load_p1(h: np.ndarray, qa: np.ndarray, qb: np.ndarray) -> np.ndarray:
    """End loads ``[h(2qa + qb)/6, h(qa + 2qb)/6]`` of a linearly varying load on a P1 field
    (axial, twist, or the transverse load of a pin-ended bar), shape (..., 2)."""
    h, qa, qb = (np.asarray(a, dtype=float) for a in (h, qa, qb))
    return np.stack([h * (2 * qa + qb) / 6.0, h * (qa + 2 * qb) / 6.0], axis=-1)


#: Three-point Gauss–Legendre rule on [−1, 1]: exact to degree 5 (a linear load times a cubic).
_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(3)


def _gauss_on(xi0: np.ndarray, xi1: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gauss points ``ξ`` (..., 3) on ``[ξ₀, ξ₁]``, their weights as fractions of the element
    length, and the linear weight ``t`` (0 at ``ξ₀``, 1 at ``ξ₁``) of each point."""
    xi0, xi1 = np.asarray(xi0, float)[..., None], np.asarray(xi1, float)[..., None]
    t = 0.5 * (_GAUSS_X + 1.0)
    return xi0 + (xi1 - xi0) * t, 0.5 * (xi1 - xi0) * _GAUSS_W, t


def part_load_bending(h: np.ndarray, phi: np.ndarray, xi0: np.ndarray, xi1: np.ndarray,
                      qa: np.ndarray, qb: np.ndarray) -> np.ndarray:
    """Fixed-end forces ``[F_a, M_a, F_b, M_b]`` of a load varying linearly from ``qa`` at
    ``ξ₀`` to ``qb`` at ``ξ₁`` on the part ``[ξ₀, ξ₁]`` of a bending element,
    ``∫ q N_i dx`` by the Gauss rule of the module notes, shape (..., 4).

    Examples
    --------
    Over the whole element it is the closed form :func:`linear_load_bending`:

    >>> bool(np.allclose(part_load_bending(2.0, 0.3, 0.0, 1.0, 5.0, 7.0),
    ...                  linear_load_bending(2.0, 0.3, 5.0, 7.0)))
    True
    """
    h, p = np.asarray(h, float), np.asarray(phi, float)
    xi, w, t = _gauss_on(xi0, xi1)
    q = np.asarray(qa, float)[..., None] * (1 - t) + np.asarray(qb, float)[..., None] * t
    N = deflection_shapes(xi, h[..., None], p[..., None])                  # (..., 3, 4)
    return h[..., None] * np.einsum("...g,...gi->...i", q * w, N)


def part_load_p1(h: np.ndarray, xi0: np.ndarray, xi1: np.ndarray, qa: np.ndarray,
                 qb: np.ndarray) -> np.ndarray:
    """End loads ``∫ q [1 − ξ, ξ] dx`` of a load varying linearly from ``qa`` at ``ξ₀`` to
    ``qb`` at ``ξ₁`` on the part ``[ξ₀, ξ₁]`` of a P1 field, shape (..., 2).

    Examples
    --------
    A uniform 6 N/m on the last quarter of a 4 m bar: 6 N at 7/8 of its length.

    >>> part_load_p1(4.0, 0.75, 1.0, 6.0, 6.0).tolist()
    [0.75, 5.25]
    """
    h = np.asarray(h, float)
    xi, w, t = _gauss_on(xi0, xi1)
    q = np.asarray(qa, float)[..., None] * (1 - t) + np.asarray(qb, float)[..., None] * t
    qw = h[..., None] * q * w
    return np.stack([np.sum(qw * (1 - xi), axis=-1), np.sum(qw * xi, axis=-1)], axis=-1)


def point_load_bending(xi: np.ndarray, h: np.ndarray, phi: np.ndarray, P: np.ndarray,
                       C: np.ndarray) -> np.ndarray:
    """Fixed-end forces ``P N_i(ξ) + C ψ_i(ξ)`` of a point force ``P`` and a couple ``C``
    (conjugate to ``v'``) at ``ξ``, shape (..., 4)."""
    P, C = np.asarray(P, float)[..., None], np.asarray(C, float)[..., None]
    return P * deflection_shapes(xi, h, phi) + C * rotation_shapes(xi, h, phi)


def point_load_p1(xi: np.ndarray, h: np.ndarray, P: np.ndarray, C: np.ndarray) -> np.ndarray:
    """End loads ``[P(1 − ξ) − C/h, Pξ + C/h]`` of a point force and couple on a P1 field,
    shape (..., 2)."""
    xi, h, P, C = (np.asarray(a, dtype=float) for a in (xi, h, P, C))
    return np.stack([P * (1 - xi) - C / h, P * xi + C / h], axis=-1)


def resultant(L: np.ndarray, q1: np.ndarray, q2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Resultant ``(q₁ + q₂)L/2`` of a linearly varying load and its position from the start,
    ``L(q₁ + 2q₂)/(3(q₁ + q₂))`` (the centroid of the trapezoid; ``nan`` for a zero
    resultant), per component.

    Examples
    --------
    >>> R, x = resultant(np.array(3.0), np.array(200.0), np.array(600.0))
    >>> float(R), float(x)
    (1200.0, 1.75)
    """
    L, q1, q2 = (np.asarray(a, dtype=float) for a in (L, q1, q2))
    R = 0.5 * (q1 + q2) * L
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.where(q1 + q2 != 0, L * (q1 + 2 * q2) / (3 * (q1 + q2)), np.nan)
    return R, x


def span_integrals(x: np.ndarray, c: np.ndarray, d: np.ndarray, q1: np.ndarray,
                   q2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``Q(x) = ∫₀ˣ q`` and ``Q₁(x) = ∫₀ˣ (x − s) q(s) ds`` of loads varying linearly from
    ``q1`` at ``c`` to ``q2`` at ``d`` (zero outside ``[c, d]``; module notes).

    Parameters
    ----------
    x : ndarray, shape (l, s)
        Stations of each load's member.
    c, d : ndarray, shape (l,)
        Span of each load, m from the start node.
    q1, q2 : ndarray, shape (l, 3)

    Returns
    -------
    Q, Q1 : ndarray, shape (l, s, 3)

    Examples
    --------
    A uniform 2 N/m on [1, 3] m of a member: 4 N beyond it, acting 2 m before x = 4 m.

    >>> Q, Q1 = span_integrals(np.array([[4.0]]), np.array([1.0]), np.array([3.0]),
    ...                        np.array([[2.0, 0, 0]]), np.array([[2.0, 0, 0]]))
    >>> float(Q[0, 0, 0]), float(Q1[0, 0, 0])
    (4.0, 8.0)
    """
    x = np.asarray(x, dtype=float)
    c = np.asarray(c, float)[:, None]
    d = np.asarray(d, float)[:, None]
    y = (np.clip(x, c, d) - c)[..., None]                          # covered length before x
    k = ((q2 - q1) / (d - c))[:, None, :]
    qa = q1[:, None, :]
    Q = qa * y + k * y**2 / 2
    # the part of the span before x acts on the lever x − s: its own moment about its end
    # c + y plus Q times the distance beyond it (no cancellation inside the span)
    Q1 = (x - c)[..., None] - y
    Q1 = Q1 * Q + qa * y**2 / 2 + k * y**3 / 6
    return Q, Q1


def section_forces_along(x: np.ndarray, L: np.ndarray, start: np.ndarray,
                         row: np.ndarray, point: np.ndarray, q1: np.ndarray, q2: np.ndarray,
                         a: np.ndarray, F: np.ndarray, C: np.ndarray,
                         span: np.ndarray | None = None) -> np.ndarray:
    """Section forces at stations along members from their start sections and their loads.

    Parameters
    ----------
    x : ndarray, shape (r, s)
        Stations of each of ``r`` members (NaN padding allowed).
    L : ndarray, shape (r,)
        Member lengths.
    start : ndarray, shape (r, 6)
        Section forces ``[N, Vy, Vz, T, My, Mz]`` at ``x = 0``.
    row : ndarray of int, shape (l,)
        Member (row of ``x``) of each load.
    point : ndarray of bool, shape (l,)
        Point loads; the others vary linearly from ``q1`` to ``q2`` over their span.
    q1, q2, F : ndarray, shape (l, 3)
        Intensities and point forces, member axes.
    a : ndarray, shape (l,)
        Position of a point load, m from the start.
    C : ndarray, shape (l, 3)
        Point couples about the member axes.
    span : ndarray, shape (l, 2), optional
        Span of each distributed load, m from the start (default: the whole member).

    Returns
    -------
    ndarray, shape (r, s, 6)
        The formulas of the module notes.
    """
    x = np.asarray(x, dtype=float)
    S0 = np.asarray(start, dtype=float)
    out = np.empty(x.shape + (6,))
    out[...] = S0[:, None, :]
    out[..., 4] += x * S0[:, None, 2]
    out[..., 5] -= x * S0[:, None, 1]
    xl = x[row]                                                    # (l, s)
    Lr = np.asarray(L, float)[row]
    Ll = Lr[:, None]
    if span is None:
        span = np.stack([np.zeros_like(Lr), Lr], axis=1)
    Q, Q1 = span_integrals(xl, span[:, 0], span[:, 1], q1, q2)
    al = np.asarray(a, float)[:, None]
    tol = AT_STATION * Ll
    beyond = (xl > al + tol) | ((np.abs(xl - al) <= tol) & (xl < Ll - tol))
    Qp = np.where(beyond[..., None], F[:, None, :], 0.0)
    Q1p = np.where(beyond[..., None], (xl - al)[..., None] * F[:, None, :], 0.0)
    Cp = np.where(beyond[..., None], C[:, None, :], 0.0)
    pt = np.asarray(point, bool)[:, None, None]
    Q = np.where(pt, Qp, Q)
    Q1 = np.where(pt, Q1p, Q1)
    Cp = np.where(pt, Cp, 0.0)
    d = np.zeros(xl.shape + (6,))
    d[..., 0] = -Q[..., 0]
    d[..., 1] = -Q[..., 1]
    d[..., 2] = -Q[..., 2]
    d[..., 3] = -Cp[..., 0]
    d[..., 4] = -Q1[..., 2] - Cp[..., 1]
    d[..., 5] = Q1[..., 1] - Cp[..., 2]
    np.add.at(out, np.asarray(row, dtype=np.int64), np.nan_to_num(d))
    return out
