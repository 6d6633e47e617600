# SPDX-License-Identifier: MIT
"""Linear buckling where the axial force varies along a member (docs/modal-buckling.md): each
element takes N averaged along it, so the load factor converges as h² and its error may have
either sign.

Independent references, computed here by a Rayleigh–Ritz solution with the sine series
w = Σ aₙ sin(nπx/L) (complete for pinned ends, 120 terms, Gauss–Legendre quadrature of the
load term), which converges from above:

* a pinned–pinned column under its own weight q: critical q L = 18.5687 EI/L² (Timoshenko &
  Gere, Theory of Elastic Stability, §2.13, give 18.6 EI/L²);
* a pinned–pinned column under an axial point load P at a L from its base (compression P
  below the load, none above it): P_cr L²/EI = 19.578 for a = 0.3 L and 18.666 for
  a = 0.5 L.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
from numpy.polynomial.legendre import leggauss

import trussfe
from trussfe.fem.buckling import solve_buckling
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

E = 2.0e11
I = 1.0e-6
A = 1.0e-3
L = 10.0


def rayleigh_ritz(compression, upper: float = 1.0, terms: int = 120) -> float:
    """Smallest λ of a pinned–pinned unit column (EI = L = 1) whose compression is
    λ·compression(x) on 0 ≤ x ≤ upper and zero above."""
    n = np.arange(1, terms + 1)
    K = np.diag((n * np.pi) ** 4 / 2.0)
    x, w = leggauss(400)
    x = (x + 1.0) / 2.0 * upper
    w = w / 2.0 * upper
    d = (n[:, None] * np.pi) * np.cos(n[:, None] * np.pi * x[None, :])
    G = (d * (compression(x) * w)) @ d.T
    return 1.0 / sla.eigh(G, K, eigvals_only=True)[-1]


def test_rayleigh_ritz_reproduces_euler():
    """The reference solver itself: a uniform compression gives π² (Euler)."""
    assert rayleigh_ritz(lambda x: np.ones_like(x)) == pytest.approx(np.pi**2, rel=1e-12)


def test_pinned_heavy_column_converges_from_above():
    """Own weight, pinned–pinned: 1.1 % high with 4 elements, 0.27 % with 8, 0.065 % with
    16 (h²)."""
    rho, g = 7850.0, 9.81
    qL_ref = rayleigh_ritz(lambda x: x) * E * I / L**2      # x from the free-to-slide top
    assert qL_ref * L**2 / (E * I) == pytest.approx(18.5687, abs=1e-4)
    s = build_structure([[0, 0], [0, L]], [(0, 1)],
                        section=Section("s", area=A, Iz=I, c=0.05),
                        material=Material("st", E=E, G=E / 2.6, density=rho),
                        supports={0: "xy", 1: "x"}, gravity=[0.0, -g])
    err = np.array([solve_buckling(s, count=1, subdivisions=k).load_factors[0]
                    * rho * A * g * L / qL_ref - 1.0 for k in (4, 8, 16)])
    assert err == pytest.approx([0.0113, 0.00267, 0.00065], rel=0.03)
    assert np.log2(err[:-1] / err[1:]) == pytest.approx([2.0, 2.0], abs=0.1)


@pytest.mark.parametrize("at, errors", [(0.3, [0.0431, 0.0237, 0.00463, 0.00163]),
                                        (0.5, [1.34e-3, 8.5e-5, 5.3e-6, 3.3e-7])])
def test_axial_point_load_along_a_pinned_column(at, errors):
    """An axial point load inside an element (0.3 L) converges slowly and irregularly, from
    above; one at an element node (0.5 L) converges as h⁴."""
    P = 1000.0
    ref = rayleigh_ritz(lambda x: np.ones_like(x), upper=at) * E * I / L**2 / P
    data = {
        "member_loads": [{"member": "AB", "kind": "point", "at": at, "F": [0.0, -P]}],
        "model": {"name": "column with an axial point load", "dimension": 2},
        "materials": {"st": {"E": E}},
        "sections": {"s": {"area": A, "Iz": I, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, L]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st"}},
        "supports": {"A": ["x", "y"], "B": ["x"]},
    }
    structure = trussfe.model_from_dict(data)
    err = np.array([trussfe.buckling(structure, count=1, subdivisions=k).load_factors[0]
                    / ref - 1.0 for k in (4, 8, 16, 32)])
    assert np.all(err > 0)
    assert err == pytest.approx(errors, rel=0.03)
