# SPDX-License-Identifier: MIT
"""Member mechanics (trussfe.mechanics) against closed forms.

Sources: Lacy (1991) eqs. 2.23–2.26, 4.75/4.76; Gere & Goodno, *Mechanics of Materials*
(biaxial bending of a rectangle, §6.4 and of a round section, §5.5); Timoshenko & Gere,
*Theory of Elastic Stability* §2.1–2.3 (Euler loads with effective lengths); Cook, Malkus,
Plesha & Witt, *Concepts and Applications of FEA* §11.3 (consistent and lumped bar mass).
"""
from __future__ import annotations

import math
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError
from trussfe.fem import discretise
from trussfe.fem.modal import active_member_mass
from trussfe.mechanics.euler import euler_load, member_euler_loads
from trussfe.mechanics.geometry import (frame_rotations, from_end_node, local_axes,
                                        member_lengths, member_vectors, stations,
                                        transverse_frames, unit_vectors)
from trussfe.mechanics.mass import (centroidal_inertia, gyration_squared, member_mass,
                                    rigid_line_mass, tube_moments)
from trussfe.mechanics.stress import round_sections, von_mises
from trussfe.model.active import ActiveMember
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

TUBE = Section.tube("t", 0.0254, 0.022225)          # Lacy Appendix B
AL = Material("al", E=71e9, G=26.2e9, density=2711.5)


# ----------------------------------------------------------------------------- von Mises
def test_tube_von_mises_by_hand():
    """Thin tube (Lacy eqs. 2.23–2.25): τ = 2V/A at the neutral axis, σ_M = |M| c/I at the
    outer fibre with the resultant moment, S1 = sqrt(σ² + 3τ²), S2 = |σ| + σ_M."""
    N, Vy, Vz, My, Mz = -100.0, 30.0, 40.0, 3.0, 4.0
    A, I, c = TUBE.area, TUBE.Iy, TUBE.c
    r = von_mises(np.array(N), Vy, Vz, My, Mz, A, I, I, c, c, True)
    sig, tau = N / A, 2.0 * 50.0 / A                    # |V| = 50 N
    assert_allclose(r.s1, math.sqrt(sig ** 2 + 3 * tau ** 2), rtol=1e-14)
    assert_allclose(r.s2, abs(sig) + 5.0 * c / I, rtol=1e-14)          # |M| = 5 N·m
    assert_allclose(r.von_mises, max(r.s1, r.s2), rtol=0)


def test_rectangle_von_mises_at_the_corner():
    """Rectangle b = 20 mm (along z) × h = 40 mm (along y), N = 1 kN, My = 10, Mz = 20 N·m:
    σ = N/A + My (b/2)/Iy + Mz (h/2)/Iz = 1.25 + 3.75 + 3.75 = 8.75 MPa at a corner
    (Gere & Goodno §6.4, by hand).  The round-section resultant would give only 6.55 MPa."""
    b, h = 0.02, 0.04
    A, Iy, Iz = b * h, h * b ** 3 / 12, b * h ** 3 / 12
    r = von_mises(np.array(1000.0), 0.0, 0.0, 10.0, 20.0, A, Iy, Iz, h / 2, b / 2, False)
    assert_allclose(r.s2, 8.75e6, rtol=1e-13)
    assert_allclose(r.s1, 1.25e6, rtol=1e-13)           # no shear: the axial stress alone
    round_form = von_mises(np.array(1000.0), 0.0, 0.0, 10.0, 20.0, A, Iy, Iz, h / 2, b / 2,
                           True)
    assert_allclose(round_form.s2, 1.25e6 + math.hypot(3.75e6, 3.75e6), rtol=1e-13)
    # bending about one axis: the two rules agree
    one = [von_mises(np.array(0.0), 0.0, 0.0, 0.0, 20.0, A, Iy, Iz, h / 2, b / 2, rnd).s2
           for rnd in (True, False)]
    assert_allclose(one, [3.75e6, 3.75e6], rtol=1e-13)


