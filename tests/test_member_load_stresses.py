# SPDX-License-Identifier: MIT
"""The largest von Mises stress of a member that carries member loads is taken over its
length: its moment peaks under a point load between finite-element stations, and a pin-ended
bar bends between its joints.  References: the statics of a simply supported member and
Lacy's eqs. 2.23–2.25 (S1 = √3·2V/A at the neutral axis, S2 = |N|/A + Mc/I at the outer fibre
of a tube), with global equilibrium checked."""
import numpy as np
import pytest

import trussfe
from trussfe.errors import InputError
from trussfe.fem.static import solve_static
from trussfe.model.sections import Section

L = 3.0
TUBE = Section.tube("tube", 0.05, 0.04)


def _bar(load: dict, member_type: str = "bar", section: dict | None = None):
    """A horizontal member A–B of span L, pinned at A, on a roller at B, carrying ``load``."""
    sec = section or {"outer_diameter": 0.05, "inner_diameter": 0.04}
    return trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"st": {"E": 2.0e11, "G": 8.0e10}},
        "sections": {"t": sec},
        "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "t", "material": "st",
                           "type": member_type}},
        "supports": {"A": ["x", "y"], "B": ["y"]},
        "member_loads": [{"member": "AB", **load}]})


def _tube_stress(M: float, V: float) -> float:
    """max(S1, S2) of the tube with N = 0: S2 = M c/I, S1 = √3 · 2V/A."""
    return max(abs(M) * TUBE.c / TUBE.Iz, np.sqrt(3.0) * 2.0 * abs(V) / TUBE.area)


@pytest.mark.parametrize("bar_model, k", [("truss", None), ("pinned-beam", 4)])
def test_a_bar_under_a_uniform_member_load_bends_between_its_joints(bar_model, k,
                                                                     equilibrium):
    """A pin-ended bar under q = 2 kN/m: midspan moment qL²/8, end shear qL/2.  With the
    truss bar model the bar has no station inside, yet ``max_von_mises`` must include the
    bending stress at midspan (a station of its member loads' statics)."""
    q = 2000.0
    s = _bar({"kind": "uniform", "q": [0.0, -q]})
    r = solve_static(s, bar_model=bar_model, subdivisions=k)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    expected = _tube_stress(q * L**2 / 8.0, q * L / 2.0)
    assert r.max_von_mises[0] == pytest.approx(expected, rel=1e-9)
    doc = trussfe.static(s, bar_model=bar_model, subdivisions=k).to_dict()
    assert doc["members"]["AB"]["max_von_mises"] == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("member_type, bar_model, k", [
    ("bar", "truss", None), ("beam", "truss", 4), ("beam", "truss", 3)])
def test_the_moment_under_a_point_load_between_stations_counts(member_type, bar_model, k,
                                                                equilibrium):
    """A point load P = 5 kN at a = 0.3 L, between the quarter-point stations of four
    elements and the third-point stations of three: the moment P a b / L under it is the
    largest, and ``max_von_mises`` is its bending stress (the shear stress beside it is
    smaller)."""
    P, a = 5000.0, 0.3 * L
    s = _bar({"kind": "point", "at": 0.3, "F": [0.0, -P]}, member_type)
    r = solve_static(s, bar_model=bar_model, subdivisions=k)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    b = L - a
    expected = _tube_stress(P * a * b / L, P * b / L)
    assert expected == pytest.approx(P * a * b / L * TUBE.c / TUBE.Iz)
    assert r.max_von_mises[0] == pytest.approx(expected, rel=1e-9)


def test_a_bending_bar_without_an_outer_fibre_distance_is_refused():
    """A bar of a section given by its area alone cannot have a bending stress: a transverse
    member load on it is refused in one line naming the section and the member, instead of
    a largest stress that leaves the bending out."""
    s = _bar({"kind": "uniform", "q": [0.0, -1000.0]}, section={"area": 1.0e-4})
    with pytest.raises(InputError, match=r"sections\.t: .*member AB.*bends"):
        solve_static(s)


