# SPDX-License-Identifier: MIT
"""Lacy's triangular truss (1991, chapters 2–3, Appendix A) with the rigid-body model."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.studies.lacy_rigid import base_simulation, static_reactions, triangular_truss
from trussfe.rigid.simulate import simulate


@pytest.fixture(scope="module")
def static():
    return static_reactions()


def test_table_3_2_no_gravity(static):
    """Table 3.2 (98.1 N at B, no member weight): every printed digit (rtol 5e-6)."""
    r = static["table_3_2"]
    assert_allclose(r["O2"], [17.1813, 21.4594], rtol=5e-6)
    assert_allclose(r["O1"], [-17.1813, 76.6406], rtol=5e-6)
    assert_allclose([r["tension"]["follower"], r["tension"]["active"]], [-78.5429, -27.4900],
                    rtol=5e-6)
    assert_allclose([r["von_mises"]["follower"], r["von_mises"]["active"]],
                    [6.6136e5, 2.3148e5], rtol=5e-5)


def test_static_with_member_weight(static):
    """Text after Table 3.2: O1 reaction −20.1303 N, 92.9545 N (downward gravity)."""
    assert_allclose(static["with_weight"]["O1"], [-20.1303, 92.9545], rtol=5e-6)


def test_static_is_pin_jointed_equilibrium():
    """Without gravity the bar forces solve Bᵀ t = f (independent dense solve)."""
    from trussfe.kinematics import equilibrium_matrix
    s = triangular_truss(mass=0.0, gravity=False, load=-98.1)
    r = simulate(s)
    Bt = equilibrium_matrix(s.coords, s.connectivity, ~s.translation_supports).toarray()
    t = np.linalg.solve(Bt, [0.0, -98.1])
    assert_allclose(r.forces.tension_end[0], t, rtol=1e-12)
    assert_allclose(r.midpoint_axial_force[0], t, rtol=1e-12)


@pytest.fixture(scope="module")
def base():
    return base_simulation()


def test_base_simulation_velocity(base):
    """Section 3.7: maximum actuator velocity 1.2477 m/s."""
    assert_allclose(base["max_actuator_velocity"], 1.2477, rtol=5e-5)


def test_base_simulation_follower(base):
    """Section 3.3: follower 4.3393e6 at 1.8 s (static there 3.9695e6), motion-induced
    4.7361e5 at 1.5 s; section 3.5: static maximum 4.0917e6 (thesis scheme, rtol 5e-5)."""
    f = base["follower"]
    assert_allclose(f["max_von_mises"], 4.3393e6, rtol=5e-5)
    assert_allclose(f["thesis_time"], 1.8, rtol=1e-12)
    assert_allclose(f["static_at_max"], 3.9695e6, rtol=5e-5)
    assert_allclose(f["static_max"], 4.0917e6, rtol=5e-5)
    assert_allclose(f["motion_induced_max"], 4.7361e5, rtol=5e-5)
    assert_allclose(f["motion_induced_thesis_time"], 1.5, rtol=1e-12)


def test_base_simulation_leadscrew_tube(base):
    """Section 3.3: tube 2.6256e7, static 2.4501e7, motion-induced 2.3014e6 at 1.44 s, at the
    cantilever connection."""
    t = base["leadscrew_tube"]
    assert_allclose(t["max_von_mises"], 2.6256e7, rtol=5e-5)
    assert_allclose(t["static_max"], 2.4501e7, rtol=5e-5)
    assert_allclose(t["motion_induced_max"], 2.3014e6, rtol=5e-5)
    assert_allclose(t["motion_induced_thesis_time"], 1.44, rtol=1e-12)
    assert t["section"] == pytest.approx(2.0)


def test_table_3_3_buckling(base):
    """Table 3.3: allowable 1481.2 N; 10 kg compressions 308.6 N and 86.9 N, all to 5e-5."""
    b = base["buckling"]
    assert_allclose(b["allowable"], [1481.2, 1481.2], rtol=5e-5)
    assert_allclose(b["follower_max_compression"], 308.6, rtol=5e-5)
    assert_allclose(b["tube_max_compression"], 86.9, rtol=5e-5)


def test_forty_kg_variant():
    """Section 3.5 and Table 3.3 with 40 kg: static max 1.0296e7, motion-induced 1.4617e6 (to
    5e-5); the compressions, printed 1115.1 / 336.2 N, fall one unit of the printed last digit
    short: they round to 1115.0 / 336.1 N (unexplained in the thesis)."""
    r = base_simulation(mass=40.0)
    assert_allclose(r["follower"]["static_max"], 1.0296e7, rtol=5e-5)
    assert_allclose(r["follower"]["motion_induced_max"], 1.4617e6, rtol=5e-5)
    b = r["buckling"]
    assert round(b["follower_max_compression"], 1) == 1115.0
    assert round(b["tube_max_compression"], 1) == 336.1
    # The printed last digits are not reached (unexplained in the thesis).
    assert abs(r["buckling"]["follower_max_compression"] / 1115.1 - 1) > 1e-4


def test_longer_motions_approach_static():
    """Section 3.4: slower motions (5 s, 10 s) lower the follower maximum towards the static
    stress, which depends on position only."""
    r3, r5, r10 = (base_simulation(duration=T) for T in (3.0, 5.0, 10.0))
    m = [r["follower"]["max_von_mises"] for r in (r3, r5, r10)]
    assert m[0] > m[1] > m[2] > r3["follower"]["static_max"]
    assert_allclose(r10["follower"]["static_max"], r3["follower"]["static_max"], rtol=1e-3)


def test_exact_and_thesis_schemes_converge():
    """The thesis' backward differences are first order: the gap to the exact kinematics
    shrinks about linearly with the step (independent check of both schemes)."""
    gaps = []
    for n in (50, 100, 200):
        a = base_simulation(steps=n, scheme="thesis")["leadscrew_tube"]["max_von_mises"]
        b = base_simulation(steps=n, scheme="exact")["leadscrew_tube"]["max_von_mises"]
        gaps.append(abs(a - b))
    assert gaps[1] < 0.7 * gaps[0] and gaps[2] < 0.7 * gaps[1]
