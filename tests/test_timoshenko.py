"""Shear-deformable (Timoshenko) beams: sections with a shear area.

Sources: Timoshenko & Gere, Mechanics of Materials — a cantilever's tip deflection under an
end load is PL³/3EI + PL/(κGA) (bending plus shear); the fixed-end moments of a Timoshenko
beam under a point load P at a (b = L − a) are Pab(b + ΦL/2)/(L²(1 + Φ)) and
Pab(a + ΦL/2)/(L²(1 + Φ)), Φ = 12EI/(κGAL²) (the reactions of the exact two-node element,
Friedman & Kosmatka 1993); the natural frequencies of a simply supported Timoshenko beam
(shear and rotary inertia) are the roots of a quadratic in ω² (below).  Static results are in global equilibrium (tests/conftest.py).
"""
import math

import numpy as np
import pytest

from trussfe.api.model import model_from_dict
from trussfe.errors import InputError
from trussfe.fem.modal import solve_modes
from trussfe.fem.static import solve_static
from trussfe.model import Material, MemberLoad, Section, build_structure

E, G = 2.0e11, 8.0e10
ALL3 = ["x", "y", "z", "rx", "ry", "rz"]


def cantilever(dim, L, section, tip):
    nodes = [[0, 0], [L, 0]] if dim == 2 else [[0, 0, 0], [L, 0, 0]]
    sup = {0: ["x", "y", "rz"]} if dim == 2 else {0: ALL3}
    return build_structure(nodes, [(0, 1)], section=section, material=Material("m", E, G),
                           supports=sup, loads={1: tip}, is_beam=True)


@pytest.mark.parametrize("k", [1, 2, 5])
@pytest.mark.parametrize("L", [0.3, 2.0, 300.0])
def test_cantilever_tip_2d(k, L):
    # one element already exact, for deep (L = 0.3) and very slender (L = 300) beams alike:
    # no shear locking
    A, I, As, P = 4e-3, 8e-6, 3e-3, -1000.0
    sec = Section("s", area=A, Iy=I, Iz=I, J=2 * I, c=0.05, shear_area_y=As,
                  shear_area_z=As)
    r = solve_static(cantilever(2, L, sec, [0.0, P, 0.0]), subdivisions=k)
    expect = P * L**3 / (3 * E * I) + P * L / (G * As)
    assert r.displacements[1, 1] == pytest.approx(expect, rel=1e-10)
    # the Euler–Bernoulli tip deflection is smaller by PL/(κGA): shear flexibility shows
    eb = solve_static(cantilever(2, L, Section("e", area=A, Iz=I, c=0.05),
                                 [0.0, P, 0.0]), subdivisions=k)
    assert eb.displacements[1, 1] == pytest.approx(P * L**3 / (3 * E * I), rel=1e-10)


@pytest.mark.parametrize("k", [1, 3])
def test_cantilever_tip_3d_both_planes(k):
    # a beam along X: local y = global Z (bends about local z: Iz, shear_area_y), local
    # z = −Y (bends about local y: Iy, shear_area_z)
    L, A, Iy, Iz, Asy, Asz, P = 0.5, 4e-3, 8e-6, 5e-6, 2e-3, 3e-3, -1000.0
    sec = Section("s", area=A, Iy=Iy, Iz=Iz, J=1e-5, c=0.05, shear_area_y=Asy,
                  shear_area_z=Asz)
    r = solve_static(cantilever(3, L, sec, [0.0, P, P, 0, 0, 0]), subdivisions=k)
    assert r.displacements[1, 2] == pytest.approx(P * L**3 / (3 * E * Iz) + P * L / (G * Asy),
                                                  rel=1e-10)
    assert r.displacements[1, 1] == pytest.approx(P * L**3 / (3 * E * Iy) + P * L / (G * Asz),
                                                  rel=1e-10)


