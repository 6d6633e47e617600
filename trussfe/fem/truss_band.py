# SPDX-License-Identifier: MIT
"""The banded stiffness of a pin-jointed truss straight from its bars, and K·u bar by bar.

For a model of truss bars only (one element per member, no frames), the static solve does
not need the global sparse K: the free-DOF stiffness goes from the bars' ``EA/L · e eᵀ``
blocks directly into LAPACK band storage, and the products K·u of the iterative refinement,
the residual and the reactions are the bars' internal forces assembled at the nodes,

.. math:: (K u)_a = \\sum_{e \\ni a} \\mp \\frac{EA}{L} e\\,e^T (u_b - u_a),

the same stiffness as :meth:`FEModel.stiffness` (the reference element of
:func:`~trussfe.fem.discretisation.reference_bar` is ``[[1, −1], [−1, 1]]``).  On a chain of
100,000 bays this skips the sparse matrix of 27 million entries, its extraction and its
reordering: the memory the model touches, which is what costs time on a virtual machine.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..linalg.banded import NATURAL_BANDWIDTH_OK, SummedBandLayout
from ..linalg.sparse import FreeBlock
from .discretisation import FEModel, node_diagonal_blocks, reference_bar


def is_plain_truss(fe: FEModel) -> bool:
    """True when every member is one two-node bar (the ``truss`` model without beams) and
    no spring adds to the bars' stiffness."""
    ref = reference_bar()["stiffness"]
    # K = Bᵀ diag(EA/L) B holds for the P1 bar's [[1, −1], [−1, 1]]
    return (len(fe.groups) == 1 and fe.groups[0].kind == "bar"
            and fe.spring_stiffness is None
            and fe.n_elements == fe.structure.n_members
            and bool(np.allclose(ref, [[1.0, -1.0], [-1.0, 1.0]], rtol=1e-14, atol=0.0)))


def internal_forces(fe: FEModel, u: np.ndarray) -> np.ndarray:
    """``K @ u`` of a plain truss (:func:`is_plain_truss`) as ``Bᵀ (k · B u)``
    (:meth:`FEModel.bar_elongation`): the bars' axial forces from their elongations,
    assembled at the nodes.

    Parameters
    ----------
    fe : FEModel
    u : ndarray, shape (n_dof,) or (n_dof, r)

    Returns
    -------
    ndarray, same shape as ``u``
    """
    B, k = fe.bar_elongation(fe.groups[0])
    u = np.asarray(u, dtype=float)
    N = B @ u
    N *= k if u.ndim == 1 else k[:, None]
    return B.T @ N


class TrussStiffness(FreeBlock):
    """K_ff of a plain truss as an operator, from its bars: products (:func:`internal_forces`),
    the diagonal, and the sparse matrix only when a caller asks for it.

    Examples
    --------
    >>> from trussfe.models import double_octahedral_chain
    >>> from trussfe.fem import discretise
    >>> fe = discretise(double_octahedral_chain(3), "truss")
    >>> op, K = TrussStiffness(fe), fe.stiffness()[fe.free][:, fe.free]
    >>> x = np.linspace(0.0, 1.0, fe.free.size)
    >>> bool(np.allclose(op @ x, K @ x)), bool(np.allclose(op.diagonal(), K.diagonal()))
    (True, True)
    """

    def __init__(self, fe: FEModel):
        super().__init__(None, fe.free, n_dof=fe.n_dof)
        self.fe = fe

    def _product(self, full: np.ndarray) -> np.ndarray:
        return internal_forces(self.fe, full)

    def _matrix(self) -> sp.csr_matrix:
        return self.fe.stiffness(copy=False)

    def diagonal(self) -> np.ndarray:
        """``K_ii`` of the free DOFs: Σ over the bars at the node of ``EA/L · e_j²``."""
        B, k = self.fe.bar_elongation(self.fe.groups[0])
        return (B.multiply(B).T @ k)[self.free]


#: Bars looked at by :func:`_width_lower_bound` (evenly spread): enough to meet the wide
#: bars of a lattice, few enough to cost nothing on a chain that passes (0.1 ms instead of
#: 6 ms for all 180,000 bars of 10,000 bays).
WIDTH_SAMPLE = 4096


