# SPDX-License-Identifier: MIT
"""Arc-length control passes the corner at the end of a softening law.

The three-bar truss pushed up (compression), the vertical 1 m strut with a ``softening``
law (P_cr = 10 kN, falling to residual 0 over a strain of 5e-4), the inclined bars elastic.
The strut softens faster than the inclined bars stiffen, so the load factor falls from the
buckling point at v = 0.5 mm to v = 1 mm, where the strut's force reaches 0 and its tangent
jumps from −2e7 N/m to 0: the total tangent jumps from negative to positive without passing
a singular state — a corner at which the load factor turns back and rises again.  Closed
form (joint 0 up by v, co-rotational bars): λP = −N_c(−v) − 2EA(ℓ_s/√2 − 1)(1 − v)/ℓ_s with
ℓ_s = √(1 + (1 − v)²) and N_c the softening law.  Bisecting the corner for a singular state
found none, and the shortened steps crept up to it without end ("completed N steps" at
v = 1 mm).
"""
from __future__ import annotations

import math

import numpy as np
from numpy.testing import assert_allclose

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, build_failure_laws, follow_path

A, E = 1e-4, 2e11
EA = E * A
SEC = Section(name="s", area=A, Iy=1e-8, Iz=1e-8, J=2e-8, c=0.01)
MAT = Material(name="m", E=E, G=8e10, density=0.0, yield_strength=2.5e8)
PCR, ES = 1e4, 5e-4


def _strut_force(eps: float) -> float:
    ecr = -PCR / EA
    if eps >= ecr:
        return EA * eps
    return -PCR * (1.0 - min((ecr - eps) / ES, 1.0))


def _lam(v: float) -> float:
    ls = math.hypot(1.0, 1.0 - v)
    return (-_strut_force(-v) - 2.0 * EA * (ls / math.sqrt(2.0) - 1.0) * (1.0 - v) / ls) / 1e3


def test_arc_length_turns_at_the_corner_and_follows_the_closed_form():
    s = build_structure([[0.0, 0.0], [-1.0, 1.0], [0.0, 1.0], [1.0, 1.0]],
                        [(1, 0), (2, 0), (3, 0)], section=SEC, material=MAT,
                        supports={1: "xy", 2: "xy", 3: "xy"}, loads={0: [0.0, 1000.0]})
    law = {"buckling": "softening", "critical_load": PCR, "residual": 0.0,
           "softening_strain": ES}
    m = NonlinearModel(s, laws=build_failure_laws(s, per_member={1: law}))
    r = follow_path(m, "arc-length", steps=60, step=5e-5, monitor=1)
    v = r.displacement()
    assert v.max() > 5e-3                          # well past the corner at v = 1 mm
    assert_allclose(r.load_factors, [_lam(x) for x in v], rtol=1e-9, atol=1e-9)
    corner = [e for e in r.events if e.kind == "limit_point" and "corner" in e.detail]
    assert len(corner) == 1
    assert_allclose(v[corner[0].point], 1e-3, rtol=1e-6)
    assert_allclose(corner[0].load_factor, _lam(1e-3), rtol=1e-9)
    # the load factor falls to the corner and rises after it
    k = corner[0].point
    assert np.all(np.diff(r.load_factors[k:]) > 0)
    assert r.load_factors[k] < r.load_factors[k - 1]
