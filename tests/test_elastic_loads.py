# SPDX-License-Identifier: MIT
"""Load assembly of the elastic response along a motion: analytic members and the rigid-body
model's resultants."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.response.along_motion import elastic_along_motion, stacked_structure
from trussfe.response.loads import element_load_components, motion_loads, rotations3
from trussfe.fem.discretisation import discretise
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.rigid.forces import member_bodies, nodal_forces
from trussfe.rigid.kinematics import Kinematics
from trussfe.studies.lacy_rigid import triangular_truss
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import L2, L3MIN
from trussfe.rigid.sections import section_forces
from trussfe.rigid.simulate import simulate

RHO, OD, ID, L = 2711.5, 0.0254, 0.022225, 2.0
TUBE = Section.tube("tube", OD, ID)
AL = Material("al", 71e9, 26.2e9, density=RHO)


def _bar():
    """A bar along x, pinned at A (x, y) with a roller at B (y): statically determinate."""
    return build_structure([[0.0, 0.0], [L, 0.0]], [(0, 1)], section=TUBE, material=AL,
                           supports={0: "xy", 1: "y"})


def _rotating_kinematics(omega: float, alpha: float) -> Kinematics:
    """The bar turning about A with angular velocity ω and acceleration α (along x now)."""
    z = np.zeros((1, 1, 3))
    acc = np.array([[[0.0, 0.0, 0.0], [-omega ** 2 * L, alpha * L, 0.0]]])
    vel = np.array([[[0.0, 0.0, 0.0], [0.0, omega * L, 0.0]]])
    return Kinematics(time=np.zeros(1), coords=np.array([[[0.0, 0.0], [L, 0.0]]]),
                      velocity=vel, acceleration=acc, length=np.full((1, 1), L),
                      length_rate=np.zeros((1, 1)), length_acc=np.zeros((1, 1)),
                      unit=np.array([[[1.0, 0.0, 0.0]]]),
                      unit_rate=np.array([[[0.0, omega, 0.0]]]),
                      unit_acc=np.array([[[-omega ** 2, alpha, 0.0]]]),
                      omega=z + [0.0, 0.0, omega], alpha=z + [0.0, 0.0, alpha])


X_FROM_END = np.linspace(0.0, L, 9)[None, :]          # sections, distance from the end node


def test_constant_spin_axial_force():
    """Constant ω about one end: N(x) = ρAω²(L² − x²)/2 (centripetal load ρAω²x, free end);
    no shear, no moment.  Closed form; tolerance 1e-10 relative (exact elements)."""
    s, omega = _bar(), 3.0
    r = elastic_along_motion(s, _rotating_kinematics(omega, 0.0), positions=X_FROM_END,
                             subdivisions=4)
    x = L - X_FROM_END[0]
    mu = RHO * TUBE.area
    expect = mu * omega ** 2 * (L ** 2 - x ** 2) / 2.0
    assert_allclose(r.sections.tension[0, 0], expect, rtol=1e-10, atol=1e-10 * expect.max())
    assert np.abs(r.sections.shear).max() < 1e-10 * expect.max()
    assert np.abs(r.sections.moment).max() < 1e-10 * expect.max() * L


def test_uniform_angular_acceleration_shear_and_moment():
    """ω = 0, α about one end, simply supported (pin A, roller B): transverse load −ρAαx and
    rotary couple −ρIα.  Closed form: R_B = ρAα(L²/3 + r²) with r² = I/A; on the end-side
    piece V = ρAα(L² − x²)/2 − R_B, M = −(L − x)R_B + ρAα[(L³ − x³)/3 − x(L² − x²)/2]
    + ρIα(L − x).  Tolerance 1e-10 relative to the largest value."""
    s, alpha = _bar(), 5.0
    r = elastic_along_motion(s, _rotating_kinematics(0.0, alpha), positions=X_FROM_END,
                             subdivisions=3)            # sections fall inside elements too
    x = L - X_FROM_END[0]
    mu = RHO * TUBE.area
    r2 = TUBE.Iy / TUBE.area
    RB = mu * alpha * (L ** 2 / 3.0 + r2)
    V = mu * alpha * (L ** 2 - x ** 2) / 2.0 - RB
    M = (-(L - x) * RB + mu * alpha * ((L ** 3 - x ** 3) / 3.0 - x * (L ** 2 - x ** 2) / 2.0)
         + mu * r2 * alpha * (L - x))
    assert_allclose(r.sections.shear[0, 0, :, 1], V, rtol=0, atol=1e-10 * np.abs(V).max())
    assert_allclose(r.sections.moment[0, 0, :, 2], M, rtol=0, atol=1e-10 * np.abs(M).max())
    assert_allclose(r.reactions[0, 1, 1], RB, rtol=1e-10)
    # the rigid-body model (Lacy eqs. 2.16-2.18) gives the same, from its own equations
    kin = _rotating_kinematics(0.0, alpha)
    b = member_bodies(s)
    sf = section_forces(s, kin, nodal_forces(s, kin, b), b, positions=X_FROM_END)
    assert_allclose(sf.moment[0, 0, :, 2], M, rtol=0, atol=1e-10 * np.abs(M).max())


def test_resultants_equal_rigid_member_equations():
    """Σ loads on each member = −R and their moment about the start node = −M_a of the
    rigid model (Lacy eq. 4.20), along the Base Simulation: same mass model.  1e-12."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 3.0, 20)
    sim = simulate(s, m, actuators=False)
    kin = sim.kinematics
    ml = motion_loads(s, kin, sim.bodies)
    Lm = kin.length[..., None]
    F, M = ml.piece_resultant(np.full_like(Lm, -1e-9), Lm, np.zeros_like(Lm))
    # rigid: node forces on the member balance the loads: Fa + Fb + ΣF = 0, moments too
    Fa, Fb = sim.forces.end_force[:, :, 0], sim.forces.end_force[:, :, 1]
    scale = np.abs(sim.forces.end_force).max()
    assert_allclose(F[:, :, 0] + Fa + Fb, 0.0, atol=1e-12 * scale)
    Mb = np.cross(kin.length[..., None] * kin.unit, Fb)
    assert_allclose(M[:, :, 0] + Mb, 0.0, atol=1e-12 * scale * 4.0)


