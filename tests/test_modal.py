# SPDX-License-Identifier: MIT
"""Modal analysis against closed-form frequencies (physics first), then bookkeeping checks.

Sources: axial bar fixed–free ω_n = (2n − 1)π/(2L) √(E/ρ); simply supported Euler–Bernoulli beam
ω_n = (nπ/L)² √(EI/(ρA)) (e.g. Clough & Penzien, Dynamics of Structures, ch. 18); a
consistent mass over-estimates and a lumped mass under-estimates the frequencies of a bar
(Rayleigh bound / lumping error of opposite sign), with error O(h²) for P1 bars and O(h⁴) for
Hermite beams.
"""
from __future__ import annotations


import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError, InputError
from trussfe.fem import discretise
from trussfe.fem.modal import (active_member_mass, mass_matrix, modes_json, rigid_translations,
                               solve_modes)
from trussfe.model.active import ActiveMember
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

STEEL = Material("steel", E=2.1e11, G=8.1e10, density=7850.0)
TUBE = Section.tube("tube", 0.02, 0.016)


def axial_bar(n_el: int, L: float = 2.0):
    """Fixed–free bar along x from n_el truss elements; transverse DOFs held."""
    x = np.c_[np.linspace(0, L, n_el + 1), np.zeros(n_el + 1)]
    conn = np.c_[np.arange(n_el), np.arange(1, n_el + 1)]
    sup = {i: "y" for i in range(1, n_el + 1)}
    sup[0] = "xy"
    return build_structure(x, conn, section=TUBE, material=STEEL, supports=sup)


def ss_beam(dim: int = 2, L: float = 2.0):
    """One pinned–pinned bar (pinned-beam model), free to slide axially at its end."""
    if dim == 2:
        return build_structure([[0, 0], [L, 0]], [(0, 1)], section=TUBE, material=STEEL,
                               supports={0: "xy", 1: "y"})
    return build_structure([[0, 0, 0], [L, 0, 0]], [(0, 1)], section=TUBE, material=STEEL,
                           supports={0: "xyz", 1: "yz"})


def test_axial_bar_closed_form():
    """Consistent P1 mass, 200 elements: relative error (kh)²/24 ≈ 3e-6 for mode 1."""
    L = 2.0
    r = solve_modes(axial_bar(200, L), count=3)
    c = np.sqrt(STEEL.E / STEEL.density)
    exact = (2 * np.arange(1, 4) - 1) * np.pi / (2 * L) * c / (2 * np.pi)
    assert_allclose(r.frequencies_hz, exact, rtol=1e-4)
    assert np.all(r.frequencies_hz > exact)          # consistent mass: upper bound
    lumped = solve_modes(axial_bar(200, L), count=3, mass="lumped")
    assert_allclose(lumped.frequencies_hz, exact, rtol=1e-4)
    assert np.all(lumped.frequencies_hz < exact)     # lumped mass: below
    # mass normalisation φᵀMφ = 1 and M-orthogonality
    M = mass_matrix(r.fe)
    assert_allclose(r.shapes.T @ (M @ r.shapes), np.eye(3), atol=1e-10)


def test_axial_bar_convergence_rate():
    """P1 bars: frequency error O(h²): halving h divides the error by ≈ 4."""
    c = np.sqrt(STEEL.E / STEEL.density)
    exact = np.pi / (2 * 2.0) * c / (2 * np.pi)
    err = [solve_modes(axial_bar(n), count=1).frequencies_hz[0] / exact - 1 for n in (10, 20, 40)]
    rates = np.log2(np.array(err[:-1]) / np.array(err[1:]))
    assert_allclose(rates, 2.0, atol=0.05)


@pytest.mark.parametrize("k", [32])
def test_simply_supported_beam_closed_form(k):
    """Pinned-beam model, one member cut into k = 32 Hermite elements: the first three
    bending frequencies within 1e-5 of (nπ/L)²√(EI/ρA)/2π.  The discretisation error grows
    as (n h/L)⁴: with k = 16 mode 3 is 8.3e-5 high (measured), with k = 32 about 5e-6."""
    L = 2.0
    r = solve_modes(ss_beam(2, L), count=3, bar_model="pinned-beam", subdivisions=k)
    n = np.arange(1, 4)
    exact = (n * np.pi / L) ** 2 * np.sqrt(STEEL.E * TUBE.Iz / (STEEL.density * TUBE.area)) \
        / (2 * np.pi)
    assert_allclose(r.frequencies_hz, exact, rtol=1e-5)
    # the truss model has no bending modes: its only mode is the axial one
    axial = solve_modes(ss_beam(2, L), count=1)
    assert axial.frequencies_hz[0] > 10 * exact[0]