@pytest.mark.parametrize("frac", [0.2, 0.5, 0.7])
def test_fixed_fixed_point_load_timoshenko(frac):
    L, A, I, As, P = 1.0, 4e-3, 8e-6, 1e-3, -5000.0
    sec = Section("s", area=A, Iz=I, c=0.05, shear_area_y=As)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=Material("m", E, G),
                        supports={0: ["x", "y", "rz"], 1: ["x", "y", "rz"]}, is_beam=True)
    s = s.with_extensions(member_loads=[MemberLoad(0, "point", at=frac, force=(0.0, P))])
    phi = 12 * E * I / (G * As * L**2)
    a, b = frac * L, (1 - frac) * L
    Ma = abs(P) * a * b * (b + phi * L / 2) / (L**2 * (1 + phi))
    Mb = abs(P) * a * b * (a + phi * L / 2) / (L**2 * (1 + phi))
    for k in (1, 4):
        r = solve_static(s, subdivisions=k)
        assert np.abs(r.reactions[:, 2]) == pytest.approx([Ma, Mb], rel=1e-10)


def test_simply_supported_uniform_timoshenko():
    # midspan deflection 5qL⁴/384EI + qL²/(8κGA) (Timoshenko & Gere: the shear deflection
    # of a simply supported beam is M(x)/κGA)
    L, A, I, As, q = 1.0, 4e-3, 8e-6, 1e-3, -1.0e4
    sec = Section("s", area=A, Iz=I, c=0.05, shear_area_y=As)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=Material("m", E, G),
                        supports={0: ["x", "y"], 1: ["y"]}, is_beam=True)
    s = s.with_extensions(member_loads=[MemberLoad.uniform(0, (0.0, q))])
    r = solve_static(s, subdivisions=2)
    mid = r.fe.station_displacements(r.u)[0, 1, 1]
    assert mid == pytest.approx(5 * q * L**4 / (384 * E * I) + q * L**2 / (8 * G * As),
                                rel=1e-10)


def timoshenko_frequency(n, L, E, G, kappa, rho, A, I):
    """The bending frequency (Hz) of mode n of a simply supported Timoshenko beam: the lower
    root of det [[κGAk² − ρAω², −κGAk], [−κGAk, EIk² + κGA − ρIω²]] = 0, k = nπ/L (the
    Timoshenko beam equations with w = W sin kx, ψ = Ψ cos kx)."""
    k = n * math.pi / L
    kG = kappa * G * A
    a = rho * A * rho * I
    b = -(rho * A * (E * I * k**2 + kG) + rho * I * kG * k**2)
    c = kG * k**2 * (E * I * k**2 + kG) - (kG * k) ** 2
    return math.sqrt((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)) / (2 * math.pi)


def test_deep_beam_frequencies():
    # a simply supported deep beam, L/h = 4: shear and rotary inertia lower the bending
    # frequencies well below Euler–Bernoulli's; FE (consistent Timoshenko mass) against the
    # closed form of the module notes
    L, h, rho = 1.0, 0.25, 7850.0
    A, I = h * h, h**4 / 12
    kappa = 5.0 / 6.0
    mat = Material("m", E, G, density=rho)
    sec = Section("s", area=A, Iz=I, c=h / 2, shear_area_y=kappa * A)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=mat,
                        supports={0: ["x", "y"], 1: ["y"]}, is_beam=True)
    err = {}
    for k in (20, 40):
        f = np.sort(solve_modes(s, count=8, subdivisions=k).frequencies_hz)
        for n in (1, 2, 3):
            fn = timoshenko_frequency(n, L, E, G, kappa, rho, A, I)
            kn = n * math.pi / L
            assert fn < 0.95 * math.sqrt(E * I * kn**4 / (rho * A)) / (2 * math.pi)
            # the bending frequency among the modes (axial ones lie between them)
            err[k, n] = float(np.min(np.abs(f - fn) / fn))
    for n in (1, 2, 3):
        # the element's shape functions tend to linear ones as Φ = 12EI/(κGAh²) grows with
        # finer elements, so frequencies converge at second order in h: the error falls
        # four-fold when the elements halve, to below 1.2e-3 (mode 3) with 40 of them
        assert 3.8 < err[20, n] / err[40, n] < 4.2, err
        assert err[40, n] < 1.2e-3, err


