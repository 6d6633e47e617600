# SPDX-License-Identifier: MIT
"""Mass and geometric stiffness used end to end: Euler buckling of a pinned column and the
first bending frequency of a pinned member, against their classical closed forms."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
from numpy.testing import assert_allclose

from trussfe.fem import discretise, solve_static
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

AL = Material("al", E=7.1e10, G=2.62e10, density=2711.5)
TUBE = Section.tube("tube", 0.01905, 0.016)
L = 0.889


def _column():
    return build_structure([[0.0, 0.0], [L, 0.0]], [(0, 1)], section=TUBE, material=AL,
                           supports={0: "xy", 1: "y"}, loads={1: [-1000.0, 0.0]})


def _buckling_load(k):
    s = _column()
    r = solve_static(s, bar_model="pinned-beam", subdivisions=k)
    assert_allclose(r.element_axial_force, -1000.0, rtol=1e-10)
    fe = r.fe
    K = fe.stiffness().toarray()[np.ix_(fe.free, fe.free)]
    Kg = fe.geometric_stiffness(r.element_axial_force).toarray()[np.ix_(fe.free, fe.free)]
    # K φ = λ (−K_g) φ with −K_g only semi-definite: solve −K_g φ = μ K φ, λ = 1/μ_max
    mu = sla.eigh(-Kg, K, eigvals_only=True)
    return 1000.0 / mu.max()


def test_euler_buckling_of_a_pinned_column():
    """λ·1000 N → π² EI / L² (Euler).  Cubic Hermite elements with the consistent geometric
    stiffness converge from above as h⁴: 8 elements are within 3.3e-5, and halving h divides
    the error by ≈ 16."""
    p_cr = np.pi**2 * AL.E * TUBE.Iz / L**2
    p4, p8 = _buckling_load(4), _buckling_load(8)
    assert_allclose(p8, p_cr, rtol=4e-5)
    assert p4 > p8 > p_cr
    assert 14.0 < (p4 - p_cr) / (p8 - p_cr) < 18.0


@pytest.mark.parametrize("kind,rtol", [("consistent", 3e-5), ("lumped", 1e-2)])
def test_first_bending_frequency_of_a_pinned_member(kind, rtol):
    """f₁ = (π/2L²) sqrt(EI/(ρA)) (simply supported Euler–Bernoulli beam).  8 elements:
    consistent mass converges as h⁴ from above (error 1.6e-5), lumped as h² (< 1 %)."""
    s = _column()
    fe = discretise(s, bar_model="pinned-beam", subdivisions=8)
    K = fe.stiffness().toarray()[np.ix_(fe.free, fe.free)]
    M = fe.mass(kind).toarray()[np.ix_(fe.free, fe.free)]
    # lumped mass leaves rotations massless: condense them out (static condensation)
    if kind == "lumped":
        has = np.diag(M) > 0
        Kaa, Kab, Kbb = K[np.ix_(has, has)], K[np.ix_(has, ~has)], K[np.ix_(~has, ~has)]
        K = Kaa - Kab @ np.linalg.solve(Kbb, Kab.T)
        M = M[np.ix_(has, has)]
    w2 = sla.eigh(K, M, eigvals_only=True)
    f = np.sqrt(w2[w2 > 1e-6 * w2.max()]) / (2 * np.pi)
    f1 = np.pi / (2 * L**2) * np.sqrt(AL.E * TUBE.Iz / (AL.density * TUBE.area))
    # the supports leave no rigid motion; the lowest frequency is the first bending mode
    assert_allclose(f.min(), f1, rtol=rtol)