def test_beam_convergence_with_subdivisions():
    """First bending frequency converges as h⁴ (Hermite cubic with consistent mass)."""
    L = 2.0
    exact = (np.pi / L) ** 2 * np.sqrt(STEEL.E * TUBE.Iz / (STEEL.density * TUBE.area)) \
        / (2 * np.pi)
    err = np.array([solve_modes(ss_beam(2, L), count=1, bar_model="pinned-beam",
                                subdivisions=k).frequencies_hz[0] / exact - 1
                    for k in (2, 4, 8)])
    assert np.all(err > 0)
    rates = np.log2(err[:-1] / err[1:])
    assert np.all(rates > 3.7), rates


def test_3d_beam_bending_pairs():
    """In 3-D a tube bends equally in two planes: modes come in equal pairs."""
    r = solve_modes(ss_beam(3), count=4, bar_model="pinned-beam", subdivisions=8)
    f = r.frequencies_hz
    assert_allclose(f[0], f[1], rtol=1e-9)
    assert_allclose(f[2], f[3], rtol=1e-9)
    exact = (np.pi / 2.0) ** 2 * np.sqrt(STEEL.E * TUBE.Iz / (STEEL.density * TUBE.area)) \
        / (2 * np.pi)
    assert_allclose(f[0], exact, rtol=1e-4)


def triangle_truss(**kw):
    return build_structure([[0, 0], [2, 0], [1, 1.5], [3, 1.5]],
                           [(0, 1), (1, 2), (2, 0), (1, 3), (2, 3)], section=TUBE,
                           material=STEEL, masses={3: 5.0}, **kw)


@pytest.mark.parametrize("mass", ["consistent", "lumped"])
def test_effective_mass_sums_to_total(mass):
    """Σ over all modes of the effective mass = r_dᵀ M r_d (completeness of the modes);
    for a free-floating structure it is the whole mass: members ρAL + nodal masses."""
    s = triangle_truss()
    r = solve_modes(s, count=8, mass=mass)                 # all 4 nodes × 2 DOFs
    assert r.rigid_modes == 3                              # 2 translations + 1 rotation
    assert_allclose(r.frequencies_hz[:3], 0.0, rtol=0, atol=0)
    assert r.kinds[:3] == ["rigid"] * 3 and r.kinds[3] == "elastic"
    total = np.sum(s.member_mass) + 5.0
    assert_allclose(r.total_mass, [total, total], rtol=1e-12)
    assert_allclose(r.effective_mass.sum(axis=0), r.total_mass, rtol=1e-10)
    # elastic modes of a free body carry no net momentum
    assert_allclose(r.participation[3:], 0.0, atol=1e-9 * np.sqrt(total))


def test_rigid_translation_strains_nothing():
    s = triangle_truss(supports={0: "xy"})
    fe = discretise(s, bar_model="pinned-beam", subdivisions=3)
    R = rigid_translations(fe)
    K = fe.stiffness()
    assert_allclose(K @ R, 0.0, atol=1e-6 * abs(K).max())
    # and carries the whole mass (consistent mass, pinned-beam)
    M = mass_matrix(fe)
    assert_allclose(np.diag(R.T @ (M @ R)), np.sum(s.member_mass) + 5.0, rtol=1e-12)


def test_mechanism_reported_as_zero_modes():
    """A pin-jointed square without diagonal, pinned at two base nodes: one mechanism."""
    s = build_structure([[0, 0], [1, 0], [1, 1], [0, 1]], [(0, 1), (1, 2), (2, 3), (3, 0)],
                        section=TUBE, material=STEEL, supports={0: "xy", 1: "xy"})
    r = solve_modes(s, count=2)
    assert r.rigid_modes == 1
    assert r.frequencies_hz[0] == 0.0 and r.frequencies_hz[1] > 100.0
    doc = modes_json(r)
    assert doc["rigid_modes"] == 1 and doc["modes"][0]["kind"] == "rigid"


