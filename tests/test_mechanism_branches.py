# SPDX-License-Identifier: MIT
"""Mechanism analysis against closed forms and pyrigi: branch switching at the flat state of a
parallelogram linkage, fewer drives than degrees of freedom at a regular state, and the order
of a four-bar whose ground bar is modelled."""
import math

import numpy as np
import pytest

import trussfe
from trussfe.errors import InputError
from trussfe.kinematics.mechanism import _other_root


def _model(nodes, bars, supports=None):
    nodes = {str(i): [float(c) for c in p] for i, p in enumerate(nodes)}
    d = {"model": {"dimension": len(next(iter(nodes.values()))), "name": "m"},
         "materials": {"m": {"E": 1e9}}, "sections": {"s": {"area": 1e-4}},
         "nodes": nodes,
         "members": {f"b{i}": {"nodes": [str(a), str(b)], "section": "s", "material": "m"}
                     for i, (a, b) in enumerate(bars)}}
    if supports:
        d["supports"] = {str(k): v for k, v in supports.items()}
    return trussfe.model_from_dict(d)


def _parallelogram(theta_deg=40.0):
    """Ground 0–3 (length 2), crank 0–1 and rocker 3–2 (length 1), coupler 1–2 (length 2)."""
    th = math.radians(theta_deg)
    nodes = [[0, 0], [math.cos(th), math.sin(th)], [2 + math.cos(th), math.sin(th)], [2, 0]]
    return _model(nodes, [(0, 1), (1, 2), (3, 2)], {0: ["x", "y"], 3: ["x", "y"]})


def _angles(P):
    crank = np.arctan2(P[:, 1, 1], P[:, 1, 0])
    rocker = np.arctan2(P[:, 2, 1], P[:, 2, 0] - 2.0)
    return crank, rocker


def _freudenstein(P, a=2.0, b=1.0, c=2.0, d=1.0):
    """Freudenstein's loop equation of the four-bar, K1 cos θ4 − K2 cos θ2 + K3 − cos(θ2 − θ4)."""
    t2, t4 = _angles(P)
    K1, K2, K3 = a / b, a / d, (a * a + b * b - c * c + d * d) / (2 * b * d)
    return K1 * np.cos(t4) - K2 * np.cos(t2) + K3 - np.cos(t2 - t4)


def test_other_root_of_binary_quadric():
    """Closed form: at the flat state of the parallelogram linkage the self-stress ω = (1, 1, −1)
    gives ωᵀq(v) = y1² + (y2 − y1)²/2 − y2² = (3 y1 + y2)(y1 − y2)/2; knowing the root (1, 1),
    the other is (1, −3), not the orthogonal (1, −1)."""
    M = np.array([[[1.5, -0.5], [-0.5, -0.5]]])
    a = _other_root(M, np.array([1.0, 1.0]))
    assert a[1] / a[0] == pytest.approx(-3.0, rel=1e-12)


def test_parallelogram_switches_to_crossed_branch():
    """Closed form: the parallelogram linkage traced through its flat change point with
    ``branch`` 1 and 2 leaves for the crossed (antiparallelogram) branch, whose tangent at the
    flat state is y2 = −3 y1 (roots of ωᵀq above), in its two directions.  Every state keeps
    the bar lengths and satisfies Freudenstein's equation (1e-9); after the switch θ4 ≠ θ2."""
    m = _parallelogram()
    conn = m.connectivity
    ends = {}
    for branch in (1, 2):
        t = trussfe.trace(m, drive="1:y", step=-0.05, steps=30, branch=branch)
        P = t.position
        L = np.linalg.norm(P[:, conn[:, 1]] - P[:, conn[:, 0]], axis=2)
        assert np.abs(L - L[0]).max() < 1e-9
        assert np.abs(_freudenstein(P)).max() < 1e-9
        assert any(e.get("branch") == branch for e in t.events)
        t2, t4 = _angles(P)
        assert np.all(np.abs(t2[:6] - t4[:6]) < 1e-9)   # parallelogram before the flat state
        assert abs(t4[-1] - t2[-1]) > 0.5                # crossed branch at the end
        k = int(np.argmin(np.abs(t2) + np.abs(t4)))      # the switch, near the flat state
        assert t4[k + 2] / t2[k + 2] == pytest.approx(-3.0, rel=0.1)
        ends[branch] = t2[-1]
    assert np.sign(ends[1]) == -np.sign(ends[2])         # the two directions


