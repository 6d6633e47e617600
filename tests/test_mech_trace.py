"""Finite-mechanism motion: over-constrained, compound and spatial assemblies, limit points,
bifurcations and bad input (Hortobágyi 1999, sections 3–9)."""
import numpy as np
from numpy.testing import assert_allclose
import pytest

from trussfe.errors import AnalysisError, InputError
from trussfe.kinematics import trace_mechanism, trace_structure
from trussfe.models.mechanisms import CATALOGUE


def _lengths(x, bars):
    return np.linalg.norm(x[..., bars[:, 1], :] - x[..., bars[:, 0], :], axis=-1)


def _trace(name, **kw):
    e = CATALOGUE[name]
    kw.setdefault("step", e.step)
    return e, trace_mechanism(e.coords, e.bars, e.free, drives=[e.drive_index()], **kw)


def test_bricard_least_squares():
    """Bricard's octahedron (12 bars, 12 free coordinates, one self-stress): every bar keeps
    its length to the corrector tolerance (1e-10·L) along 60 steps and ρ(B) stays 11."""
    e, r = _trace("mech_bricard", steps=60)
    L0 = _lengths(e.coords, e.bars)
    assert np.max(np.abs(_lengths(r.coords, e.bars) - L0)) < 1e-9
    assert np.all(r.rank == 11)
    assert np.ptp(r.coords[:, 5, 0]) > 0.25               # it really moves


def test_section8_moves_only_downward():
    """Hortobágyi section 8: from the symmetric state (ρ = 14, μ·j − ρ = 2) the ends of the
    connecting bar can move downward; ρ = 15 after the step; upward there is no compatible
    state, which is reported with the divergence message."""
    e, r = _trace("mech_sec8_compound", steps=20)
    assert r.rank[0] == 14 and np.all(r.rank[1:] == 15)
    assert r.events[0]["kind"] == "bifurcation" and r.events[0]["step"] == 0
    assert r.coords[-1, 4, 1] < 0 and r.coords[-1, 10, 1] < 0
    assert np.max(np.abs(_lengths(r.coords, e.bars) - _lengths(e.coords, e.bars))) < 1e-9
    with pytest.raises(AnalysisError, match="leaves the motion region"):
        _trace("mech_sec8_compound", steps=20, step=-e.step)


def test_section8_branches_are_mirror_images():
    """Branch 1 (prescribe the other end) is the mirror image of branch 0 (symmetry)."""
    e, r0 = _trace("mech_sec8_compound", steps=5, branch=0)
    _, r1 = _trace("mech_sec8_compound", steps=5, branch=1)
    np.testing.assert_allclose(r0.coords[-1, 4] * [-1, 1], r1.coords[-1, 10], atol=1e-8)


def test_section9_bifurcation_detected():
    """Section 9 construction (17 joints, 50 bars, 3·17 − 50 = 1): the four-bar inside it
    reaches its flat position (crank angle 180°), where all bars at the crank joint are
    coplanar; the sign of det [B; τ] changes there and the trace passes through."""
    e, r = _trace("mech_sec9_space", steps=30)
    assert np.all(r.rank == 50)
    bif = [ev["step"] for ev in r.events if ev["kind"] == "bifurcation"]
    assert len(bif) == 1
    ang = np.degrees(np.arctan2(r.coords[:, 0, 1], r.coords[:, 0, 0])) % 360
    k = bif[0]
    assert ang[k - 1] <= 180.0 + 1e-9 <= ang[k + 1] or ang[k] <= 180 <= ang[k + 1]


def test_limit_point_passed_with_pivoting():
    """Section 5: the crank pin's y is the drive; at its extreme the largest-velocity
    coordinate takes over, the motion continues and a limit point is reported."""
    e, r = _trace("mech_fourbar", steps=120, step=0.05)
    assert any(ev["kind"] == "limit_point" for ev in r.events)
    assert np.max(np.abs(_lengths(r.coords, e.bars) - _lengths(e.coords, e.bars))) < 1e-9


