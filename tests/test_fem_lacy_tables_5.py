# SPDX-License-Identifier: MIT
"""Lacy Tables 5.2–5.4: the double-octahedral bay of Appendix D, as MSC/PAL modelled it
(pin-jointed truss members of area 9.0245e-5 m², base nodes N1–N3 fixed, vertical loads at the
top nodes N7–N9), solved by the finite-element core.

Reference facts (found by recomputation and checked here; docs/model-format.md):

* the load that reproduces the tables is 44.498 N per top node (4.536 kg × 9.81), not the
  stated 46.0 N: at the symmetric equilibrium position each base node carries the full node
  load vertically, and Table 5.2 prints −44.498 N; with 46.0 N every value is 46.0/44.498 − 1
  = 3.4 % high;
* the short slewed active length is 1.1079 m (printed 1.1077);
* the numbers printed as the *first* slewed position (Table 5.3) belong to M7/8 at its
  minimum, those of Table 5.4 to M7/8 at its maximum (captions swapped);
* stress = force / 9.0245e-5 m² (Appendix D's area).

Member numbering follows Appendix D's "Connect" lines and Table 4.1: M6 = N2–N5,
M7/8 = N4–N5, M9/10 = N5–N6, M11/12 = N4–N6, M19 = N7–N9.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.fem import solve_static
from trussfe.kinematics.assembly import solve_positions
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

#: every force and stress value within 0.02 %
RTOL = 2e-4

ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
SECTION = Section("appendix_d", area=9.0245e-5)
LOAD = 44.498            # N per top node (see module docstring)

NODES = np.array([[-0.6096, -0.3519, 0.0], [0.6096, -0.3519, 0.0], [-0.0000, 0.7039, 0.0],
                  [-0.5842, 0.3373, 0.5609], [0.5842, 0.3373, 0.5609], [0.0, -0.6746, 0.5609],
                  [-0.6096, -0.3519, 1.1218], [0.0, 0.7039, 1.1218],
                  [0.6096, -0.3519, 1.1218]])
CONNECT = [(2, 6), (1, 6), (1, 4), (3, 4), (3, 5), (2, 5), (4, 5), (5, 6), (4, 6), (6, 9),
           (6, 7), (4, 7), (4, 8), (5, 8), (5, 9), (7, 9), (8, 7), (8, 9)]
MEMBER_IDS = ["M1", "M2", "M3", "M4", "M5", "M6", "M7/8", "M9/10", "M11/12", "M13", "M14",
              "M15", "M16", "M17", "M18", "M19", "M20", "M21"]
ACTIVE = [MEMBER_IDS.index(k) for k in ("M7/8", "M9/10", "M11/12")]
M6, M19 = MEMBER_IDS.index("M6"), MEMBER_IDS.index("M19")

# (reaction N1 x, y, z; N M6; N M19 (compression negative); σ M6; σ M19), MATLAB columns
TABLE_5_2 = (-25.1882, -14.5430, -44.4980, 35.2648, -16.7923, 3.9077e5, 1.8608e5)
TABLE_5_3 = (-31.5663, -11.0051, -50.1415, 41.0997, -24.6389, 4.5543e5, 2.7302e5)
TABLE_5_4 = (-19.6748, -18.0142, -38.9220, 31.3596, -9.4169, 3.4750e5, 1.0435e5)


def bay(coords=NODES, load=LOAD):
    conn = np.array(CONNECT) - 1
    return build_structure(coords, conn, section=SECTION, material=ALUMINIUM,
                           supports={0: "xyz", 1: "xyz", 2: "xyz"},
                           loads={6: [0, 0, load], 7: [0, 0, load], 8: [0, 0, load]},
                           node_ids=[f"N{i}" for i in range(1, 10)], member_ids=MEMBER_IDS)


#: Exact base triangle (side 1.2192 m, centroid at the origin) that Appendix D rounds to 4 digits
SIDE, LONGERON = 1.2192, 0.889
BASE = np.array([[-SIDE / 2, -SIDE / (2 * np.sqrt(3)), 0.0],
                 [SIDE / 2, -SIDE / (2 * np.sqrt(3)), 0.0],
                 [0.0, SIDE / np.sqrt(3), 0.0]])


def slewed(l78, l910_1112):
    """Node positions with the active members at the given lengths: base triangle and top
    triangle sides 1.2192 m, cross longerons 0.889 m (the lengths Appendix D's coordinates
    imply; docs/model-format.md), found by the forward-position solver starting from Appendix D."""
    conn = np.array(CONNECT) - 1
    lengths = np.full(len(CONNECT), LONGERON)
    lengths[[MEMBER_IDS.index(k) for k in ("M19", "M20", "M21")]] = SIDE
    lengths[ACTIVE] = [l78, l910_1112, l910_1112]
    x0 = NODES.copy()
    x0[:3] = BASE
    fixed = np.zeros(NODES.shape, bool)
    fixed[:3] = True
    return solve_positions(x0, conn, lengths, fixed).coords


def _values(r):
    return np.r_[r.reactions[0, :3], r.axial_force[[M6, M19]], r.max_von_mises[[M6, M19]]]


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
@pytest.mark.parametrize("geometry", ["exact", "appendix_d"])
def test_table_5_2_equilibrium(bar_model, geometry):
    """Equilibrium position (all active members 1.1684 m).  With the exact lengths the worst
    error is 6e-5; Appendix D's 4-digit coordinates give 1.8e-4, still within 0.02 %."""
    s = bay(slewed(1.1684, 1.1684) if geometry == "exact" else NODES)
    if bar_model == "pinned-beam":
        # the tube behind Appendix D's area: OD 0.75 in, ID 0.62 in (A = 9.0245e-5 m²)
        s = s.with_sections([Section.tube("tube", 0.01905, 0.62 * 0.0254)] * s.n_members)
    r = solve_static(s, bar_model=bar_model)
    assert_allclose(_values(r), TABLE_5_2, rtol=RTOL)


