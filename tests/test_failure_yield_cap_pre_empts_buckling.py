"""A strut with a yield ``cap`` below its Euler load yields in compression and never buckles.

Hand statics of two collinear bars sharing node 0 (bar 0: L = 1 m, bar 1: L = 2 m, both
EA = 2e7 N, pushed along −x by λ·1000 N, displacement u < 0 of node 0): bar 0 carries
EA·u/L₁ until it yields at A f_y = 25 kN, i.e. u = −1.25 mm, λ = 25 + 12.5 = 37.5; from then on
it carries −A f_y while bar 1 stays elastic, so λ = 25 + EA|u|/(2 m)/1000.  Its elastic force
EA(ε − ε_p) never exceeds A f_y = 25 kN in magnitude, so a buckling law with P_cr = 30 kN never
acts — whatever the step size of the path.
"""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, build_failure_laws, follow_path

A, E, FY = 1e-4, 2e11, 2.5e8
SEC = Section(name="s", area=A, Iy=1e-8, Iz=1e-8, J=2e-8, c=0.01)
MAT = Material(name="m", E=E, G=8e10, density=0.0, yield_strength=FY)


def _pair():
    return build_structure([[0.0, 0.0], [-1.0, 0.0], [-2.0, 0.0]], [(1, 0), (2, 0)],
                           section=SEC, material=MAT, supports={1: "xy", 2: "xy", 0: "y"},
                           loads={0: [-1000.0, 0.0]})


@pytest.mark.parametrize("buckling", [
    {"buckling": "cap", "critical_load": 30000.0},
    {"buckling": "remove", "critical_load": 30000.0},
    {"buckling": "softening", "critical_load": 30000.0, "residual": 0.2,
     "softening_strain": 1e-4},
])
@pytest.mark.parametrize("control, step", [("displacement", 1e-4), ("displacement", 5e-4),
                                           ("displacement", 2e-3), ("arc-length", 2e-3)])
def test_yielded_strut_does_not_buckle(buckling, control, step):
    s = _pair()
    m = NonlinearModel(s, laws=build_failure_laws(s, per_member={0: {"yield": "cap",
                                                                     **buckling}}))
    r = follow_path(m, control, steps=max(4, round(4e-3 / step)), step=step, monitor=0)
    ev = [(e.kind, e.member) for e in r.events if e.member is not None]
    assert ev == [("yield", 0)]
    yield_event = next(e for e in r.events if e.kind == "yield")
    assert_allclose(yield_event.load_factor, 37.5, rtol=1e-9)
    late = [p for p in r.path if p.u[0] < -1.3e-3]
    assert late
    for p in late:
        assert p.alive.all()
        assert_allclose(p.forces[0], -A * FY, rtol=1e-12)
        assert_allclose(p.load_factor, 25.0 - E * A * p.u[0] / 2.0 / 1000.0, rtol=1e-9)
    assert np.all(np.diff(r.load_factors) > 0)
