# SPDX-License-Identifier: MIT
"""Finite elements with scikit-fem: truss and Euler–Bernoulli frame members on local axes."""
