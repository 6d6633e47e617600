# SPDX-License-Identifier: MIT
"""Member buckling utilisation of ``trussfe buckling``: the largest compression along the member
over its Euler load, as the check along a motion takes it (Lacy eq. 2.26 with the largest
compression over the member's sections, his Appendix A ``max(abs(min(tension)))``).

Independent values by statics, by hand:

* a pinned vertical bar carrying an axial point load P at a fraction a of its length from its
  lower, supported end: the part below the load carries the compression P, the part above it
  nothing (a simply supported member under an axial point load); Euler load π²EI/L².
* a fixed–free vertical column under its own weight q per unit length: compression q L at the
  base, q L / 2 at mid-height.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe

E = 2.0e11
I = 1.0e-6
A = 1.0e-3
L = 10.0
P = 1000.0


def _bar_with_axial_point_load(at: float, kind: str) -> dict:
    return {
        "member_loads": [{"member": "AB", "kind": "point", "at": at, "F": [0.0, -P]}],
        "model": {"name": "bar with an axial point load", "dimension": 2},
        "materials": {"st": {"E": E}},
        "sections": {"s": {"area": A, "Iz": I, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, L]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st",
                           "type": kind}},
        "supports": {"A": ["x", "y"], "B": ["x"]},
    }


@pytest.mark.parametrize("kind", ["bar", "beam"])
@pytest.mark.parametrize("at", [0.3, 0.5, 0.8])
def test_axial_point_load_compresses_part_of_the_member(at, kind):
    """The part below the load carries P in compression: utilisation P / (π²EI/L²), whether
    or not the load lies below mid-length (at 0.3 the midpoint force is zero)."""
    structure = trussfe.model_from_dict(_bar_with_axial_point_load(at, kind))
    r = trussfe.buckling(structure, count=1, subdivisions=4)
    pe = np.pi**2 * E * I / L**2
    assert_allclose(r.euler_load, [pe], rtol=1e-12)
    assert_allclose(r.buckling_utilisation, [P / pe], rtol=1e-9)
    doc = r.to_dict()
    assert_allclose(doc["members"]["AB"]["buckling_utilisation"], P / pe, rtol=1e-9)


def test_heavy_column_base_compression():
    """A fixed–free column under its own weight: the base carries q L (the midpoint q L / 2)."""
    rho, g = 7850.0, 9.81
    data = {
        "model": {"name": "heavy column", "dimension": 2, "gravity": [0.0, -g]},
        "materials": {"st": {"E": E, "density": rho}},
        "sections": {"s": {"area": A, "Iz": I, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, L]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st",
                           "type": "beam"}},
        "supports": {"A": ["x", "y", "rz"]},
    }
    r = trussfe.buckling(trussfe.model_from_dict(data), count=1, subdivisions=4)
    qL = rho * A * g * L
    pe = np.pi**2 * E * I / L**2
    assert_allclose(r.buckling_utilisation, [qL / pe], rtol=1e-9)
    assert_allclose(r.to_dict()["members"]["AB"]["axial_force"], -qL / 2, rtol=1e-9)


def test_tension_everywhere_is_zero():
    """A bar pulled by an axial point load at its middle carries no compression anywhere: the
    part below the load is in tension P, the part above it unstressed (to round-off)."""
    data = _bar_with_axial_point_load(0.5, "bar")
    data["member_loads"][0]["F"] = [0.0, P]
    data["supports"] = {"A": ["x", "y"], "B": ["x"]}
    r = trussfe.buckling(trussfe.model_from_dict(data), count=1, subdivisions=4)
    assert 0.0 <= r.buckling_utilisation[0] < 1e-12 * P / (np.pi**2 * E * I / L**2)


@pytest.mark.parametrize("at", [0.3, 0.8])
def test_show_utilisation_reads_the_largest_compression(at):
    """``trussfe show --color utilisation`` from a static document: the buckling ratio is the
    largest compression along the member (P, below the load) over π²EI/L², read from the
    document's end forces and stations, not its midpoint force (0 for a load at 0.3 L)."""
    from trussfe.io.model_picture import results_from_document, utilisation
    structure = trussfe.model_from_dict(_bar_with_axial_point_load(at, "beam"))
    doc = trussfe.static(structure, subdivisions=4).to_dict()
    pictured = results_from_document(doc, structure)
    pe = np.pi**2 * E * I / L**2
    # the section has no yield strength: the utilisation is the buckling ratio alone
    assert_allclose(utilisation(structure, pictured), [P / pe], rtol=1e-9)
