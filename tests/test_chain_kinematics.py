# SPDX-License-Identifier: MIT
"""Bay-by-bay chain kinematics (Lacy chapter 6) against the direct analysis of the whole chain."""
import numpy as np
import pytest
import scipy.sparse.linalg as spla
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError
from trussfe.kinematics import compatibility_matrix, solve_positions
from trussfe.rigid.chain import (bay_kinematics, chain_kinematics, rigid_rates, stack_bays,
                                 thesis_angular_acceleration, triangle_frame)
from trussfe.rigid.motion import third_order_response
from trussfe.studies.lacy_rigid import EQUILIBRIUM_LENGTH, double_octahedron

NB = 3


@pytest.fixture(scope="module")
def bay():
    return double_octahedron()


@pytest.fixture(scope="module")
def motion():
    """Every active member of every bay moves by its own amount (up to ±6 cm) in 2 s, so the
    bays tilt about different axes; 21 samples of the third-order model."""
    t = np.linspace(0.0, 2.0, 21)
    y, dy, ddy = third_order_response(t, 2.0)
    amp = np.array([[0.05, -0.03, 0.01], [-0.04, 0.02, 0.06], [0.03, 0.05, -0.05]])  # (bay, act)
    L = EQUILIBRIUM_LENGTH + y[:, None, None] * amp
    return t, L, dy[:, None, None] * amp, ddy[:, None, None] * amp


def direct(chain, lengths):
    """Independent reference: the whole chain as one assembly — forward position by Newton
    (solve_positions, warm-started), velocities from B v = L̇ and accelerations from
    B a = L̈ − (|v_rel|² − L̇²)/L with B the chain's sparse compatibility matrix."""
    L, Ld, Ldd = lengths
    nt = L.shape[0]
    acts = np.array([a.member for a in chain.extensions["active_members"]])
    conn, fixed = chain.connectivity, chain.translation_supports
    free = ~fixed
    X, V, A = (np.zeros((nt, chain.n_nodes, 3)) for _ in range(3))
    x = chain.coords
    for k in range(nt):
        Lk = chain.lengths().copy()
        Lk[acts] = L[k].ravel()
        x = solve_positions(x, conn, Lk, fixed).coords
        X[k] = x
        B = compatibility_matrix(x, conn, free=free).tocsc()
        lu = spla.splu(B)
        e = np.zeros(conn.shape[0])
        e[acts] = Ld[k].ravel()
        V[k][free] = lu.solve(e)
        vrel = V[k][conn[:, 1]] - V[k][conn[:, 0]]
        g = np.zeros(conn.shape[0])
        g[acts] = Ldd[k].ravel()
        g -= (np.sum(vrel ** 2, axis=1) - e ** 2) / Lk
        A[k][free] = lu.solve(g)
    return X, V, A


def test_stacked_chain_members_keep_the_bay_lengths(bay):
    """Stacking is a rigid placement: every member of the chain has its template length, and
    the chain has 18 n members and 3 + 6 n nodes (Lacy Fig. 6.1)."""
    c = stack_bays(bay, NB)
    assert (c.n_members, c.n_nodes) == (18 * NB, 3 + 6 * NB)
    assert_allclose(c.lengths(), np.tile(bay.lengths(), NB), rtol=1e-13)
    assert len(c.extensions["active_members"]) == 3 * NB


def test_bay_by_bay_equals_direct_chain(bay, motion):
    """Positions, velocities and accelerations of every node of a 3-bay chain: the bay-by-bay
    recursion (eqs. 6.1–6.13) equals the direct whole-chain kinematics to round-off (1e-9 of
    each field's largest value)."""
    t, L, Ld, Ldd = motion
    chain = stack_bays(bay, NB)
    ck = chain_kinematics(bay, L, Ld, Ldd)
    X, V, A = direct(chain, (L, Ld, Ldd))
    assert_allclose(ck.coords, X, atol=1e-9 * np.abs(X).max())
    assert_allclose(ck.velocity, V, atol=1e-9 * np.abs(V).max())
    assert_allclose(ck.acceleration, A, atol=1e-9 * np.abs(A).max())
    assert np.abs(V).max() > 0.01 and np.abs(A).max() > 0.01     # the chain really moves


def test_velocities_match_finite_differences_of_positions(bay, motion):
    """Independent of the compatibility equations: central differences of the bay-by-bay
    positions on a fine time grid (dt = 5 ms) reproduce the velocities; the differencing error
    O(dt² v'''/6) of this fast move (real pole at 8.3 rad/s) is below 5e-4 of the peak."""
    t = np.linspace(0.0, 2.0, 401)
    y, dy, ddy = third_order_response(t, 2.0)
    amp = np.array([[0.05, -0.03, 0.01], [-0.04, 0.02, 0.06], [0.03, 0.05, -0.05]])
    ck = chain_kinematics(bay, EQUILIBRIUM_LENGTH + y[:, None, None] * amp,
                          dy[:, None, None] * amp, ddy[:, None, None] * amp)
    vfd = np.gradient(ck.coords, t, axis=0)
    inner = slice(2, -2)
    assert np.abs(vfd - ck.velocity)[inner].max() < 5e-4 * np.abs(ck.velocity).max()


