# SPDX-License-Identifier: MIT
"""Arc-length step control (trussfe.nonlinear.path): limit points in the right order, each at
a singular tangent, with the default step control; the default first step.

References: OpenSeesPy (``corotTruss`` under displacement control, computed here) for the
first limit point of the twin arch; the limit-point sequence of the twin arch followed with a
held step (max_step = step); the closed form of the von Mises truss (co-rotational bars with
engineering strain: P(v) = −2 N (h − v)/ℓ, N = EA (ℓ − L)/L).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import minimize_scalar

from trussfe.io import toml_text
from trussfe.io.model_file import parse_model
from trussfe.models.materials import ALUMINIUM, octahedral_tube
from trussfe.model.structure import build_structure
from trussfe.nonlinear.model import NonlinearModel
from trussfe.nonlinear.path import (DEFAULT_STEP_FRACTION, _inertia, _next_sign,
                                    follow_path)
from trussfe.linalg.eigen import nearest_zero_mode as critical_mode

TWIN_ARCH = """
[model]
name = "twin arch"
dimension = 2
[materials.m]
E = 1.0e10
[sections.s]
area = 1.0e-4
[nodes]
S0 = [-2.0, 0.0]
S1 = [0.0, 0.0]
S2 = [2.0, 0.0]
A = [-1.0, 0.12]
B = [1.0, 0.079]
[members]
a0 = { nodes = ["S0", "A"], section = "s", material = "m" }
a1 = { nodes = ["A", "S1"], section = "s", material = "m" }
b0 = { nodes = ["S1", "B"], section = "s", material = "m" }
b1 = { nodes = ["B", "S2"], section = "s", material = "m" }
t = { nodes = ["A", "B"], section = "s", material = "m" }
[supports]
S0 = ["x", "y"]
S1 = ["x", "y"]
S2 = ["x", "y"]
[loads]
A = [0.0, -1.0]
B = [0.0, -0.3]
"""


def _twin_arch():
    return parse_model(toml_text.loads(TWIN_ARCH), ".", "twin_arch.toml")


def _limit_points(model, res):
    """Load factors of the reported limit points and the smallest |eigenvalue| of the tangent
    there relative to the unloaded one's."""
    free = np.flatnonzero(model.free)
    w0 = abs(critical_mode(model.evaluate(np.zeros(model.ndof))["tangent"][free][:, free])[0])
    out = []
    for e in res.events:
        if e.kind == "limit_point":
            K = model.evaluate(res.path[e.point].u)["tangent"][free][:, free]
            out.append((e.load_factor, abs(critical_mode(K)[0]) / w0))
    return np.array(out)


def _run_twin(**kw):
    s = _twin_arch()
    m = NonlinearModel(s)
    res = follow_path(m, "arc-length", steps=3000, step=0.002, max_displacement=0.264,
                      monitor=m.dof(s.node_index("A"), 1), **kw)
    return m, res


@pytest.fixture(scope="module")
def twin_default():
    return _run_twin()


def test_twin_arch_limit_points_in_order_with_the_default_step_control(twin_default):
    """The default step control finds the limit points in the order of the path followed
    with a held step (626.56, −113.41, 531.47, −626.28, 626.28, −531.47, 113.41, −626.56),
    each where the tangent is singular (smallest eigenvalue below 1e-4 of the unloaded)."""
    m, res = twin_default
    held = _limit_points(*_run_twin(max_step=0.002))
    got = _limit_points(m, res)
    assert_allclose(held[:, 0], [626.56, -113.41, 531.47, -626.28, 626.28, -531.47, 113.41,
                                 -626.56], atol=0.01)
    assert got.shape == held.shape
    assert_allclose(got[:, 0], held[:, 0], rtol=1e-6)
    assert np.all(got[:, 1] < 1e-4) and np.all(held[:, 1] < 1e-4)


def _opensees_twin_arch_peak():
    """First limit load of the twin arch in OpenSees: displacement control of B (monotonic
    through the first peak) in 0.1 mm steps, the peak refined by a parabola through the
    three largest load factors."""
    ops = pytest.importorskip("openseespy.opensees")
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    s = _twin_arch()
    for i, x in enumerate(s.coords):
        ops.node(i + 1, *map(float, x))
        if s.supports[i, :2].any():
            ops.fix(i + 1, 1, 1)
    ops.uniaxialMaterial("Elastic", 1, 1.0e10)
    for j, (a, b) in enumerate(s.connectivity):
        ops.element("corotTruss", j + 1, int(a) + 1, int(b) + 1, 1.0e-4, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 0.0, -1.0)
    ops.load(5, 0.0, -0.3)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    h = 1e-4
    ops.integrator("DisplacementControl", 5, 2, -h)
    ops.analysis("Static")
    lam = []
    for _ in range(600):
        assert ops.analyze(1) == 0
        lam.append(ops.getLoadFactor(1))
        if len(lam) > 3 and lam[-1] < lam[-2] < lam[-3]:
            break
    ops.wipe()
    i = int(np.argmax(lam))
    y0, y1, y2 = lam[i - 1], lam[i], lam[i + 1]
    return y1 + (y2 - y0) ** 2 / (8.0 * (2 * y1 - y0 - y2))


