# SPDX-License-Identifier: MIT
"""Linear buckling of frames and trusses against closed forms and characteristic equations
solved here with scipy.

* Euler columns with the classic end conditions, P = π²EI/(KL)² (Timoshenko & Gere, Theory
  of Elastic Stability, §2.1–2.3): pinned–pinned K = 1, fixed–free K = 2, fixed–pinned
  kL = 4.4934 (tan kL = kL), fixed–fixed K = 0.5, fixed–guided K = 1; the second
  fixed–pinned root kL = 7.7253 and the second fixed–fixed mode 8.183 π²EI/L²
  (tan(kL/2) = kL/2).
* Portal frames of columns h, EI_c and a beam b, EI_b under equal loads P on the column
  tops, solved as the slope-deflection equations of the alignment charts (exact for this
  symmetric portal, the beam carrying no axial force; G = (I_c/h)/(I_b/b), u = h√(P/EI_c)):
  sway, fixed base  u/tan u + 6/G = 0;   sway, pinned base  G u²/6 − u/tan u = 0;
  symmetric, fixed base  (G/2)(1 − u/tan u) + 2 tan(u/2)/u − 1 = 0;
  symmetric, pinned base  G u²/4 + (1 − u/tan u)/2 = 0.
  Columns of large area make the FE's axial shortening negligible.
* The two-bar (von Mises) truss with bars at α to the horizontal, load P at the apex, linear
  buckling of the truss model about its linear state: the vertical stiffness
  2(EA sin²α − P cos²α /(2 sin α))/L vanishes at P = 2EA sin³α / cos²α, the horizontal one at
  P = 2EA cos²α / sin α; as pinned beams each bar buckles at π²EI/L², P = 2 sin α π²EI/L².
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

import trussfe
from trussfe.fem.buckling import solve_buckling
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

E = 2.0e11
STEEL = Material("st", E=E, G=8.0e10, density=0.0)
SEC = Section("s", area=1.0e-3, Iy=2.0e-6, Iz=1.0e-6, J=3.0e-6, c=0.05)
L = 3.0
FIXED = ["x", "y", "rz"]


def _column(top: list[str], base=FIXED):
    supports = {0: base}
    if top:
        supports[1] = top
    return build_structure([[0, 0], [0, L]], [(0, 1)], section=SEC, material=STEEL,
                           supports=supports, loads={1: [0.0, -1.0]}, is_beam=True)


PE = np.pi**2 * E * SEC.Iz / L**2


@pytest.mark.parametrize("name, base, top, ratios", [
    ("pinned-pinned", ["x", "y"], ["x"], [1.0, 4.0, 9.0]),
    ("fixed-free", FIXED, [], [0.25, 2.25, 6.25]),
    ("fixed-pinned", FIXED, ["x"], [(4.493409458 / np.pi) ** 2, (7.725251837 / np.pi) ** 2]),
    ("fixed-fixed", FIXED, ["x", "rz"], [4.0, (2 * 4.493409458 / np.pi) ** 2, 16.0]),
    ("fixed-guided", FIXED, ["rz"], [1.0, 4.0, 9.0]),
])
def test_end_conditions_converge_from_above(name, base, top, ratios):
    """λ_n / (π²EI/L²) → the closed form from above as the columns are subdivided."""
    s = _column(top, base)
    err = []
    for k in (4, 8, 16):
        lam = solve_buckling(s, count=len(ratios), subdivisions=k).load_factors / PE
        err.append(lam / np.array(ratios) - 1.0)
    err = np.array(err)
    assert np.all(err > 0), name
    assert np.all(np.diff(err, axis=0) < 0), name
    assert err[-1, 0] < 5e-5 and err[-1].max() < 1e-3, name


def _portal(h, b, Ib, base, A=10.0, P=1000.0):
    Ic = 8.0e-6
    sup = ["x", "y", "rz"] if base == "fixed" else ["x", "y"]
    return {
        "model": {"name": "portal", "dimension": 2},
        "materials": {"st": {"E": E, "G": 8.0e10}},
        "sections": {"col": {"area": A, "Iz": Ic, "c": 0.1},
                     "bm": {"area": A, "Iz": Ib, "c": 0.1}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, h], "C": [b, h], "D": [b, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "col", "material": "st", "type": "beam"},
                    "BC": {"nodes": ["B", "C"], "section": "bm", "material": "st", "type": "beam"},
                    "DC": {"nodes": ["D", "C"], "section": "col", "material": "st", "type": "beam"}},
        "supports": {"A": sup, "D": sup},
        "loads": {"B": [0.0, -P], "C": [0.0, -P]},
    }, Ic, P


def _roots(f, hi, n=2):
    u = np.linspace(0.05, hi, 200001)
    v = f(u)
    out = []
    for i in np.flatnonzero(np.sign(v[:-1]) != np.sign(v[1:])):
        if np.isfinite(v[i]) and np.isfinite(v[i + 1]) and abs(v[i] - v[i + 1]) < 1.0:
            out.append(brentq(f, u[i], u[i + 1]))
    return out[:n]


@pytest.mark.parametrize("base", ["fixed", "pinned"])
@pytest.mark.parametrize("ratio", [1.0, 4.0])
def test_portal_sway_and_symmetric_modes(base, ratio):
    """The sway load and the first symmetric load of a portal (h = 4, b = 6) from its
    slope-deflection characteristic equations, to 2e-5 with 16 elements per member."""
    h, b = 4.0, 6.0
    data, Ic, P = _portal(h, b, ratio * 8.0e-6, base)
    G = (Ic / h) / (ratio * Ic / b)
    if base == "fixed":
        sway = lambda u: u / np.tan(u) + 6.0 / G
        sym = lambda u: (G / 2) * (1 - u / np.tan(u)) + 2 * np.tan(u / 2) / u - 1
    else:
        sway = lambda u: G * u**2 / 6.0 - u / np.tan(u)
        sym = lambda u: G * u**2 / 4.0 + 0.5 * (1 - u / np.tan(u))
    u_sway = _roots(sway, 2 * np.pi - 1e-3, 1)[0]
    u_sym = _roots(sym, 3 * np.pi, 1)[0]
    expected = np.array([u_sway, u_sym]) ** 2 * E * Ic / h**2 / P
    r = trussfe.buckling(trussfe.model_from_dict(data), count=2, subdivisions=16)
    assert r.load_factors == pytest.approx(expected, rel=2e-5)


@pytest.mark.parametrize("rise", [0.2, 1.0, 4.0])
def test_two_bar_truss(rise):
    """Joint instability (truss model) and member buckling (pinned beams) of the two-bar
    truss with half-span 2 m."""
    a = 2.0
    sec = Section("bar", area=1.0e-4, Iy=2.0e-9, Iz=1.0e-9, J=3.0e-9, c=0.01)
    s = build_structure([[-a, 0], [0, rise], [a, 0]], [(0, 1), (2, 1)], section=sec,
                        material=STEEL, supports={0: "xy", 2: "xy"}, loads={1: [0.0, -1.0]})
    alpha = np.arctan2(rise, a)
    bar = np.hypot(a, rise)
    joint = sorted([2 * E * sec.area * np.sin(alpha) ** 3 / np.cos(alpha) ** 2,
                    2 * E * sec.area * np.cos(alpha) ** 2 / np.sin(alpha)])
    assert solve_buckling(s, count=2, bar_model="truss").load_factors == pytest.approx(
        joint, rel=1e-10)
    member = 2 * np.sin(alpha) * np.pi**2 * E * 1.0e-9 / bar**2
    r = solve_buckling(s, count=2, subdivisions=16)
    assert r.load_factors == pytest.approx([member, member], rel=1e-5)
    assert r.utilisation * member == pytest.approx([1.0, 1.0], rel=1e-9)


# ---------------------------------------------------------------- shear and torsion
@pytest.mark.parametrize("top, K", [(["x"], 1.0), ([], 2.0)])
def test_timoshenko_columns_converge_to_engesser(top, K):
    """A shear-deformable column buckles at Engesser's P_E / (1 + P_E/κGA) (Timoshenko &
    Gere, Theory of Elastic Stability, §2.17), P_E = π²EI/(KL)²; here κGA = 0.68 P_E for the
    cantilever.  The geometric stiffness of the element's own shape functions (the slope of
    its deflection, bending and shear) converges to it from above; that of the Euler–Bernoulli
    element converged 3.4 % below it."""
    import dataclasses
    sec = dataclasses.replace(SEC, shear_area_y=1e-6)         # κGA = 8e4 N
    base = ["x", "y"] if top else FIXED
    s = build_structure([[0, 0], [0, L]], [(0, 1)], section=sec, material=STEEL,
                        supports={0: base, **({1: top} if top else {})},
                        loads={1: [0.0, -1.0]}, is_beam=True)
    pe = np.pi**2 * E * SEC.Iz / (K * L) ** 2
    engesser = pe / (1.0 + pe / (STEEL.G * 1e-6))
    err = [solve_buckling(s, count=1, subdivisions=k).load_factors[0] / engesser - 1.0
           for k in (4, 16, 64)]
    assert np.all(np.array(err) > 0) and np.all(np.diff(err) < 0)
    assert err[-1] < 1e-4


def test_loads_that_only_bend_have_no_buckling_load():
    """A cantilever under a transverse tip load carries no axial force: there is no linear
    buckling load, and the message says why (it said "the structure is unloaded")."""
    from trussfe.errors import AnalysisError
    s = build_structure([[0, 0], [0, L]], [(0, 1)], section=SEC, material=STEEL,
                        supports={0: FIXED}, loads={1: [1000.0, 0.0]}, is_beam=True)
    with pytest.raises(AnalysisError, match="no member carries an axial force"):
        solve_buckling(s)


def test_the_default_count_takes_the_finite_load_factors_there_are():
    """A leaning column: a pinned strut CD carries the load and leans on a cantilever AB
    (fixed base, 3EI/L³ of sway stiffness) through a stiff link BD.  With truss bars the
    geometric stiffness has one finite load factor, the sway at P = 3EI/L² (the strut's
    P/L against the cantilever; the link's and strut's axial flexibility, EA = 2e10 and 2e8
    N, lower it by 3e-6).  Without a count the one finite factor is computed (four were
    asked for and refused); an explicit count above it is refused."""
    from trussfe.errors import AnalysisError
    s = trussfe.model_from_dict({
        "model": {"name": "lean", "dimension": 2},
        "materials": {"steel": {"E": E, "density": 0.0}},
        "sections": {"s": {"area": 1.0e-3, "Iz": SEC.Iz, "c": 0.05},
                     "big": {"area": 1.0e-1, "Iz": SEC.Iz, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, L], "C": [2.0, 0.0], "D": [2.0, L]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "steel",
                           "type": "beam"},
                    "CD": {"nodes": ["C", "D"], "section": "s", "material": "steel"},
                    "BD": {"nodes": ["B", "D"], "section": "big", "material": "steel"}},
        "supports": {"A": FIXED, "C": ["x", "y"]}, "loads": {"D": [0.0, -1000.0]}})
    r = solve_buckling(s, bar_model="truss")
    assert r.load_factors.size == 1
    assert r.load_factors[0] * 1000.0 == pytest.approx(3 * E * SEC.Iz / L**2, rel=1e-5)
    with pytest.raises(AnalysisError, match="only 1 finite"):
        solve_buckling(s, count=3, bar_model="truss")
