# SPDX-License-Identifier: MIT
"""Per-member section and material properties as arrays, from the members' objects.

A model names one :class:`~trussfe.model.sections.Section` and one
:class:`~trussfe.model.sections.Material` per member, but members share few distinct objects
(a 100,000-bay chain has one tube and one aluminium); :func:`member_properties` reads each
distinct object once and spreads its values over the members by one gather.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .sealed import sealed
from .sections import Material, Section

#: Section attributes spread over the members, and the material ones.
SECTION_PROPERTIES = ("area", "Iy", "Iz", "J", "c", "shear_area_y", "shear_area_z")
MATERIAL_PROPERTIES = ("E", "G", "density", "yield_strength", "thermal_expansion")


@dataclass(frozen=True, eq=False)
class MemberProperties:
    """Section and material properties of every member, read-only arrays of shape (m,).

    Attributes
    ----------
    area, Iy, Iz, J, c : ndarray
        Area (m²), second moments about local y and z (m⁴), torsion constant (m⁴), outer-fibre
        distance (m); ``nan`` where the section does not define the value.
    shear_area_y, shear_area_z : ndarray
        Effective shear areas κA for shear along local y and z, m² (``nan``: no shear
        deformation).
    E, G, density, yield_strength : ndarray
        Young's and shear moduli (Pa), density (kg/m³), yield strength (Pa, ``nan`` if unknown).
    thermal_expansion : ndarray
        Coefficient of linear thermal expansion, 1/K (``nan`` if unknown).
    """

    area: np.ndarray
    Iy: np.ndarray
    Iz: np.ndarray
    J: np.ndarray
    c: np.ndarray
    shear_area_y: np.ndarray
    shear_area_z: np.ndarray
    E: np.ndarray
    G: np.ndarray
    density: np.ndarray
    yield_strength: np.ndarray
    thermal_expansion: np.ndarray


def object_groups(objs: Sequence[object]) -> tuple[np.ndarray, np.ndarray]:
    """Which members share an object: (first member of each group, group of each member).

    Identity, not equality, defines a group: the reader hands every member of a section the
    same object, and equal-valued objects give equal properties anyway.
    """
    ids = np.fromiter(map(id, objs), dtype=np.int64, count=len(objs))
    _, first, inverse = np.unique(ids, return_index=True, return_inverse=True)
    return first, inverse.reshape(-1)


def _code_groups(code: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(first member of each code value, code value of each member), without a sort.

    Codes are small non-negative integers (a mesh reader's cell-set numbers): the code is its
    own group number.  Each used code gets one of its members (any: they share their objects),
    a code no member uses gets member 0 (its row is never gathered).
    """
    first = np.zeros(int(code.max()) + 1, dtype=np.int64)
    first[code] = np.arange(code.shape[0])
    return first, code


def _spread(objs: Sequence[object], attrs: tuple[str, ...],
            groups: tuple[np.ndarray, np.ndarray]) -> list[np.ndarray]:
    first, inverse = groups
    table = np.array([[getattr(objs[i], a) for a in attrs] for i in first], dtype=float)
    if len(first) == 1:
        # one object for every member (the usual large model): a read-only broadcast view
        # of its value, no memory per member
        return [np.broadcast_to(sealed(np.array(v)), inverse.shape) for v in table[0]]
    # one gather into an (attribute, member) array: every property a contiguous row
    rows = sealed(np.take(np.ascontiguousarray(table.T), inverse, axis=1))
    return list(rows)


def member_properties(sections: Sequence[Section], materials: Sequence[Material],
                      groups: np.ndarray | None = None) -> MemberProperties:
    """Spread the section and material properties over the members.

    Parameters
    ----------
    sections, materials : sequence, length m
        Section and material of each member.
    groups : ndarray of int, shape (m,), optional
        A code per member such that members with equal codes share their section object and
        their material object (a mesh reader's cell-set code); spares the pass over every
        member that finds the groups.

    Returns
    -------
    MemberProperties

    Examples
    --------
    >>> t, s = Section("t", area=2.0), Section("s", area=3.0)
    >>> steel = Material("steel", E=2.0e11, G=8.0e10)
    >>> member_properties([t, s, t], [steel] * 3).area.tolist()
    [2.0, 3.0, 2.0]
    """
    m = len(sections)
    if m == 0:
        empty = sealed(np.zeros(0))
        return MemberProperties(*([empty] * (len(SECTION_PROPERTIES)
                                             + len(MATERIAL_PROPERTIES))))
    if groups is not None:
        code = np.asarray(groups).reshape(-1)
        if code.dtype.kind in "iu" and code.min() >= 0 and code.max() <= 2 * m:
            shared = _code_groups(code.astype(np.int64, copy=False))
        else:
            _, first, inverse = np.unique(code, return_index=True, return_inverse=True)
            shared = (first, inverse.reshape(-1))
        sec_groups = mat_groups = shared
    else:
        sec_groups, mat_groups = object_groups(sections), object_groups(materials)
    return MemberProperties(*_spread(sections, SECTION_PROPERTIES, sec_groups),
                            *_spread(materials, MATERIAL_PROPERTIES, mat_groups))

