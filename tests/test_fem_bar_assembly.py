# SPDX-License-Identifier: MIT
"""The fast assembly of truss bars (scikit-fem reference element scaled per bar, node-block
sparse pattern) equals the general path ``Tᵀ X_local T`` over the exploded local-axis mesh
to round-off (1e-12 relative), for every matrix and vector a bar contributes to.

The general path is the independent computation here: it assembles every bar with
scikit-fem on its own local axis and rotates it through the sparse transformation ``T``
(docs/fem.md), and is itself checked against closed-form
element matrices in ``tests/test_fem_local_matrices.py``.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.fem import discretise
from trussfe.fem.discretisation import reference_bar
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.models import double_octahedral_chain

MAT = Material("al", E=7.1e10, G=2.62e10, density=2711.5)
SEC = Section("s", area=3.1e-4, Iy=2.2e-8, Iz=4.7e-8, J=5.5e-8, c=0.02)
ROUND_OFF = 1e-12


def _mixed_3d():
    """Bars and beams sharing joints, some axis-aligned (exact zeros in e eᵀ), one released
    beam end, gravity: every group and DOF kind present."""
    rng = np.random.default_rng(3)
    x = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0.8], [1.3, 0.4, 0.6]],
                 float) + 0.01 * rng.standard_normal((6, 3))
    x[1] = [1.0, 0.0, 0.0]                       # member 0 along global x exactly
    members = [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 4), (2, 4), (3, 4), (4, 5), (1, 5)]
    beam = np.zeros(len(members), bool)
    beam[[1, 8]] = True
    s = build_structure(x, members, section=SEC, material=MAT, is_beam=beam,
                        supports={0: "xyz", 3: "xyz", 2: "z"}, loads={4: [1.0, -2.0, -3.0]},
                        masses={5: 2.5}, gravity=[0.0, 0.0, -9.81])
    return s.with_member_data(releases={8: [False, True]})


def _truss_2d():
    x = np.array([[0, 0], [1, 0], [2, 0], [0.5, 0.7], [1.5, 0.9]], float)
    members = [(0, 1), (1, 2), (0, 3), (3, 1), (1, 4), (4, 2), (3, 4)]
    return build_structure(x, members, section=SEC, material=MAT, supports={0: "xy", 2: "y"},
                           loads={3: [0.0, -5.0]}, gravity=[0.0, -9.81])


CASES = {"mixed 3-D": (_mixed_3d, "truss"), "2-D truss": (_truss_2d, "truss"),
         "chain of 3 bays": (lambda: double_octahedral_chain(3), "truss"),
         "mixed 3-D pinned-beam": (_mixed_3d, "pinned-beam")}


def _general(fe, local):
    """Σ_g Tᵀ X_local(g) T through the exploded scikit-fem meshes."""
    out = sp.csr_matrix((fe.n_dof, fe.n_dof))
    for g in fe.groups:
        out = out + g.T.T @ local(g) @ g.T
    return out.toarray()


def _close(got, want):
    got = got.toarray() if sp.issparse(got) else np.asarray(got)
    assert_allclose(got, want, rtol=0, atol=ROUND_OFF * np.abs(want).max())


@pytest.mark.parametrize("case", CASES)
def test_matrices_equal_general_path(case):
    build, bar_model = CASES[case]
    fe = discretise(build(), bar_model)
    _close(fe.stiffness(), _general(fe, fe.local_stiffness))
    _close(fe.mass(include_nodal_masses=False), _general(fe, fe.local_mass))
    N = np.linspace(-3e3, 2e3, fe.n_elements)
    _close(fe.geometric_stiffness(N), _general(fe, lambda g: fe.local_geometric_stiffness(g, N)))


@pytest.mark.parametrize("case", CASES)
def test_vectors_equal_general_path(case):
    build, bar_model = CASES[case]
    s = build()
    fe = discretise(s, bar_model)
    f = fe.load_vector()
    want = np.zeros(fe.n_dof)
    for g in fe.groups:
        want += g.T.T @ fe.local_self_weight(g, s.gravity)
    want[fe.node_dofs[:, : s.dim]] += s.masses[:, None] * s.gravity[None, :]
    want += fe.load_vector(self_weight=False)
    _close(f, want)
    u = np.random.default_rng(0).standard_normal(fe.n_dof)
    got = fe.element_forces(u)
    ref = np.zeros_like(got)
    for g, fl in zip(fe.groups, fe.element_self_weight_local()):
        fel = g.S.T @ (fe.local_stiffness(g) @ (g.T @ u) - fl)
        comp = fel.reshape(g.elements.size, 2, g.ncomp)
        ref[g.elements, :, : s.dim] = comp[:, :, : s.dim]
        if g.kind == "frame":
            if s.dim == 2:
                ref[g.elements, :, 5] = comp[:, :, 2]
            else:
                ref[g.elements, :, 3:] = comp[:, :, 3:]
    _close(got, ref)


def test_lumped_mass_is_half_each_end():
    """Lumped bar mass: ρAL/2 on each end's translations (docs/cli.md, ``--bar-model``)."""
    s = _truss_2d()
    fe = discretise(s)
    d = fe.mass("lumped").diagonal()
    half = 0.5 * MAT.density * SEC.area * s.lengths()
    want = np.zeros(s.n_nodes)
    np.add.at(want, s.connectivity[:, 0], half)
    np.add.at(want, s.connectivity[:, 1], half)
    assert_allclose(d.reshape(-1, 2), np.repeat(want[:, None], 2, axis=1), rtol=1e-14)


