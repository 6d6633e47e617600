# SPDX-License-Identifier: MIT
"""Midpoint axial force of truss bars (``bar_model="truss"``) in the transient response.

Reference: the closed-form axial equilibrium of a bar turning about a fixed pin.  A bar of
mass ρA per length, turning at ω about its end O1, carries the outward axial load
``q(s) = ρA ω² s``, so ``N(L/2) = N(L) + ∫_{L/2}^{L} q = N(L) + 3 ρA ω² L²/8``, while its
FE force ``EA Δu/L`` is ``N(L) + ρA ω² L²/3``: the midpoint carries ``ρA ω² L²/24`` more.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import trussfe
from trussfe.model.active import ActiveMember
from trussfe.response.transient import transient_response
from trussfe.rigid.motion import Motion, third_order_motion
from trussfe.studies.lacy_rigid import L2, L3MIN, triangular_truss

L, H, V = 2.0, 1.5, 3.0                   # follower length, active length, its rate (m, m/s)
RHO, D_OUT, D_IN = 7850.0, 0.02, 0.016


def _turning_follower():
    """Follower O1–B horizontal, massless active member O2–B vertical below B: lengthening
    the active member at V turns the follower about O1 at ω = V/L; no gravity, no mass at B,
    so B's horizontal equilibrium leaves the follower's end force N(L) = 0."""
    s = trussfe.model_from_dict({
        "model": {"name": "turning follower", "dimension": 2},
        "materials": {"steel": {"E": 210e9, "G": 81e9, "density": RHO},
                      "light": {"E": 210e9, "G": 81e9, "density": 0.0}},
        "sections": {"tube": {"outer_diameter": D_OUT, "inner_diameter": D_IN}},
        "nodes": {"O1": [0.0, 0.0], "O2": [L, -H], "B": [L, 0.0]},
        "members": {"fol": {"nodes": ["O1", "B"], "section": "tube", "material": "steel"},
                    "act": {"nodes": ["O2", "B"], "section": "tube", "material": "light"}},
        "supports": {"O1": ["x", "y"], "O2": ["x", "y"]}})
    return s.with_extensions(active_members=[ActiveMember(
        member=1, base_mass=0.0, base_length=0.1, base_cg=0.0, base_inertia=0.0,
        tube_length=0.5 * H)])


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_turning_bar_midpoint_force_closed_form(bar_model):
    s = _turning_follower()
    t = np.array([0.0, 1e-3, 2e-3])
    mot = Motion(t, [1], (H + V * t)[:, None], np.full((3, 1), V), np.zeros((3, 1)))
    r = transient_response(s, mot, bar_model=bar_model)
    rho_a = RHO * math.pi / 4 * (D_OUT ** 2 - D_IN ** 2)
    omega = V / L
    expected = 3.0 * rho_a * omega ** 2 * L ** 2 / 8.0          # N(L) = 0
    # the bar's constant FE force, ρA ω² L²/3, is 11 % below it
    assert r.axial_force_qs[0, 0] == pytest.approx(expected, rel=1e-9)
    assert r.axial_force[0, 0] == pytest.approx(expected, rel=1e-9)   # starts quasi-static


def test_truss_bar_quasi_static_midpoint_equals_rigid_body():
    """Triangular truss, truss bars, T = 0.3 s: the follower's quasi-static midpoint force
    equals the rigid-body one, as the pinned-beam model's does (the bar's constant FE force
    differs from it by ρA L Δa/24, up to 4.8 N here)."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 0.3, 100, include_end=True)
    r = transient_response(s, m, bar_model="truss")
    peak = np.abs(r.axial_force_rigid).max(axis=0)
    assert np.all(np.abs(r.axial_force_qs - r.axial_force_rigid).max(axis=0) < 1e-5 * peak)