def test_five_bar_with_one_drive_is_refused():
    """Closed form (Grübler): the five-bar linkage has 2·3 − 4 = 2 degrees of freedom and no
    state of self-stress, so no state of it is a bifurcation point; one drive does not fix its
    motion and is refused in one line instead of reporting a bifurcation at every state.  With
    two drives it is traced, each drive moving by its step."""
    m = _model([[0, 0], [0.5, 1.0], [2, 2.0], [3.6, 1.2], [4, 0]],
               [(0, 1), (1, 2), (2, 3), (3, 4)], {0: ["x", "y"], 4: ["x", "y"]})
    r = trussfe.mechanism(m)
    assert (r.mechanisms, r.self_stress_states) == (2, 0)
    with pytest.raises(InputError, match="2 degrees of freedom"):
        trussfe.trace(m, drive="1:x", step=0.02, steps=3)
    t = trussfe.trace(m, drive=["1:x", "3:x"], step=[0.02, -0.03], steps=4)
    assert np.allclose(np.diff(t.position[:, 1, 0]), 0.02)
    assert np.allclose(np.diff(t.position[:, 3, 0]), -0.03)
    assert t.events == []


def test_free_triangle_trace_is_refused():
    """pyrigi: the triangle is infinitesimally rigid (rigidity-matrix rank 3 = 2·3 − 3) with the
    three trivial motions only; without supports those are rigid-body motions, not a
    mechanism with bifurcations, and a one-drive trace is refused."""
    pyrigi = pytest.importorskip("pyrigi")
    F = pyrigi.Framework(pyrigi.Graph([(0, 1), (1, 2), (0, 2)]),
                         {0: [0, 0], 1: [1, 0], 2: [0, 1]})
    assert F.rigidity_matrix_rank() == 3 and F.is_inf_rigid()
    assert len(F.trivial_inf_flexes()) == 3
    m = _model([[0, 0], [1, 0], [0, 1]], [(0, 1), (1, 2), (2, 0)])
    r = trussfe.mechanism(m)
    assert (r.rank, r.mechanisms, r.rigid_body_motions) == (3, 0, 3)
    with pytest.raises(InputError, match="3 degrees of freedom"):
        trussfe.trace(m, drive="2:x", step=0.1, steps=2)


def test_fourbar_with_ground_bar_is_finite():
    """Closed form: a Grashof four-bar (ground 3, crank 1, coupler 2.5, rocker 2.6) is a finite
    mechanism; modelling its ground bar between the two pinned joints adds only a zero row of B
    (a self-stress no motion can load), so the order is infinite, as without it.  The traced
    motion satisfies Freudenstein's equation with the ground bar present."""
    a, b, c, d = 3.0, 1.0, 2.5, 2.6
    A = np.array([math.cos(0.1), math.sin(0.1)])
    D = np.array([a, 0.0])
    w = D - A
    dist = np.linalg.norm(w)
    x = (c * c - d * d + dist * dist) / (2 * dist)
    u = w / dist
    B = A + x * u + math.sqrt(c * c - x * x) * np.array([-u[1], u[0]])
    nodes = [[0, 0], A, B, D]
    sup = {0: ["x", "y"], 3: ["x", "y"]}
    plain = trussfe.mechanism(_model(nodes, [(0, 1), (1, 2), (3, 2)], sup))
    m = _model(nodes, [(0, 1), (1, 2), (3, 2), (0, 3)], sup)
    grounded = trussfe.mechanism(m)
    assert plain.order == math.inf
    assert (grounded.mechanisms, grounded.self_stress_states) == (1, 1)
    assert grounded.order == math.inf
    assert grounded.order_analysis.status == "finite"
    t = trussfe.trace(m, drive="1:y", step=0.02, steps=20)
    P = t.position
    t2 = np.arctan2(P[:, 1, 1], P[:, 1, 0])
    t4 = np.arctan2(P[:, 2, 1], P[:, 2, 0] - a)
    K1, K2, K3 = a / b, a / d, (b * b - c * c + d * d + a * a) / (2 * b * d)
    assert np.abs(K1 * np.cos(t4) - K2 * np.cos(t2) + K3 - np.cos(t2 - t4)).max() < 1e-9


def test_ground_bar_does_not_hide_an_obstruction():
    """Closed form (Connelly and Servatius): two collinear bars between fixed joints have order 1;
    adding a bar between the two fixed joints keeps order 1 (the real self-stress still
    obstructs)."""
    m = _model([[0, 0], [1, 0], [2, 0]], [(0, 1), (1, 2), (0, 2)],
               {0: ["x", "y"], 2: ["x", "y"]})
    r = trussfe.mechanism(m)
    assert (r.mechanisms, r.self_stress_states) == (1, 2)
    assert r.order == 1
