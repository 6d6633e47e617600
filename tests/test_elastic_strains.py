# SPDX-License-Identifier: MIT
"""M6 strains: gauge fibres, Table 5.5 and Lacy's section 5.6 zeroing procedure."""
import numpy as np
from numpy.testing import assert_allclose

from trussfe.response.along_motion import elastic_along_motion
from trussfe.studies.lacy_elastic import TABLE_5_5, slew, table_5_5
from trussfe.response.strains import gauge_strains, static_strain, zeroed_strain
from trussfe.studies.lacy_rigid import double_octahedron

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.rigid.kinematics import Kinematics

L = 2.0
TUBE = Section.tube("tube", 0.0254, 0.022225)
X_FROM_END = np.linspace(0.0, L, 9)[None, :]


def _bar():
    """A bar along x, pinned at A (x, y) with a roller at B (y)."""
    return build_structure([[0.0, 0.0], [L, 0.0]], [(0, 1)], section=TUBE,
                           material=Material("al", 71e9, 26.2e9, density=2711.5),
                           supports={0: "xy", 1: "y"})


def _spin_up(alpha: float) -> Kinematics:
    """The bar at rest along x, starting to turn about A with angular acceleration α."""
    z = np.zeros((1, 1, 3))
    return Kinematics(time=np.zeros(1), coords=np.array([[[0.0, 0.0], [L, 0.0]]]),
                      velocity=np.zeros((1, 2, 3)),
                      acceleration=np.array([[[0.0, 0.0, 0.0], [0.0, alpha * L, 0.0]]]),
                      length=np.full((1, 1), L), length_rate=np.zeros((1, 1)),
                      length_acc=np.zeros((1, 1)), unit=np.array([[[1.0, 0.0, 0.0]]]),
                      unit_rate=z.copy(), unit_acc=np.array([[[0.0, alpha, 0.0]]]),
                      omega=z.copy(), alpha=z + [0.0, 0.0, alpha])


def test_gauge_fibres_pure_bending():
    """Bar under uniform angular acceleration (no axial force): a gauge at the bottom fibre
    reads +|M|c/(EI) (sagging: tension below), the top one −|M|c/(EI), and three gauges at 120°
    average to the axial strain 0.  Beam theory; 1e-12 relative."""
    s = _bar()
    r = elastic_along_motion(s, _spin_up(5.0), positions=X_FROM_END)
    j = 4                                                     # midspan
    M = r.sections.moment[0, 0, j, 2]
    assert M < 0                                              # sagging under the downward load
    g = gauge_strains(s, r.sections, 0, j, angles_deg=(0.0, 180.0))   # b1 = −y: bottom first
    amp = abs(M) * TUBE.c / (s.E[0] * TUBE.Iy)
    assert_allclose(g[0], [amp, -amp], rtol=1e-12)
    g3 = gauge_strains(s, r.sections, 0, j)
    assert abs(g3.mean()) < 1e-12 * amp


def test_table_5_5_positions_and_modulus():
    """Table 5.5 at 46.0 N: our strains (E = 71 GPa, A = 9.0245e-5 m²) are 2.8-3.1 % below the
    thesis' MATLAB column at all three positions; scaled to E = 1e7 psi = 68.948 GPa they match
    it to 2e-3 (finding: the strain calculation used that modulus).  Slew position 1 is M7/8 at
    its maximum (the larger strain belongs to M7/8 at its minimum)."""
    ours = table_5_5(46.0)
    for k, (matlab, measured) in TABLE_5_5.items():
        assert 0.97 < ours[k] / matlab < 0.973
        assert_allclose(ours[k] * 71.0 / 68.948, matlab, rtol=2e-3)
    assert ours["slew2"] > ours["equilibrium"] > ours["slew1"]


def test_static_strain_is_fe_static():
    """static_strain = N/(EA) of the FE static solution (trussfe.fem.static, pinned-beam,
    loads only) at M6's midpoint; 1e-9."""
    from trussfe.fem.static import solve_static
    s = double_octahedron(top_load=46.0)
    i6 = s.member_index("M6")
    eps = static_strain(s, i6)
    s2 = double_octahedron(top_load=46.0)
    s2 = s2.without_extensions("active_members")
    st = solve_static(s2, "pinned-beam", subdivisions=6, self_weight=False)
    assert_allclose(eps, st.strain[i6], rtol=1e-9)


def test_zeroing_procedure():
    """Lacy section 5.6 along slew 1 (22 steps): ε_nog + (ε_grav − ε_grav,eq) equals what a
    gauge zeroed at equilibrium under gravity reads, ε_full − ε_grav,eq (linearity, 1e-12),
    and ε_grav,eq is the static gravity-only strain at the equilibrium position."""
    sim, _ = slew(1, steps=22)
    s = sim.structure
    i6 = s.member_index("M6")
    eq = double_octahedron(gravity=-9.81)
    z = zeroed_strain(s, sim.kinematics, eq, i6)
    assert_allclose(z.zeroed, z.full - z.gravity_equilibrium, rtol=0,
                    atol=1e-12 * np.abs(z.full).max())
    assert_allclose(z.gravity_equilibrium, static_strain(eq, i6, gravity=True), rtol=1e-12)
    # the gravity strain changes along the motion (so the correction matters): > 10 %
    assert np.ptp(z.gravity) > 0.1 * abs(z.gravity_equilibrium)
