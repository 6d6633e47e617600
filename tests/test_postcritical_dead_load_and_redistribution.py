# SPDX-License-Identifier: MIT
"""Post-critical paths where the weight, a spring or several members decide the outcome,
against closed forms of small trusses (stated in each test):

* the start under the dead load alone: the von Mises truss under an apex weight below its
  limit load starts on its original branch; above it, there is no such start (a load
  increment used to land silently on the inverted form);
* springs that still carry the load when every member has failed;
* members reaching their limits at the same instant of a redistribution, and a mechanism's
  equilibrium form that would need a member beyond its limit.
"""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.errors import AnalysisError

EA, A_HALF, RISE = 1.0e6, 1.0, 0.1          # the von Mises truss: EA, half-span, rise
L0 = math.hypot(A_HALF, RISE)


def _von_mises(apex_mass):
    return trussfe.model_from_dict({
        "model": {"name": "von Mises", "dimension": 2, "gravity": [0.0, -9.81]},
        "materials": {"m": {"E": 1.0e10, "density": 0.0}},
        "sections": {"b": {"area": 1.0e-4}},
        "nodes": {"left": [-A_HALF, 0.0], "apex": [0.0, RISE], "right": [A_HALF, 0.0]},
        "members": {"L": {"nodes": ["left", "apex"], "section": "b", "material": "m"},
                    "R": {"nodes": ["apex", "right"], "section": "b", "material": "m"}},
        "supports": {"left": ["x", "y"], "right": ["x", "y"], "apex": ["x"]},
        "loads": {"apex": [0.0, -1.0]}, "masses": {"apex": apex_mass}})


def _apex_load(v):
    """Closed form of the von Mises truss: the apex load that holds it lowered by v,
    P(v) = 2 EA w (1/ℓ − 1/L), w = h − v, ℓ = √(a² + w²)."""
    w = RISE - v
    return 2.0 * EA * w * (1.0 / math.hypot(A_HALF, w) - 1.0 / L0)


#: the limit load of the closed form, at ℓ³ = a² L
LIMIT = _apex_load(RISE - math.sqrt((A_HALF ** 2 * L0) ** (2.0 / 3.0) - A_HALF ** 2))


@pytest.mark.parametrize("mass", [20.0, 37.0])
def test_a_weight_below_the_limit_starts_on_the_original_branch(mass):
    """Apex weights of 196 and 363 N (the limit load is 381.087 N): the path starts at the
    closed-form equilibrium under the weight alone, P(v) = m g to Newton's tolerance (1e-9
    of the load), on the branch of the unloaded truss (the smaller root, before the
    limit)."""
    W = mass * 9.81
    assert W < LIMIT
    v_limit = RISE - math.sqrt((A_HALF ** 2 * L0) ** (2.0 / 3.0) - A_HALF ** 2)
    r = trussfe.postcritical(_von_mises(mass), control="arc-length", steps=2, step=1e-4)
    v = -r.displacement[0, 1, 1]                     # the start point's apex, lowered
    assert 0.0 < v < v_limit
    assert _apex_load(v) == pytest.approx(W, rel=1e-9)
    assert r.load_factors[0] == 0.0


def test_a_weight_beyond_the_limit_has_no_start():
    """An apex weight of 490.5 N exceeds the limit load 381.087 N: the truss cannot carry
    its weight in its own form (it would snap through to hang upside down, where a load
    increment used to land and start the path without a word).  The dead load is followed
    to its limit, at 381.087/490.5 = 0.777 of the weight, and refused there."""
    with pytest.raises(AnalysisError, match="cannot carry its own weight") as e:
        trussfe.postcritical(_von_mises(50.0), control="arc-length", steps=2)
    frac = float(str(e.value).split("a limit at ")[1].split(" ")[0])
    assert frac == pytest.approx(LIMIT / (50.0 * 9.81), abs=2e-3)


# --------------------------------------------------------------------- springs and members
def _bar_and_spring(law):
    """Joint A held in y, a bar to B (L = 1 m, EA = 2e7 N, N_y = 25 kN) and a spring
    k = 5e6 N/m along x; load 1000 N along x."""
    return trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"m": {"E": 2e11, "yield_strength": 2.5e8}},
        "sections": {"s": {"area": 1e-4}},
        "nodes": {"A": [0.0, 0.0], "B": [-1.0, 0.0]},
        "members": {"M": {"nodes": ["B", "A"], "section": "s", "material": "m"}},
        "supports": {"B": ["x", "y"], "A": ["y"]}, "springs": {"A": {"x": 5e6}},
        "loads": {"A": [1000.0, 0.0]}, "failure": {"default": {"yield": law}}})


