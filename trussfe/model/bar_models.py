# SPDX-License-Identifier: MIT
"""How a pin-jointed bar is discretised, and how finely frame members are subdivided.

One definition for every analysis: the linear FE core (:mod:`trussfe.fem`), the transient
elastic analysis and the co-rotational post-critical analysis (:mod:`trussfe.nonlinear`).

``"truss"``
    a bar is one axial two-node element (never subdivided);
``"pinned-beam"``
    a bar is a beam member with both end moments released, subdivided like a frame member, so
    that it can buckle by bending between its joints.

Members of type ``beam`` are frame members in both models.
"""
from __future__ import annotations

#: The bar models, in the order the command line lists them.
BAR_MODELS = ("truss", "pinned-beam")

#: Default number of sub-elements of a frame member (beams and pinned-beam bars) of the linear
#: analyses (static, modal, buckling, transient).  Four cubic (Hermite) elements give the
#: midspan moment of a uniformly loaded pinned member exactly at the nodes and deflections to
#: round-off; truss bars are never subdivided.
DEFAULT_FRAME_SUBDIVISIONS = 4

#: Default number of co-rotational beam elements per frame member of the post-critical
#: analysis.  A co-rotational element is straight with a cubic deflection *in its own
#: rotated frame*: large bending deflections (an elastica, a buckled column followed far into
#: its post-buckling branch) need the member's curvature resolved by more elements than the
#: linear analyses' four, and the post-critical validation cases' numbers are stated for 8.
DEFAULT_POSTCRITICAL_SUBDIVISIONS = 8