def test_lacy_per_axis_convention():
    """Lacy eqs. 4.75/4.76: each moment at its extreme fibre with the shear that peaks there,
    sqrt((|σ| + |My| c/I)² + 3 (2Vy/A)²) and the same about z, the larger governs."""
    A, I, c = TUBE.area, TUBE.Iy, TUBE.c
    N, Vy, Vz, My, Mz = 50.0, 20.0, 5.0, 2.0, 1.0
    r = von_mises(np.array(N), Vy, Vz, My, Mz, A, I, I, c, c, True, convention="lacy-per-axis")
    sa = math.sqrt((N / A + My * c / I) ** 2 + 3 * (2 * Vy / A) ** 2)
    sb = math.sqrt((N / A + Mz * c / I) ** 2 + 3 * (2 * Vz / A) ** 2)
    assert_allclose(r.s2, max(sa, sb), rtol=1e-14)
    # without shear and with one moment, the per-axis and the combined forms coincide
    a = von_mises(np.array(N), 0.0, 0.0, My, 0.0, A, I, I, c, c, True,
                  convention="lacy-per-axis")
    b = von_mises(np.array(N), 0.0, 0.0, My, 0.0, A, I, I, c, c, True)
    assert_allclose(a.s2, b.s2, rtol=1e-15)
    with pytest.raises(ValueError, match="convention"):
        von_mises(np.array(N), 0.0, 0.0, 0.0, 0.0, A, I, I, c, c, convention="tresca")


def test_axial_bar_needs_no_bending_properties():
    """An axial bar (no I, no c) under N alone: S1 = S2 = |N|/A, no NaN from 0·NaN."""
    r = von_mises(np.array([-78.5429]), 0.0, 0.0, 0.0, 0.0, TUBE.area, np.nan, np.nan,
                  np.nan, np.nan)
    assert_allclose([r.s1[0], r.s2[0]], [78.5429 / TUBE.area] * 2, rtol=1e-15)


def test_round_sections():
    rect = Section("r", area=8e-4, Iy=2.7e-8, Iz=1.1e-7, c=0.02)
    assert round_sections([TUBE, rect, TUBE]).tolist() == [True, False, True]


# ----------------------------------------------------------------------------- Euler load
def test_euler_load_of_a_pinned_column_and_effective_lengths():
    """P = π² E I / (K L)² (Timoshenko & Gere §2.1–2.3): pinned K = 1, fixed–free K = 2,
    fixed–fixed K = 1/2; Lacy Table 3.3's 1481.2 N for the 2 m follower (eq. 2.26, C = 1)."""
    E, I, L = 200e9, 1e-6, 2.0
    assert_allclose(euler_load(E, I, L), math.pi ** 2 * E * I / L ** 2, rtol=1e-15)
    assert_allclose(euler_load(E, I, L, [2.0, 0.5]) / euler_load(E, I, L), [0.25, 4.0],
                    rtol=1e-15)
    assert round(float(euler_load(AL.E, TUBE.Iy, 2.0)), 1) == 1481.2


def test_member_euler_loads_use_the_weak_axis():
    rect = Section("r", area=8e-4, Iy=2e-8, Iz=1e-7, c=0.02)
    s = build_structure([[0, 0, 0], [3, 0, 0]], [(0, 1)], section=rect, material=AL)
    assert_allclose(member_euler_loads(s), math.pi ** 2 * AL.E * 2e-8 / 9.0, rtol=1e-15)
    assert_allclose(member_euler_loads(s, length=np.array([1.5]), effective_length_factor=2.0),
                    math.pi ** 2 * AL.E * 2e-8 / 9.0, rtol=1e-15)


