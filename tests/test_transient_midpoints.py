# SPDX-License-Identifier: MIT
"""FE response along a motion (trussfe.response.transient) against independent references:
the rigid-body section forces of a statically determinate truss, a hand-written Newmark
integration on trussfe's own K and M, the closed-form single-DOF response with viscous
damping, and OpenSeesPy's Newmark with Rayleigh damping.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.fem.discretisation import discretise
from trussfe.fem.modal import mass_matrix
from trussfe.model.active import ActiveMember
from trussfe.response.transient import transient_response
from trussfe.response.transient_fe import massless_active
from trussfe.rigid.motion import Motion, third_order_motion
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_rigid import L2, L3MIN, triangular_truss
from trussfe.studies.transient_slews import double_octahedron_slew, sdof_bar


def _two_bar(mass=5.0):
    """O and C pinned, B carries ``mass``; the active member O–B is massless (no base, no
    tube mass), the follower C–B a steel tube.  Two free DOFs with the truss bar model."""
    s = trussfe.model_from_dict({
        "model": {"name": "two-bar", "dimension": 2, "gravity": [0.0, -9.81]},
        "materials": {"steel": {"E": 210e9, "G": 81e9, "density": 7850.0},
                      "light": {"E": 210e9, "G": 81e9, "density": 0.0}},
        "sections": {"tube": {"outer_diameter": 0.02, "inner_diameter": 0.016}},
        "nodes": {"O": [0.0, 0.0], "C": [2.0, 0.0], "B": [1.0, 1.0]},
        "members": {"act": {"nodes": ["O", "B"], "section": "tube", "material": "light"},
                    "fol": {"nodes": ["C", "B"], "section": "tube", "material": "steel"}},
        "supports": {"O": ["x", "y"], "C": ["x", "y"]},
        "masses": {"B": mass}})
    L = float(s.lengths()[0])
    # the tube is massless: its length (half the member's, so that the motion never draws
    # the member shorter than it) changes no force
    return s.with_extensions(active_members=[ActiveMember(
        member=0, base_mass=0.0, base_length=0.1, base_cg=0.0, base_inertia=0.0,
        tube_length=0.5 * L)])


def _sine(s, amp, freq, duration, dt):
    """Active length L0 + amp sin(2π freq t), sampled every dt (rates exact)."""
    L0 = float(s.lengths()[s.extensions["active_members"][0].member])
    w = 2 * math.pi * freq
    t = dt * np.arange(round(duration / dt) + 1)
    return Motion(time=t, members=[0], length=(L0 + amp * np.sin(w * t))[:, None],
                  velocity=(amp * w * np.cos(w * t))[:, None],
                  acceleration=(-amp * w * w * np.sin(w * t))[:, None])


# ---------------------------------------------------------------------- odd subdivisions
@pytest.mark.parametrize("k", [1, 3, 5])
def test_odd_subdivisions_midpoint_equals_rigid_body(k):
    """Reference: the rigid-body section forces (Lacy eqs. 2.15–2.18) at the follower's
    midpoint, which the quasi-static FE forces of this determinate truss must equal whatever
    the number of elements (they do to 1e-13 for even k).  The midpoint of an odd k lies
    inside an element; averaging its end values gave a moment of 0 (k = 1), 8/9 (k = 3)
    and 24/25 (k = 5) of the parabolic midpoint moment."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 1.0, 40, include_end=True)
    r = transient_response(s, m, k=k)
    ref = r.moment_rigid[:, 0]
    assert ref.max() > 1.0                                   # N·m: a real bending moment
    assert np.abs(r.moment_qs[:, 0] - ref).max() < 1e-8 * ref.max()
    peak = np.abs(r.axial_force_rigid).max(axis=0)
    assert np.all(np.abs(r.axial_force_qs - r.axial_force_rigid).max(axis=0) < 1e-5 * peak)


@pytest.mark.parametrize("k", [1, 3, 5])
def test_odd_subdivisions_midpoint_of_timoshenko_members_equals_rigid_body(k):
    """As above with shear areas (A/2, a thin tube's) on every section: Timoshenko members,
    whose mass has rotary inertia.  The equilibrium of the half element interpolates the
    acceleration with the element's own (Timoshenko) shapes and adds the rotary inertia's
    couple; with the cubic Hermite shapes and no couple the midpoint moment was off by
    1.3e-4 (k = 1), 4.3e-5 (k = 3) and 2.6e-5 (k = 5) of its peak."""
    import dataclasses
    s = triangular_truss()
    s = s.variant(sections=tuple(dataclasses.replace(c, shear_area_y=0.5 * c.area,
                                                     shear_area_z=0.5 * c.area)
                                 for c in s.sections))
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 1.0, 40, include_end=True)
    r = transient_response(s, m, k=k)
    ref = r.moment_rigid[:, 0]
    assert ref.max() > 1.0
    assert np.abs(r.moment_qs[:, 0] - ref).max() < 1e-10 * ref.max()