def test_rigid_rates_of_a_spinning_triangle():
    """A triangle spinning at ω = (0.3, −0.2, 1.0) rad/s with α = (0.1, 0.5, −0.4) rad/s²:
    v = ω × r, a = α × r + ω × (ω × r) are inverted exactly."""
    x = np.array([[0.0, 0, 0], [1.2, 0.1, 0.2], [0.3, 1.0, -0.1]])
    w, al = np.array([0.3, -0.2, 1.0]), np.array([0.1, 0.5, -0.4])
    r = x - x.mean(axis=0)
    v = np.cross(w, r) + [1.0, 2.0, 3.0]
    a = np.cross(al, r) + np.cross(w, np.cross(w, r))
    vo, ao, w2, al2 = rigid_rates(x, v, a)
    assert_allclose(w2, w, rtol=1e-13)
    assert_allclose(al2, al, rtol=1e-13)
    assert_allclose(vo, [1.0, 2.0, 3.0], rtol=1e-13)
    _, R = triangle_frame(x)
    assert_allclose(R.T @ R, np.eye(3), atol=1e-15)


def test_equation_6_14_misses_the_transport_terms(bay, motion):
    """Lacy's eq. 6.14 (sum of relative angular accelerations) is exact for bay 2 (the first
    moving frame) and misses ω₂ × ω₃ for bay 3's frame when the bays turn about different
    axes (Coriolis theorem for angular velocity)."""
    t, L, Ld, Ldd = motion
    ck = chain_kinematics(bay, L, Ld, Ldd)
    f = ck.frames
    al_thesis = thesis_angular_acceleration(f)
    assert_allclose(al_thesis[:, :2], f.alpha[:, :2], atol=1e-12)
    miss = f.alpha[:, 2] - al_thesis[:, 2]
    assert_allclose(miss, np.cross(f.omega[:, 1], f.omega[:, 2]), atol=1e-12)
    assert np.abs(miss).max() > 1e-4 * np.abs(f.alpha[:, 2]).max()


def test_singular_bay_is_reported(bay):
    """A bay driven to a flat (singular) position gives an AnalysisError, not garbage."""
    n = 2
    L = np.full((n, 3), EQUILIBRIUM_LENGTH)
    L[1] = 3.0                       # no assembly: active members longer than possible
    with pytest.raises(AnalysisError):
        bay_kinematics(bay, L, np.zeros_like(L), np.zeros_like(L))


def test_batched_positions_equal_the_step_by_step_solution(bay, motion):
    """All bays and steps at once by Newton from the template (the fast path) give the
    positions of the warm-started step-by-step forward-position solver (the reference,
    ``solve_positions``) to 1e-12 m."""
    from trussfe.rigid.chain import _all_lengths, _batched_positions, _sequential_positions
    _, L, _, _ = motion
    nt, nb, _ = L.shape
    Lall = _all_lengths(bay, L.transpose(1, 0, 2).reshape(nb * nt, 3))
    X, ok = _batched_positions(bay, Lall, bay.coords)
    assert ok.all()
    for k in range(nb):
        ref = _sequential_positions(bay, Lall[k * nt:(k + 1) * nt], bay.coords, "bay")
        assert_allclose(X[k * nt:(k + 1) * nt], ref, rtol=0, atol=1e-12)


def test_steps_not_reached_from_the_template_fall_back_to_continuation(bay, motion,
                                                                       monkeypatch):
    """When the batched Newton reports a step as not converged, that bay is re-solved step by
    step: the result equals the normal one (atol 1e-12 of the largest coordinate)."""
    import trussfe.rigid.chain as ch
    t, L, Ld, Ldd = motion
    ref = chain_kinematics(bay, L, Ld, Ldd)
    real = ch._batched_positions

    def half_failed(b, Lm, x0, **kw):
        X, ok = real(b, Lm, x0, **kw)
        ok[::2] = False
        return X, ok

    monkeypatch.setattr(ch, "_batched_positions", half_failed)
    ck = chain_kinematics(bay, L, Ld, Ldd)
    assert_allclose(ck.coords, ref.coords, rtol=0, atol=1e-12 * np.abs(ref.coords).max())
    assert_allclose(ck.acceleration, ref.acceleration, rtol=0,
                    atol=1e-10 * np.abs(ref.acceleration).max())


def test_triangle_frame_origin_is_numpy_mean_to_the_last_bit():
    """The frame's origin (Lacy eq. 6.2, the centroid) equals numpy's mean of the three nodes
    bit for bit, on triangles of widely different scales and signs."""
    import numpy as np
    from trussfe.rigid.chain import triangle_frame
    rng = np.random.default_rng(4)
    x = rng.standard_normal((400, 3, 3)) * 10.0 ** rng.integers(-6, 6, size=(400, 3, 3))
    o, R = triangle_frame(x)
    np.testing.assert_array_equal(o, x.mean(axis=-2))
    np.testing.assert_allclose(np.einsum("tji,tjk->tik", R, R), np.broadcast_to(np.eye(3),
                               R.shape), atol=1e-12)
