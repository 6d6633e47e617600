# SPDX-License-Identifier: MIT
"""Springs in the post-critical analysis, lumped-mass modes of structures with massless
mechanisms, and the convergence of buckling under self-weight: each against a closed form or
the linear static analysis, named in the test."""
from __future__ import annotations

import numpy as np
import pytest

import trussfe

EA = 1.0e6                          # N: E = 1e10 Pa, A = 1e-4 m²
A_HALF, RISE = 1.0, 0.1             # m: half-span and rise of the von Mises truss


def _von_mises(dim: int, spring: float) -> trussfe.Structure:
    """The shallow two-bar truss of meshes/postcritical_von_mises.toml with a vertical
    spring k (N/m) from its apex to the ground; in 3-D the apex is held out of plane by
    another spring instead of a support."""
    z = [0.0] if dim == 3 else []
    springs = {"y": spring} | ({"z": 1.0e5} if dim == 3 else {})
    return trussfe.model_from_dict({
        "model": {"dimension": dim},
        "materials": {"m": {"E": 1.0e10}},
        "sections": {"s": {"area": 1.0e-4}},
        "nodes": {"l": [-A_HALF, 0.0] + z, "c": [0.0, RISE] + z, "r": [A_HALF, 0.0] + z},
        "members": {"L": {"nodes": ["l", "c"], "section": "s", "material": "m"},
                    "R": {"nodes": ["c", "r"], "section": "s", "material": "m"}},
        "supports": {"l": ["x", "y", "z"][:dim], "r": ["x", "y", "z"][:dim], "c": ["x"]},
        "springs": {"c": springs},
        "loads": {"c": [0.0, -1.0] + z}})


def _von_mises_load(v: np.ndarray, k: float) -> np.ndarray:
    """Closed form of the path: the downward apex load at apex displacement v (< 0 down),
    P = 2EA·w(1/ℓ − 1/L) − k v with w = h + v the current rise (bars' vertical resistance,
    docs/postcritical.md, plus the spring's force −k v)."""
    L = np.hypot(A_HALF, RISE)
    w = RISE + v
    ell = np.hypot(A_HALF, w)
    return 2.0 * EA * w * (1.0 / ell - 1.0 / L) - k * v


@pytest.mark.parametrize("dim", [2, 3])
def test_postcritical_path_includes_springs(dim):
    """Reference: closed form of the von Mises truss plus a linear spring at its apex
    (docs/fem.md: "a spring adds k to the diagonal of K at its DOF (in every analysis)").
    The post-critical path ignored [springs]: its limit load was that of the bare truss
    (381.09 N) and, in 3-D, the apex held only by a spring out of plane was a mechanism."""
    k = 2.0e3
    r = trussfe.postcritical(_von_mises(dim, k), control="arc-length", steps=200,
                             step=0.002, max_step=0.004, max_displacement=0.25,
                             monitor="c:y")
    v = r.displacement[:, 1, 1]
    assert v.min() < -0.2                                 # through the snap
    np.testing.assert_allclose(r.load_factors, _von_mises_load(v, k), rtol=0,
                               atol=1e-6 * _von_mises_load(v, k).max())
    limit = [e.load_factor for e in r.events if e.kind == "limit_point"]
    vv = np.linspace(-0.1, 0.0, 200001)
    assert limit and abs(limit[0] - _von_mises_load(vv, k).max()) < 1e-6 * limit[0]


def _rotational_spring_cantilever(dim: int, k_theta: float, M: float):
    """A stiff cantilever on a rotational spring at its root (root translations supported),
    loaded by a moment M at its tip about the global z axis."""
    if dim == 2:
        sup, spr, load = ["x", "y"], {"rz": k_theta}, [0.0, 0.0, M]
        nodes = {"A": [0.0, 0.0], "B": [1.0, 0.0]}
    else:
        sup, spr = ["x", "y", "z", "rx", "ry"], {"rz": k_theta}
        load = [0.0, 0.0, 0.0, 0.0, 0.0, M]
        nodes = {"A": [0.0, 0.0, 0.0], "B": [1.0, 0.0, 0.0]}
    return trussfe.model_from_dict({
        "model": {"dimension": dim},
        "materials": {"m": {"E": 2.0e11, "G": 8.0e10}},
        "sections": {"s": {"area": 1.0e-2, "Iy": 1.0e-3, "Iz": 1.0e-3, "J": 2.0e-3,
                           "c": 0.1}},
        "nodes": nodes,
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "m",
                           "type": "beam"}},
        "supports": {"A": sup},
        "springs": {"A": spr},
        "loads": {"B": load}})


