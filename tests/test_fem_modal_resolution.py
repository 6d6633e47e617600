# SPDX-License-Identifier: MIT
"""Resolution of the lowest modes of very slender chains of double-octahedral bays.

Physics first: a chain of bays is a slender cantilever, so its first (bending) frequency
follows Euler–Bernoulli's f₁ ∝ L⁻² (f₁ = (1.875²/2π) √(EI/μ) / L², the same section and
mass per length at every length).  Where double precision resolves the modes the computed
frequencies follow that law and their eigen-residual is small; where it does not, the
residual exposes it and ``solve_modes`` refuses (``check_resolution``).
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError
from trussfe.fem.modal import RESOLVED_RESIDUAL, solve_modes
from trussfe.models import double_octahedral_chain


@pytest.fixture(scope="module")
def chains():
    return {n: solve_modes(double_octahedral_chain(n), count=2, check_resolution=False)
            for n in (100, 1000)}


def test_first_frequency_scales_as_inverse_square_length(chains):
    """Euler–Bernoulli cantilever: f₁(1000 bays) = f₁(100 bays) / 10², to the 0.2 % that
    the 100-bay chain's shear flexibility and discrete bays allow (measured 0.15 %)."""
    assert_allclose(chains[1000].frequencies_hz[0], chains[100].frequencies_hz[0] / 100,
                    rtol=2e-3)


def test_resolved_modes_have_small_residuals(chains):
    """Measured: 5e-7 at 100 bays, 4e-3 at 1,000 bays; both well under the threshold."""
    assert chains[100].residuals.max() < 1e-5
    assert chains[1000].residuals.max() < RESOLVED_RESIDUAL / 10
    # the two bending modes of the symmetric section are equal (1e-4 apart at 1,000 bays)
    f = chains[1000].frequencies_hz
    assert abs(f[1] / f[0] - 1) < 1e-3


def test_unresolved_modes_are_refused():
    """3,000 bays: ω₁² is 5e-16 of the largest K_ii/M_ii; the residual (~0.4) shows the
    two equal bending frequencies no longer come out equal, and the analysis refuses."""
    s = double_octahedral_chain(3000)
    with pytest.raises(AnalysisError, match="cannot be resolved in double precision"):
        solve_modes(s, count=2)
    r = solve_modes(s, count=2, check_resolution=False)
    assert r.residuals.max() > RESOLVED_RESIDUAL
    assert np.all(np.isfinite(r.frequencies_hz))


def test_a_nearly_flat_truss_says_which_modes_it_resolves():
    """Two bars of 1 m meeting 1e-9 m above their line, a 10 kg mass at the apex: the
    vertical stiffness is 2EA/L·(h/L)² ≈ 1e-12 of the horizontal one, so the two
    frequencies lie 1e6 apart and 1/ω² of the upper one is below the round-off of the
    lower's.  The message said "only 1 DOFs carry mass" (both do); it says that the upper
    mode lies beyond what double precision resolves beside the lower, and which count
    works — and that count gives the vertical mode, √(k_v/m)/2π (massless bars)."""
    import trussfe
    from trussfe.errors import AnalysisError
    d = {"model": {"name": "flat", "dimension": 2},
         "materials": {"al": {"E": 71e9, "G": 26.2e9, "density": 0.0}},
         "sections": {"tube": {"outer_diameter": 0.0254, "inner_diameter": 0.022225}},
         "nodes": {"O2": [0.0, 0.0], "B": [1.0, 1e-9], "O1": [2.0, 0.0]},
         "members": {"f": {"nodes": ["B", "O1"], "section": "tube", "material": "al"},
                     "a": {"nodes": ["O2", "B"], "section": "tube", "material": "al"}},
         "supports": {"O2": ["x", "y"], "O1": ["x", "y"]}, "masses": {"B": 10.0}}
    with pytest.raises(AnalysisError, match="only the lowest 1 of 2 modes are resolved.*"
                                            "use --count 1"):
        trussfe.modes(d, bar_model="truss")
    r = trussfe.modes(d, bar_model="truss", count=1)
    A = np.pi / 4 * (0.0254**2 - 0.022225**2)
    L = np.hypot(1.0, 1e-9)
    k_v = 2 * 71e9 * A / L * (1e-9 / L) ** 2
    assert r.frequencies_hz[0] == pytest.approx(np.sqrt(k_v / 10.0) / (2 * np.pi), rel=1e-6)
