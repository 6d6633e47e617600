# SPDX-License-Identifier: MIT
"""Frequencies of beams and shafts against closed forms, and their independence of units.

Sources: Euler–Bernoulli beams ω_n = (β_n L)² √(EI/(ρA)) / L² with β_n L = 1.87510, 4.69409,
7.85476 (cantilever), nπ (simply supported), 4.73004, 7.85320, 10.99561 (fixed–fixed and the
elastic modes of the free–free beam) — Blevins, *Formulas for Natural Frequency and Mode
Shape*, Table 8-1; Rayleigh–Ritz: a consistent mass gives upper bounds.  Shafts in torsion:
fixed–free ω_n = (2n − 1)π/(2L) √(G/ρ) for a round section (J equal to the polar moment);
a disc of inertia I_d on the tip of a massless shaft ω = √(GJ/(L I_d)), and with the shaft's
own inertia ρJL the root of β tan β = ρJL/I_d, ω = β √(G/ρ)/L (Blevins Table 8-19 and
Timoshenko, Young & Weaver, *Vibration Problems in Engineering*, §5.4).  A massless
cantilever with a tip mass m and rotary inertia I_r: the 2 × 2 eigenproblem of its exact
tip stiffness EI/L³ [[12, −6L], [−6L, 4L²]] with diag(m, I_r).
"""
from __future__ import annotations

import copy

import numpy as np
import pytest
import scipy.linalg as sla
from numpy.testing import assert_allclose
from scipy.optimize import brentq

import trussfe

E, G, RHO = 2.1e11, 8.0e10, 7850.0
A, I, L = 1.0e-3, 2.0e-7, 2.0

BETA_L = {
    "cantilever": [1.8751040687, 4.6940911330, 7.8547574382],
    "simply supported": [np.pi, 2 * np.pi, 3 * np.pi],
    "fixed-fixed": [4.7300407449, 7.8532046241, 10.9956078380],
}
SUPPORTS = {
    "cantilever": {"a": ["x", "y", "rz"]},
    "simply supported": {"a": ["x", "y"], "b": ["y"]},
    "fixed-fixed": {"a": ["x", "y", "rz"], "b": ["x", "y", "rz"]},
}


def _beam(dim=2, supports=None, section=None, material=None, masses=None, end=None):
    end = end if end is not None else ([L, 0.0] if dim == 2 else [L, 0.0, 0.0])
    d = {"model": {"dimension": dim},
         "materials": {"m": material or {"E": E, "G": G, "density": RHO}},
         "sections": {"s": section or ({"area": A, "Iz": I} if dim == 2 else
                                       {"area": A, "Iy": I, "Iz": I, "J": 2 * I})},
         "nodes": {"a": [0.0] * dim, "b": end},
         "members": {"ab": {"nodes": ["a", "b"], "section": "s", "material": "m",
                            "type": "beam"}}}
    if supports:
        d["supports"] = supports
    if masses:
        d["masses"] = masses
    return trussfe.model_from_dict(d)


def _bending_hz(beta_l, inertia=I):
    return np.square(beta_l) / L**2 * np.sqrt(E * inertia / (RHO * A)) / (2 * np.pi)


@pytest.mark.parametrize("case", list(BETA_L))
def test_euler_bernoulli_beams_consistent_above_lumped_below(case):
    """The three lowest bending frequencies (the fixed–free axial mode c/4L of the
    cantilever lies above them): consistent mass within 1e-5 with 32 elements and never
    below the closed form; lumped mass (no rotary inertia) below it, within 3e-3."""
    exact = _bending_hz(np.array(BETA_L[case]))
    beam = _beam(supports=SUPPORTS[case])
    cons = trussfe.modes(beam, count=3, subdivisions=32).frequencies_hz
    lump = trussfe.modes(beam, count=3, subdivisions=32, mass="lumped").frequencies_hz
    assert_allclose(cons, exact, rtol=1e-5)
    assert np.all(cons >= exact * (1 - 1e-12))
    assert_allclose(lump, exact, rtol=3e-3)
    assert np.all(lump <= exact)