@pytest.mark.parametrize("dim", [2, 3])
def test_postcritical_rotational_spring_large_rotation(dim):
    """Reference: a rotational spring k_θ at the root of a cantilever under a tip moment M
    turns by M/k_θ, and the beam bends by ML/EI (exact for a moment of fixed direction about
    a fixed axis, whatever the rotation); here 0.8 rad in all, ≈ 0.8 rad in the spring.
    The post-critical analysis ignored the spring: the root was free to turn."""
    k_theta, M = 1.0e4, 8.0e3
    EI = 2.0e11 * 1.0e-3
    r = trussfe.postcritical(_rotational_spring_cantilever(dim, k_theta, M), control="load",
                             steps=16, max_load_factor=1.0, subdivisions=4)
    assert r.load_factors[-1] == pytest.approx(1.0)
    theta = M / k_theta + M * 1.0 / EI
    # the tip of a rigid bar turned by θ about the root; the beam's own bending moves it by
    # less than 1e-4 m at this EI
    tip = r.displacement[-1, 1]
    expect = [np.cos(theta) - 1.0, np.sin(theta)] + ([0.0] if dim == 3 else [])
    np.testing.assert_allclose(tip, expect, atol=2e-4)


def test_postcritical_small_load_matches_linear_static_with_springs():
    """Reference: trussfe.static (linear, springs included) on a braced portal with a
    horizontal spring; a load step of 1e-6 of the reference load must give the linear
    displacements (docs/postcritical.md: the tangent at the undeformed state is the core's
    K + K_g)."""
    frame = trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"m": {"E": 2.0e11}},
        "sections": {"s": {"area": 4.0e-3, "Iz": 8.0e-6, "c": 0.1}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0.0]},
        "members": {m: {"nodes": list(m), "section": "s", "material": "m", "type": "beam"}
                    for m in ("AB", "BC", "CD")},
        "supports": {"A": ["x", "y", "rz"], "D": ["x", "y"]},
        "springs": {"C": {"x": 3.0e5}, "D": {"rz": 2.0e6}},
        "loads": {"B": [2000.0, -1000.0, 0.0]}})
    lin = trussfe.static(frame, subdivisions=4)
    r = trussfe.postcritical(frame, control="load", steps=1, max_load_factor=1e-6,
                             subdivisions=4)
    # Newton's tolerance (1e-9 of the load) and the co-rotational terms of order λ leave
    # ~1e-7 of the largest displacement, with or without springs; ignoring the springs
    # nearly doubles the sway (3.6 mm against 1.9 mm)
    np.testing.assert_allclose(r.displacement[-1] / 1e-6, lin.displacement, rtol=0,
                               atol=1e-6 * np.abs(lin.displacement).max())


# ---------------------------------------------------------------------- modal
E_ST, RHO_ST, A_B, I_B, L_B = 2.0e11, 7850.0, 1.0e-3, 2.0e-6, 3.0


def _beam(dim: int, supports: dict) -> trussfe.Structure:
    """A straight steel beam along x, equal bending stiffness about both axes."""
    z = [0.0] if dim == 3 else []
    return trussfe.model_from_dict({
        "model": {"dimension": dim},
        "materials": {"m": {"E": E_ST, "G": E_ST / 2.6, "density": RHO_ST}},
        "sections": {"s": {"area": A_B, "Iz": I_B, "Iy": I_B, "J": 2 * I_B}},
        "nodes": {"a": [0.0, 0.0] + z, "b": [L_B, 0.0] + z},
        "members": {"ab": {"nodes": ["a", "b"], "section": "s", "material": "m",
                           "type": "beam"}},
        "supports": supports})


