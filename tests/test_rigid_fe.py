# SPDX-License-Identifier: MIT
"""The rigid-body model at rest against the finite-element static solution:
truss bar model without gravity, pinned-beam bar model with gravity — every force to 1e-9
relative to the largest force."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.fem.static import solve_static
from trussfe.studies.lacy_rigid import double_octahedron, triangular_truss
from trussfe.rigid.sections import section_forces
from trussfe.rigid.simulate import simulate

RTOL = 1e-9


def _passive(s):
    """FE members are uniform tubes: compare on the structure without active-member bodies."""
    return s.without_extensions("active_members")


CASES_TRUSS = {
    "triangle_table_3_2": lambda: triangular_truss(mass=0.0, gravity=False, load=-98.1),
    "octahedron_slewed": lambda: double_octahedron((1.1079, 1.2289, 1.2289), top_load=44.498),
}
CASES_BEAM = {
    "triangle_with_weight": lambda: triangular_truss(),
    "octahedron_standing": lambda: double_octahedron((1.2289, 1.1079, 1.1079), top_load=46.0,
                                                     gravity=9.81, top_masses=2.0),
    "octahedron_hanging": lambda: double_octahedron(gravity=-9.81, top_load=-46.0),
}


@pytest.mark.parametrize("case", list(CASES_TRUSS))
def test_truss_bar_model_no_gravity(case):
    s = _passive(CASES_TRUSS[case]())
    fe = solve_static(s, "truss")
    r = simulate(s)
    scale = np.abs(fe.reactions).max()
    assert_allclose(r.forces.reactions[0], fe.reactions[:, : s.dim], rtol=0, atol=RTOL * scale)
    assert_allclose(r.midpoint_axial_force[0], fe.axial_force, rtol=0, atol=RTOL * scale)


@pytest.mark.parametrize("case", list(CASES_BEAM))
def test_pinned_beam_bar_model_with_gravity(case):
    """Reactions, end axial forces, and axial force, shear and bending moment magnitudes at
    every FE station along every member."""
    s = _passive(CASES_BEAM[case]())
    fe = solve_static(s, "pinned-beam")
    r = simulate(s)
    scale = np.abs(fe.reactions).max()
    tol = dict(rtol=0, atol=RTOL * scale)
    assert_allclose(r.forces.reactions[0], fe.reactions[:, : s.dim], **tol)
    assert_allclose(r.forces.tension_start[0], fe.end_forces[:, 0, 0], **tol)
    assert_allclose(r.forces.tension_end[0], fe.end_forces[:, 1, 0], **tol)
    x = fe.station_x                                     # from the start node
    ok = np.isfinite(x).all(axis=0)
    x = x[:, ok]
    L = s.lengths()
    sf = section_forces(s, r.kinematics, r.forces, r.bodies, positions=L[:, None] - x)
    fsf = fe.section_forces[:, ok]
    assert_allclose(sf.tension[0], fsf[..., 0], **tol)
    assert_allclose(sf.shear_magnitude[0], np.hypot(fsf[..., 1], fsf[..., 2]), **tol)
    assert_allclose(sf.moment_magnitude[0], np.hypot(fsf[..., 4], fsf[..., 5]), **tol)
