# SPDX-License-Identifier: MIT
"""Comparison of a trussfe static result with a PyNite model analysed beside it (the
cross-checks of the member-load tests)."""
import pytest

#: PyNite's displacement and reaction attributes, in trussfe's DOF order.
DISPLACEMENTS = ("DX", "DY", "DZ", "RX", "RY", "RZ")
REACTIONS = ("RxnFX", "RxnFY", "RxnFZ", "RxnMX", "RxnMY", "RxnMZ")


def assert_nodes_match_pynite(result, model, combo, moving, supported):
    """The displacements of the nodes ``moving`` and the reactions of the nodes
    ``supported`` of a 3-D static ``result`` equal those of the PyNite ``model`` under its
    load combination ``combo`` (relative 1e-7; absolute 1e-13 m and 1e-5 N)."""
    s = result.structure
    for n in moving:
        theirs = [getattr(model.nodes[n], c)[combo] for c in DISPLACEMENTS]
        assert result.displacements[s.node_index(n)] == pytest.approx(theirs, rel=1e-7,
                                                                      abs=1e-13)
    for n in supported:
        theirs = [getattr(model.nodes[n], c)[combo] for c in REACTIONS]
        assert result.reactions[s.node_index(n)] == pytest.approx(theirs, rel=1e-7, abs=1e-5)