def test_frozen_iteration_also_converges():
    """The paper's frozen B11 converges too, with more iterations than Newton."""
    e, rn = _trace("mech_fourbar", steps=3, step=0.1)
    _, rf = _trace("mech_fourbar", steps=3, step=0.1, newton=False)
    np.testing.assert_allclose(rn.coords[-1], rf.coords[-1], atol=1e-9)
    assert rf.iterations.sum() > rn.iterations.sum()


def test_two_drives():
    """A five-bar chain (two degrees of freedom) driven by two coordinates: both follow the
    prescribed increments exactly."""
    x = np.array([[0, 0], [0, 1], [1, 1.5], [2, 1], [2, 0]], float)
    bars = np.array([[0, 1], [1, 2], [2, 3], [3, 4]])
    free = np.ones_like(x, bool)
    free[[0, 4]] = False
    r = trace_mechanism(x, bars, free, drives=[2, 6], step=[0.02, -0.02], steps=5)
    np.testing.assert_allclose(r.coords[-1, 1, 0], 0.1, atol=1e-12)
    np.testing.assert_allclose(r.coords[-1, 3, 0], 1.9, atol=1e-12)


# ----------------------------------------------------------------------------- bad input
def test_drive_on_fixed_node():
    s = CATALOGUE["mech_fourbar"].structure()
    with pytest.raises(InputError, match="fixed"):
        trace_structure(s, "1:x", 0.1, 3)


def test_drive_on_missing_axis_or_node():
    s = CATALOGUE["mech_fourbar"].structure()
    with pytest.raises(InputError, match="axis 'z' does not exist"):
        trace_structure(s, "2:z", 0.1, 3)
    with pytest.raises(InputError, match="not defined"):
        trace_structure(s, "9:x", 0.1, 3)
    with pytest.raises(InputError, match="NODE:AXIS"):
        trace_structure(s, "2", 0.1, 3)


def test_rigid_assembly_refused():
    e = CATALOGUE["mech_octahedron_rigid"]
    with pytest.raises(AnalysisError, match="rigid"):
        trace_mechanism(e.coords, e.bars, e.free, drives=[e.drive_index()], step=0.02, steps=3)


def test_infinitesimal_only_mechanism_not_crept_along():
    """A taut chain between two supports (a second-order infinitesimal mechanism, no finite
    motion): the minimum step stops the halving and the divergence message is given."""
    x = np.array([[0, 0], [1, 0], [2, 0]], float)
    free = np.array([[0, 0], [1, 1], [0, 0]], bool)
    with pytest.raises(AnalysisError, match="not a finite mechanism"):
        trace_mechanism(x, np.array([[0, 1], [1, 2]]), free, drives=[3], step=0.1, steps=2)


def test_bad_step_values():
    e = CATALOGUE["mech_fourbar"]
    with pytest.raises(InputError):
        trace_mechanism(e.coords, e.bars, e.free, drives=[3], step=0.0, steps=3)
    with pytest.raises(InputError):
        trace_mechanism(e.coords, e.bars, e.free, drives=[3], step=0.1, steps=0)


def test_section9_branch_switch():
    """At the four-bar's change point (crank and rocker both at 180°) the traced path (crank
    on, rocker back) meets the other branch (crank and rocker turning together).  branch=1 and
    branch=2 leave for that branch in its two directions; bars keep their lengths (1e-9)."""
    e = CATALOGUE["mech_sec9_space"]
    L0 = _lengths(e.coords, e.bars)

    def angles(r):
        crank = np.degrees(np.arctan2(r.coords[:, 0, 1], r.coords[:, 0, 0])) % 360
        rocker = np.degrees(np.arctan2(r.coords[:, 1, 1], r.coords[:, 1, 0] - 3.0)) % 360
        return crank[-1] - 180.0, rocker[-1] - 180.0

    out = {}
    for br in (0, 1, 2):
        _, r = _trace("mech_sec9_space", steps=20, branch=br)
        assert np.max(np.abs(_lengths(r.coords, e.bars) - L0)) < 1e-9
        out[br] = angles(r)
    c0, r0 = out[0]
    assert c0 > 5 and r0 < -5                              # traced path: opposite senses
    for br in (1, 2):
        c, r = out[br]
        assert abs(c) > 5 and np.sign(c) == np.sign(r)     # other branch: same sense
    assert np.sign(out[1][0]) != np.sign(out[2][0])        # the two directions


