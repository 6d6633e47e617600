"""Validation of the post-critical analysis against closed-form and independent solutions
(trussfe.studies.postcritical; the same numbers appear in ``trussfe validate``)."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.studies import postcritical as R


@pytest.fixture(scope="module")
def von_mises():
    return R.von_mises_truss()


@pytest.fixture(scope="module")
def column():
    return R.euler_column()


@pytest.fixture(scope="module")
def lattice():
    return R.lattice_progressive()


def test_von_mises_limit_load_closed_form(von_mises):
    """Limit load of the two-bar truss, ℓ³ = a²L (dP/dv = 0 of P = 2EAw(1/ℓ − 1/L)):
    381.0871904 N for a = 1, h = 0.1, EA = 1e6; located by bisection of the inertia change to
    a step fraction of 1e-7, so the load (flat at the maximum) agrees to ~1e-10."""
    assert von_mises["limit_points"] == 2
    assert_allclose(von_mises["limit_load"], von_mises["limit_load_closed_form"], rtol=1e-9)
    assert_allclose(von_mises["lower_limit_load"], -von_mises["limit_load_closed_form"],
                    rtol=1e-9)
    # the deflection at a flat maximum is located less sharply: O(sqrt(load error))
    assert_allclose(von_mises["limit_deflection"], von_mises["limit_deflection_closed_form"],
                    rtol=1e-5)


def test_von_mises_full_snap_through_path(von_mises):
    """Every arc-length point of the path — rise, snap-through, negative branch, tension
    branch beyond v = 2h — lies on the closed form P(v) to the Newton tolerance (1e-9)."""
    assert von_mises["final_deflection"] > 0.2              # beyond the mirror image (v = 2h)
    assert von_mises["path_max_error"] < 1e-9


def test_euler_column_imperfect_path_approaches_elastica(column):
    """Imperfect column (L/1000 in the first mode): at mid-span deflections of 0.2 L and
    0.3 L the load ratio is within the imperfection's influence, of order e0/δ = 5e-3 and
    3.3e-3, of the inextensible elastica (Timoshenko & Gere §2.7)."""
    for k, e0_over_d in ((2, 5e-3), (3, 3.4e-3)):
        assert_allclose(column[f"imperfect_load_ratio_at_{k}"],
                        column[f"elastica_load_ratio_at_{k}"], rtol=e0_over_d)
    # ... and the imperfect load stays below the perfect elastica's (a softer path)
    assert column["imperfect_load_ratio_at_1"] < column["elastica_load_ratio_at_1"]


def test_euler_column_perfect_bifurcation_and_branch(column):
    """Perfect column: the inertia count finds a bifurcation at P_E(1 + P_E/EA), the
    extensible column's critical load (pre-buckling shortening), within the 16-element
    discretisation error 2.1e-6 of the linear buckling load; the branch taken on the
    eigenvector follows the elastica within the extensibility P_E/EA = 4.0e-4 (+ 1e-4)."""
    assert_allclose(column["bifurcation_load_ratio"], column["extensible_euler_ratio"],
                    rtol=3e-6)
    assert column["branch_max_deflection"] > 0.3
    assert column["branch_max_error"] < 5e-4


def test_linear_buckling_agrees_with_euler_and_fe_core():
    """First linear buckling factor of the column: Euler's π²EI/L² within the Hermite
    discretisation error (16 elements: 2.1e-6, fourth-order convergence), and the FE core's
    eigen solution (trussfe.cli.cmd_buckling when installed) to 1e-8."""
    out = R.linear_buckling_agreement()
    assert_allclose(out["load_factor"], out["euler_load_factor"], rtol=3e-6)
    assert_allclose(out["second_load_factor"], out["second_euler_load_factor"], rtol=5e-5)
    if "fe_core_load_factor" in out:
        assert_allclose(out["load_factor"], out["fe_core_load_factor"], rtol=1e-8)


def test_linear_buckling_equals_fe_core_matrices():
    """The same eigenproblem built from the FE core's K and Kg (trussfe.fem) gives the same
    first two load factors to 1e-9: the tangent at the reference state is K + Kg."""
    fem = pytest.importorskip("trussfe.fem.discretisation")
    static = pytest.importorskip("trussfe.fem.static")
    import scipy.linalg as sla
    from trussfe._resources import mesh_path
    from trussfe.io.model_file import read_model
    s = read_model(mesh_path("postcritical_euler_column.toml"))
    fe = fem.discretise(s, "pinned-beam", 16)
    st = static.solve_static(s, "pinned-beam", 16)
    N = st.axial_force[fe.element_member]
    f = fe.free
    K = fe.stiffness()[f][:, f].toarray()
    Kg = fe.geometric_stiffness(N)[f][:, f].toarray()
    mu = sla.eigh(-Kg, K, eigvals_only=True)
    lam_fe = np.sort(1.0 / mu[mu > 1e-12])[:2]
    out = R.linear_buckling_agreement()
    assert_allclose([out["load_factor"], out["second_load_factor"]], lam_fe, rtol=1e-9)


def test_lattice_progressive_failure_events(lattice):
    """The dome loses four apex bars by buckling (removal law) and becomes a one-degree-of-
    freedom mechanism; every failure — on the path or during the redistribution at constant
    λ — is located where the member force equals its P_cr (event tolerance 1e-6)."""
    assert lattice["failures"] == 4
    assert lattice["failures_by_redistribution"] >= 1
    assert lattice["event_force_error"] <= 1e-6
    # A1 (P_cr = 2600 N) fails first; linear apex-bar force 849.8 N per unit λ, plus the
    # geometric nonlinearity of the shallow apex (a few per cent)
    assert 2600 / 849.8 * 0.95 < lattice["first_failure_load_factor"] < 2600 / 849.8
    assert lattice["mechanism_load_factor"] >= lattice["first_failure_load_factor"]


def test_lattice_equilibrium_form_of_the_mechanism(lattice):
    """The apex left on two bars is a pendulum about the axis through their far ends; its
    equilibrium form under the dead load is straight below that axis (analytic, 1e-10), with
    both bars in tension, a stable potential minimum, and Bᵀt = λf to 1e-12."""
    assert lattice["equilibrium_form_found"] == 1.0
    assert lattice["apex_bars_left"] == 2
    assert lattice["apex_form_error"] < 1e-10
    assert_allclose(lattice["apex_form_z"], lattice["apex_form_z_expected"], rtol=1e-10)
    assert lattice["apex_bars_in_tension"] == 1.0
    assert lattice["equilibrium_stable"] == 1.0
    assert lattice["equilibrium_residual"] < 1e-12


def test_portal_frame_southwell_plot_gives_the_sway_buckling_load(tmp_path):
    """A rigid-jointed portal frame (co-rotational beams, 6 per member) under two column
    loads and a 0.1 % lateral disturbance: Southwell's plot (δ/λ against δ is a straight line
    of slope 1/λ_cr for small sway δ; Southwell 1932) recovers the linear sway buckling load
    factor within 1 % — the nonlinear frame path and the eigen analysis agree."""
    from trussfe.io.model_file import read_model
    from trussfe.nonlinear import NonlinearModel, linear_buckling, run_postcritical
    p = tmp_path / "frame.toml"
    p.write_text("""