def test_odd_subdivisions_midpoint_3d_both_bending_planes():
    """Reference: the rigid-body midpoint moments of the slewing double-octahedral bay (3-D,
    both bending planes, sparse path) with three elements per member."""
    r = double_octahedron_slew(0.5, 0.025, k=3)
    passive = ~np.isin(np.arange(r.structure.n_members),
                       [a.member for a in r.structure.extensions["active_members"]])
    mr = r.moment_rigid[:, passive]
    assert np.abs(r.moment_qs[:, passive] - mr).max() < 1e-8 * mr.max()


def test_odd_subdivisions_dynamic_midpoint_moment_converges():
    """Reference: the same FE model refined to 16 elements per member, where the midpoint is a
    station.  With 3 elements the dynamic midpoint-moment peak is within 1 % of it (the mean
    of the middle element's end values was 13 % low)."""
    s = _two_bar()
    mot = _sine(s, 0.01, 20.0, 0.1, 5e-5)
    fine = transient_response(s, mot, k=16)
    coarse = transient_response(s, mot, k=3)
    ref = np.abs(fine.moment[:, 1]).max()
    assert ref > 10.0
    assert abs(np.abs(coarse.moment[:, 1]).max() - ref) < 0.01 * ref


# ---------------------------------------------------------------------- independent Newmark
def _newmark(s, mot, alpha, beta, frozen=False):
    """Average-acceleration Newmark on the per-step K and M of trussfe.fem (discretise,
    mass_matrix; the first step's when ``frozen``), truss bars, with the d'Alembert load
    f_g − M a of the node accelerations."""
    kin = simulate(s, mot, actuators=False).kinematics
    s0 = massless_active(s)
    dt = float(mot.time[1] - mot.time[0])
    out = []
    for n in range(mot.n_steps):
        geometry = kin.coords[0 if frozen else n][:, :s.dim]
        fe = discretise(s0.with_coords(geometry), "truss")
        K, M = fe.stiffness().toarray(), mass_matrix(fe).toarray()
        ar = np.zeros(fe.n_dof)
        ar[fe.node_dofs[:, :s.dim]] = kin.acceleration[n][:, :s.dim]
        f = fe.load_vector() - M @ ar
        fr = fe.free
        Kf, Mf, ff = K[np.ix_(fr, fr)], M[np.ix_(fr, fr)], f[fr]
        Cf = alpha * Mf + beta * Kf
        if n == 0:
            u, v, a = np.linalg.solve(Kf, ff), np.zeros(fr.size), np.zeros(fr.size)
        else:
            up, vp = u + dt * v + 0.25 * dt * dt * a, v + 0.5 * dt * a
            a = np.linalg.solve(Mf + 0.5 * dt * Cf + 0.25 * dt * dt * Kf,
                                ff - Kf @ up - Cf @ vp)
            u, v = up + 0.25 * dt * dt * a, vp + 0.5 * dt * a
        U = np.zeros(fe.n_dof)
        U[fr] = u
        out.append(U[fe.node_dofs[:, :s.dim]])
    return np.array(out)


@pytest.mark.parametrize("update", ["frozen", "per-step"])
def test_damped_history_equals_hand_written_newmark(update):
    """Reference: a hand-written Newmark (β = 1/4, γ = 1/2) on the K(t), M(t) of
    trussfe.fem with Rayleigh damping C = αM + βK, rotating two-bar truss."""
    s = _two_bar()
    mot = _sine(s, 0.01, 20.0, 0.06, 2e-4)
    alpha, beta = 20.0, 2e-5
    r = transient_response(s, mot, bar_model="truss", update=update, damping=(alpha, beta))
    U = _newmark(s, mot, alpha, beta, frozen=update == "frozen")
    assert_allclose(r.displacement, U, rtol=0, atol=1e-9 * np.abs(U).max())