def test_an_axial_member_load_needs_no_outer_fibre_distance(equilibrium):
    """An axial member load does not bend the bar: a section of area alone is enough, and
    the largest stress is |N|/A at the loaded end (all of the load reaches A)."""
    s = _bar({"kind": "uniform", "q": [800.0, 0.0]}, section={"area": 1.0e-4})
    r = solve_static(s)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    assert r.max_von_mises[0] == pytest.approx(800.0 * L / 1.0e-4, rel=1e-12)


def test_a_triangular_load_peaks_where_the_shear_vanishes(equilibrium):
    """A pin-ended bar under a load rising linearly from 0 to q: the moment peaks at
    x = L/√3 with M = qL²/(9√3) (simply supported beam under a triangular load), which is a
    station of the JSON and sets ``max_von_mises``."""
    q = 3000.0
    s = _bar({"kind": "trapezoidal", "q_start": [0.0, 0.0], "q_end": [0.0, -q]})
    r = solve_static(s)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    M = q * L**2 / (9.0 * np.sqrt(3.0))
    assert r.max_von_mises[0] == pytest.approx(_tube_stress(M, q * L / 3.0), rel=1e-9)
    st = trussfe.static(s).to_dict()["members"]["AB"]["stations"]
    j = int(np.argmax(np.abs(st["Mz"])))
    assert st["x"][j] == pytest.approx(L / np.sqrt(3.0), rel=1e-12)
    assert abs(st["Mz"][j]) == pytest.approx(M, rel=1e-9)
    assert abs(st["Vy"][j]) < 1e-9 * q * L


def test_a_propped_cantilever_shows_its_span_moment(equilibrium):
    """A beam fixed at A and on a roller at B under a uniform load q, two elements: besides
    the support moment qL²/8 at A, its span moment 9qL²/128 at x = 5L/8, where the shear
    vanishes, is a station (between the element stations L/2 and L)."""
    q = 2000.0
    d = {"model": {"dimension": 2},
         "materials": {"st": {"E": 2.0e11, "G": 8.0e10}},
         "sections": {"t": {"outer_diameter": 0.05, "inner_diameter": 0.04}},
         "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
         "members": {"AB": {"nodes": ["A", "B"], "section": "t", "material": "st",
                            "type": "beam"}},
         "supports": {"A": ["x", "y", "rz"], "B": ["y"]},
         "member_loads": [{"member": "AB", "kind": "uniform", "q": [0.0, -q]}]}
    s = trussfe.model_from_dict(d)
    r = solve_static(s, subdivisions=2)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    st = trussfe.static(s, subdivisions=2).to_dict()["members"]["AB"]["stations"]
    x, Mz = np.array(st["x"]), np.array(st["Mz"])
    j = int(np.argmin(np.abs(x - 5.0 * L / 8.0)))
    assert x[j] == pytest.approx(5.0 * L / 8.0, rel=1e-12)
    assert abs(Mz[j]) == pytest.approx(9.0 * q * L**2 / 128.0, rel=1e-9)
    assert np.max(np.abs(Mz)) == pytest.approx(q * L**2 / 8.0, rel=1e-9)
    assert r.max_von_mises[0] == pytest.approx(_tube_stress(q * L**2 / 8.0, 5 * q * L / 8),
                                               rel=1e-9)


def test_a_point_load_on_a_station_is_seen_after_it_in_both_outputs(equilibrium):
    """docs/json.md: the ``stations`` give the section just after a point load; the
    finite-element stations (the ``_stations.vtu`` file) give the same where the load sits
    on one of them.  Reference: statics of a simply supported member of span L = 3 m under a
    point load (300 N along, −1000 N across) at midspan: just after it V = +500 N and N = 0
    (A takes the axial load), M = PL/4 = 750 N·m."""
    s = _bar({"kind": "point", "at": 0.5, "F": [300.0, -1000.0]}, "beam")
    r = solve_static(s, subdivisions=4)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    fe_mid = r.section_forces[0, 2]                 # station 2 of 4: the midspan
    _, x, F = r.loaded_stations
    j = int(np.flatnonzero(np.isclose(x[0], L / 2))[0])
    for got in (fe_mid, F[0, j]):
        assert got[0] == pytest.approx(0.0, abs=1e-9)
        assert got[1] == pytest.approx(500.0, rel=1e-9)
        assert abs(got[5]) == pytest.approx(1000.0 * L / 4.0, rel=1e-9)
