# SPDX-License-Identifier: MIT
"""Every gallery script of ``examples/`` runs, draws its figure, and reproduces its numbers.

Each script lists its comparisons in ``CHECKS`` as (quantity, computed, reference, tolerance,
source) and asserts them itself; this test runs the script and checks the computed values
again against the references below, written independently of the script with their sources,
so that a script cannot drift from its source unnoticed.
"""
from __future__ import annotations

import math
import runpy
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
plt = pytest.importorskip("matplotlib.pyplot")

#: Example -> {quantity: (reference, relative or absolute tolerance, source)}.
REFERENCES = {
    "plot_01_static_truss": {
        "follower axial force, N": (-78.5429, 5e-6, "Lacy Table 3.2"),
        "active member axial force, N": (-27.49, 5e-6, "Lacy Table 3.2"),
        "O1 reaction x, N": (-17.1813, 5e-6, "Lacy Table 3.2"),
        "O1 reaction y, N": (76.6406, 5e-6, "Lacy Table 3.2"),
        "O2 reaction y, N": (21.4594, 5e-6, "Lacy Table 3.2"),
    },
    "plot_02_base_simulation": {
        "follower max von Mises, Pa": (4.3393e6, 5e-5, "Lacy section 3.3"),
        "leadscrew tube max von Mises, Pa": (2.6256e7, 5e-5, "Lacy section 3.3"),
    },
    "plot_03_slew_actuators": {
        "step of the largest M7/8 compression": (0, 0.0, "Lacy section 5.7"),
        "M7/8 compression decreasing (1 = yes)": (1, 0.0, "Lacy section 5.7, fig. 5.13"),
        # 18.879 V back emf + 3.175 V armature drop at the 70.90 N start force
        "M7/8 peak motor voltage, V": (22.054, 5e-3, "Lacy eq. 2.44, closed form"),
    },
    "plot_04_modes_buckling": {
        # f1 = π/(2L²)·√(EI/ρA) for the 2 m tube OD 25.4 mm, ID 22.225 mm, E 71 GPa,
        # ρ 2770 kg/m³ (closed form of the simply supported beam)
        "first bending frequency, Hz": (16.7752, 1e-4, "simply supported beam, closed form"),
        "second bending frequency, Hz": (4 * 16.7752, 1e-3, "simply supported beam, f2 = 4 f1"),
        "Euler load, N": (1481.2, 1e-4, "Lacy eq. 2.26"),
        "Euler load of the Table 3.3 follower, N": (1481.2, 1e-4, "Lacy Table 3.3"),
    },
    "plot_05_postcritical_dome": {
        "apex bars failed before the mechanism": (4, 0.0,
                                                  "four of six apex bars must go first"),
    },
    "plot_07_member_loads": {
        # Roark's Formulas for Stress and Strain, Table 8.1 case 2e: L = 3 m, q = 1 kN/m,
        # EI = 1.6e6 N·m²
        "reaction at A, N": (1500.0, 1e-10, "qL/2"),
        "reaction at B, N": (1500.0, 1e-10, "qL/2"),
        "midspan deflection, m": (-6.591796875e-4, 1e-10, "5qL⁴/(384EI)"),
        "midspan moment, N·m": (1125.0, 1e-10, "qL²/8"),
    },
    "plot_08_load_cases": {
        # Roark's Formulas for Stress and Strain, Table 8.1: fixed-fixed beam, L = 4 m,
        # q = 2 kN/m, EI = 1.6e6 N·m², end settlement 5 mm
        "dead: end moment at A, N·m": (2000.0 * 16 / 12, 1e-10, "qL²/12"),
        "dead: end shear at A, N": (4000.0, 1e-10, "qL/2"),
        "settlement: end moment at A, N·m": (6 * 1.6e6 * 0.005 / 16, 1e-10, "6EIδ/L²"),
        "settlement: end shear at A, N": (12 * 1.6e6 * 0.005 / 64, 1e-10, "12EIδ/L³"),
        "ULS: moment at A over 1.35 dead + settlement": (1.0, 1e-12, "factored sum"),
    },
    "plot_06_mechanism_trace": {
        "mechanisms": (1, 0.0, "Grübler: 2·2 − 3 = 1"),
        "joint 3 position error, m": (0.0, 1e-8, "closed-form circle intersection"),
        "coupler length change, m": (0.0, 1e-8, "rigid bars"),
    },
}
SCRIPTS = sorted(EXAMPLES.glob("plot_*.py"))


def test_every_script_has_references():
    assert {p.stem for p in SCRIPTS} == set(REFERENCES)


@pytest.mark.parametrize("script", SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_gallery_script(script, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)                 # anything a script writes stays here
    before = set(plt.get_fignums())
    try:
        ns = runpy.run_path(str(script), run_name="__main__")
        figures = [plt.figure(n) for n in set(plt.get_fignums()) - before]
        assert figures, "the script draws no figure"
        for k, fig in enumerate(figures):
            out = tmp_path / f"figure_{k}.png"
            fig.savefig(out)
            assert out.stat().st_size > 5000
    finally:
        for n in set(plt.get_fignums()) - before:
            plt.close(n)
    checks = {name: (value, ref) for name, value, ref, _tol, _src in ns["CHECKS"]}
    for name, (ref, tol, source) in REFERENCES[script.stem].items():
        assert name in checks, f"{name} is not checked by the script"
        value, script_ref = checks[name]
        assert script_ref == pytest.approx(ref, rel=1e-4, abs=1e-12), \
            f"{name}: the script's reference {script_ref} is not {ref} ({source})"
        value = float(value)
        assert math.isfinite(value)
        if ref == 0.0 or tol == 0.0:
            assert abs(value - ref) <= tol, f"{name}: {value} against {ref} ({source})"
        else:
            assert abs(value - ref) <= tol * abs(ref), f"{name}: {value} against {ref} ({source})"
    if script.stem == "plot_05_postcritical_dome":
        # the failure law: each removed bar carried its critical force when it went
        for name, value, ref, tol, _src in ns["CHECKS"][1:]:
            assert np.isclose(value, ref, rtol=1e-5), name
