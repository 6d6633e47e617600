# SPDX-License-Identifier: MIT
"""A static solve without self-weight recovers the section forces of the applied loads only.

A pin-jointed triangle of pinned beams (apex load P, gravity set in the model): solved with
``self_weight=False`` its members carry the closed-form axial forces of the nodal load —
base tension P/2·cot θ, rafters −P/(2 sin θ) (method of joints) — and no shear or bending; the
same solve with self-weight bends every member.  Linear buckling without self-weight equals
buckling of the same model with no gravity at all.
"""
from __future__ import annotations

import numpy as np

from trussfe.fem.buckling import solve_buckling
from trussfe.fem.static import solve_static
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

P = 10.0


def _triangle(gravity):
    return build_structure([[0.0, 0.0], [2.0, 0.0], [1.0, 0.6]], [(0, 1), (1, 2), (0, 2)],
                           section=Section.tube("t", 0.0254, 0.022225),
                           material=Material("al", E=71e9, G=26.2e9, density=2711.5),
                           supports={0: ["x", "y"], 1: ["y"]}, loads={2: [0.0, -P, 0.0]},
                           gravity=gravity)


def test_section_forces_are_those_of_the_nodal_load_only(equilibrium):
    r = solve_static(_triangle([0.0, -9.81]), bar_model="pinned-beam", subdivisions=4,
                     self_weight=False)
    equilibrium(r, self_weight=False)      # the nodal load and the reactions balance
    theta = np.arctan2(0.6, 1.0)
    want = [P / 2 / np.tan(theta), -P / (2 * np.sin(theta)), -P / (2 * np.sin(theta))]
    np.testing.assert_allclose(r.axial_force, want, rtol=1e-9)
    np.testing.assert_allclose(r.section_forces[:, :, 0], np.repeat(np.array(want)[:, None],
                               r.section_forces.shape[1], axis=1), rtol=1e-9)
    # no load acts across the members: no shear, no bending anywhere along them
    assert np.abs(r.section_forces[:, :, 1:]).max() < 1e-9 * P
    weighted = solve_static(_triangle([0.0, -9.81]), bar_model="pinned-beam", subdivisions=4)
    assert np.abs(weighted.section_forces[:, :, 5]).max() > 1e-3


def test_buckling_without_self_weight_is_buckling_without_gravity():
    a = solve_buckling(_triangle([0.0, -9.81]), count=2, subdivisions=4, self_weight=False)
    b = solve_buckling(_triangle([0.0, 0.0]), count=2, subdivisions=4)
    np.testing.assert_allclose(a.load_factors, b.load_factors, rtol=1e-10)
