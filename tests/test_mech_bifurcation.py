"""Bifurcation detection along a traced motion (Hortobágyi 1999, sections 4 and 9): the sign
of det [B; τᵀ] and, where two bifurcations fall in one step and the signs cancel, the dip of
the smallest singular value of [B; τᵀ] with step refinement."""
import numpy as np
import pytest

from trussfe.kinematics import trace_mechanism
from trussfe.kinematics import mechanism as mech


def _fourbar_q(P, D, coupler, rocker):
    """Rocker joint Q of a four-bar on the branch through the flat change point."""
    w = D - P
    dist = np.linalg.norm(w)
    u = w / dist
    along = (coupler ** 2 - rocker ** 2 + dist ** 2) / (2 * dist)
    h = np.sqrt(coupler ** 2 - along ** 2)
    return P + along * u - h * np.array([-u[1], u[0]])


def twin_fourbars(delta_deg: float, extra: int = 0, seed: int = 0):
    """Two change-point four-bars (ground 3, crank 1, coupler 2.5, rocker 1.5) on one crank
    O–P, the second rotated by δ about O.  Each is flat — a bifurcation, all bars at P and at
    its rocker joint collinear — at crank angle 180° resp. 180° + δ.  ``extra`` joints are
    added to the rigid crank and rocker bodies by Henneberg steps (two bars each), which
    keeps one degree of freedom and the two bifurcations."""
    rng = np.random.default_rng(seed)
    d = np.deg2rad(delta_deg)
    th = np.deg2rad(147.3)
    P = np.array([np.cos(th), np.sin(th)])
    D1 = np.array([3.0, 0.0])
    D2 = 3.0 * np.array([np.cos(np.pi + d), np.sin(np.pi + d)]) * -1.0
    Q = _fourbar_q(P, D1, 2.5, 1.5)
    R = _fourbar_q(P, D2, 2.5, 1.5)
    pts = [np.zeros(2), P, Q, D1, R, D2]
    bars = [(0, 1), (1, 2), (2, 3), (1, 4), (4, 5)]
    bodies = [[0, 1], [2, 3], [4, 5]]
    for k in range(extra):
        body = bodies[k % 3]
        a, b = rng.choice(np.array(body), 2, replace=False)
        mid = (pts[a] + pts[b]) / 2
        e = pts[b] - pts[a]
        nrm = np.array([-e[1], e[0]]) / np.linalg.norm(e)
        pts.append(mid + nrm * rng.uniform(0.3, 0.8) * rng.choice([-1, 1])
                   + rng.normal(0, 0.05, 2))
        bars += [(int(a), len(pts) - 1), (int(b), len(pts) - 1)]
        body.append(len(pts) - 1)
    X = np.array(pts)
    free = np.ones(X.shape, bool)
    free[[0, 3, 5]] = False
    return X, np.array(bars), free


def _bifurcations(events):
    """Bifurcations found during the motion; ``step`` is the state just after the crossing."""
    return [e for e in events if e["kind"] == "bifurcation"]


def test_two_bifurcations_in_one_step_are_both_reported():
    """δ = 2°: the two flat positions (crank 180° and 182°) fall inside one step of 0.12 in
    P_y (crank 176.5° → 183.4°).  The determinant sign changes twice and cancels; the dip of the
    smallest singular value triggers step refinement, which reports both."""
    X, bars, free = twin_fourbars(2.0)
    r = trace_mechanism(X, bars, free, drives=[3], step=-0.12, steps=8)
    ev = _bifurcations(r.events)
    assert len(ev) == 2
    assert all("refinement" in e.get("detected_by", "") for e in ev)
    # both lie where the crank passes 180°..182°
    ang = np.degrees(np.arctan2(r.coords[:, 1, 1], r.coords[:, 1, 0])) % 360
    for e in ev:
        assert ang[e["step"] - 1] <= 182.0 + 1e-6 and ang[e["step"]] >= 180.0 - 1e-6


def test_sign_test_alone_misses_the_double_crossing(monkeypatch):
    """Control: with refinement disabled the same trace reports no bifurcation — the failure
    mode the refinement is there for."""
    monkeypatch.setattr(mech, "DIP_RATIO", 0.0)
    X, bars, free = twin_fourbars(2.0)
    r = trace_mechanism(X, bars, free, drives=[3], step=-0.12, steps=8)
    assert _bifurcations(r.events) == []


def test_large_model_reports_known_bifurcations():
    """The same two bifurcations in a model of 156 joints (312 coordinates, sparse path above
    the dense limit): 150 Henneberg joints on the crank and rocker bodies.  Small steps
    (each bifurcation in its own step, found by the sign test) and large steps (both in one
    step, found by refinement) both report two bifurcations near crank 180°–182°."""
    X, bars, free = twin_fourbars(2.0, extra=150)
    assert free.sum() >= 300 and free.sum() > mech.DENSE_LIMIT
    L0 = np.linalg.norm(X[bars[:, 1]] - X[bars[:, 0]], axis=1)
    for step, steps in ((-0.03, 45), (-0.12, 12)):
        r = trace_mechanism(X, bars, free, drives=[3], step=step, steps=steps)
        ev = _bifurcations(r.events)
        assert len(ev) == 2, (step, r.events)
        ang = np.degrees(np.arctan2(r.coords[:, 1, 1], r.coords[:, 1, 0])) % 360
        for e in ev:
            assert ang[e["step"] - 1] <= 182.0 + 1e-6 and ang[e["step"]] >= 180.0 - 1e-6
        L = np.linalg.norm(r.coords[-1][bars[:, 1]] - r.coords[-1][bars[:, 0]], axis=1)
        assert np.abs(L - L0).max() < 1e-8


@pytest.mark.parametrize("n", [30, 250])
def test_test_function_sign_matches_determinant(n):
    """The signed smallest singular value has the determinant's sign (dense: slogdet of the
    same matrix; sparse path above the dense limit checked against the dense SVD)."""
    rng = np.random.default_rng(n)
    X, bars, free = twin_fourbars(2.0, extra=n)
    c = rng.normal(size=int(free.sum()))
    phi = mech._test_function(X, bars, free, c)
    B = mech.compatibility_matrix(X, bars, free).toarray()
    A = np.vstack([B, c / np.linalg.norm(c)])
    sign, _ = np.linalg.slogdet(A)
    smin = np.linalg.svd(A, compute_uv=False)[-1]
    assert np.sign(phi) == sign
    np.testing.assert_allclose(abs(phi), smin, rtol=0.05)
