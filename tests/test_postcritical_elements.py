"""Co-rotational elements and assembly (trussfe.nonlinear.elements).

Every tangent is checked against an independent computation: central finite differences of
the internal forces, the closed-form Hermite geometric stiffness, the FE core's ``K + Kg``.
"""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel
from trussfe.nonlinear.elements import beam2d_local, beam2d_matrices

SEC = Section(name="s", area=1e-4, Iy=2e-8, Iz=2e-8, J=4e-8, c=0.01)
MAT = Material(name="m", E=2e11, G=8e10, density=7800.0, yield_strength=2.5e8)


def _fd_tangent(model, u, h=1e-7):
    """Central differences of the internal force vector, column by column."""
    K = np.zeros((model.ndof, model.ndof))
    for j in range(model.ndof):
        up, um = u.copy(), u.copy()
        up[j] += h
        um[j] -= h
        K[:, j] = (model.evaluate(up, False)["internal"]
                   - model.evaluate(um, False)["internal"]) / (2 * h)
    return K


def _frame2d():
    """A plane portal: two columns and a beam with rigid joints, one bar brace."""
    s = build_structure([[0, 0], [0, 1], [1.2, 1.1], [1.2, 0]],
                        [(0, 1), (1, 2), (2, 3), (0, 2)], section=SEC, material=MAT,
                        supports={0: ["x", "y", "rz"], 3: ["x", "y"]},
                        loads={1: [100.0, -50.0, 0.0]},
                        is_beam=np.array([True, True, True, False]))
    return s


@pytest.mark.parametrize("case", ["truss2d", "truss3d", "pinned-beam", "frame"])
def test_tangent_equals_finite_differences(case):
    """Consistent tangent = derivative of the internal forces (central differences, rtol 1e-6
    of the largest entry: the FD truncation error at h = 1e-7 m is ~1e-9 relative)."""
    rng = np.random.default_rng(3)
    if case == "truss3d":
        s = build_structure([[0, 0, 0], [1, 0.2, 0.1], [2, 0, 0.3], [1, 1, 0.5]],
                            [(0, 1), (1, 2), (0, 3), (2, 3), (1, 3)], section=SEC, material=MAT,
                            supports={0: "xyz", 2: "xyz"})
        m = NonlinearModel(s)
    elif case == "frame":
        m = NonlinearModel(_frame2d(), subdivisions=3)
    else:
        s = build_structure([[0, 0], [1, 0.2], [2, 0]], [(0, 1), (1, 2)], section=SEC,
                            material=MAT, supports={0: "xy", 2: "xy"})
        m = NonlinearModel(s, bar_model="truss" if case == "truss2d" else "pinned-beam",
                           subdivisions=4)
    u = rng.normal(size=m.ndof) * 0.02                    # large rotations included
    K = m.evaluate(u)["tangent"].toarray()
    assert_allclose(K, _fd_tangent(m, u), atol=1e-6 * np.abs(K).max())
    assert_allclose(K, K.T, atol=1e-12 * np.abs(K).max())


def test_rigid_rotation_gives_no_force():
    """A rigid-body rotation of 60° leaves a co-rotational beam and bar unstrained."""
    s = build_structure([[0, 0], [1, 0.3]], [(0, 1)], section=SEC, material=MAT,
                        supports={0: "xy"})
    m = NonlinearModel(s, bar_model="pinned-beam", subdivisions=3)
    a = np.pi / 3
    R = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    u = np.zeros(m.ndof)
    u[: m.n_points * 2] = (m.X @ R.T - m.X).ravel()
    u[m.n_points * 2:] = a
    # round-off floor: EA = 2e7 N times machine epsilon ~ 1e-9 N
    assert_allclose(m.evaluate(u, False)["internal"], 0.0, atol=1e-12 * SEC.area * MAT.E)


def test_beam_reference_tangent_is_linear_plus_consistent_geometric_stiffness():
    """At the undeformed state the co-rotational beam's tangent with axial force N equals the
    Euler–Bernoulli stiffness plus the consistent geometric stiffness
    N/(30L)[[36, 3L, -36, 3L], [3L, 4L², -3L, -L²], ...] (Przemieniecki; Crisfield vol. 1)."""
    L, EA, EI, N = 0.7, 3e6, 150.0, -1234.0
    X = np.array([[0.0, 0.0], [L, 0.0]])
    out = beam2d_local(X, np.array([[0, 1]]), np.zeros((1, 2)), X)
    _, k, _, _ = beam2d_matrices(*out, np.array([EA]), np.array([EI]),
                                 N_override=np.array([N]))
    idx = [1, 2, 4, 5]                                     # v1, θ1, v2, θ2
    Kb = EI / L ** 3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                                 [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
    Kg = N / (30 * L) * np.array([[36, 3 * L, -36, 3 * L], [3 * L, 4 * L * L, -3 * L, -L * L],
                                  [-36, -3 * L, 36, -3 * L], [3 * L, -L * L, -3 * L, 4 * L * L]])
    assert_allclose(k[0][np.ix_(idx, idx)], Kb + Kg, rtol=1e-12, atol=1e-9)
    assert_allclose(k[0][np.ix_([0, 3], [0, 3])], EA / L * np.array([[1, -1], [-1, 1]]),
                    rtol=1e-12)


def test_truss_tangent_equals_fe_core_stiffness_plus_geometric_stiffness():
    """The nonlinear tangent at the reference state with the linear static forces equals the
    FE core's ``K + Kg(N)`` (trussfe.fem) for the 3-D lattice dome, to round-off."""
    fem = pytest.importorskip("trussfe.fem.discretisation")
    static = pytest.importorskip("trussfe.fem.static")
    from trussfe._resources import mesh_path
    from trussfe.io.model_file import read_model
    s = read_model(mesh_path("postcritical_dome.toml"))
    fe = fem.discretise(s, "truss")
    st = static.solve_static(s, "truss")
    m = NonlinearModel(s)
    N = st.axial_force
    idx = fe.node_dofs[:, :3].ravel()
    K_fe = (fe.stiffness() + fe.geometric_stiffness(N))[idx][:, idx].toarray()
    K_nl = m.reference_tangent(N).toarray()
    assert_allclose(K_nl, K_fe, atol=1e-12 * np.abs(K_fe).max())
    # and the linear axial forces of the two agree
    free = np.flatnonzero(m.free)
    u = np.zeros(m.ndof)
    u[free] = sp.linalg.spsolve(m.reference_tangent()[free][:, free].tocsc(), m.load[free])
    assert_allclose(m.linear_axial_forces(u)[0], N, rtol=1e-9, atol=1e-9 * np.abs(N).max())
