"""Lacy eqs. 4.75/4.76 (convention ``"lacy-per-axis"``) against the resultant bending of a tube
(``"combined"``): closed forms, and the thesis' own M6 numbers of section 5.7 (Fig. 5.12)."""
import math

import numpy as np
import pytest

from trussfe.mechanics.stress import von_mises
from trussfe.studies.lacy_stress_components import FIG_5_12, thesis_components_combined


def _vm(My, Mz, convention, N=1.0, Vy=0.0, Vz=0.0):
    a = lambda x: np.array([float(x)])
    return von_mises(a(N), a(Vy), a(Vz), a(My), a(Mz), 1.0, 1.0, 1.0, 1.0, 1.0, True,
                     convention=convention).von_mises[0]


def test_one_axis_bending_agrees_split_bending_does_not():
    """Unit section: a moment about one axis gives |σ_T| + |M| both ways; a moment split 1:1
    gives |σ_T| + M/√2 per axis and |σ_T| + M as a resultant (closed forms)."""
    for conv in ("lacy-per-axis", "combined"):
        assert _vm(3.0, 0.0, conv) == pytest.approx(4.0, rel=1e-15)
        assert _vm(0.0, -3.0, conv) == pytest.approx(4.0, rel=1e-15)
    m = 3.0 / math.sqrt(2.0)
    assert _vm(m, m, "lacy-per-axis") == pytest.approx(1.0 + m, rel=1e-15)
    assert _vm(m, m, "combined") == pytest.approx(4.0, rel=1e-15)
    # each axis keeps its own shear: sqrt((|σ_T| + |σ_Mz|)² + 3 τ_z²), τ_z = 2 Vz / A
    assert _vm(0.0, 3.0, "lacy-per-axis", Vz=0.5) == pytest.approx(math.sqrt(16.0 + 3.0))


def test_thesis_fig_5_12_components_combine_per_axis():
    """Lacy section 5.7: 8.4e5 + 4.5e5 (eq. 4.76, shear 230.8 Pa negligible) = 1.29e6, the
    printed 1.294e6 to the components' two digits; as a resultant 8.4e5 + sqrt(4.5e5² +
    3.95e5²) = 1.439e6, 11 % off."""
    d = thesis_components_combined()
    assert d["per_axis"] == pytest.approx(math.sqrt(1.29e6 ** 2 + 3 * 230.8 ** 2), rel=1e-12)
    assert abs(d["per_axis"] / FIG_5_12["von_mises"] - 1) < 8e-3
    assert d["combined"] == pytest.approx(8.4e5 + math.hypot(4.5e5, 3.95e5), rel=1e-12)
    assert d["combined"] / FIG_5_12["von_mises"] - 1 > 0.1