def test_reference_bar_is_the_p1_element():
    """Analytic P1 bar on [0, 1]: ∫u'v' = [[1,-1],[-1,1]], ∫uv = [[2,1],[1,2]]/6, ∫v = ½."""
    ref = reference_bar()
    assert_allclose(ref["stiffness"], [[1, -1], [-1, 1]], atol=1e-14)
    assert_allclose(ref["mass"], np.array([[2, 1], [1, 2]]) / 6, atol=1e-14)
    assert_allclose(ref["load"], [0.5, 0.5], atol=1e-14)


def test_duplicate_bars_are_summed():
    """Two bars on one node pair (built in code; the file reader refuses them) add up:
    the pair is twice as stiff as one bar, EA/L·e eᵀ each (analytic)."""
    x = np.array([[0.0, 0.0], [0.6, 0.8]])
    one = discretise(build_structure(x, [(0, 1)], section=SEC, material=MAT)).stiffness()
    two = discretise(build_structure(x, [(0, 1), (1, 0)], section=SEC, material=MAT)).stiffness()
    _close(two, 2 * one.toarray())
    e = np.array([0.6, 0.8])
    assert_allclose(one.toarray()[:2, :2], MAT.E * SEC.area * np.outer(e, e), rtol=1e-14)


def test_free_submatrix_equals_scipy_indexing():
    """free_submatrix(K, free) is scipy's K[free][:, free] (independent implementation),
    including fixed DOFs at both ends and in the middle of the numbering."""
    from trussfe.linalg import free_submatrix

    fe = discretise(double_octahedral_chain(4))
    K = fe.stiffness()
    rng = np.random.default_rng(5)
    fixed = np.r_[0, 1, rng.choice(fe.n_dof, 10, replace=False), fe.n_dof - 1]
    free = np.setdiff1d(np.arange(fe.n_dof), fixed)
    got = free_submatrix(K, free)
    assert_allclose(got.toarray(), K[free][:, free].toarray(), rtol=0, atol=0)
    assert got.has_sorted_indices


def test_large_chain_mechanism_still_detected():
    """A 300-bay chain (5,400 free DOFs: the banded path) is statically determinate
    (Lacy ch. 4: 18 members, 6 nodes per bay); without one member it is a mechanism.  Round-off
    keeps its pivots above the singularity tests of every backend (banded LU, SuperLU,
    PARDISO: measured), so the residual check of solve_static must catch it."""
    from trussfe.errors import MechanismError
    from trussfe.fem.static import solve_static

    s = double_octahedral_chain(300)
    keep = np.ones(s.n_members, bool)
    keep[18 * 150 + 3] = False                     # one member in the middle bay
    for backend in ("auto", "superlu"):
        with pytest.raises(MechanismError) as err:
            solve_static(s.subset_members(keep), backend=backend)
        assert err.value.mechanisms >= 1
    ok = solve_static(s)
    assert ok.backend in ("banded", "banded-lu") and ok.residual < 1e-8