# ----------------------------------------------------------------------------- geometry
def test_member_vectors_over_time_steps():
    x = np.array([[[0.0, 0.0], [3.0, 4.0], [3.0, 0.0]],
                  [[0.0, 0.0], [6.0, 8.0], [0.0, 1.0]]])                # (time, node, dim)
    conn = np.array([[0, 1], [1, 2]])
    d = member_vectors(x, conn)
    assert d.shape == (2, 2, 2)
    assert_allclose(member_lengths(x, conn), [[5.0, 4.0], [10.0, math.hypot(6, 7)]])
    e, L = unit_vectors(d)
    assert_allclose(e[0, 0], [0.6, 0.8])
    assert_allclose(L, member_lengths(x, conn))


def test_local_axes_of_a_frame():
    """3-D frame: horizontal member along x → y = global Z, z = x × y = −Y; a vertical member
    → y = global X; an orientation vector sets y; 2-D: y = x turned by +90°."""
    s = build_structure([[0, 0, 0], [2, 0, 0], [2, 0, 3], [2, 2, 3]],
                        [(0, 1), (1, 2), (2, 3)], section=TUBE, material=AL)
    s = s.with_member_data(orientation={2: (0.0, 1.0, 1.0)})   # member 2 along +Y, y ← +Z
    R = local_axes(s)
    assert_allclose(R[0], [[1, 0, 0], [0, 0, 1], [0, -1, 0]], atol=1e-15)
    assert_allclose(R[1], [[0, 0, 1], [1, 0, 0], [0, 1, 0]], atol=1e-15)
    assert_allclose(R[2], [[0, 1, 0], [0, 0, 1], [1, 0, 0]], atol=1e-15)
    assert_allclose(np.einsum("mij,mkj->mik", R, R), np.broadcast_to(np.eye(3), R.shape),
                    atol=1e-15)                          # orthonormal, right-handed
    assert_allclose(np.linalg.det(R), 1.0)
    with pytest.raises(InputError, match="parallel"):
        local_axes(s.with_member_data(orientation={2: (0.0, 5.0, 0.0)}))   # along the member
    e = np.array([[math.cos(0.5), math.sin(0.5)]])
    assert_allclose(frame_rotations(e)[0], [[math.cos(0.5), math.sin(0.5)],
                                            [-math.sin(0.5), math.cos(0.5)]])


def test_lacy_transverse_frames_are_the_local_axes():
    """Away from the vertical, Lacy's b1 = e × Z/|e × Z| is local z and b2 = e × b1 is −y."""
    e = np.array([[0.6, 0.0, 0.8], [0.0, 1.0, 0.0]])
    b1, b2 = transverse_frames(e)
    R = frame_rotations(e)
    assert_allclose(b1, R[:, 2], atol=1e-15)
    assert_allclose(b2, -R[:, 1], atol=1e-15)


def test_stations_from_the_start_node():
    L = np.array([2.0, 4.0])
    x = stations(L, 5)
    assert_allclose(x[1], [0.0, 1.0, 2.0, 3.0, 4.0])
    assert_allclose(stations(L, 1), [[1.0], [2.0]])
    u = from_end_node(x, L)                              # Lacy's u from the end node B
    assert_allclose(u[1], [4.0, 3.0, 2.0, 1.0, 0.0])
    assert_allclose(from_end_node(u, L), x)              # its own inverse


# ----------------------------------------------------------------------------- mass
def test_member_mass_and_fe_mass_sums():
    """ρAL; the consistent bar matrix ρAL/6 [[2, 1], [1, 2]] and the lumped ρAL/2 each carry
    the whole member mass in every direction (Cook et al. §11.3)."""
    s = build_structure([[0, 0], [2, 0], [2, 1.5]], [(0, 1), (1, 2), (0, 2)], section=TUBE,
                        material=AL)
    total = member_mass(AL.density, TUBE.area, s.lengths()).sum()
    assert_allclose(total, AL.density * TUBE.area * (2 + 1.5 + 2.5), rtol=1e-15)
    fe = discretise(s)
    for kind in ("consistent", "lumped"):
        M = fe.mass(kind=kind).toarray()
        for d in range(2):
            u = np.zeros(fe.n_dof)
            u[fe.node_dofs[:, d]] = 1.0                  # rigid translation along d
            assert_allclose(u @ M @ u, total, rtol=1e-13)
    Mc = fe.mass(kind="consistent").toarray()
    m0 = member_mass(AL.density, TUBE.area, 2.0)
    ix = fe.node_dofs[[0, 1], 0]
    assert_allclose(Mc[ix[0], ix[1]], m0 / 6.0, rtol=1e-13)  # only member 0 joins nodes 0, 1


