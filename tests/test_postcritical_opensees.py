"""Independent cross-check with OpenSeesPy's corotational truss (skipped when ``openseespy``
is not installed; it is an optional extra, ``pip install trussfe[peers]``)."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe._resources import mesh_path
from trussfe.io.model_file import read_model
from trussfe.nonlinear import NonlinearModel, follow_path

ops = pytest.importorskip("openseespy.opensees")


def _opensees_von_mises(step, n):
    """Two-bar truss with ``corotTruss`` under displacement control of the apex."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, -1.0, 0.0)
    ops.node(2, 0.0, 0.1)
    ops.node(3, 1.0, 0.0)
    ops.fix(1, 1, 1)
    ops.fix(3, 1, 1)
    ops.fix(2, 1, 0)
    ops.uniaxialMaterial("Elastic", 1, 1e10)
    ops.element("corotTruss", 1, 1, 2, 1e-4, 1)
    ops.element("corotTruss", 2, 2, 3, 1e-4, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, -1.0)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", 2, 2, -step)
    ops.analysis("Static")
    lam = []
    for _ in range(n):
        assert ops.analyze(1) == 0
        lam.append(ops.getLoadFactor(1))
    ops.wipe()
    return np.array(lam)


def test_von_mises_path_agrees_with_opensees_corotational_truss():
    """Displacement control in steps of 2 mm through the snap-through (v = 0 … 0.24 m): the
    load factors of trussfe and OpenSees agree to 1e-9 of the limit load at every step."""
    s = read_model(mesh_path("postcritical_von_mises.toml"))
    m = NonlinearModel(s)
    r = follow_path(m, "displacement", steps=120, step=0.002, monitor=m.dof(1, 1),
                    locate_critical=False)
    ours = r.load_factors[1:]
    theirs = _opensees_von_mises(0.002, len(ours))
    assert_allclose(-r.displacement()[1:], 0.002 * np.arange(1, len(ours) + 1), rtol=1e-12)
    assert_allclose(ours, theirs, atol=1e-9 * 381.0871904)