@pytest.mark.parametrize("lengths,table", [((1.1079, 1.2289), TABLE_5_3),
                                           ((1.2289, 1.1079), TABLE_5_4)],
                         ids=["M7/8 short (printed as Table 5.3)",
                              "M7/8 long (printed as Table 5.4)"])
def test_tables_5_3_and_5_4_slewed(lengths, table):
    r = solve_static(bay(slewed(*lengths)))
    assert_allclose(_values(r), table, rtol=RTOL)


def test_stated_46_newton_load_is_3_4_percent_high():
    """With the stated 46.0 N every value scales by 46.0/44.498 (linear analysis): 3.4 %."""
    r = solve_static(bay(load=46.0))
    assert_allclose(_values(r) / np.array(TABLE_5_2), 46.0 / 44.498, rtol=RTOL)
    assert 0.033 < 46.0 / 44.498 - 1 < 0.035


def test_printed_short_length_1_1077_misses_the_tolerance():
    """The printed 1.1077 m misses some value by more than 0.02 % (worst 5.6e-4 here)."""
    r = solve_static(bay(slewed(1.1077, 1.2289)))
    err = np.abs(_values(r) / np.array(TABLE_5_3) - 1)
    assert err.max() > RTOL


def test_captions_of_tables_5_3_and_5_4_are_swapped():
    """Read with its caption (M7/8 at its maximum 1.2289 m for the first slewed position),
    Table 5.3 is off by tens of per cent; the swapped reading matches to 1e-4 (above)."""
    r = solve_static(bay(slewed(1.2289, 1.1079)))
    err = np.abs(_values(r) / np.array(TABLE_5_3) - 1)
    assert err.max() > 0.3


def test_equilibrium_base_reaction_carries_the_node_load():
    """Symmetry and statics: at the equilibrium position the three base reactions together
    carry 3 × 44.498 N, so each carries −44.498 N vertically (Table 5.2's −44.4980)."""
    r = solve_static(bay())
    assert_allclose(r.reactions[:3, 2], -LOAD, rtol=1e-9)