def test_tube_inertia_and_rotary_term():
    """A tube piece about its centre: m (3 OD² + 3 ID² + 4 ℓ²)/48 (Lacy Appendix A)."""
    m, ell = 0.7, 1.3
    r2 = gyration_squared(TUBE.Iy, TUBE.Iz, TUBE.area)
    lacy = m * (3 * 0.0254 ** 2 + 3 * 0.022225 ** 2 + 4 * ell ** 2) / 48
    assert_allclose(centroidal_inertia(m, ell, r2), lacy, rtol=1e-13)
    mt, S, I = tube_moments(2.0, 1.0, 3.0, r2)           # ρA = 2 kg/m from 1 to 3 m
    assert_allclose([mt, S], [4.0, 8.0])
    assert_allclose(I, 2.0 * (27 - 1) / 3 + 4.0 * r2, rtol=1e-15)   # = m (r² + ℓ²/12) + m s̄²
    assert_allclose(I, centroidal_inertia(4.0, 2.0, r2) + 4.0 * 2.0 ** 2, rtol=1e-14)


def test_rigid_line_mass_of_a_uniform_rod():
    """A uniform rod (m, S = mL/2, I = mL²/3 + m r²) following its rigid motion: transversely
    the consistent bar matrix m/6 [[2, 1], [1, 2]] plus the rotary term m r²/L² [[1, −1],
    [−1, 1]] (kinetic energy of a rigid rod, Cook et al. §11.3 and the Rayleigh beam)."""
    m, L, r2 = 3.0, 2.0, 0.01
    e = np.array([[1.0, 0.0]])
    blk = rigid_line_mass(np.array([L]), e, np.array([m]), np.array([m * L / 2]),
                          np.array([m * L ** 2 / 3 + m * r2]), np.array([m / 2]),
                          np.array([m / 2]))[0]          # (end, dim, end, dim)
    expected = m / 6 * np.array([[2, 1], [1, 2]]) + m * r2 / L ** 2 * np.array([[1, -1],
                                                                             [-1, 1]])
    assert_allclose(blk[:, 1, :, 1], expected, rtol=1e-14)       # transverse (y)
    assert_allclose(blk[:, 0, :, 0], np.diag([m / 2, m / 2]), atol=1e-15)  # axial, as given


def test_active_member_mass_includes_the_tube_rotary_inertia():
    """The FE active-member mass and the rigid-body force model see the same tube: its
    moment about the start node is the line's ρA(L³ − a³)/3 plus m_t I/A."""
    L, lt = 3.0, 2.0
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=TUBE, material=AL)
    s = s.with_extensions(active_members=[ActiveMember(
        member=0, base_mass=0.0, base_length=0.5, base_cg=0.0, base_inertia=0.0,
        tube_length=lt)])
    Ma = active_member_mass(discretise(s)).toarray()
    rot = np.array([0, 0, 0, L])                         # unit rotation about node 0
    rhoA = AL.density * TUBE.area
    mt = rhoA * lt
    assert_allclose(rot @ Ma @ rot, rhoA * (L ** 3 - (L - lt) ** 3) / 3
                    + mt * TUBE.Iy / TUBE.area, rtol=1e-13)