def test_rayleigh_limit_converges_at_fourth_order():
    # a very large shear area (Φ → 0): the Timoshenko mass is the cubic one plus rotary
    # inertia ρI ψ², a Rayleigh beam, f = √(EIk⁴/(ρA + ρIk²))/2π (Han, Benaroya & Wei,
    # "Dynamics of transversely vibrating beams using four engineering theories", J. Sound
    # Vib. 225, 1999); the cubic elements converge at fourth order
    L, h, rho = 1.0, 0.25, 7850.0
    A, I = h * h, h**4 / 12
    sec = Section("s", area=A, Iz=I, c=h / 2, shear_area_y=1.0e6)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec,
                        material=Material("m", E, G, density=rho),
                        supports={0: ["x", "y"], 1: ["y"]}, is_beam=True)
    k = math.pi / L
    fr = math.sqrt(E * I * k**4 / (rho * A + rho * I * k**2)) / (2 * math.pi)
    err = [float(np.min(np.abs(np.sort(solve_modes(s, count=4, subdivisions=n)
                                       .frequencies_hz) - fr) / fr)) for n in (5, 10)]
    assert 14.0 < err[0] / err[1] < 18.0 and err[1] < 1e-5, err


def test_section_keys_and_bad_shear_area():
    base = {"model": {"dimension": 2}, "materials": {"st": {"E": E, "G": G}},
            "nodes": {"A": [0, 0], "B": [1, 0]},
            "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                               "type": "beam"}},
            "supports": {"A": ["x", "y", "rz"]}}
    s = model_from_dict({**base, "sections": {"b": {
        "area": 4e-3, "Iz": 8e-6, "beam_theory": "timoshenko", "shear_coefficient": 0.5}}})
    assert s.shear_area_y[0] == pytest.approx(2e-3)
    assert s.shear_area_z[0] == pytest.approx(2e-3)
    for bad, item in (({"shear_area_y": 0.0}, "sections.b.shear_area_y"),
                      ({"beam_theory": "timoshenko"}, "sections.b.beam_theory"),
                      ({"beam_theory": "timoshenko", "shear_coefficient": 0.0},
                       "sections.b.shear_coefficient"),
                      ({"beam_theory": "rayleigh"}, "sections.b.beam_theory")):
        with pytest.raises(InputError) as e:
            model_from_dict({**base, "sections": {"b": {"area": 4e-3, "Iz": 8e-6, **bad}}})
        assert e.value.item == item


def test_couple_inside_an_element_is_exact():
    # a couple C at 0.3L of a fixed-fixed Timoshenko beam: with one element it acts inside
    # the element (fixed-end forces C ψᵢ(ξ)); with ten elements it sits at a node and is a
    # plain nodal moment.  The exact element gives the same reactions either way, and they
    # satisfy statics (R_B L + M_A + M_B + C = 0, checked by the equilibrium of every solve)
    L, A, I, As, C = 1.0, 4e-3, 8e-6, 1e-3, 800.0
    sec = Section("s", area=A, Iz=I, c=0.05, shear_area_y=As)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=Material("m", E, G),
                        supports={0: ["x", "y", "rz"], 1: ["x", "y", "rz"]}, is_beam=True)
    s = s.with_extensions(member_loads=[MemberLoad(0, "point", at=0.3, moment=(C,))])
    one = solve_static(s, subdivisions=1).reactions
    ten = solve_static(s, subdivisions=10).reactions
    assert one == pytest.approx(ten, rel=1e-9, abs=1e-9)
    # and the shear flexibility changes them (Φ = 0.4 here): not the Euler–Bernoulli values
    eb = solve_static(s.with_sections({0: Section("e", area=A, Iz=I, c=0.05)}),
                      subdivisions=1).reactions
    assert abs(one[0, 2] - eb[0, 2]) > 1e-3 * abs(eb[0, 2])


def test_trapezoidal_load_inside_one_element_is_exact():
    # the closed-form fixed-end forces of a linearly varying load on a Timoshenko element
    # (trussfe.mechanics.member_loads) give the same reactions with one element as with
    # many (each then carrying its own piece of the load): the element is exact
    L, A, I, As = 1.0, 4e-3, 8e-6, 1e-3
    sec = Section("s", area=A, Iz=I, c=0.05, shear_area_y=As)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=Material("m", E, G),
                        supports={0: ["x", "y", "rz"], 1: ["x", "y", "rz"]}, is_beam=True)
    s = s.with_extensions(member_loads=[MemberLoad(0, "trapezoidal", (0.0, -2.0e3),
                                                   (0.0, -8.0e3))])
    one = solve_static(s, subdivisions=1).reactions
    many = solve_static(s, subdivisions=7).reactions
    assert one == pytest.approx(many, rel=1e-9)
