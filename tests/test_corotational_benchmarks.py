"""Large-rotation benchmarks of the co-rotational beams against closed-form solutions.

References: the cantilever rolled up by an end moment (constant curvature M/EI: tip at
``(L/φ) sin φ, (L/φ)(1 − cos φ)`` with ``φ = ML/EI``); the elastica of a cantilever under a
transverse tip dead load (Mattiasson 1981, here integrated by shooting with
``scipy.integrate.solve_ivp``); the pure twist of a straight shaft, ``φ = TL/GJ``.
"""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, follow_path
from trussfe.nonlinear.beam3d import expm_so3, reference_frames

MAT = Material(name="steel", E=2.0e11, G=8.0e10, density=0.0, yield_strength=math.nan)
#: unequal bending stiffnesses, so that a moment about the wrong axis would show
SEC = Section(name="rect", area=3.0e-4, Iy=2.0e-8, Iz=5.0e-8, J=4.0e-8, c=0.02)
CLAMP = ["x", "y", "z", "rx", "ry", "rz"]


def _cantilever(axis, load, sec=SEC, orientation=None):
    """A 3-D cantilever of length 1 m along ``axis``, clamped at node 0, tip load ``load``
    (3 forces and 3 moments) at node 1."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    s = build_structure([[0.0, 0.0, 0.0], list(a)], [(0, 1)], section=sec, material=MAT,
                        is_beam=True, supports={0: CLAMP}, loads={1: list(load)})
    if orientation is not None:
        s = s.with_member_data(orientation={0: tuple(orientation)})
    return s, a


def _local_axes(axis, orientation=None):
    s, _ = _cantilever(axis, [0.0] * 6, orientation=orientation)
    return reference_frames(s.coords, s.connectivity, s.orientation)[0]   # columns e1 e2 e3


@pytest.mark.parametrize("turns, axis", [(1, (1.0, 0.0, 0.0)), (2, (1.0, 0.0, 0.0)),
                                         (1, (0.0, 1.0, 0.0)), (1, (0.0, 0.0, 1.0)),
                                         (1, (1.0, 1.0, 1.0))],
                         ids=["x-1", "x-2", "y-1", "z-1", "oblique-1"])
def test_arc_length_rolls_a_3d_cantilever_into_full_circles(turns, axis):
    """Cantilever along ``axis`` (x, y, z, oblique) under an end moment
    ``M = 2π·turns·EI_z/L`` about its local z axis (fixed direction), 16 elements,
    arc-length control (the default control): the path reaches the full load and every path
    point lies on the closed-form arc, tip at ``(L/φ)(sin φ e1 + (1 − cos φ) e3 × e1)``, to
    2e-5 L.  Without the LU fallback the diagonal-pivot LDLᵀ of the tangent breaks down — a
    vanishing pivot of a regular, slightly unsymmetric tangent — as the tip rotation nears
    2π, and the path stops at λ = 0.970 (one turn) or 0.485 (two)."""
    R0 = _local_axes(list(axis))
    EI = MAT.E * SEC.Iz
    M = 2 * np.pi * turns * EI
    s, a = _cantilever(list(axis), [0.0, 0.0, 0.0, *(M * R0[:, 2])])
    nl = NonlinearModel(s, subdivisions=16)
    res = follow_path(nl, "arc-length", steps=600, step=0.02 / turns, max_load_factor=1.0,
                      locate_critical=False)
    assert res.termination.startswith("reached the maximum load factor"), res.termination
    assert res.load_factors[-1] >= 1.0
    side = np.cross(R0[:, 2], a)
    for p in res.path[1:]:
        phi = 2 * np.pi * turns * p.load_factor
        exact = (np.sin(phi) * a + (1.0 - np.cos(phi)) * side) / phi
        assert_allclose(nl.positions(p.u)[1], exact, rtol=0, atol=2e-5)


def _elastica_tip(k):
    """Tip displacements (along the beam, transverse) of the inextensible cantilever elastica
    under a transverse dead load, ``k = PL²/EI``, L = 1 (Mattiasson's tables): shooting on
    ``θ'' = −k cos θ``, ``θ(0) = 0``, ``θ'(1) = 0``."""
    def end(c):
        sol = solve_ivp(lambda s, y: [y[1], -k * np.cos(y[0]), np.cos(y[0]), np.sin(y[0])],
                        (0.0, 1.0), [0.0, c, 0.0, 0.0], rtol=1e-12, atol=1e-12)
        return sol.y[:, -1]
    c = brentq(lambda c: end(c)[1], 0.0, k + 1e-9)
    y = end(c)
    return y[2] - 1.0, y[3]


@pytest.mark.parametrize("axis, orientation", [([1.0, 0.0, 0.0], None),
                                               ([1.0, 2.0, -1.5], (0.3, -0.5, 0.8))])
def test_cantilever_elastica_under_tip_dead_load(axis, orientation):
    """Cantilever (EA large: inextensible) under a transverse tip dead load up to
    ``PL²/EI = 10`` along its local y axis, along x and oblique with an orientation vector,
    16 elements, load control: tip displacements at every point within 1e-5 L of the elastica
    (Mattiasson 1981: at k = 10, u = −0.5550, v = 0.8106)."""
    sec = Section(name="stiff", area=1.0, Iy=SEC.Iy, Iz=SEC.Iz, J=SEC.J, c=0.02)
    R0 = _local_axes(axis, orientation)
    P = 10.0 * MAT.E * SEC.Iz
    s, a = _cantilever(axis, [*(P * R0[:, 1]), 0.0, 0.0, 0.0], sec=sec, orientation=orientation)
    nl = NonlinearModel(s, subdivisions=16)
    res = follow_path(nl, "load", steps=40, step=0.05, max_load_factor=1.0,
                      locate_critical=False)
    assert res.load_factors[-1] == pytest.approx(1.0)
    for p in res.path[1:]:
        d = nl.positions(p.u)[1] - nl.X[1]
        assert_allclose([d @ a, d @ R0[:, 1]], _elastica_tip(10.0 * p.load_factor),
                        rtol=0, atol=1e-5)


def test_pure_twist_of_a_straight_shaft_is_exact():
    """A torque T about the axis of an oblique straight cantilever twists it by ``TL/GJ``
    (here 7 rad, past 2π) with no displacement and no axial force (no coupling)."""
    a = np.array([1.0, 2.0, -1.5]) / np.linalg.norm([1.0, 2.0, -1.5])
    T = 7.0 * MAT.G * SEC.J
    s, a = _cantilever(a, [0.0, 0.0, 0.0, *(T * a)])
    nl = NonlinearModel(s, subdivisions=8)
    res = follow_path(nl, "load", steps=20, step=0.05, max_load_factor=1.0,
                      locate_critical=False)
    tip = nl.n_points * 3 + 3 * nl.joint_slot[1]
    for p in res.path[1:]:
        assert_allclose(expm_so3(p.u[tip:tip + 3]), expm_so3(7.0 * p.load_factor * a),
                        rtol=0, atol=1e-12)
        assert np.abs(nl.positions(p.u) - nl.X).max() < 1e-12
        assert np.abs(p.forces).max() < 1e-6
    assert res.load_factors[-1] == pytest.approx(1.0)