def _width_lower_bound(ndof: np.ndarray, ends: np.ndarray, coords: np.ndarray) -> int:
    """A lower bound on the half-bandwidth of K_ff in the free-DOF numbering ``ndof`` (node,
    component; −1 = fixed) from one entry of each of :data:`WIDTH_SAMPLE` bars spread over
    the model: the (c, c) entry of a bar's block, with c its largest direction component, is
    ``EA/L · e_c² ≠ 0``, so it is stored whenever both of its DOFs are free (any subset of
    the entries bounds the largest from below)."""
    if ends.shape[0] == 0:
        return 0
    ends = ends[:: max(1, ends.shape[0] // WIDTH_SAMPLE)]
    d = np.abs(coords[ends[:, 1]] - coords[ends[:, 0]])
    c = np.argmax(d, axis=1)
    a, b = ndof[ends[:, 0], c], ndof[ends[:, 1], c]
    both = (a >= 0) & (b >= 0)
    return int(np.abs(a[both] - b[both]).max()) if np.any(both) else 0


def truss_band_layout(fe: FEModel, max_bandwidth: int) -> SummedBandLayout | None:
    """The band layout of K_ff of a plain truss from its bars, or None when the DOF order is
    not narrow (half-bandwidth above :data:`~trussfe.linalg.banded.NATURAL_BANDWIDTH_OK` or
    ``max_bandwidth``: the general path then reorders the sparse K_ff).

    The ordering is the DOF numbering restricted to the free DOFs, reversed when that puts the
    DOFs coupled to a support towards the end (as :func:`~trussfe.linalg.banded.band_layout`).
    Entries: the upper half of every node's diagonal block (Σ of its bars' blocks) and one
    off-diagonal block per bar, each entry moved to the upper triangle (K is symmetric).
    """
    s = fe.structure
    dim = fe.ndim
    n_nodes = s.n_nodes
    free = fe.free
    nfree = free.size
    it = np.int32 if fe.n_dof < 2**31 else np.int64
    new = np.full(fe.n_dof, -1, dtype=it)
    new[free] = np.arange(nfree, dtype=it)
    ndof = new[fe.node_dofs[:, :dim]]                          # (node, dim), −1 = fixed
    ends = s.connectivity
    if _width_lower_bound(ndof, ends, s.coords[:, :dim]) > min(NATURAL_BANDWIDTH_OK,
                                                               max_bandwidth):
        return None                 # not narrow: skip gathering the bars' blocks
    ref = reference_bar()["stiffness"]
    iu, ju = np.triu_indices(dim)
    nd = n_nodes * iu.size
    m = ends.shape[0]
    E = nd + m * dim * dim
    data = np.empty(E)
    # the off-diagonal blocks straight into their place in the entry array
    g = fe.groups[0]
    mem, _, _, L = fe._bar_geometry(g)
    blocks = data[nd:].reshape(m, dim * dim)
    blocks[:] = fe.bar_blocks(g, (s.E * s.area)[mem] / L).reshape(m, dim * dim)
    # upper half of the node blocks
    data[:nd].reshape(n_nodes, iu.size)[:] = node_diagonal_blocks(
        n_nodes, ends, ref, blocks[:, iu * dim + ju])
    blocks *= ref[0, 1]                                        # the off-diagonal blocks
    A, B = ndof[ends[:, 0]], ndof[ends[:, 1]]                  # (bar, dim)
    row = np.empty(E, dtype=it)
    col = np.empty(E, dtype=it)
    np.minimum(ndof[:, iu], ndof[:, ju], out=row[:nd].reshape(n_nodes, -1))
    np.maximum(ndof[:, iu], ndof[:, ju], out=col[:nd].reshape(n_nodes, -1))
    np.minimum(A[:, :, None], B[:, None, :], out=row[nd:].reshape(-1, dim, dim))
    np.maximum(A[:, :, None], B[:, None, :], out=col[nd:].reshape(-1, dim, dim))
    del blocks
    nonzero = data != 0.0
    kept = row >= 0                                            # both DOFs free
    width = col - row
    width[~(kept & nonzero)] = 0
    bw = int(width.max()) if E else 0
    del width
    if bw > min(NATURAL_BANDWIDTH_OK, max_bandwidth):
        return None
    # DOFs coupled to a support: a nonzero entry between a free and a fixed DOF
    anchored = np.zeros(nfree, dtype=bool)
    anchored[col[~kept & nonzero & (col >= 0)]] = True
    reverse = bool(np.any(anchored)) and np.mean(np.flatnonzero(anchored)) < 0.5 * (nfree - 1)
    # eliminate a cantilever from its free end (see trussfe.linalg.banded.band_layout)
    perm = np.arange(nfree, dtype=np.int64)
    if reverse:
        perm = perm[::-1].copy()
    return SummedBandLayout(perm, bw, row, col, data, reverse)
