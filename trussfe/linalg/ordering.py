# SPDX-License-Identifier: MIT
"""Fill-reducing ordering of a sparse symmetric matrix from the positions of its unknowns:
geometric nested dissection.

A structure's unknowns sit at points (joints, points inside subdivided members), and two
unknowns are coupled only when a member joins their points.  Cutting the points of a region
in half by a plane across its longest extent therefore separates the two halves once the
unknowns coupled across the plane are set aside; nested dissection orders each half
recursively and the separator last, so that eliminating one half makes no fill in the other
(George, "Nested dissection of a regular finite element mesh", SIAM J. Numer. Anal. 10,
1973; Miller, Teng, Thurston and Vavasis, "Geometric separators for finite-element meshes",
SIAM J. Sci. Comput. 19, 1998).

The halves are cut on the points, the separators are chosen on the unknowns: of an
unknown pair coupled across a cut, one unknown joins the separator, and only the
components a member couples do (a bar along x couples the x translations of its ends
only).  For each cut the separator is the side with fewer such unknowns.  On a
square-on-square space grid of 180 × 180 cells (195,471 unknowns) this takes 0.046 s and
gives PARDISO a factor of 21.8 million entries (7.8 GFlop) where MKL's nested dissection
of the same matrix, ~0.4 s, gives 22.6 million (8.0 GFlop); at 410 × 410 (10⁶ unknowns),
0.4 s and 137 million entries (91 GFlop) against ~3 s and 145 million (106 GFlop).  A
dissection of the points instead of the unknowns, with every component of a separator
point in the separator, gives 14.7 GFlop at 180 × 180.

It is meant for layers of joints — grids, plates, shells — whose cuts are lines of ~√n
unknowns.  A cut plane through a three-dimensional lattice is improved on by graph
partitioning (MKL's nested dissection of a braced cube of 30³ joints: 76 against 103
GFlop), so the ordering declines when its first separator is larger than a layer's
(:data:`SEPARATOR_FACTOR`).

Everything is vectorised: the cuts of one level are made together (a stable partition of
one order of the points per axis), and the level at which two coupled unknowns part is the
highest bit in which their regions' numbers differ, so that the matrix is read once.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Points per region at which the dissection stops (the regions are then ordered as they
#: come; PARDISO's supernodes take them as dense blocks).  8, 16 and 32 give factors within
#: 5 % of one another on the space grids; 16 is the fastest to compute of the two best.
LEAF_POINTS = 16
#: The first separator of ``n`` unknowns may hold at most this many times ``√n`` unknowns
#: for the ordering to be used: what a cut through a two-dimensional mesh (a grid, plate or
#: shell of joints) gives, with margin — 1.6 √n on the square-on-square space grids (243
#: of 21,951 unknowns at 60 × 60, 723 of 195,471 at 180 × 180).  A cut plane through a
#: three-dimensional lattice holds ~1.4 n^(2/3) (7–9 √n for braced cubes of 20³ and 30³
#: joints), where graph partitioning does better than planes (MKL's nested dissection: 76
#: against 103 GFlop at 30³); members joining far-apart points make it of the order of
#: ``n``.
SEPARATOR_FACTOR = 4.0


@dataclass(frozen=True)
class Points:
    """Where the unknowns of a system sit.

    Attributes
    ----------
    of_unknown : ndarray of int, shape (n,)
        The point of each unknown (several unknowns share a point: a joint's translations
        and rotations).
    coords : ndarray, shape (p, d)
        Coordinates of the points.
    """

    of_unknown: np.ndarray
    coords: np.ndarray


def _region_bits(coords: np.ndarray, depth: int) -> np.ndarray:
    """The region of each point after ``depth`` levels of halving: bit ``depth − 1 − l`` of
    the result says on which side of the level-``l`` cut the point lies.

    Each level cuts every region at the median of its points along its longest extent.  The
    regions of level ``l`` hold the points ``⌊k g / 2^l⌋ … ⌊(k + 1) g / 2^l⌋ − 1`` of one order
    of the ``g`` points, so that the halves of one level are the regions of the next.  The
    points are kept in one order per axis, sorted by region and, within a region, by that
    coordinate: a region's extent is read at its ends, and each cut is a stable partition
    of the orders (no sort after the first: 0.22 s instead of 0.45 s for the 337,000 joints
    of a 410 × 410 space grid), and a region's values reach its points by repetition
    (``numpy.repeat``), not by a gather (0.14 s instead of 0.20 s).
    """
    g, d = coords.shape
    it = np.int32 if g < 2**31 else np.int64
    orders = np.empty((d, g), dtype=it)
    for a in range(d):
        orders[a] = np.argsort(coords[:, a], kind="stable")
    flat = orders.reshape(-1)
    bits = np.zeros(g, dtype=np.int64)
    pos = np.arange(g, dtype=it)
    side = np.empty(g, dtype=np.int8)
    scratch = np.empty(g, dtype=it)
    for level in range(depth):
        nr = 1 << level
        bounds = (np.arange(nr + 1) * g) // nr
        counts = np.diff(bounds)
        first, last = bounds[:-1], np.maximum(bounds[1:] - 1, bounds[:-1])
        extent = np.stack([coords[orders[a, last], a] - coords[orders[a, first], a]
                           for a in range(d)], axis=1)
        axis = np.argmax(extent, axis=1)
        middle = ((2 * np.arange(nr) + 1) * g) // (2 * nr)
        # a region's values spread over its positions by repetition, not a gather: the
        # regions are contiguous runs of the orders
        middle_at = np.repeat(middle.astype(it), counts)
        at = np.repeat((axis * g).astype(it), counts)       # the cut axis's order, flat
        at += pos
        side[flat[at]] = pos >= middle_at
        bits <<= 1
        bits |= side
        for a in range(d):
            # stable partition of every region of this order: its lower half, then its upper
            s = side[orders[a]]
            ones = np.cumsum(s, dtype=it)
            ones -= s                                  # upper points before, in the order
            ones -= np.repeat(ones[first], counts)     # ... within the region
            new = np.where(s.astype(bool), middle_at + ones, pos - ones)
            scratch[new] = orders[a]
            orders[a] = scratch
    return bits


def nested_dissection(indptr: np.ndarray, indices: np.ndarray, points: Points,
                      leaf: int = LEAF_POINTS,
                      separator_factor: float = SEPARATOR_FACTOR) -> np.ndarray | None:
    """A nested-dissection ordering of a symmetric sparse matrix from its unknowns' points.

    Parameters
    ----------
    indptr, indices : ndarray of int
        Sparsity of the matrix (CSR, zero-based; its upper triangle is enough).
    points : Points
        Where the unknowns sit.
    leaf : int
        Points per region at which the dissection stops.
    separator_factor : float
        The first separator may hold at most ``separator_factor · √n`` unknowns.

    Returns
    -------
    ndarray of int, shape (n,) or None
        ``perm`` with ``perm[k]`` the unknown eliminated k-th; None when the first separator
        holds more than ``separator_factor · √n`` unknowns (a three-dimensional lattice, or
        members joining far-apart points: a graph ordering does better).

    Examples
    --------
    A chain of five points, one unknown each: the middle one is eliminated last.

    >>> import scipy.sparse as sp
    >>> A = sp.csr_matrix(sp.diags([1.0, 2.0, 1.0], [-1, 0, 1], shape=(5, 5)))
    >>> pts = Points(np.arange(5), np.arange(5.0)[:, None])
    >>> nested_dissection(A.indptr, A.indices, pts, leaf=1).tolist()
    [0, 1, 4, 3, 2]
    """
    n = indptr.size - 1
    of = np.asarray(points.of_unknown, dtype=np.int64)
    # the points that hold an unknown, numbered in their order (a count, not a sort)
    held = np.zeros(len(points.coords), dtype=bool)
    held[of] = True
    used = np.flatnonzero(held)
    number = np.cumsum(held) - 1
    point = number[of]
    coords = np.asarray(points.coords, dtype=float)[used]
    g = used.size
    depth = int(np.ceil(np.log2(g / leaf))) if g > leaf else 0
    # int32 where it fits: the pass over the matrix's entries moves half the memory
    it = np.int32 if max(n, 1 << depth) < 2**31 else np.int64
    region = _region_bits(coords, depth).astype(it)[point]           # (n,)
    counts = np.diff(indptr)
    rows = np.repeat(np.arange(n, dtype=it), counts)
    cols = np.asarray(indices).astype(it, copy=False)
    differ = np.repeat(region, counts)               # region[rows], by repetition
    differ ^= region[cols]
    cut = np.flatnonzero(differ)                                     # pairs across a cut
    r, c = rows[cut].astype(np.int64), cols[cut].astype(np.int64)
    differ = differ[cut].astype(np.int64)
    del rows, cols
    upper_triangle = c > r
    r, c, differ = r[upper_triangle], c[upper_triangle], differ[upper_triangle]
    region = region.astype(np.int64)
    # the level at which the pair parts: the highest differing bit of their regions
    width = np.frexp(differ.astype(float))[1].astype(np.int64)      # bit length
    level = depth - width
    r_upper = ((region[r] >> (width - 1)) & 1).astype(bool)
    upper = np.where(r_upper, r, c)
    lower = np.where(r_upper, c, r)
    # each cut (a node of the dissection tree, numbered as in a heap) takes the side with
    # fewer distinct unknowns coupled across it
    cut_id = (np.int64(1) << level) + (region[r] >> width)
    size = 1 << (depth + 1)
    levels = max(depth, 1)

    def distinct(side):
        mark = np.zeros(n * levels, dtype=bool)
        mark[side * levels + level] = True
        k = np.flatnonzero(mark)
        u, lv = k // levels, k % levels
        return np.bincount((np.int64(1) << lv) + (region[u] >> (depth - lv)), minlength=size)

    take_upper = distinct(upper) <= distinct(lower)
    chosen = np.where(take_upper[cut_id], upper, lower)
    sep_level = np.full(n, depth, dtype=np.int64)
    np.minimum.at(sep_level, chosen, level)               # the first cut that takes it
    if depth > 0 and np.count_nonzero(sep_level == 0) > separator_factor * np.sqrt(n):
        return None
    # post-order of the dissection tree: a tree node comes after every region up to the
    # last region below it, and after its descendants with the same last region
    shift = depth - sep_level
    last = (((region >> shift) + 1) << shift) - 1
    # one stable sort of (last, shift) packed in one integer: a third faster than lexsort
    return np.argsort((last << int(depth).bit_length()) | shift, kind="stable")