def test_free_free_3d_beam_six_rigid_modes_then_both_bending_planes():
    """An unsupported 3-D beam with Iy ≠ Iz: six 0 Hz rigid modes, then the free–free
    bending frequencies β L = 4.73004, 7.85320 about both axes."""
    Iy, Iz = 2.0e-7, 3.0e-7
    beam = _beam(dim=3, section={"area": A, "Iy": Iy, "Iz": Iz, "J": Iy + Iz})
    r = trussfe.modes(beam, count=10, subdivisions=32)
    assert r.rigid_modes == 6 and np.all(r.frequencies_hz[:6] == 0.0)
    exact = np.sort([_bending_hz(b, i) for b in (4.7300407449, 7.8532046241)
                     for i in (Iy, Iz)])
    assert_allclose(r.frequencies_hz[6:], exact, rtol=1e-5)


def test_lumped_mass_beams_from_below_at_second_order():
    """docs/modal-buckling.md: the lumped mass (no rotary inertia) gives the first free–free
    frequency (β L = 4.73004) 1.2 % low with 16 elements and 0.30 % low with 32, the
    cantilever's (β L = 1.87510) 0.18 % and 0.045 % low — second order in the element
    length."""
    free = _bending_hz(4.7300407449)
    err = [trussfe.modes(_beam(), count=4, subdivisions=k, mass="lumped").frequencies_hz[3]
           / free - 1 for k in (16, 32)]
    assert_allclose(err, [-0.0119, -0.0030], atol=5e-5)
    assert 3.9 < err[0] / err[1] < 4.1
    fixed = _bending_hz(1.8751040687)
    err = [trussfe.modes(_beam(supports=SUPPORTS["cantilever"]), count=1, subdivisions=k,
                         mass="lumped").frequencies_hz[0] / fixed - 1 for k in (16, 32)]
    assert_allclose(err, [-0.00179, -0.00045], atol=5e-6)


def test_torsion_of_a_round_shaft_fixed_free():
    """A solid round shaft clamped at one end: the torsional frequencies (2n − 1)/(4L) √(G/ρ)
    appear among the bending pairs (consistent mass, ρJ on the twist; J = polar moment),
    from above with the linear twist elements' error (kh)²/24, k = (2n − 1)π/(2L)."""
    beam = _beam(dim=3, supports={"a": ["x", "y", "z", "rx", "ry", "rz"]},
                 section={"outer_diameter": 0.04, "inner_diameter": 0.0})
    f = trussfe.modes(beam, count=24, subdivisions=32).frequencies_hz
    h = L / 32
    for n in (1, 2):
        exact = (2 * n - 1) / (4 * L) * np.sqrt(G / RHO)
        err = f[np.argmin(np.abs(f / exact - 1))] / exact - 1
        assert 0.0 < err < 1.05 * ((2 * n - 1) * np.pi / (2 * L) * h) ** 2 / 24


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_disc_on_a_massless_shaft(axis):
    """A disc (mass 20 kg, rotary inertia about the global axes) on the tip of a massless
    cantilever shaft along global x, y or z: the torsional mode √(GJ/(L I_d)) with I_d the
    disc's inertia about the shaft axis, and the axial mode √(EA/(L m))."""
    Ld, m, inertia = 1.5, 20.0, [0.3, 0.2, 0.5]
    Js = 6.0e-8
    end = [0.0, 0.0, 0.0]
    end[axis] = Ld
    beam = trussfe.model_from_dict({
        "model": {"dimension": 3},
        "materials": {"m": {"E": E, "G": G, "density": 0.0}},
        "sections": {"s": {"area": 3.0e-4, "Iy": 2.0e-8, "Iz": 5.0e-8, "J": Js}},
        "nodes": {"a": [0.0, 0.0, 0.0], "b": end},
        "members": {"ab": {"nodes": ["a", "b"], "section": "s", "material": "m",
                           "type": "beam"}},
        "supports": {"a": ["x", "y", "z", "rx", "ry", "rz"]},
        "masses": {"b": {"mass": m, "inertia": inertia}}})
    f = trussfe.modes(beam, count=6, subdivisions=1).frequencies_hz
    torsion = np.sqrt(G * Js / (Ld * inertia[axis])) / (2 * np.pi)
    axial = np.sqrt(E * 3.0e-4 / (Ld * m)) / (2 * np.pi)
    assert np.min(np.abs(f / torsion - 1)) < 1e-12
    assert np.min(np.abs(f / axial - 1)) < 1e-12


