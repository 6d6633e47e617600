# SPDX-License-Identifier: MIT
"""FE (pinned-beam) section forces along Lacy's maneuvers equal the rigid-body model's internal
forces at every step (required: 1e-6 relative or better), and bad input gives a
one-line error."""
import numpy as np
import pytest

from trussfe.response.along_motion import compare_with_rigid, simulate_elastic
from trussfe.studies.lacy_elastic import base_simulation, slew
from trussfe.errors import AnalysisError, InputError, MechanismError, TrussfeError
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import L2, L3MIN, double_octahedron, triangular_truss

#: The required agreement; the agreement found is ~1e-11 (round-off of the solves).
RTOL = 1e-6


def _per_step(sim, resp):
    """Largest scaled difference of every step (scaled by each member's largest force)."""
    rs, fs = sim.sections, resp.sections
    f_scale = np.maximum(np.abs(rs.tension), np.linalg.norm(rs.shear, axis=-1)).max(axis=(0, 2))
    m_scale = np.linalg.norm(rs.moment, axis=-1).max(axis=(0, 2))
    dT = (np.abs(fs.tension - rs.tension) / f_scale[None, :, None]).max(axis=(1, 2))
    dV = (np.linalg.norm(fs.shear - rs.shear, axis=-1) / f_scale[None, :, None]).max(axis=(1, 2))
    dM = (np.linalg.norm(fs.moment - rs.moment, axis=-1)
          / m_scale[None, :, None]).max(axis=(1, 2))
    return np.maximum(np.maximum(dT, dV), dM)


@pytest.mark.parametrize("scheme", ["exact", "thesis"])
def test_triangle_base_simulation_every_step(scheme):
    """Triangular truss, Base Simulation (Lacy section 3.3, 50 steps): statics of a
    determinate truss makes the FE forces equal the rigid ones; the active base lies across
    the cantilever connection at the start (cg 1.05 m > L − L_t = 0.5 m)."""
    sim, resp = base_simulation(scheme)
    d = _per_step(sim, resp)
    assert d.shape == (50,)
    assert d.max() <= RTOL
    c = compare_with_rigid(sim.sections, resp, sim.forces.reactions)
    assert c["max"] <= RTOL and c["reactions"] <= RTOL
    # the check is not vacuous: motion changes the follower's midpoint moment by > 10 %
    mid = sim.sections.moment_magnitude[:, 0, 3]
    stat = sim.static_sections.moment_magnitude[:, 0, 3]
    assert np.abs(mid - stat).max() > 0.1 * stat.max()


@pytest.mark.parametrize("which,steps", [(1, 44), (2, 32)])
def test_double_octahedral_slews_every_step(which, steps):
    """Hanging double-octahedral bay, 46.0 N on N7-N9, synthetic Slewing Experiments 1 and
    2 (Lacy sections 5.5.1-5.5.2): every step, every member, every section within 1e-6."""
    sim, resp = slew(which, steps=steps)
    d = _per_step(sim, resp)
    assert d.shape == (steps + 1,)
    assert d.max() <= RTOL
    scale = np.abs(sim.forces.reactions).max()
    assert np.abs(resp.reactions - sim.forces.reactions).max() <= RTOL * scale
    assert np.abs(resp.midpoint_axial_force - sim.midpoint_axial_force).max() <= RTOL * scale


def _one_line(exc: TrussfeError):
    msg = str(exc)
    assert "\n" not in msg and msg


def test_motion_leaving_the_assembly():
    """An active member stretched past L1 + L4 = 4 m cannot close the triangle."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [4.5], 3.0, 10)
    with pytest.raises((AnalysisError, InputError)) as err:
        simulate_elastic(s, m)
    _one_line(err.value)


def test_mechanism_is_refused():
    """The bay without M19 (a top-plane member) is a mechanism: no forces."""
    s = double_octahedron(top_load=46.0)
    keep = np.ones(s.n_members, bool)
    keep[s.member_index("M19")] = False
    s = s.subset_members(keep).without_extensions("active_members")
    with pytest.raises((AnalysisError, MechanismError)) as err:
        simulate_elastic(s)
    _one_line(err.value)


def test_bad_options():
    s = triangular_truss()
    with pytest.raises(InputError) as err:
        simulate_elastic(s, subdivisions=0)
    _one_line(err.value)
    assert "subdivisions" in str(err.value)


def test_at_rest_matches_fe_static():
    """One step at rest: the along-motion solution equals the FE static solve
    (trussfe.fem.static, pinned-beam, self-weight + loads) on a passive truss, 1e-9."""
    from trussfe.fem.static import solve_static
    s = double_octahedron((1.2289, 1.1079, 1.1079), top_load=46.0, gravity=9.81)
    s = s.without_extensions("active_members")
    sim, resp, cmp = simulate_elastic(s, subdivisions=4)
    st = solve_static(s, "pinned-beam", subdivisions=4)
    scale = np.abs(st.axial_force).max()
    np.testing.assert_allclose(resp.midpoint_axial_force[0], st.axial_force, rtol=0,
                               atol=1e-9 * scale)
    np.testing.assert_allclose(resp.displacements[0], st.displacements[:, :3], rtol=0,
                               atol=1e-9 * np.abs(st.displacements).max())
    assert cmp["max"] <= RTOL


def test_comparison_needs_the_same_sections():
    """Section forces at other positions cannot be compared: one-line AnalysisError."""
    sim, resp = base_simulation("exact", steps=5)
    other = type(sim.sections)(position=sim.sections.position * 0.5,
                               tension=sim.sections.tension, shear=sim.sections.shear,
                               moment=sim.sections.moment, unit=sim.sections.unit)
    with pytest.raises(AnalysisError) as err:
        compare_with_rigid(other, resp)
    _one_line(err.value)
