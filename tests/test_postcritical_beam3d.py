"""Co-rotational 3-D beams (trussfe.nonlinear.beam3d and NonlinearModel in 3-D).

Sources of the expected values are named in each test: the linear frame stiffness and the
consistent geometric stiffness of ``trussfe.fem`` (an independent scikit-fem assembly), central
finite differences of the internal forces, rigid-body invariance, and the closed-form solution
of a cantilever rolled into a circle by an end moment (radius EI/M).
"""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError
from trussfe.fem import discretise
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, follow_path
from trussfe.nonlinear.beam3d import (compose, expm_so3, inverse_tangent, logm_so3,
                                      unwrap_rotation)

MAT = Material(name="steel", E=2.1e11, G=8.1e10, density=7850.0, yield_strength=math.nan)
#: a section with unequal bending stiffnesses, so that swapped axes would show
SEC = Section(name="rect", area=2.0e-4, Iy=3.0e-9, Iz=1.1e-8, J=4.0e-9, c=0.01)


def _frame(is_beam=True, **kw):
    """Three oblique members meeting at joint 1 (no member along a global axis), with an
    orientation vector on one of them."""
    X = [[0.0, 0.0, 0.0], [0.7, 0.4, 0.5], [1.3, -0.2, 0.9], [0.2, 1.1, 1.4]]
    s = build_structure(X, [(0, 1), (1, 2), (1, 3)], section=SEC, material=MAT,
                        is_beam=is_beam, supports={0: ["x", "y", "z", "rx", "ry", "rz"],
                                                   2: ["x", "y", "z"], 3: ["x", "y", "z"]},
                        **kw)
    return s.with_member_data(orientation={2: (0.3, -0.5, 0.8)})