def test_consistent_loads_match_skfem_self_weight():
    """The hand-integrated consistent loads equal scikit-fem's assembled self-weight vector
    (trussfe.fem.forms.distributed_load) on a 3-D structure at rest: 1e-12."""
    from trussfe.studies.lacy_rigid import double_octahedron
    from trussfe.rigid.kinematics import compute_kinematics
    from trussfe.rigid.motion import rest_motion
    s = double_octahedron(gravity=9.81)
    s = s.without_extensions("active_members")    # uniform tubes: self-weight only
    kin = compute_kinematics(s, rest_motion(s)).at_rest()
    ml = motion_loads(s, kin, loads=False)
    k = 3
    fe = discretise(stacked_structure(s, kin.coords), "pinned-beam", k)
    comp = element_load_components(ml, fe.element_x.reshape(1, -1, k, 2),
                                   rotations3(fe.rotation)[None])
    g = fe.groups[0]
    ref = (g.S.T @ fe.local_self_weight(g, s.gravity)).reshape(-1, 2, 6)
    assert_allclose(comp.reshape(-1, 2, 6)[g.elements], ref, atol=1e-12 * np.abs(ref).max())


@pytest.mark.parametrize("k", [1, 2, 5])
def test_section_forces_do_not_depend_on_subdivisions(k):
    """Element end forces are exact, so the recovered sections are too: any number of elements
    per member gives the rigid model's section forces (Base Simulation, 10 steps), 1e-9."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 3.0, 10)
    sim = simulate(s, m, actuators=False)
    r = elastic_along_motion(s, sim.kinematics, subdivisions=k,
                             positions=sim.sections.position)
    scale = np.abs(sim.sections.tension).max()
    assert_allclose(r.sections.tension, sim.sections.tension, atol=1e-9 * scale)
    assert_allclose(r.sections.moment, sim.sections.moment,
                    atol=1e-9 * np.abs(sim.sections.moment).max())


def test_load_vectors_at_rest_equal_fe_load_vector():
    """At rest, the motion loads on one discretisation equal the FE model's own load vector
    (self-weight by scikit-fem's distributed-load form, nodal loads, weight of nodal masses):
    triangular truss without its active base, 1e-12."""
    from trussfe.response.loads import load_vectors
    from trussfe.rigid.kinematics import compute_kinematics
    from trussfe.rigid.motion import rest_motion
    s = triangular_truss(load=-98.1)
    s = s.without_extensions("active_members")
    kin = compute_kinematics(s, rest_motion(s)).at_rest()
    fe = discretise(s, "pinned-beam", 4)
    f, f_local = load_vectors(fe, motion_loads(s, kin))
    ref = fe.load_vector()
    assert_allclose(f[0], ref, atol=1e-12 * np.abs(ref).max())
    assert len(f_local) == 1 and f_local[0].shape == (1, fe.groups[0].n_local)


def _with_shear_areas(s, fraction):
    """``s`` with shear areas ``fraction`` × A on every section: Timoshenko members."""
    import dataclasses
    return s.variant(sections=tuple(dataclasses.replace(c, shear_area_y=fraction * c.area,
                                                        shear_area_z=fraction * c.area)
                                    for c in s.sections))


@pytest.mark.parametrize("k", [1, 3])
def test_loads_at_rest_are_the_static_consistent_loads_on_timoshenko_members(k):
    """Reference: the static load vector of the same discretisation (trussfe.fem.static:
    self-weight, the active bases and tubes as member loads, the closed-form and Gauss fixed-
    end forces of trussfe.fem.member_loads).  At rest the loads of the response along a
    motion are the same loads — the tube's weight on its part of the member, the base's at
    its point — so their work-equivalent nodal loads must be equal.  With shear areas
    (Φ up to 0.28 here) both must use the Timoshenko elements' own shape functions:
    cubic Hermite loads on them were off by up to 1.3 % of the largest entry."""
    from trussfe.fem.member_loads import member_load_vector
    from trussfe.fem.static import active_member_weight
    from trussfe.response.loads import load_vectors
    from trussfe.rigid.kinematics import compute_kinematics
    from trussfe.rigid.motion import rest_motion
    from trussfe.studies.lacy_elastic import slew1_structure
    s = _with_shear_areas(slew1_structure(), 0.05)
    fe = discretise(s, "pinned-beam", subdivisions=k)
    assert fe.shear_parameter("v", np.arange(fe.n_elements)).max() > 0.03
    joints, along = active_member_weight(fe)
    assert along                                   # the bases' weights: point loads
    f = fe.load_vector() + joints + member_load_vector(fe, along).global_vector
    ml = motion_loads(s, compute_kinematics(s, rest_motion(s)).at_rest())
    got, _ = load_vectors(fe, ml)
    assert_allclose(got[0], f, rtol=0, atol=1e-13 * np.abs(f).max())
