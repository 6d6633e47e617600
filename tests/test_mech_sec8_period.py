# SPDX-License-Identifier: MIT
"""Hortobágyi (1999) §8, Fig. 11: over one period of the compound mechanism the end points of
the connecting bar travel their trajectories twice (the section-8 construction traced once
round its loop)."""

from trussfe.kinematics.trace import trace_mechanism
from trussfe.models.mechanisms import CATALOGUE
from trussfe.studies.hortobagyi_period import (END_POINTS, PERIOD_STEPS,
                                               hortobagyi_section8_period, trajectory_passes)


def test_end_points_travel_their_trajectories_twice_per_period():
    """Traced from the symmetric state, the motion returns to it after 614 steps of 0.02 m
    (within a quarter of a step); every sampled point of either end's trajectory (away from its
    self-crossing and turning points) is passed exactly twice, as Hortobágyi (1999) §8 states
    for Fig. 11; the right end's trajectory is the mirror image of the left's (the
    construction's symmetry) to within half a step's spacing; the bars keep their lengths."""
    out = hortobagyi_section8_period()
    assert out["return_distance"] < 0.25 * 0.02
    assert out["misfit"] < 1e-9
    for side in END_POINTS:
        assert out[side]["points"] > 100
        assert out[side]["twice"] == out[side]["points"] and out[side]["other"] == 0
    assert out["right"]["mirror"] < 0.0125


def test_half_a_period_passes_once():
    """The count can fail: over the first half of the period most points of the traversed
    part are passed once, not twice."""
    e = CATALOGUE["mech_sec8_compound"]
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, PERIOD_STEPS // 2)
    c = trajectory_passes(t.coords[:, END_POINTS["left"]], 0.04)
    assert c.get(1, 0) > c.get(2, 0)
