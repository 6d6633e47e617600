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


def test_member_vectors_and_lengths_of_a_components_first_field():
    x = rng.standard_normal((20, 12, 3))
    conn = rng.integers(0, 12, (30, 2))
    d_ref = member_vectors(x, conn)
    d = member_vectors(components_first(x), conn)
    assert np.array_equal(d, d_ref) and is_components_first(d)
    assert np.array_equal(lengths(d), np.linalg.norm(d_ref, axis=-1))