[model]
dimension = 2
[materials.steel]
E = 2.1e11
[sections.ipe]
area = 2.85e-3
Iy = 1.94e-5
[nodes]
a = [0.0, 0.0]
b = [0.0, 4.0]
c = [6.0, 4.0]
d = [6.0, 0.0]
[members]
L = { nodes = ["a", "b"], section = "ipe", material = "steel", type = "beam" }
T = { nodes = ["b", "c"], section = "ipe", material = "steel", type = "beam" }
R = { nodes = ["c", "d"], section = "ipe", material = "steel", type = "beam" }
[supports]
a = ["x", "y", "rz"]
d = ["x", "y"]
[loads]
b = [100.0, -100000.0]
c = [0.0, -100000.0]
""")
    s = read_model(p)
    lam_cr = linear_buckling(NonlinearModel(s, subdivisions=6), 1)[0][0]
    r = run_postcritical(s, steps=80, subdivisions=6, monitor="b:x")
    lam, d = r.load_factors, r.displacement()
    small = (d > 0.002) & (d < 0.03)
    assert small.sum() >= 5
    slope = np.polyfit(d[small], d[small] / lam[small], 1)[0]
    assert_allclose(1.0 / slope, lam_cr, rtol=1e-2)
    # an imperfect elastic frame stays below λ_cr at moderate sway (δ < h/40); at large sway
    # its stable post-buckling path rises above it (here from δ ≈ 0.3 m)
    assert lam[d < 0.1].max() < lam_cr