def test_rigid_stresses_of_a_section_that_is_not_a_tube():
    """The rigid-body model's stresses come from the same von Mises: a section with the
    tube's A, I and c but given explicitly (not round) takes its moments in the member axes
    and sums them at the corner, so along a 3-D slew S2 lies between the round value
    |σ| + |M| c/I and |σ| + √2 |M| c/I (|My| + |Mz| ≤ √2 |M|), equal where one component
    vanishes; S1 (resultant shear) is unchanged."""
    from trussfe.rigid.motion import third_order_motion
    from trussfe.studies.lacy_rigid import double_octahedron
    from trussfe.rigid.sections import section_stresses
    from trussfe.rigid.simulate import simulate
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    r = simulate(s, third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289],
                                       2.0, 20))
    sec = s.sections[0]
    box = Section("box", area=sec.area, Iy=sec.Iy, Iz=sec.Iz, J=sec.J, c=sec.c)
    s2 = s.with_sections([box if x is sec else x for x in s.sections])
    tube, corner = section_stresses(s, r.sections), section_stresses(s2, r.sections)
    m = np.array([x is sec for x in s.sections])
    assert m.any()
    assert_allclose(corner.s1, tube.s1, rtol=1e-13)
    axial = np.abs(tube.axial[:, m])
    bend = tube.s2[:, m] - axial
    assert np.all(corner.s2[:, m] >= tube.s2[:, m] * (1 - 1e-12))
    assert np.all(corner.s2[:, m] <= axial + np.sqrt(2) * bend * (1 + 1e-12) + 1e-6)
    assert corner.s2[:, m].max() > tube.s2[:, m].max() * (1 + 1e-6)   # biaxial somewhere
    assert_allclose(corner.s2[:, ~m], tube.s2[:, ~m], rtol=1e-14)
    lacy = section_stresses(s, r.sections, convention="lacy-per-axis")
    # round-off relative to the whole bound: the shear is ~1e-10 Pa at rest
    assert np.all(lacy.s2 <= (tube.s2 + np.sqrt(3) * tube.shear) * (1 + 1e-12))


def test_beam_twist_mass_is_rho_j():
    """A 3-D beam's twist field carries ρJ: a rigid spin ω about the member's axis has kinetic
    energy ½ ρ J L ω² (J polar moment of the tube, Cook et al. §11.3)."""
    s = build_structure([[0, 0, 0], [2, 0, 0]], [(0, 1)], section=TUBE, material=AL,
                        is_beam=True)
    fe = discretise(s, subdivisions=1)                   # one element: end DOFs only
    M = fe.mass().toarray()
    spin = np.zeros(fe.n_dof)
    spin[fe.node_dofs[:, 3]] = 1.0                       # θx = 1 at both ends
    assert fe.interior_dofs.size == 0
    assert_allclose(spin @ M @ spin, AL.density * TUBE.J * 2.0, rtol=1e-12)


def test_stress_form_is_a_convention_of_the_run():
    """``Conventions(stress_form="lacy-per-axis")`` makes the rigid-body run report Lacy's
    per-axis von Mises (eqs. 4.75/4.76), the same as applying that form to the run's section
    forces; the default run reports the combined form."""
    from dataclasses import replace
    from trussfe.mechanics.conventions import PHYSICAL
    from trussfe.rigid.motion import third_order_motion
    from trussfe.rigid.sections import section_stresses
    from trussfe.rigid.simulate import simulate
    from trussfe.studies.lacy_rigid import double_octahedron
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 10)
    plain = simulate(s, m)
    per_axis = simulate(s, m, conventions=replace(PHYSICAL, stress_form="lacy-per-axis"))
    assert_allclose(per_axis.stresses.von_mises,
                    section_stresses(s, plain.sections, convention="lacy-per-axis").von_mises,
                    rtol=1e-14)
    assert_allclose(plain.stresses.von_mises,
                    section_stresses(s, plain.sections).von_mises, rtol=1e-14)
    assert not np.allclose(per_axis.stresses.von_mises, plain.stresses.von_mises, rtol=1e-6)