@pytest.mark.parametrize("control", ["load", "displacement", "arc-length"])
def test_the_spring_carries_the_load_when_the_only_member_has_failed(control):
    """Closed form: λP = (EA/L + k) u until the bar yields at u = 1.25e-3 (λ₁ = 31.25); its
    law removes it, and the spring alone then holds λP = k u — the structure has not
    collapsed (it did: "every member has failed").  Load control reaches λ = 50 (the
    located event adds a point, it does not use up a step)."""
    r = trussfe.postcritical(_bar_and_spring("remove"), control=control, steps=100,
                             max_load_factor=50.0, monitor="A:x")
    ev = [e for e in r.events if e.kind == "yield"]
    assert len(ev) == 1 and ev[0].load_factor == pytest.approx(31.25, rel=1e-6)
    assert not any(e.kind == "end" for e in r.events)
    assert r.solution.termination == "reached the maximum load factor 50"
    u = r.displacement[:, 0, 0]
    alive = np.array([p.alive[0] for p in r.solution.path])
    expected = np.where(alive, 2.5e7 * u, 5e6 * u) / 1000.0
    assert_allclose(r.load_factors, expected, rtol=1e-9, atol=1e-9)
    assert r.load_factors[-1] >= 50.0 * (1 - 1e-12)
    if control == "load":
        assert r.load_factors[-1] == pytest.approx(50.0, rel=1e-12)


def _three_bars(law_c=None):
    """Joint D at the origin hung from A(−1, 1), B(0, 1), C(1, 1); 1000 N down at D; yield
    ``remove`` on every bar (N_y = 25 kN), or on bar c at 30 kN with ``law_c``."""
    members = {"a": {"nodes": ["A", "D"], "section": "s", "material": "m"},
               "b": {"nodes": ["B", "D"], "section": "s", "material": "m"},
               "c": {"nodes": ["C", "D"], "section": "s", "material": "m"}}
    failure = {"default": {"yield": "remove"}}
    if law_c is not None:
        del members["b"]
        failure["members"] = {"c": law_c}
    return trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"m": {"E": 2e11, "yield_strength": 2.5e8}},
        "sections": {"s": {"area": 1e-4}},
        "nodes": {"D": [0.0, 0.0], "A": [-1.0, 1.0], "B": [0.0, 1.0], "C": [1.0, 1.0]},
        "members": members, "supports": {k: ["x", "y"] for k in "ABC"},
        "loads": {"D": [0.0, -1000.0]}, "failure": failure})


def test_symmetric_members_fail_together_in_a_redistribution():
    """The symmetric three-bar truss, every bar removed at N_y = 25 kN: the vertical bar b
    yields first (λ₁ = 42.694232, the closed form of
    ``test_three_bar_yield_cap_load_path_and_plastic_collapse``); releasing its 25 kN loads
    a and c alike, and both reach N_y at the same instant — both fail there, and with no
    member left the structure has collapsed.  (Only a failed, and c was reported carrying
    42.7 kN in a "stable equilibrium form".)"""
    r = trussfe.postcritical(_three_bars(), control="arc-length", steps=200,
                             max_load_factor=80.0)
    ev = [e for e in r.events if e.kind == "yield"]
    assert [r.structure.member_ids[e.member] for e in ev] == ["b", "a", "c"]
    assert_allclose([e.load_factor for e in ev], [42.6942320] * 3, rtol=1e-7)
    assert r.solution.termination.startswith("every member has failed at load factor 42.6942")
    assert r.solution.mechanism is None


def test_an_equilibrium_form_beyond_a_members_limit_is_no_resting_state():
    """Two bars at 45° hold D: a (N_y = 25 kN) and c (removed at 30 kN).  Elastic: both
    carry λP/(2 cos 45°), so a yields first, at λ = 35.3994 (in the deformed geometry).
    Then D swings on c to hang straight below C, where c carries the whole λP = 35.4 kN —
    beyond its 30 kN: the form is no resting state, c fails there and the structure
    collapses.  (The form was reported stable with c at 35.4 kN.)"""
    r = trussfe.postcritical(_three_bars({"yield": "remove", "yield_strength": 3.0e8}),
                             control="arc-length", steps=100)
    ev = [(r.structure.member_ids[e.member], e.load_factor) for e in r.events
          if e.kind == "yield"]
    assert [m for m, _ in ev] == ["a", "c"]
    assert ev[1][1] == ev[0][1]
    assert 35.39 < ev[0][1] < 35.41
    assert "at the equilibrium form" in [e for e in r.events if e.kind == "yield"][1].detail
    assert not r.solution.mechanism.converged
    assert r.solution.termination.startswith("every member has failed")


