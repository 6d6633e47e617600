# SPDX-License-Identifier: MIT
"""Member results of Slewing Experiment 1 (Lacy sections 5.7-5.8): trussfe's and Appendix C's."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe import models
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_actuators import slew1_motion, slew1_structure
from trussfe.studies.lacy_slew_members import (LISTING_TUBE, TUBE_LENGTH, listing_cantilever,
                                               listing_frame, m8_cantilever_steps,
                                               members_along_slew, slew_bay)


@pytest.fixture(scope="module")
def listing_run():
    s = slew_bay(models.STATED_LOAD, LISTING_TUBE)
    return simulate(s, slew1_motion(s, steps=22), n_sections=1)


def test_slew_stays_inside_the_stroke():
    """Lacy section 5.5: ±0.0606 m about 1.1684 m; the slew runs between section 5.1's slewed
    positions, through the equilibrium position at mid-time."""
    m = slew1_motion(steps=220)
    lo, hi = models.STROKE
    assert lo <= m.length.min() and m.length.max() <= hi
    assert_allclose(m.length[110], models.EQUILIBRIUM_LENGTH, rtol=1e-15)
    assert_allclose(m.length[[0, -1]], [models.slew_lengths("slew1"),
                                        models.slew_lengths("slew2")], rtol=1e-15)


def test_listing_frame_is_orthonormal_along_m7_8(listing_run):
    """Appendix C's direction-cosine matrix of M7/8: orthonormal rows, b3 along the member."""
    r = listing_run
    s = r.structure
    c = listing_frame(s, r.kinematics.coords)
    assert_allclose(np.einsum("tij,tkj->tik", c, c), np.broadcast_to(np.eye(3), c.shape),
                    atol=1e-14)
    assert_allclose(np.einsum("ti,ti->t", c[:, 2], r.kinematics.unit[:, s.member_index("M7_8")]),
                    1.0, rtol=1e-14)


def test_listing_cantilever_at_rest_is_the_statics_of_a_tube_hung_from_n4(listing_run):
    """At rest (the first sample) the code's equations reduce to the statics of a 0.254 m tube
    carrying the N4 pin force f at its far end and its weight W at its middle: axial force
    -(f + W)·b3, moment about b2 ls (b1·f) + (ls/2)(b1·W) with the lever ls/2, and
    (ls/2 + l2/2)(b1·f) + (l2/2)(b1·W) with the code's l2/2."""
    r = listing_run
    s = r.structure
    k = s.member_index("M7_8")
    c = listing_frame(s, r.kinematics.coords)[0]
    f = r.forces.end_force[0, k, 0]
    mass = s.materials[k].density * s.area[k] * TUBE_LENGTH
    W = mass * np.array(s.gravity)
    ls, l2 = TUBE_LENGTH, models.octahedral.LONGERON
    own = listing_cantilever(r, lever=ls / 2)
    code = listing_cantilever(r)
    assert_allclose(own["axial"][0], -(f + W) @ c[2], rtol=1e-12)
    assert_allclose(own["M2"][0], ls * (c[0] @ f) + ls / 2 * (c[0] @ W), rtol=1e-12)
    assert_allclose(code["M2"][0], (ls / 2 + l2 / 2) * (c[0] @ f) + l2 / 2 * (c[0] @ W),
                    rtol=1e-12)
    # the tube compressed by the actuator force, as the thesis' negative sign says
    assert_allclose(-code["axial"][0], r.actuator_force[0, 0], rtol=2e-3)


def test_m8_stress_is_the_listings():
    """Lacy section 5.7: M8's largest stress is 3.57e7 Pa at the beginning of the motion.
    Appendix C's cantilever (pin force at N4, lever l2/2, ID 0.63 in) gives it within 1 %
    at t = 0; trussfe's tube (pinned at N5) gives 5 times less, and each of the listing's
    changes moves it towards the thesis."""
    st = m8_cantilever_steps(steps=22)
    assert_allclose(st["listing"]["max"], 3.57e7, rtol=1e-2)
    assert st["listing"]["time"] == 0.0
    assert st["physical"]["max"] < 3.57e7 / 4.5
    assert st["physical"]["max"] < st["pin_N4"]["max"] < st["lever_l2"]["max"] \
        < st["listing"]["max"]


def test_top_plane_compressions_of_section_5_8():
    """Lacy section 5.8: M19 27.2 N, M20 22.6 N (M21 22.7 N) with the listing's tube and the
    tables' 44.498 N per top node; our slew turns about n1 only, so M21 = M20."""
    out = members_along_slew(models.TABLE_LOAD, listing=True, steps=22)["compression"]
    assert_allclose(out["M19"], 27.2, rtol=2e-3)
    assert_allclose(out["M20"], 22.6, rtol=2e-3)
    assert_allclose(out["M21"], out["M20"], rtol=1e-12)


def test_m6_and_m19_peak_at_the_end():
    """Lacy section 5.7: M6 and M19 reach their largest stress at the end of the motion."""
    out = members_along_slew(steps=22)
    assert out["M6"]["time"] == out["M19"]["time"] == 5.5


def test_study_bay_refuses_the_tilt_beyond_the_stroke():
    """The study's bay carries the stroke: the -10 deg to +10 deg tilt is refused at step 0."""
    from trussfe.errors import InputError
    from trussfe.rigid.slew import rotation_motion
    s = slew1_structure()
    m = rotation_motion({"type": "rotation", "axis": "n1", "start": -10.0, "end": 10.0,
                         "duration": 5.5, "steps": 4}, s)
    with pytest.raises(InputError, match=r"step 0 \(t = 0 s\): active member 'M7_8'"):
        simulate(s, m)