def test_too_many_modes():
    s = axial_bar(3)                                        # 3 free DOFs
    with pytest.raises(AnalysisError, match="asked for 4 modes.*only 3"):
        solve_modes(s, count=4)
    with pytest.raises(InputError, match="--count"):
        solve_modes(s, count=0)
    with pytest.raises(InputError, match="--mass"):
        solve_modes(s, count=1, mass="diagonal")


def test_no_mass():
    s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=TUBE,
                        material=Material("m", E=1e9, G=4e8, density=0.0),
                        supports={0: "xy", 1: "y"})
    with pytest.raises(AnalysisError, match="no mass"):
        solve_modes(s, count=1)


def test_active_member_rigid_body_mass():
    """Active base + leadscrew tube (Lacy §2.1): total mass for a transverse or axial rigid
    translation, moment of inertia I_b + I_t about the start node for a rotation about it,
    I_t with the rotary inertia m_t I/A of the tube's sections (rigid tube; Lacy Appendix A
    ``m (3 OD² + 3 ID² + 4 L²)/48`` about its centre)."""
    L = 3.0
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=TUBE, material=STEEL)
    act = ActiveMember(member=0, base_mass=2.4, base_length=2.1, base_cg=1.05,
                       base_inertia=2.4 * 2.1**2 / 3, tube_length=2.0)
    s = s.with_extensions(active_members=[act])
    fe = discretise(s)
    Ma = active_member_mass(fe).toarray()
    rhoA = STEEL.density * TUBE.area
    mt = rhoA * 2.0
    It = rhoA * (L**3 - (L - 2.0) ** 3) / 3 + mt * TUBE.Iy / TUBE.area
    ux = np.array([1.0, 0, 1.0, 0])                      # axial rigid translation
    uy = np.array([0, 1.0, 0, 1.0])                      # transverse translation
    rot = np.array([0, 0, 0, L])                          # unit rotation about node 0
    assert_allclose(ux @ Ma @ ux, 2.4 + mt, rtol=1e-12)
    assert_allclose(uy @ Ma @ uy, 2.4 + mt, rtol=1e-12)
    assert_allclose(rot @ Ma @ rot, act.base_inertia + It, rtol=1e-12)
    # axially the base rides on the start node and the tube on the end node
    assert_allclose(Ma[0, 0], 2.4, rtol=1e-12)
    assert_allclose(Ma[2, 2], mt, rtol=1e-12)
    # the member's own distributed mass is replaced, not added
    M = mass_matrix(fe).toarray()
    assert_allclose(uy @ M @ uy, 2.4 + mt, rtol=1e-12)


def test_active_member_pendulum_frequencies():
    """An active member pinned at a fixed node A, its end B held transversely by a massless
    spring bar: B's transverse mode is a pendulum with effective mass I_A/L² (I_A = base +
    tube moments about A, the tube's with its rotary inertia), ω² = k_spring L² / I_A; its axial mode moves the tube only (the base
    rides on A), ω² = (EA/L) / m_tube.  Closed form, rtol 1e-10."""
    L, h = 3.0, 1.0
    s = build_structure([[0, 0], [L, 0], [L, -h]], [(0, 1), (1, 2)], section=TUBE,
                        material=STEEL, supports={0: "xy", 2: "xy"})
    spring = Material("spring", E=5e9, G=2e9, density=0.0)
    act = ActiveMember(member=0, base_mass=3.0, base_length=0.7, base_cg=0.35,
                       base_inertia=3.0 * 0.7**2 / 3, tube_length=0.254)
    s = s.with_materials({1: spring}).with_extensions(active_members=[act])
    r = solve_modes(s, count=2)
    rhoA = STEEL.density * TUBE.area
    mt = rhoA * 0.254
    # the tube's moment about A: its line plus its sections' rotary inertia m_t I/A
    I_A = act.base_inertia + rhoA * (L**3 - (L - 0.254) ** 3) / 3 + mt * TUBE.Iy / TUBE.area
    k_spring = spring.E * TUBE.area / h
    k_axial = STEEL.E * TUBE.area / L
    expected = np.sort([np.sqrt(k_spring * L**2 / I_A), np.sqrt(k_axial / mt)]) / (2 * np.pi)
    assert_allclose(r.frequencies_hz, expected, rtol=1e-10)