def test_a_four_bar_beside_a_straight_chain_is_traced_and_the_chain_stays():
    """A four-bar 1–2–3–4 (ground 1–4) and, between the same supports, a straight chain of
    two bars 1–5–4: node 5 has an infinitesimal mechanism (across the chain) at every state,
    but no finite motion.  The trace refused the four-bar ("leaves the motion region": the
    square block of dependent coordinates is singular), and called every state a
    bifurcation.  It now moves the four-bar with every bar kept to the corrector tolerance
    and node 5 where it is, and reports no event."""
    x = np.array([[0.0, 0.0], [0.995004165278026, 0.0998334166468282],
                  [2.99230833478574, 2.59998862272246], [3.0, 0.0], [1.5, 0.0]])
    bars = np.array([[0, 1], [1, 2], [3, 2], [0, 4], [4, 3]])
    free = np.ones_like(x, dtype=bool)
    free[[0, 3]] = False
    r = trace_mechanism(x, bars, free, drives=[1 * 2 + 1], step=0.05, steps=5)    # 2:y
    assert np.max(np.abs(_lengths(r.coords, bars) - _lengths(x, bars))) < 1e-9
    assert np.ptp(r.coords[:, 1, 1]) > 0.2                       # the crank turned
    assert np.abs(r.coords[:, 4] - x[4]).max() < 1e-12           # node 5 stays
    assert not [e for e in r.events if e["kind"] == "bifurcation"]


def test_a_square_on_a_pin_and_a_roller_moves_as_a_parallelogram():
    """A square of four bars, node 1 pinned and node 2 on a roller along y (x held): bar 1–2
    keeps node 2 at (1, 0), and 1–4–3–2 moves as a parallelogram, node 4 = (−sin θ, cos θ),
    node 3 = node 4 + (1, 0) (the trace refused it as the square's dependent block is
    singular)."""
    x = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    bars = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    free = np.ones_like(x, dtype=bool)
    free[0] = False
    free[1, 0] = False
    r = trace_mechanism(x, bars, free, drives=[2 * 2 + 0], step=0.05, steps=10)   # 3:x
    c = r.coords
    assert np.max(np.abs(_lengths(c, bars) - 1.0)) < 1e-9
    # node 2's y is held by bar 1–2 only to second order: lengths kept to 1e-10 L leave it
    # within √(2e-10) L = 1.4e-5 L of 0 (and the parallelogram's sides with it)
    near = np.sqrt(2e-10)
    assert np.abs(c[:, 1] - [1.0, 0.0]).max() < near
    assert_allclose(np.linalg.norm(c[:, 3], axis=1), 1.0, atol=1e-9)
    assert_allclose(c[:, 2] - c[:, 3], np.broadcast_to([1.0, 0.0], c[:, 2].shape), atol=near)
    assert np.ptp(c[:, 2, 0]) > 0.4


def test_a_trace_refuses_a_tolerance_too_loose_for_its_rank_decisions():
    """The rank along a trace is decided at 100 × the bar-length tolerance: at 1e-2 every
    singular value of a regular four-bar counted as zero (a "bifurcation" at every state, and
    at 0.9 the bars off by 2.4 %).  Tolerances above 1e-4 are refused, naming the option."""
    import trussfe
    from trussfe._resources import mesh_path
    with pytest.raises(InputError, match="--tolerance"):
        trussfe.trace(mesh_path("mech_fourbar.toml"), drive="2:y", step=0.05, steps=4,
                      tolerance=1e-2)
    r = trussfe.trace(mesh_path("mech_fourbar.toml"), drive="2:y", step=0.05, steps=4,
                      tolerance=1e-4)
    assert not [e for e in r.events if e["kind"] == "bifurcation"]