# ------------------------------------------------------------------------ rotations
def test_rotation_vector_round_trip_and_unwrapping():
    """log(exp(ψ)) = ψ for |ψ| < π, near π and near 0; composing spins about a fixed axis
    adds the angles beyond π (no wrap-around jump)."""
    rng = np.random.default_rng(3)
    axes = rng.normal(size=(6, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    ang = np.array([1e-9, 1e-3, 0.5, 2.0, np.pi - 1e-7, 3.0])
    psi = axes * ang[:, None]
    assert_allclose(logm_so3(expm_so3(psi)), psi, rtol=0, atol=2e-8)   # near-π conditioning
    n = axes[0]
    p = np.zeros(3)
    for _ in range(9):                                    # 9 × 0.8 rad = 7.2 rad > 2π
        p = compose(p, 0.8 * n)
    assert_allclose(p, 7.2 * n, rtol=1e-12, atol=1e-12)
    assert_allclose(unwrap_rotation(logm_so3(expm_so3(7.2 * n)), 7.0 * n), 7.2 * n,
                    rtol=1e-12)


def test_inverse_tangent_maps_spins_to_rotation_vector_increments():
    """δθ = Tₛ⁻¹(θ) δw: exp(θ + Tₛ⁻¹ δw) = exp(δw) exp(θ) to first order (finite
    difference, h = 1e-6, error O(h²))."""
    theta = np.array([0.4, -0.9, 1.3])
    w = np.array([0.2, 0.5, -0.3])
    h = 1e-6
    lhs = (expm_so3(theta + h * inverse_tangent(theta) @ w) - expm_so3(theta)) / h
    rhs = (expm_so3(h * w) @ expm_so3(theta) - expm_so3(theta)) / h
    assert_allclose(lhs, rhs, rtol=0, atol=1e-6)


# ------------------------------------------------------------------------ tangent
@pytest.mark.parametrize("seed", [0, 1])
def test_reference_tangent_equals_linear_frame_stiffness_plus_consistent_kg(seed):
    """At the undeformed state the co-rotational tangent with element forces N equals the
    linear 3-D frame stiffness K of trussfe.fem plus its consistent geometric stiffness
    K_g(N) (scikit-fem assembly of ∫EA u'v', ∫EI v''w'', ∫GJ θ'ψ', ∫N v'w'), to 1e-8 of the
    largest entry; one element per member in both models so that the DOFs coincide."""
    s = _frame()
    nl = NonlinearModel(s, subdivisions=1)
    fe = discretise(s, subdivisions=1)
    N = np.random.default_rng(seed).uniform(-2e4, 2e4, size=3)
    # the DOF map: fem node_dofs (node, 6) -> NonlinearModel DOFs
    n = s.n_nodes
    has = fe.node_dofs[:, 3] >= 0
    fe_idx = np.concatenate([fe.node_dofs[:, :3].ravel(), fe.node_dofs[has, 3:].ravel()])
    nl_idx = np.concatenate([np.arange(3 * n),
                             (3 * n + 3 * nl.joint_slot[has][:, None]
                              + np.arange(3)).ravel()])
    assert len(fe_idx) == fe.n_dof == nl.ndof
    K_fe = (fe.stiffness() + fe.geometric_stiffness(N)).toarray()[np.ix_(fe_idx, fe_idx)]
    K_nl = nl.reference_tangent(axial_force_b=N).toarray()[np.ix_(nl_idx, nl_idx)]
    scale = np.abs(K_fe).max()
    assert_allclose(K_nl, K_fe, rtol=0, atol=1e-8 * scale)
    # and without axial force: the linear stiffness alone
    assert_allclose(nl.reference_tangent().toarray()[np.ix_(nl_idx, nl_idx)],
                    fe.stiffness().toarray()[np.ix_(fe_idx, fe_idx)], rtol=0,
                    atol=1e-8 * scale)


def _deformed_state(nl, seed=2, rotation=None):
    """A large deformed state: a rigid rotation of everything plus random displacements and
    spins (rotations composed multiplicatively)."""
    rng = np.random.default_rng(seed)
    u = np.zeros(nl.ndof)
    t = nl.n_points * 3
    Q = expm_so3(rotation) if rotation is not None else np.eye(3)
    u[:t] = (nl.X @ Q.T - nl.X + 0.02 * rng.normal(size=nl.X.shape)).ravel()
    psi = np.zeros((nl.n_rot, 3)) + (rotation if rotation is not None else 0.0)
    u[t:] = compose(psi, 0.3 * rng.normal(size=psi.shape)).ravel()
    return u


@pytest.mark.parametrize("bar_model, is_beam", [("truss", True), ("pinned-beam", False)])
def test_tangent_matches_finite_differences_at_a_deformed_state(bar_model, is_beam):
    """The assembled tangent equals the central finite-difference derivative of the internal
    forces along each DOF (spins composed multiplicatively, h = 1e-6): to 1e-6 of the
    largest entry.  Frame members and pinned-beam members (released ends, held twist), four
    elements each."""
    s = _frame(is_beam=is_beam)
    nl = NonlinearModel(s, bar_model=bar_model, subdivisions=4)
    u = _deformed_state(nl, rotation=np.array([0.6, -0.8, 1.1]))
    res = nl.evaluate(u)
    K = res["tangent"].toarray()
    free = np.flatnonzero(nl.free)
    h = 1e-6
    Kfd = np.zeros((nl.ndof, free.size))
    for j, dof in enumerate(free):
        e = np.zeros(nl.ndof)
        e[dof] = h
        Kfd[:, j] = (nl.evaluate(nl.add(u, e), tangent=False)["internal"]
                     - nl.evaluate(nl.add(u, -e), tangent=False)["internal"]) / (2 * h)
    Kf = K[np.ix_(free, free)]
    assert_allclose(Kf, Kfd[free], rtol=0, atol=1e-6 * np.abs(Kf).max())
    # the geometric terms matter at this state: the tangent is far from the reference one
    K0 = nl.reference_tangent().toarray()[np.ix_(free, free)]
    assert np.abs(Kf - K0).max() > 1e-2 * np.abs(Kf).max()


@pytest.mark.parametrize("bar_model, is_beam", [("truss", True), ("pinned-beam", False)])
def test_large_rigid_rotation_gives_no_internal_forces(bar_model, is_beam):
    """Rigid-body invariance: every point rotated by 2.6 rad about the axis (1, −2, 0.7) and
    translated, every rotation slot turned by the same rotation — internal forces vanish to
    round-off: below EA · 1e-12 (a strain of 1e-12; a 1e-6 strain would give EA · 1e-6)."""
    s = _frame(is_beam=is_beam)
    nl = NonlinearModel(s, bar_model=bar_model, subdivisions=3)
    axis = np.array([1.0, -2.0, 0.7])
    psi = 2.6 * axis / np.linalg.norm(axis)
    Q = expm_so3(psi)
    u = np.zeros(nl.ndof)
    t = nl.n_points * 3
    u[:t] = (nl.X @ Q.T - nl.X + np.array([0.3, -1.0, 2.0])).ravel()
    rot = np.tile(psi, (nl.n_rot, 1))
    if bar_model == "pinned-beam":
        # a member released at both ends keeps no rotation about its own axis at its start:
        # its points take the swing part S = R exp(−τ e1) of the rigid rotation (a uniform
        # twist of the whole member, which strains nothing)
        al = np.linalg.norm(psi)
        w, v = math.cos(al / 2), math.sin(al / 2) * psi / al          # quaternion of R
        for mem in range(s.n_members):
            e1 = s.unit_vectors()[mem]
            tau = 2 * math.atan2(v @ e1, w)
            sw = logm_so3(Q @ expm_so3(-tau * e1))
            rot[nl.b_slot[nl.b_member == mem].ravel()] = sw
    add = nl.slot_additive
    rot[add] = np.einsum("sji,sj->si", nl.slot_basis[add], rot[add])
    assert add.any() == (bar_model == "pinned-beam")
    assert_allclose(rot[add][:, 0], 0.0, atol=1e-12)                 # representable
    u[t:] = rot.ravel()
    res = nl.evaluate(u)
    EA = float(MAT.E * SEC.area)
    assert np.abs(res["internal"]).max() < 1e-12 * EA
    assert np.abs(res["b_force"]).max() < 1e-12 * EA
    assert np.abs(res["b_moment"]).max() < 1e-12 * EA * 0.01


# ------------------------------------------------------------------------ benchmark
def test_cantilever_rolls_into_a_circle_under_end_moment():
    """Classical co-rotational benchmark: a cantilever of length L under an end moment
    M = 2πEI/L about a fixed axis perpendicular to it rolls up into a full circle of radius
    EI/M = L/2π, its tip returning to the root (closed form: constant curvature M/EI).  Beam
    and moment axes are oblique to the global axes; 20 elements, load control.  Tip within
    1e-3 L of the root; every point on the circle to 1e-3 L; tip rotation 2πλ about the
    moment axis along the path."""
    L = 1.0
    a = np.array([2.0, 1.0, -1.5])
    a /= np.linalg.norm(a)
    n = np.cross(a, np.array([0.3, -0.4, 1.0]))
    n /= np.linalg.norm(n)                                  # moment axis ⊥ beam
    sec = Section(name="tube", area=3.0e-4, Iy=2.0e-8, Iz=2.0e-8, J=4.0e-8, c=0.02)
    EI = MAT.E * sec.Iy
    M = 2 * np.pi * EI / L
    s = build_structure([[0.0, 0.0, 0.0], list(L * a)], [(0, 1)], section=sec,
                        material=MAT, is_beam=True,
                        supports={0: ["x", "y", "z", "rx", "ry", "rz"]},
                        loads={1: [0.0, 0.0, 0.0, *(M * n)]})
    nl = NonlinearModel(s, subdivisions=20)
    res = follow_path(nl, "load", steps=40, step=0.05, max_load_factor=1.0,
                      locate_critical=False)
    assert_allclose(res.load_factors[-1], 1.0, rtol=1e-12)
    u = res.path[-1].u
    x = nl.positions(u)
    assert np.linalg.norm(x[1] - x[0]) < 1e-3 * L
    # all points on the circle through the root, tangent a, centre R·(n × a)
    R = EI / M
    centre = R * np.cross(n, a)
    assert_allclose(np.linalg.norm(x - centre, axis=1), R, rtol=0, atol=1e-3 * L)
    # out of the plane ⊥ n: a discretisation error of the element frame's twist definition
    # (q averaged from the end triads), 8.9e-6 L with 20 elements, 5.6e-7 L with 40 (O(h⁴))
    assert np.abs((x - x[0]) @ n).max() < 2e-5 * L
    # end rotations 2πλ about n (the rotation vector of a turn near 2π has no definite axis,
    # so the rotation matrices are compared)
    tip = nl.n_points * 3 + 3 * nl.joint_slot[1]
    for p in res.path[1:]:
        assert_allclose(expm_so3(p.u[tip:tip + 3]), expm_so3(2 * np.pi * p.load_factor * n),
                        rtol=0, atol=1e-4)


# ------------------------------------------------------------------------ Euler column
@pytest.fixture(scope="module")
def column3d():
    from trussfe.studies import postcritical as R
    return R.euler_column_3d()


def test_3d_euler_column_bifurcation_and_branch_follow_the_elastica(column3d):
    """Perfect 3-D column on the oblique axis (1, 2, 2)/3: bifurcation at the extensible
    column's P_E(1 + P_E/EA) (within the 16-element discretisation error 2.1e-6 of the linear
    buckling load); the branch taken along the eigenvector follows the elastica (Timoshenko &
    Gere §2.7) within the extensibility P_E/EA = 4.0e-4 (+ 1e-4), up to δ = 0.35 L."""
    assert_allclose(column3d["reference_over_euler"], 1.0, rtol=1e-12)
    assert_allclose(column3d["bifurcation_load_ratio"], column3d["extensible_euler_ratio"],
                    rtol=3e-6)
    assert_allclose(column3d["linear_buckling_ratio"], 1.0, rtol=3e-6)
    assert column3d["branch_max_deflection"] > 0.35
    assert column3d["branch_max_error"] < 5e-4


def test_3d_euler_column_imperfect_path_matches_the_plane_column(column3d):
    """Imperfect 3-D column (L/1000 in the first mode): within e0/δ of the elastica at
    δ = 0.2 L and 0.3 L, like the plane column; and the same path as the 2-D co-rotational
    beam (an independent, plane element: trussfe.nonlinear.elements.beam2d_matrices) to 2e-4
    — the difference being the guide links and the path points' interpolation."""
    from trussfe.studies import postcritical as R
    plane = R.euler_column()
    for k, e0_over_d in ((2, 5e-3), (3, 3.4e-3)):
        key = f"imperfect_load_ratio_at_{k}"
        assert_allclose(column3d[key], column3d[f"elastica_load_ratio_at_{k}"],
                        rtol=e0_over_d)
        assert_allclose(column3d[key], plane[key], rtol=2e-4)


# ------------------------------------------------------------------------ command line
def test_three_controls_trace_the_same_3d_path_from_the_command_line(tmp_path):
    """``trussfe postcritical`` on the 3-D column with load, displacement and arc-length
    control: every point of the load- and displacement-controlled paths lies on the
    arc-length path (λ interpolated, monotone cubic, at the same top displacement: to 2e-4,
    the interpolation error between arc-length points), and the JSON follows docs/json.md."""
    from scipy.interpolate import PchipInterpolator
    from trussfe.cli import main
    from trussfe import api
    model = str(__import__("trussfe._resources", fromlist=["mesh_path"])
                .mesh_path("postcritical_euler_column_3d.toml"))
    runs = (("arc-length", dict(steps=150, step=1e-3, max_step=4e-3)),
            ("load", dict(steps=12)), ("displacement", dict(steps=20)))
    docs = {c: api.postcritical(model, control=c, max_load_factor=1.2, **kw).to_dict()
            for c, kw in runs}

    def top(doc):
        return (np.array([p["load_factor"] for p in doc["path"]]),
                np.array([-p["displacements"]["top"][2] for p in doc["path"]]))
    lam_a, w_a = top(docs["arc-length"])
    assert np.all(np.diff(w_a) > 0)                     # the top moves down monotonically
    for c in ("load", "displacement"):
        lam, w = top(docs[c])
        assert docs[c]["command"] == "postcritical" and len(lam) > 5
        on = w <= w_a.max()
        assert_allclose(lam[on], PchipInterpolator(w_a, lam_a)(w[on]), rtol=0, atol=2e-4)
    assert main(["postcritical", model, "--control", "load", "--steps", "5",
                 "--json", str(tmp_path / "c.json")]) == 0


def test_moment_on_a_pinned_node_in_3d_is_refused():
    """A moment needs a rigid beam end at its node: on a pin joint it is named."""
    s = _frame(is_beam=False, loads={1: [0.0, 0.0, 0.0, 10.0, 0.0, 0.0]})
    with pytest.raises(InputError, match="moment on a node"):
        NonlinearModel(s, bar_model="pinned-beam")


def test_pinned_beam_start_holds_its_axial_rotation():
    """A member released at both ends has its start rotation parametrised additively with the
    component along its axis fixed (no free spin about its own axis); every other slot is a
    multiplicative spin slot, and the linear buckling load of a pin-ended member agrees with
    Euler's π²EI/L² (16 elements: 2.1e-6 discretisation error)."""
    from trussfe.nonlinear import linear_buckling
    L = 1.3
    a = np.array([1.0, 2.0, 2.0]) / 3.0
    # the top guided along the axis by two 50 m bars perpendicular to it
    X = np.array([[0.0, 0.0, 0.0], L * a, L * a + 50 * np.array([2.0, -2.0, 1.0]) / 3,
                  L * a + 50 * np.array([2.0, 1.0, -2.0]) / 3])
    s2 = build_structure(X, [(0, 1), (1, 2), (1, 3)], section=SEC, material=MAT,
                         supports={0: "xyz", 2: "xyz", 3: "xyz"}, loads={1: list(-a)},
                         is_beam=np.array([True, False, False]))
    s2 = s2.with_member_data(releases={0: [True, True]})   # both ends of the beam released
    nl = NonlinearModel(s2, subdivisions=16)
    start = nl.b_slot[0, 0]
    assert nl.slot_additive.sum() == 1 and nl.slot_additive[start]
    rot0 = nl.n_points * 3
    assert not nl.free[rot0 + 3 * start] and nl.free[rot0 + 3 * start + 1]
    assert_allclose(nl.slot_basis[start][:, 0], a, rtol=1e-12)
    lam, _ = linear_buckling(nl, count=1)
    assert_allclose(lam[0], math.pi ** 2 * MAT.E * min(SEC.Iy, SEC.Iz) / L ** 2, rtol=3e-6)
