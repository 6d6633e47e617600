# SPDX-License-Identifier: MIT
"""A mesh model's per-member properties come out the same whether the structure groups its
members itself or takes the grouping the mesh reader hands it (gmsh physical tags)."""
from __future__ import annotations

import meshio
import numpy as np
from numpy.testing import assert_array_equal

from trussfe import read_model
from trussfe.model.structure import Structure


def test_cell_set_properties(tmp_path):
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1.0]])
    lines = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [1, 4], [2, 4], [3, 4]])
    tags = np.array([1, 1, 1, 1, 2, 2, 2, 2])                    # gmsh physical groups
    mesh = meshio.Mesh(pts, [("line", lines)],
                       cell_data={"gmsh:physical": [tags], "gmsh:geometrical": [tags]})
    meshio.write(tmp_path / "m.msh", mesh, file_format="gmsh22", binary=False)
    (tmp_path / "m.toml").write_text("""
[model]
mesh = "m.msh"
[materials.al]
E = 7.0e10
density = 2700.0
[materials.st]
E = 2.0e11
density = 7850.0
[sections.thin]
area = 1.0e-4
[sections.thick]
area = 4.0e-4
[groups.1]
section = "thin"
material = "al"
[groups.2]
section = "thick"
material = "st"
[supports]
0 = ["x", "y", "z"]
""")
    s = read_model(tmp_path / "m.toml")
    # the same lists without the reader's grouping: Structure groups by object identity
    plain = Structure(name="p", dim=3, node_ids=s.node_ids, coords=s.coords,
                      member_ids=s.member_ids, connectivity=s.connectivity,
                      sections=list(s.sections), materials=list(s.materials),
                      is_beam=s.is_beam, releases=s.releases, supports=s.supports,
                      loads=s.loads, masses=s.masses, gravity=s.gravity)
    want_area = np.r_[np.full(4, 1e-4), np.full(4, 4e-4)]        # from the TOML above
    want_E = np.r_[np.full(4, 7e10), np.full(4, 2e11)]
    assert_array_equal(s.area, want_area)
    assert_array_equal(s.E, want_E)
    for attr in ("area", "Iy", "E", "G", "density"):
        assert_array_equal(getattr(s, attr), getattr(plain, attr))