def test_single_dof_viscous_damping_closed_form():
    """Reference: the exact response of m ü + c u̇ + k u = m a Ω² sin Ωt from rest
    (steady state plus the damped free vibration fitting u(0) = u̇(0) = 0), c = αm from
    mass-proportional Rayleigh damping with ζ = 0.05 at the natural frequency."""
    m, k = 10.0, 1.0e5
    s = sdof_bar(1.0, m, k)
    amp, f = 0.01, 7.0
    mot = _sine(s, amp, f, 0.6, 5e-5)
    wn = math.sqrt(k / m)
    zeta = 0.05
    r = transient_response(s, mot, bar_model="truss", update="frozen",
                           damping=(2 * zeta * wn, 0.0))
    W = 2 * math.pi * f
    p0 = m * amp * W * W
    rr = W / wn
    den = (1 - rr * rr) ** 2 + (2 * zeta * rr) ** 2
    A = p0 / k * (1 - rr * rr) / den                 # sin coefficient of the steady state
    B = -p0 / k * 2 * zeta * rr / den                 # cos coefficient
    wd = wn * math.sqrt(1 - zeta * zeta)
    C1 = -B
    C2 = (zeta * wn * C1 - A * W) / wd
    t = r.time
    u = (A * np.sin(W * t) + B * np.cos(W * t)
         + np.exp(-zeta * wn * t) * (C1 * np.cos(wd * t) + C2 * np.sin(wd * t)))
    N = k * u
    assert np.abs(r.axial_force[:, 0] - N).max() < 1e-4 * np.abs(N).max()


def test_rayleigh_damping_against_opensees():
    """Reference: OpenSeesPy, truss elements with consistent mass and Rayleigh damping
    (``-doRayleigh 1``), Newmark average acceleration, the same d'Alembert loads applied as
    nodal load histories after a static step under the first one (frozen geometry)."""
    ops = pytest.importorskip("openseespy.opensees")
    s = _two_bar()
    dt = 2e-4
    mot = _sine(s, 0.01, 20.0, 0.1, dt)
    alpha, beta = 20.0, 2e-5
    r = transient_response(s, mot, bar_model="truss", update="frozen", damping=(alpha, beta))
    kin = simulate(s, mot, actuators=False).kinematics
    aB = kin.acceleration[:, 2, :2]
    rhoA = 7850.0 * float(s.area[1])
    Lf = float(s.lengths()[1])
    mB = 5.0
    # consistent mass: B carries mB + ρAL/3 of the follower (C does not move), weight half
    fB = (np.array([0.0, -(mB + rhoA * Lf / 2) * 9.81])[None]
          - (mB + rhoA * Lf / 3) * aB)
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for tag, xy in ((1, (0.0, 0.0)), (2, (2.0, 0.0)), (3, (1.0, 1.0))):
        ops.node(tag, *xy)
    ops.fix(1, 1, 1)
    ops.fix(2, 1, 1)
    ops.mass(3, mB, mB)
    ops.uniaxialMaterial("Elastic", 1, 210e9)
    A = float(s.area[0])
    ops.element("Truss", 1, 1, 3, A, 1, "-rho", 0.0, "-cMass", 1, "-doRayleigh", 1)
    ops.element("Truss", 2, 2, 3, A, 1, "-rho", rhoA, "-cMass", 1, "-doRayleigh", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, *fB[0])
    for cmd, *args in (("system", "FullGeneral"), ("numberer", "Plain"),
                       ("constraints", "Plain"), ("integrator", "LoadControl", 1.0),
                       ("algorithm", "Linear"), ("analysis", "Static")):
        getattr(ops, cmd)(*args)
    ops.analyze(1)
    ops.loadConst("-time", 0.0)
    for c in (0, 1):
        ops.timeSeries("Path", 10 + c, "-dt", dt, "-values", *(fB[:, c] - fB[0, c]))
        ops.pattern("Plain", 10 + c, 10 + c)
        ops.load(3, *((1.0, 0.0) if c == 0 else (0.0, 1.0)))
    ops.wipeAnalysis()
    for cmd, *args in (("system", "FullGeneral"), ("numberer", "Plain"),
                       ("constraints", "Plain"), ("integrator", "Newmark", 0.5, 0.25),
                       ("algorithm", "Linear"), ("analysis", "Transient")):
        getattr(ops, cmd)(*args)
    ops.rayleigh(alpha, beta, 0.0, 0.0)
    N = [[ops.eleResponse(e, "axialForce")[0] for e in (1, 2)]]
    acc = [ops.nodeAccel(3)]
    for _ in range(1, r.time.size):
        ops.analyze(1, dt)
        N.append([ops.eleResponse(e, "axialForce")[0] for e in (1, 2)])
        acc.append(ops.nodeAccel(3))
    ops.wipe()
    N = np.array(N)
    # OpenSees gives a truss element's constant force; the follower's midpoint force differs
    # from it by its own axial inertia, ρA L (a_B − a_O1)·e / 24 (O1 fixed; a_B the rigid
    # plus the elastic acceleration of B)
    ef = np.array([-1.0, 1.0]) / np.sqrt(2.0)
    N[:, 1] -= rhoA * Lf * ((aB + np.array(acc)) @ ef) / 24.0
    assert np.abs(N).max() > 500.0
    assert np.abs(N - r.axial_force).max() < 1e-9 * np.abs(N).max()
