# SPDX-License-Identifier: MIT
"""The forms-assembled element matrices equal the closed-form 12×12 space-frame stiffness,
consistent mass and geometric stiffness (Przemieniecki, Theory of Matrix Structural Analysis,
§5.6, 11.5, 15.3; the same matrices as ``docs/derivations/frame_matrices.py`` derives with
sympy) to round-off, and the sparse transformation rotates them as Rᵀ k R."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.fem import discretise
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

MAT = Material("al", E=7.1e10, G=2.62e10, density=2711.5)
SEC = Section("s", area=3.1e-4, Iy=2.2e-8, Iz=4.7e-8, J=5.5e-8, c=0.02)
ROUND_OFF = 1e-12


def k_closed(L, E, G, A, Iy, Iz, J):
    """Przemieniecki eq. 5.116: DOF order u1 v1 w1 θx1 θy1 θz1 u2 ... θz2."""
    k = np.zeros((12, 12))
    ea, gj = E * A / L, G * J / L
    k[np.ix_([0, 6], [0, 6])] = ea * np.array([[1, -1], [-1, 1]])
    k[np.ix_([3, 9], [3, 9])] = gj * np.array([[1, -1], [-1, 1]])
    bz = E * Iz / L**3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L**2, -6 * L, 2 * L**2],
                                   [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L**2, -6 * L, 4 * L**2]])
    k[np.ix_([1, 5, 7, 11], [1, 5, 7, 11])] = bz
    by = E * Iy / L**3 * np.array([[12, -6 * L, -12, -6 * L],
                                   [-6 * L, 4 * L**2, 6 * L, 2 * L**2],
                                   [-12, 6 * L, 12, 6 * L], [-6 * L, 2 * L**2, 6 * L, 4 * L**2]])
    k[np.ix_([2, 4, 8, 10], [2, 4, 8, 10])] = by
    return k


def m_closed(L, rho, A, Ip):
    """Consistent mass without rotary inertia of bending (Przemieniecki eq. 11.42 with
    r = 0); the twist with the polar moment of area I_p = Iy + Iz."""
    m = np.zeros((12, 12))
    c = rho * A * L
    m[np.ix_([0, 6], [0, 6])] = c / 6 * np.array([[2, 1], [1, 2]])
    m[np.ix_([3, 9], [3, 9])] = rho * Ip * L / 6 * np.array([[2, 1], [1, 2]])
    h = c / 420 * np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                            [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    m[np.ix_([1, 5, 7, 11], [1, 5, 7, 11])] = h
    sgn = np.diag([1, -1, 1, -1])
    m[np.ix_([2, 4, 8, 10], [2, 4, 8, 10])] = sgn @ h @ sgn
    return m


def kg_closed(L, N):
    """Geometric stiffness of a beam-column (Przemieniecki eq. 15.34), both planes."""
    g = N / (30 * L) * np.array([[36, 3 * L, -36, 3 * L], [3 * L, 4 * L**2, -3 * L, -L**2],
                                 [-36, -3 * L, 36, -3 * L], [3 * L, -L**2, -3 * L, 4 * L**2]])
    kg = np.zeros((12, 12))
    kg[np.ix_([1, 5, 7, 11], [1, 5, 7, 11])] = g
    sgn = np.diag([1, -1, 1, -1])
    kg[np.ix_([2, 4, 8, 10], [2, 4, 8, 10])] = sgn @ g @ sgn
    return kg


def _element(direction, L=1.37):
    e = np.asarray(direction, float)
    e /= np.linalg.norm(e)
    s = build_structure([[0.1, -0.2, 0.3], np.array([0.1, -0.2, 0.3]) + L * e], [(0, 1)],
                        section=SEC, material=MAT, is_beam=True)
    fe = discretise(s, subdivisions=1)
    return fe, fe.groups[0], L


def _comp(g, A):
    """Element-component matrix Sᵀ A S (12×12, local axes)."""
    return (g.S.T @ A @ g.S).toarray()


def test_stiffness_equals_closed_form():
    fe, g, L = _element([1, 0, 0])
    k = _comp(g, fe.local_stiffness(g))
    ref = k_closed(L, MAT.E, MAT.G, SEC.area, SEC.Iy, SEC.Iz, SEC.J)
    assert_allclose(k, ref, rtol=ROUND_OFF, atol=ROUND_OFF * abs(ref).max())


def test_mass_equals_closed_form():
    fe, g, L = _element([1, 0, 0])
    m = _comp(g, fe.local_mass(g))
    ref = m_closed(L, MAT.density, SEC.area, SEC.Iy + SEC.Iz)
    assert_allclose(m, ref, rtol=ROUND_OFF, atol=ROUND_OFF * abs(ref).max())


def test_geometric_stiffness_equals_closed_form():
    fe, g, L = _element([1, 0, 0])
    N = -1234.5
    kg = _comp(g, fe.local_geometric_stiffness(g, np.array([N])))
    ref = kg_closed(L, N)
    assert_allclose(kg, ref, rtol=ROUND_OFF, atol=ROUND_OFF * abs(ref).max())


@pytest.mark.parametrize("direction", [[1, 2, 3], [0, 0, 1], [-1, 0.5, 0]])
def test_global_matrices_are_rotated_closed_forms(direction):
    """K = Λᵀ k Λ with Λ = diag(R, R, R, R) (the textbook transformation)."""
    fe, g, L = _element(direction)
    R = fe.rotation[0]
    Lam = np.kron(np.eye(4), R)
    # global DOF order of this model: node translations first, then node rotations
    order = np.r_[fe.node_dofs[0, :3], fe.node_dofs[0, 3:], fe.node_dofs[1, :3],
                  fe.node_dofs[1, 3:]]
    for got, ref in [(fe.stiffness(), k_closed(L, MAT.E, MAT.G, SEC.area, SEC.Iy, SEC.Iz,
                                               SEC.J)),
                     (fe.mass(), m_closed(L, MAT.density, SEC.area, SEC.Iy + SEC.Iz)),
                     (fe.geometric_stiffness(np.array([250.0])), kg_closed(L, 250.0))]:
        G = got.toarray()[np.ix_(order, order)]
        want = Lam.T @ ref @ Lam
        assert_allclose(G, want, rtol=ROUND_OFF, atol=ROUND_OFF * abs(want).max())


def test_truss_bar_mass_and_geometric_stiffness():
    """Truss bar: consistent mass ρAL/6 [[2,1],[1,2]] on every translation, lumped ρAL/2 per
    end, geometric stiffness N/L (I − e eᵀ) (docs/cli.md, ``--bar-model``)."""
    e = np.array([2.0, -1.0, 2.0]) / 3.0
    L = 1.5
    s = build_structure([[0, 0, 0], L * e], [(0, 1)], section=SEC, material=MAT)
    fe = discretise(s)
    rAL = MAT.density * SEC.area * L
    assert_allclose(fe.mass().toarray(), np.kron(rAL / 6 * np.array([[2, 1], [1, 2]]),
                                                 np.eye(3)), rtol=ROUND_OFF,
                    atol=ROUND_OFF * rAL)
    assert_allclose(fe.mass("lumped").toarray(), rAL / 2 * np.eye(6), rtol=ROUND_OFF,
                    atol=ROUND_OFF * rAL)
    N = 800.0
    P = np.eye(3) - np.outer(e, e)
    assert_allclose(fe.geometric_stiffness(np.array([N])).toarray(),
                    N / L * np.kron(np.array([[1, -1], [-1, 1]]), P),
                    rtol=ROUND_OFF, atol=ROUND_OFF * N / L)
    EA = MAT.E * SEC.area
    assert_allclose(fe.stiffness().toarray(),
                    EA / L * np.kron(np.array([[1, -1], [-1, 1]]), np.outer(e, e)),
                    rtol=ROUND_OFF, atol=ROUND_OFF * EA / L)


def test_nodal_masses_and_lumped_frame_mass_total():
    """Total translational mass = Σ ρAL + Σ nodal masses, per direction, for both kinds."""
    s = build_structure([[0, 0, 0], [1, 0, 0], [1, 1, 0]], [(0, 1), (1, 2)], section=SEC,
                        material=MAT, is_beam=True, masses={2: 4.0})
    fe = discretise(s, subdivisions=3)
    total = MAT.density * SEC.area * 2.0 + 4.0
    # a rigid translation in x: every translation DOF (joint: global x; interior: member axes)
    st = np.zeros(fe.n_dof)
    st[fe.node_dofs[:, 0]] = 1.0
    for pt, mem in enumerate(fe.interior_member):
        st[fe.interior_dofs[pt, :3]] = fe.rotation[mem] @ [1.0, 0.0, 0.0]
    for kind in ("consistent", "lumped"):
        M = fe.mass(kind)
        assert_allclose(st @ M @ st, total, rtol=1e-12)


def test_forms_equal_the_sympy_derivation():
    """docs/derivations/frame_matrices.py integrates the shape functions symbolically; the
    forms-assembled matrices agree with it to round-off."""
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "docs" / "derivations" / "frame_matrices.py"
    spec = importlib.util.spec_from_file_location("frame_matrices", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    fe, g, L = _element([1, 0, 0])
    N = 512.0
    K, M, Kg = mod.numeric({"L": L, "E": MAT.E, "G": MAT.G, "A": SEC.area, "Iy": SEC.Iy,
                            "Iz": SEC.Iz, "J": SEC.J, "rho": MAT.density, "N": N})
    for got, want in [(_comp(g, fe.local_stiffness(g)), K), (_comp(g, fe.local_mass(g)), M),
                      (_comp(g, fe.local_geometric_stiffness(g, np.array([N]))), Kg)]:
        assert_allclose(got, want, rtol=ROUND_OFF, atol=ROUND_OFF * abs(want).max())