@pytest.mark.parametrize("subdivisions", [16, 200])        # dense and sparse eigen paths
def test_lumped_modes_of_beam_free_to_twist(subdivisions):
    """Reference: simply supported Euler–Bernoulli beam, f_n = n²π/(2L²)·√(EI/ρA), each
    frequency twice in 3-D (equal Iy, Iz).  Between ball joints the beam can twist freely;
    lumped mass puts no mass on rotations, so the twist is a massless mechanism.  It was
    counted as a zero-frequency mode: with 16 subdivisions the first bending frequency came
    out once (its copy reported as a 0 Hz 'rigid' mode), with 200 (sparse path) the
    analysis stopped with a SingularMatrixError traceback."""
    beam = _beam(3, {"a": ["x", "y", "z"], "b": ["y", "z"]})
    r = trussfe.modes(beam, count=4, mass="lumped", subdivisions=subdivisions)
    f1 = np.pi / (2 * L_B ** 2) * np.sqrt(E_ST * I_B / (RHO_ST * A_B))
    assert r.solution.rigid_modes == 0
    np.testing.assert_allclose(r.frequencies_hz / f1, [1.0, 1.0, 4.0, 4.0], rtol=2e-4)
    # the modes still M-orthonormal and the bending pair in the two planes
    res = r.solution
    assert np.all(res.residuals < 1e-6)


def test_lumped_free_free_3d_beam_agrees_with_2d():
    """Reference: the 2-D model of the same free–free beam (the same discretisation of the
    bending in each plane; 3 rigid-body modes in 2-D, 6 in 3-D of which the spin about the
    beam's axis carries no mass under lumped mass, so 5 zero-frequency modes).  The 3-D
    lumped analysis reported 6 zero-frequency modes and lost one of the two first bending
    modes."""
    r2 = trussfe.modes(_beam(2, {}), count=5, mass="lumped", subdivisions=16)
    r3 = trussfe.modes(_beam(3, {}), count=9, mass="lumped", subdivisions=16)
    assert r2.solution.rigid_modes == 3 and r3.solution.rigid_modes == 5
    bend2 = r2.frequencies_hz[3:]
    np.testing.assert_allclose(r3.frequencies_hz[:5], 0.0)
    np.testing.assert_allclose(r3.frequencies_hz[5:], np.repeat(bend2, 2), rtol=1e-9)
    # consistent mass: the spin has the sections' polar inertia ρJ and is a rigid mode
    rc = trussfe.modes(_beam(3, {}), count=7, mass="consistent", subdivisions=16)
    assert rc.solution.rigid_modes == 6


def test_self_weight_buckling_converges_as_h_squared_from_below():
    """docs/modal-buckling.md: with one axial force per element, a column whose N varies
    along it converges as h², on the safe side.  Reference: Greenhill's cantilever under its
    own weight, critical total weight qL = 7.837347 EI/L² (Timoshenko & Gere, Theory of
    Elastic Stability, §2.13).  The documented errors are 2.6 %, 0.64 % and 0.16 % low with
    4, 8 and 16 elements."""
    E, A, I, rho, g, L = 2.0e11, 1.0e-3, 1.0e-7, 7850.0, 9.81, 5.0
    exact = 7.837347 * E * I / (L**3 * rho * A * g)
    errors = []
    for k in (4, 8, 16):
        s = trussfe.model_from_dict({
            "model": {"dimension": 2, "gravity": [0.0, -g]},
            "materials": {"st": {"E": E, "G": 8.0e10, "density": rho}},
            "sections": {"b": {"area": A, "Iz": I, "c": 0.05}},
            "nodes": {"A": [0.0, 0.0], "B": [0.0, L]},
            "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                               "type": "beam"}},
            "supports": {"A": ["x", "y", "rz"]}})
        errors.append(trussfe.buckling(s, count=1, subdivisions=k).load_factors[0] / exact - 1)
    assert all(e < 0 for e in errors), errors
    assert [round(-100 * e, 2) for e in errors] == [2.57, 0.64, 0.16], errors
    assert 3.8 < errors[0] / errors[1] < 4.2 and 3.8 < errors[1] / errors[2] < 4.2, errors
