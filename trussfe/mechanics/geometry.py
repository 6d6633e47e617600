# SPDX-License-Identifier: MIT
"""Member geometry: end-to-end vectors, lengths, unit vectors, local frames and stations.

Every function is vectorised over members and over any leading axes (time steps, copies):
node arrays have shape ``(..., n, dim)`` and member arrays ``(..., m, dim)``.

Local axes
----------
x runs from the start to the end node.  2-D: y = x rotated by +90°.  3-D: y is the member's
``orientation`` vector made orthogonal to x when given; otherwise the global Z axis made
orthogonal to x (so local y points "up" for a non-vertical member) or, for a vertical member,
the global X axis; z = x × y.  The linear (fem), the co-rotational (nonlinear) and the
elastic models all use these axes, so ``Iy``/``Iz`` mean the same in each.

Stations
--------
A station is a cross-section of a member at distance x from its **start node**, 0 ≤ x ≤ L (the
finite-element results, ``station_x``).  Lacy cuts the follower and the leadscrew tube from the
end node (point B), and the rigid-body model and the elastic response along a motion keep his
distances u from the end node for their sections: the sections of an active member's leadscrew
tube are material points that ride with the end node while the member telescopes, so u stays
fixed where x = L(t) − u would move with the stroke.  :func:`from_end_node` converts between
the two (x = L − u); the results name which one they hold.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from ..model.geometry import lengths, member_lengths, member_vectors, unit_vectors

__all__ = [
    "VERTICAL", "member_vectors", "lengths", "member_lengths", "unit_vectors", "frame_rotations",
    "parallel_orientation", "local_axes", "transverse_frames", "stations", "from_end_node",
]

if TYPE_CHECKING:
    from ..model.structure import Structure

#: ``|e·Z|`` above which a member counts as vertical (its default local y is then global X).
VERTICAL = 1.0 - 1e-9


def frame_rotations(unit: np.ndarray, orientation: np.ndarray | None = None) -> np.ndarray:
    """Rotation matrices from global to member axes for member unit vectors.

    Parameters
    ----------
    unit : ndarray, shape (..., m, dim)
        Member unit vectors (local x).
    orientation : ndarray, shape (m, 3), optional
        3-D only: a vector in each member's local x–y plane; NaN rows (or None) take the
        default (module docstring).

    Returns
    -------
    ndarray, shape (..., m, dim, dim)
        Local axes as rows, ``x_local = R @ x_global``; NaN rows where an orientation vector
        is parallel to its member (:func:`parallel_orientation` finds them).
    """
    ex = np.asarray(unit, dtype=float)
    dim = ex.shape[-1]
    R = np.empty(ex.shape + (dim,))
    R[..., 0, :] = ex
    if dim == 2:
        R[..., 1, 0], R[..., 1, 1] = -ex[..., 1], ex[..., 0]
        return R
    ref = np.full(ex.shape, np.nan) if orientation is None else \
        np.broadcast_to(np.asarray(orientation, dtype=float), ex.shape).copy()
    missing = ~np.all(np.isfinite(ref), axis=-1)
    vertical = np.abs(ex[..., 2]) > VERTICAL
    ref[missing & ~vertical] = (0.0, 0.0, 1.0)
    ref[missing & vertical] = (1.0, 0.0, 0.0)
    ey = ref - np.einsum("...i,...i->...", ref, ex)[..., None] * ex
    norm = np.sqrt(np.einsum("...i,...i->...", ey, ey))
    with np.errstate(invalid="ignore", divide="ignore"):
        ey /= np.where(norm < 1e-9, np.nan, norm)[..., None]
    R[..., 1, :] = ey
    # ez = ex × ey, component by component into its row (no temporaries of np.cross)
    R[..., 2, 0] = ex[..., 1] * ey[..., 2] - ex[..., 2] * ey[..., 1]
    R[..., 2, 1] = ex[..., 2] * ey[..., 0] - ex[..., 0] * ey[..., 2]
    R[..., 2, 2] = ex[..., 0] * ey[..., 1] - ex[..., 1] * ey[..., 0]
    return R


def parallel_orientation(R: np.ndarray) -> np.ndarray:
    """Members whose orientation vector is parallel to them (NaN axes), bool (..., m)."""
    return ~np.isfinite(R[..., -1, -1])


def local_axes(structure: Structure, coords: np.ndarray | None = None) -> np.ndarray:
    """Rotation matrices from global to member axes of a structure.

    Parameters
    ----------
    structure : Structure
    coords : ndarray, shape (n, dim), optional
        Node positions (default ``structure.coords``).

    Returns
    -------
    ndarray, shape (m, dim, dim)
        ``R[i]`` has the member's local axes as rows, so ``x_local = R[i] @ x_global``.

    Raises
    ------
    InputError
        An orientation vector is parallel to its member.

    Examples
    --------
    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0, 0], [1, 0, 0]], [(0, 1)], section=Section.tube("t", .02),
    ...                     material=Material("al", 7e10, 2.6e10))
    >>> local_axes(s)[0]
    array([[ 1.,  0.,  0.],
           [ 0.,  0.,  1.],
           [ 0., -1.,  0.]])
    """
    x = structure.coords if coords is None else coords
    e, _ = unit_vectors(member_vectors(np.asarray(x, dtype=float), structure.connectivity))
    R = frame_rotations(e, structure.orientation if e.shape[-1] == 3 else None)
    bad = parallel_orientation(R)
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise InputError(f"members.{structure.member_ids[i]}",
                         "orientation vector is parallel to the member; give a vector "
                         "in the local x-y plane that is not along the member")
    return R


def transverse_frames(unit: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lacy's two unit vectors b1, b2 perpendicular to each member, (..., 3) each.

    b1 = e × k / ``|e × k|`` with k the global z axis (the global x axis for a member within 25°
    of z), b2 = e × b1.  In 2-D (e in the x–y plane) b1 is the in-plane normal and b2 = −z:
    the planar shear is the b1 component and the planar moment minus the b2 component.
    Away from the vertical, b1 is local z and b2 is minus local y of :func:`frame_rotations`.
    """
    helper = np.where(np.abs(unit[..., 2:3]) < 0.9, [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    b1 = np.cross(unit, helper)
    b1 /= np.linalg.norm(b1, axis=-1, keepdims=True)
    b2 = np.cross(unit, b1)
    return b1, b2


def stations(length: np.ndarray, n: int) -> np.ndarray:
    """``n`` equidistant distances 0 … ``length`` over each length, shape (..., n).

    ``n = 1`` gives the midpoint only (Lacy's choice for the spatial truss); ``n ≥ 2`` includes
    both ends.
    """
    frac = np.array([0.5]) if n == 1 else np.linspace(0.0, 1.0, n)
    return np.asarray(length, dtype=float)[..., None] * frac


def from_end_node(distance: np.ndarray, length: np.ndarray) -> np.ndarray:
    """Convert distances from the end node to distances from the start node and back.

    x = L − u: the map is its own inverse.  Lacy's section tables (and his code's ``u``) count
    from the end node B; trussfe's stations count from the start node.
    """
    return np.asarray(length, dtype=float)[..., None] - np.asarray(distance, dtype=float)


def rotation_length(lengths: np.ndarray) -> float:
    """The length (m) per radian in which a model's rotations are measured beside its
    translations: the median of the member ``lengths`` given, 1 when there is none.

    A stiffness or a displacement vector with rotations mixes N/m with N·m/rad and metres
    with radians, whose ratio changes with the unit of length; a rotation times this length
    (a moment divided by it) is the same in every consistent unit system and for every
    geometrically similar model.  The linear factorisation
    (:func:`trussfe.fem.solver.rotation_scale`) and the post-critical path
    (:func:`trussfe.nonlinear.path.rotation_length`) measure rotations in it.

    Examples
    --------
    >>> rotation_length(np.array([2.0, 4.0, 3.0])), rotation_length(np.zeros(0))
    (3.0, 1.0)
    """
    length = float(np.median(lengths)) if np.size(lengths) else 0.0
    return length if np.isfinite(length) and length > 0.0 else 1.0