def test_twin_arch_first_limit_point_agrees_with_opensees(twin_default):
    m, res = twin_default
    first = _limit_points(m, res)[0, 0]
    assert_allclose(first, _opensees_twin_arch_peak(), rtol=1e-6)


def _von_mises(load=1.0):
    """Half-span 1 m, rise 0.1 m, the 3/4-inch tube, aluminium (E = 71 GPa), apex load."""
    return build_structure([[-1.0, 0.0], [0.0, 0.1], [1.0, 0.0]], [(0, 1), (1, 2)],
                           section=octahedral_tube(), material=ALUMINIUM,
                           supports={0: "xy", 2: "xy", 1: "x"}, loads={1: [0.0, -load]})


def _von_mises_limit(EA, a=1.0, h=0.1):
    L = math.hypot(a, h)

    def P(v):
        ell = math.hypot(a, h - v)
        return 2.0 * EA * (L - ell) / L * (h - v) / ell
    r = minimize_scalar(lambda v: -P(v), bounds=(0.0, h), method="bounded",
                        options={"xatol": 1e-12})
    return P(r.x)


@pytest.mark.parametrize("load", [1.0, 1000.0])
def test_default_run_passes_the_first_limit_point_of_the_von_mises_truss(load):
    """Every setting default but the control: the run passes the limit point, located at
    the closed form's limit load (≈ 2.47 kN) to 1e-6, whatever the size of the reference
    load."""
    s = _von_mises(load)
    m = NonlinearModel(s)
    res = follow_path(m, "arc-length")
    lims = [e for e in res.events if e.kind == "limit_point"]
    assert lims, res.termination
    EA = ALUMINIUM.E * octahedral_tube().area
    assert_allclose(lims[0].load_factor * load, _von_mises_limit(EA), rtol=1e-6)


def test_default_first_step_moves_the_structure_a_fraction_of_its_size():
    s = _von_mises()
    m = NonlinearModel(s)
    res = follow_path(m, "arc-length", steps=1)
    du = np.linalg.norm(res.path[1].u - res.path[0].u)
    assert_allclose(du, DEFAULT_STEP_FRACTION * 2.0, rtol=1e-9)


def test_direction_at_a_limit_point_from_the_inertia():
    """The load increment's sign flips across a limit point (odd change of the negative
    pivots), is kept across a bifurcation and between critical points; an unknown inertia
    (None, or −1 from a factorisation that did not count) is never compared."""
    du = np.array([1.0, 0.0])
    assert _next_sign(1.0, 0, 1, True, None, du) == -1.0
    assert _next_sign(-1.0, 1, 0, True, None, du) == 1.0
    assert _next_sign(1.0, 0, 1, False, None, du) == 1.0
    assert _next_sign(1.0, 2, 2, False, np.array([-1.0, 0.0]), du) == 1.0
    assert _next_sign(1.0, None, 1, True, np.array([-1.0, 0.0]), du) == -1.0

    import scipy.sparse as sp
    from trussfe.linalg import factor
    K = sp.csr_matrix(np.diag([2.0, -1.0, 3.0]))
    assert _inertia(factor(K, "symmetric")) == 1
    # a general LU does not count negative pivots: unknown, never a count
    assert factor(K, "general").inertia is None
    assert _inertia(factor(K, "general")) is None and _inertia(None) is None


def test_unknown_inertia_is_not_reported_as_a_count():
    """Where the factorisation does not count negative pivots (inertia None) the message says
    no number of negative eigenvalues (a count of −1 would be nonsense)."""
    from trussfe.nonlinear.path import _cannot_continue
    assert "negative eigenvalue" not in _cannot_continue("load", 2.0, None)
    assert "3 negative eigenvalue(s)" in _cannot_continue("load", 2.0, 3)


@pytest.mark.parametrize("control", ["displacement", "arc-length"])
def test_a_step_past_a_stop_lands_on_it(control):
    """The von Mises truss (the closed form above): a step that passes ``max_load_factor``
    (300 N, before the limit load 381 N) or ``max_displacement`` (0.1234 m, past the limit)
    lands on it, on the closed-form path — the path went on to 308.5 N and 0.126 m, and the
    termination said the stop was reached.  (Under load control the last step is already
    cut to the stop.)"""
    import trussfe
    from trussfe._resources import mesh_path
    vm = mesh_path("postcritical_von_mises.toml")
    r = trussfe.postcritical(vm, control=control, max_load_factor=300.0, steps=400)
    assert r.load_factors[-1] == pytest.approx(300.0, rel=1e-12)
    assert r.solution.termination == "reached the maximum load factor 300"
    r = trussfe.postcritical(vm, control=control, max_displacement=0.1234, steps=400)
    apex = r.node_ids.index("apex")
    v = -r.displacement[:, apex, 1]
    assert v[-1] == pytest.approx(0.1234, rel=1e-12) and v.max() <= 0.1234 * (1 + 1e-12)
    w, L = 0.1 - v[-1], math.hypot(1.0, 0.1)
    ell = math.hypot(1.0, w)
    assert r.load_factors[-1] == pytest.approx(2 * 1e6 * w * (1 / ell - 1 / L), rel=1e-8)