def test_disc_on_a_shaft_with_its_own_inertia():
    """The first torsional frequency of a round shaft carrying a disc, from β tan β = ρJL/I_d
    (the massless-shaft value is 0.2 % higher): 1e-6 with 4 elements."""
    D, Ls, I_d = 0.04, 1.2, 0.2
    beam = _beam(dim=3, supports={"a": ["x", "y", "z", "rx", "ry", "rz"]},
                 section={"outer_diameter": D, "inner_diameter": 0.0}, end=[0.0, 0.0, Ls],
                 masses={"b": {"mass": 30.0, "inertia": [0.1, 0.1, I_d]}})
    Jp = np.pi * D**4 / 32
    beta = brentq(lambda b: b * np.tan(b) - RHO * Jp * Ls / I_d, 1e-9, np.pi / 2 - 1e-12)
    exact = beta * np.sqrt(G / RHO) / Ls / (2 * np.pi)
    f = trussfe.modes(beam, count=6, subdivisions=4).frequencies_hz
    assert np.min(np.abs(f / exact - 1)) < 1e-6


def test_plane_tip_mass_with_rotary_inertia():
    """2-D: a massless inclined cantilever with a tip mass and rotary inertia (one value,
    about z) — the 2 × 2 closed form for bending and √(EA/(L m)) axially."""
    m, Ir, Lc = 12.0, 0.8, 1.7
    Ic = 3.0e-7
    beam = _beam(supports={"a": ["x", "y", "rz"]}, section={"area": A, "Iz": Ic},
                 material={"E": E, "density": 0.0}, end=[0.6 * Lc, 0.8 * Lc],
                 masses={"b": {"mass": m, "inertia": Ir}})
    K = E * Ic / Lc**3 * np.array([[12.0, -6 * Lc], [-6 * Lc, 4 * Lc**2]])
    lam = sla.eigh(K, np.diag([m, Ir]), eigvals_only=True)
    exact = np.sort(np.r_[np.sqrt(lam), np.sqrt(E * A / (Lc * m))]) / (2 * np.pi)
    f = trussfe.modes(beam, count=3, subdivisions=1).frequencies_hz
    assert_allclose(f, exact, rtol=1e-12)


def test_pinned_beam_member_bends_about_both_axes():
    """A bar pinned at both ends (``pinned-beam``, 16 elements) with Iy ≠ Iz: the bending
    frequencies n²π/(2L²) √(EI/(ρA)) for I = Iy and Iz; the lowest (about local y, the
    smaller I, local y vertical by default) moves horizontally."""
    Iy, Iz, Lb = 4.0e-8, 9.0e-8, 2.5
    s = trussfe.model_from_dict({
        "model": {"dimension": 3},
        "materials": {"al": {"E": 7.0e10, "density": 2700.0}},
        "sections": {"t": {"area": 3.0e-4, "Iy": Iy, "Iz": Iz, "J": 1.0e-8}},
        "nodes": {"a": [0.0, 0.0, 0.0], "b": [1.5, 2.0, 0.0]},
        "members": {"ab": {"nodes": ["a", "b"], "section": "t", "material": "al"}},
        "supports": {"a": ["x", "y", "z"], "b": ["x", "y", "z"]}})
    r = trussfe.modes(s, count=6, bar_model="pinned-beam", subdivisions=16)
    exact = np.sort([n * n * np.pi / (2 * Lb**2) * np.sqrt(7.0e10 * i / (2700.0 * 3.0e-4))
                     for n in (1, 2, 3) for i in (Iy, Iz)])
    assert_allclose(r.frequencies_hz, exact, rtol=2e-4)
    fe = r.solution.fe
    along = np.asarray(fe.station_displacements(r.solution.shapes[:, 0])).reshape(-1, 3)
    mid = along[np.argmax(np.linalg.norm(along, axis=1))]
    assert abs(mid[2]) < 1e-9 * np.linalg.norm(mid)
    assert abs(mid @ np.array([1.5, 2.0, 0.0])) < 1e-9 * np.linalg.norm(mid)