# --------------------------------------------------------------------- corners and snap-backs
def _capped_von_mises():
    """The von Mises truss with the apex free in x and y (two DOFs) and a buckling ``cap`` of
    P_cr = 40 N on both bars."""
    return trussfe.model_from_dict({
        "model": {"dimension": 2}, "materials": {"m": {"E": 1e10}},
        "sections": {"s": {"area": 1e-4, "Iy": 1e-9}},
        "nodes": {"left": [-A_HALF, 0.0], "apex": [0.0, RISE], "right": [A_HALF, 0.0]},
        "members": {"L": {"nodes": ["left", "apex"], "section": "s", "material": "m"},
                    "R": {"nodes": ["apex", "right"], "section": "s", "material": "m"}},
        "supports": {"left": ["x", "y"], "right": ["x", "y"]}, "loads": {"apex": [0, -1.0]},
        "failure": {"default": {"buckling": "cap", "critical_load": 40.0}}})


def test_arc_length_passes_a_corner_of_two_members_laws():
    """Both bars reach their cap together: the tangent loses two eigenvalues at once (the
    vertical stiffness and the sway) without a singular state, and every step over that
    corner was rejected as crossing several critical points while the accepted steps only
    came closer — the path piled 95 points on one state and reported "completed".  It now
    steps over the corner and follows the capped branch: λ = 2 P_cr w/ℓ (w = h − v,
    ℓ = √(a² + w²), the bars at −P_cr), falling as the apex descends, to Newton's tolerance
    (1e-9 of the load scale)."""
    r = trussfe.postcritical(_capped_von_mises(), control="arc-length", steps=60,
                             monitor="apex:y")
    i = r.node_ids.index("apex")
    v = -r.displacement[:, i, 1]
    w = RISE - v
    lam = r.load_factors
    capped = np.all(r.axial_force <= -40.0 * (1 - 1e-9), axis=1)
    assert capped.sum() > 20
    assert_allclose(lam[capped], 2.0 * 40.0 * w[capped] / np.hypot(A_HALF, w[capped]),
                    rtol=0, atol=1e-8 * lam.max())
    # every point a new state but the corner's (the events and the critical point there)
    assert len(np.unique(np.round(v, 12))) >= len(v) - 1
    # down the capped branch to near the flat position (λ → 0 as w → 0)
    assert lam[capped].min() < 1.0 < 7.9 < lam[capped].max()
    turn = [e for e in r.events if e.kind == "limit_point"]
    assert turn and "the load turns back" in turn[0].detail
    assert abs(r.displacement[:, i, 0]).max() < 1e-12          # the symmetric branch


def test_displacement_control_stops_at_a_snap_back_and_says_so():
    """The von Mises truss under a soft strut (k = 2000 N/m) loaded at its top T: the top's
    displacement u_T = v + P(v)/k turns back where 1 + P'(v)/k = 0 (a snap-back), which
    displacement control of u_T cannot pass.  The path ends there with a message (it piled
    its remaining steps on that point and reported "completed")."""
    from scipy.optimize import brentq
    k = 2000.0
    s = trussfe.model_from_dict({
        "model": {"dimension": 2}, "materials": {"m": {"E": 1e10}, "soft": {"E": 2e7}},
        "sections": {"s": {"area": 1e-4}},
        "nodes": {"left": [-A_HALF, 0.0], "apex": [0.0, RISE], "right": [A_HALF, 0.0],
                  "T": [0.0, RISE + 1.0]},
        "members": {"L": {"nodes": ["left", "apex"], "section": "s", "material": "m"},
                    "R": {"nodes": ["apex", "right"], "section": "s", "material": "m"},
                    "S": {"nodes": ["apex", "T"], "section": "s", "material": "soft"}},
        "supports": {"left": ["x", "y"], "right": ["x", "y"], "apex": ["x"], "T": ["x"]},
        "loads": {"T": [0.0, -1.0]}})
    r = trussfe.postcritical(s, control="displacement", steps=400, step=0.002, monitor="T:y")
    assert "snap-back" in r.solution.termination and "arc-length" in r.solution.termination
    h = 1e-7
    slope = lambda v: 1.0 + (_apex_load(v + h) - _apex_load(v - h)) / (2 * h) / k  # noqa: E731
    v_sb = brentq(slope, 0.03, 0.07, xtol=1e-14)
    uT_sb = v_sb + _apex_load(v_sb) / k
    uT = -r.displacement[:, r.node_ids.index("T"), 1]
    assert uT.max() == pytest.approx(uT_sb, abs=1e-5)
    assert len(uT) < 200                       # no pile of points at the snap-back
