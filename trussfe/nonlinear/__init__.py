# SPDX-License-Identifier: MIT
"""Geometrically nonlinear (post-critical) analysis: co-rotational elements, path following
with load, displacement and arc-length control, bifurcation detection, member failure laws,
progressive failure and the hand-over to finite-mechanism motion."""
