# SPDX-License-Identifier: MIT
"""The thesis' choices as one frozen Conventions object: each field reaches the rigid-body
solver (checked against the definition it selects: eq. 2.24's S1 = √(σ² + k τ²), the
whole-length inertia changing only the moments, the scheme's first-step rates)."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.mechanics.conventions import PHYSICAL, THESIS, Conventions
from trussfe.rigid.motion import third_order_motion
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_rigid import L2, L3MIN, triangular_truss


@pytest.fixture(scope="module")
def base():
    s = triangular_truss()
    return s, third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 3.0, 20)


def test_frozen_and_named_presets():
    with pytest.raises(dataclasses.FrozenInstanceError):
        THESIS.shear_factor = 1.0
    assert Conventions.from_scheme("exact") is PHYSICAL
    assert THESIS.finite_difference_rates and THESIS.full_length_inertia
    with pytest.raises(ValueError, match="scheme"):
        Conventions.from_scheme("approximate")


def test_shear_factor_reaches_s1(base):
    """S1 = √(σ² + k τ²) with the k of the conventions (eq. 2.24; Lacy's code uses 1)."""
    s, m = base
    for k in (3.0, 1.0):
        r = simulate(s, m, conventions=Conventions(shear_factor=k))
        st = r.stresses
        assert_allclose(st.s1, np.sqrt(st.axial ** 2 + k * st.shear ** 2), rtol=1e-14)
        assert r.options["shear_factor"] == k


def test_full_length_inertia_changes_only_moments(base):
    """The section inertia enters the moment alone (I α): tensions and shears equal."""
    s, m = base
    a = simulate(s, m)
    b = simulate(s, m, conventions=Conventions(full_length_inertia=True))
    assert_allclose(b.sections.tension, a.sections.tension, rtol=1e-12, atol=1e-9)
    assert_allclose(b.sections.shear, a.sections.shear, rtol=1e-12, atol=1e-9)
    assert np.abs(b.sections.moment - a.sections.moment).max() > 1e-6
    assert b.options["full_length_inertia"] and not a.options["full_length_inertia"]


def test_finite_difference_rates_start_at_rest(base):
    """Lacy's backward differences give zero angular rates at the first step (Appendix A);
    the exact kinematics do not (the third-order response has zero velocity at t = 0 too,
    so compare a later step: the schemes differ there)."""
    s, m = base
    fd = simulate(s, m, conventions=Conventions(finite_difference_rates=True))
    ex = simulate(s, m, conventions=PHYSICAL)
    assert fd.options["scheme"] == "thesis" and ex.options["scheme"] == "exact"
    assert np.abs(fd.kinematics.omega[0]).max() == 0.0
    assert np.abs(fd.kinematics.omega[5] - ex.kinematics.omega[5]).max() > 0.0
