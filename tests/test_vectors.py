# SPDX-License-Identifier: MIT
"""3-vector arrays stored components first (trussfe.vectors) give the same numbers, to the
last bit, as the usual order: the reference is numpy's own einsum / take / cross on the
usual-order copy of the same data."""
import numpy as np
import pytest

from trussfe.model.geometry import lengths, member_vectors
from trussfe.vectors import components_first, cross, dot, empty_vectors, is_components_first, take

rng = np.random.default_rng(7)


def test_components_first_keeps_values_and_stores_each_component_contiguously():
    a = rng.standard_normal((40, 25, 3))
    c = components_first(a)
    assert c.shape == a.shape and np.array_equal(c, a)
    assert is_components_first(c) and not is_components_first(a)
    assert all(c[..., k].flags.c_contiguous for k in range(3))
    assert components_first(c) is c                                   # no second copy
    assert is_components_first(c[5:17])                               # steps sliced
    assert not is_components_first(c[:, 3:9])                         # members sliced
    e = empty_vectors((4, 5, 3))
    assert e.shape == (4, 5, 3) and is_components_first(e)


def test_dot_adds_in_einsum_order_bit_for_bit_in_either_layout():
    a, b = rng.standard_normal((2, 300, 50, 3))
    ref = np.einsum("tmi,tmi->tm", a, b)            # numpy's sum over a contiguous axis
    assert np.array_equal(dot(a, b), ref)
    assert np.array_equal(dot(components_first(a), components_first(b)), ref)
    # broadcasting, and a plain sum in another order differs somewhere (the test can fail)
    g = rng.standard_normal(3)
    assert np.array_equal(dot(np.broadcast_to(g, a.shape), a),
                          np.einsum("tmi,tmi->tm", np.broadcast_to(g, a.shape), a))
    p = a * b
    assert not np.array_equal((p[..., 0] + p[..., 1]) + p[..., 2], ref)
    assert dot(np.array([1.0, 2.0, 3.0]), np.array([4.0, 5.0, 6.0])) == 32.0


def test_cross_equals_numpy_cross_and_follows_the_layout():
    a, b = rng.standard_normal((2, 200, 30, 3))
    ref = np.cross(a, b)
    assert np.array_equal(cross(a, b), ref)
    c = cross(components_first(a), components_first(b))
    assert np.array_equal(c, ref) and is_components_first(c)


@pytest.mark.parametrize("axis", [1, -2, 0])
def test_take_equals_numpy_take_in_either_layout(axis):
    a = rng.standard_normal((30, 40, 3))
    idx = rng.integers(0, a.shape[axis], 55)
    ref = np.take(a, idx, axis=axis)
    got = take(components_first(a), idx, axis=axis)
    assert np.array_equal(got, ref) and is_components_first(got)
    assert np.array_equal(take(a, idx, axis=axis), ref)
    two = idx[:54].reshape(6, 9)                       # indices of any shape, as numpy's
    assert np.array_equal(take(components_first(a), two, axis=axis),
                          np.take(a, two, axis=axis))


def test_take_of_a_block_of_steps_gathers_component_by_component():
    """A block of steps of a components-first array (its components no longer one
    contiguous block) is gathered component by component, with the same numbers as numpy's
    take, and the result's components stored first."""
    a = components_first(rng.standard_normal((30, 40, 3)))[5:20]
    assert not np.moveaxis(a, -1, 0).flags.c_contiguous
    idx = rng.integers(0, 40, 25)
    got = take(a, idx, axis=1)
    assert np.array_equal(got, np.take(np.ascontiguousarray(a), idx, axis=1))
    assert is_components_first(got)


def test_member_vectors_and_lengths_of_a_components_first_field():
    x = rng.standard_normal((20, 12, 3))
    conn = rng.integers(0, 12, (30, 2))
    d_ref = member_vectors(x, conn)
    d = member_vectors(components_first(x), conn)
    assert np.array_equal(d, d_ref) and is_components_first(d)
    assert np.array_equal(lengths(d), np.linalg.norm(d_ref, axis=-1))


@pytest.mark.parametrize("blocks", [False, True])
def test_rigid_body_histories_are_stored_components_first(blocks, monkeypatch):
    """docs/rigid-body.md: the vector histories of a simulation keep their shapes and store
    each component contiguously (the whole motion at once, and in blocks of 100 steps), and
    the numbers equal numpy's own products of the usual-order copies (e = d/|d|, ω = e × ė)."""
    import trussfe.rigid.simulate as sim
    from trussfe.rigid.motion import third_order_motion
    from trussfe.rigid.simulate import simulate
    from trussfe.studies.lacy_rigid import double_octahedron
    if blocks:
        monkeypatch.setattr(sim, "CHUNK_ENTRIES", 100 * 18)
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 400)
    r = simulate(s, m, n_sections=3)
    k = r.kinematics
    for a in (k.velocity, k.acceleration, k.unit, k.unit_rate, k.unit_acc, k.omega, k.alpha,
              r.forces.end_force[:, :, 0], r.forces.end_force[:, :, 1], r.sections.shear,
              r.sections.moment, r.static_sections.shear):
        assert is_components_first(a), a.shape
    assert k.unit.shape == (400, s.n_members, 3)
    assert r.forces.end_force.shape == (400, s.n_members, 2, 3)
    assert r.sections.shear.shape == (400, s.n_members, 3, 3)
    d = member_vectors(np.ascontiguousarray(k.coords), s.connectivity)
    np.testing.assert_array_equal(k.unit, d / np.linalg.norm(d, axis=-1)[..., None])
    np.testing.assert_array_equal(k.omega, np.cross(np.ascontiguousarray(k.unit),
                                                    np.ascontiguousarray(k.unit_rate)))