# ---------------------------------------------------------------------- units
FRAME = {
    "model": {"dimension": 3},
    "materials": {"st": {"E": 2.0e11, "G": 7.7e10, "density": 7850.0}},
    "sections": {"box": {"area": 4.0e-3, "Iy": 8.0e-6, "Iz": 3.0e-6, "J": 5.0e-6},
                 "rod": {"area": 5.0e-4, "Iy": 2.0e-8, "Iz": 2.0e-8, "J": 4.0e-8}},
    "nodes": {"A": [0, 0, 0], "B": [4, 0, 0], "E": [0, 0, 3], "F": [4, 0, 3],
              "G": [4, 3, 3.5]},
    "members": {
        "AE": {"nodes": ["A", "E"], "section": "box", "material": "st", "type": "beam"},
        "BF": {"nodes": ["B", "F"], "section": "box", "material": "st", "type": "beam",
               "orientation": [0, 1, 0]},
        "EF": {"nodes": ["E", "F"], "section": "box", "material": "st", "type": "beam",
               "releases": {"end": ["mz"]}},
        "FG": {"nodes": ["F", "G"], "section": "box", "material": "st", "type": "beam"},
        "AG": {"nodes": ["A", "G"], "section": "rod", "material": "st"}},
    "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"], "B": ["x", "y", "z"]},
    "springs": {"G": {"z": 5e6, "rx": 1e5}},
    "masses": {"G": {"mass": 50.0, "inertia": [2.0, 3.0, 4.0]}, "E": 30.0},
}


def _in_mm_t_s(d):
    """The same model in mm, t, s, N (MPa, t/mm³, N/mm, N·mm/rad, t·mm²)."""
    d = copy.deepcopy(d)
    mat = d["materials"]["st"]
    mat.update(E=mat["E"] * 1e-6, G=mat["G"] * 1e-6, density=mat["density"] * 1e-12)
    for sec in d["sections"].values():
        sec.update(area=sec["area"] * 1e6, Iy=sec["Iy"] * 1e12, Iz=sec["Iz"] * 1e12,
                   J=sec["J"] * 1e12)
    d["nodes"] = {k: [1000.0 * c for c in v] for k, v in d["nodes"].items()}
    d["springs"] = {k: {dof: k_ * (1e-3 if dof in "xyz" else 1e3) for dof, k_ in v.items()}
                    for k, v in d["springs"].items()}
    d["masses"] = {"G": {"mass": 0.05, "inertia": [2.0e3, 3.0e3, 4.0e3]}, "E": 0.03}
    return d


@pytest.mark.parametrize("mass", ["consistent", "lumped"])
@pytest.mark.parametrize("supported", [True, False])
def test_mm_tonne_second_units_give_the_same_frequencies(mass, supported):
    """Frequencies do not depend on the unit system: a frame with bars, a release, springs
    and rotary inertia in m–kg–s and in mm–t–s gives the same Hz (supported, and unsupported
    with its six rigid-body modes)."""
    si, mm = copy.deepcopy(FRAME), _in_mm_t_s(FRAME)
    if not supported:
        for d in (si, mm):
            d.pop("supports")
            d.pop("springs")
    a = trussfe.modes(si, count=12, subdivisions=4, mass=mass)
    b = trussfe.modes(mm, count=12, subdivisions=4, mass=mass)
    assert a.rigid_modes == b.rigid_modes == (0 if supported else 6)
    assert_allclose(b.frequencies_hz, a.frequencies_hz, rtol=1e-9, atol=0.0)


def test_torsion_of_a_non_round_shaft_uses_the_polar_moment():
    """A clamped–free shaft of a thin-walled non-round section (Iy = 2e-4, Iz = 8e-4 m⁴, a
    torsion constant J = 1e-7 m⁴ far below its polar moment, as of an open section):
    St-Venant torsion ρ I_p θ̈ = G J θ'' with I_p = Iy + Iz (Blevins, Formulas for Natural
    Frequency and Mode Shape, Table 8-19) gives its first mode, torsional, at
    √(GJ/(ρ I_p)) / (4L) = 3.99 Hz; ρJ as rotary inertia would give √(G/ρ)/(4L) = 399 Hz.
    16 elements converge from above within 1e-3."""
    E, G, rho, L = 2.0e11, 8.0e10, 7850.0, 2.0
    Iy, Iz, J, A = 2e-4, 8e-4, 1e-7, 1e-3
    s = trussfe.model_from_dict({
        "model": {"name": "shaft", "dimension": 3},
        "materials": {"st": {"E": E, "G": G, "density": rho}},
        "sections": {"r": {"area": A, "Iy": Iy, "Iz": Iz, "J": J, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0, 0.0], "B": [L, 0.0, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "r", "material": "st",
                           "type": "beam"}},
        "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"]},
    })
    f1 = trussfe.modes(s, count=1, subdivisions=16).frequencies_hz[0]
    exact = np.sqrt(G * J / (rho * (Iy + Iz))) / (4 * L)
    assert exact <= f1 <= exact * (1 + 1e-3)
