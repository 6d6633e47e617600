# SPDX-License-Identifier: MIT
"""Input and output at the edge: model files, JSON, VTK."""
