# SPDX-License-Identifier: MIT
"""Batched solves of one sparse pattern over many time steps.

The compatibility matrix B of a truss keeps its sparsity pattern along a motion; only the
values (unit vectors) change.  Small systems are solved as a stack of dense matrices
(``numpy.linalg.solve`` over the time axis); large ones as a block-diagonal sparse matrix over
a chunk of time steps, factorised once by SuperLU.  Either way there is no Python loop per
time step, and a singular step is reported by its index.

The compatibility matrix of a truss built joint by joint or bay by bay is, after a row and
column permutation, **block lower triangular** (its Dulmage–Mendelsohn fine decomposition):
a double-octahedral bay splits into two 9 × 9 blocks (the midplane nodes, then the top
nodes), a 100-bay chain into 200 of them.  :func:`block_triangular_form` finds that form
from the sparsity pattern (a maximum matching puts a non-zero on the diagonal, the strongly
connected components of the resulting dependency graph are the blocks, a topological order
of the components is the solve order), which a model's compatibility pattern keeps with
the model; :class:`CompatSolver` then keeps the stacked inverses of the small diagonal
blocks of every step and solves ``B x = b`` by forward and ``Bᵀ y = c`` by backward block
substitution, a loop over blocks with every step at once.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components, maximum_bipartite_matching

from ..linalg.factor import Factor, factor
from ..threads import contiguous_spans, parallel_map, worker_count

#: Largest system solved as a dense stack.
DENSE_LIMIT = 36
#: Steps per anchor factorisation of large systems (:class:`CompatSolver`).
ANCHOR_SPACING = 8
#: Refinement sweeps allowed before a step counts as singular.
REFINEMENT_SWEEPS = 200
#: Reciprocal condition number below which a step counts as singular.  The positions are
#: solved to 1e-12 of the truss size, so a singular (flat) position is only resolved to an
#: angle of about 1e-6: below 1e-5 the forces would be round-off magnified by 1e5 and more.
SINGULAR_RCOND = 1e-5


class SingularStep(Exception):
    """A time step whose matrix is singular; ``step`` is its index."""

    def __init__(self, step: int):
        super().__init__(step)
        self.step = step


def batched_solve(rows: np.ndarray, cols: np.ndarray, vals: np.ndarray, shape: tuple[int, int],
                  rhs: np.ndarray, check: bool = True) -> np.ndarray:
    """Solve ``A_k x_k = b_k`` for every step k; all ``A_k`` share one sparsity pattern.

    Parameters
    ----------
    rows, cols : ndarray of int, shape (nnz,)
        Pattern (duplicates are summed).
    vals : ndarray, shape (nt, nnz)
        Values per step.
    shape : (int, int)
        Square shape of each ``A_k``.
    rhs : ndarray, shape (nt, n) or (nt, n, r)
        Right-hand sides.
    check : bool
        Test every step for singularity (reciprocal condition number, dense path); skip when
        the same matrices were checked already.

    Returns
    -------
    ndarray, same shape as ``rhs``

    Raises
    ------
    SingularStep
        At the first step whose matrix is (numerically) singular.

    Examples
    --------
    >>> x = batched_solve(np.array([0, 1]), np.array([0, 1]), np.array([[2.0, 4.0]]),
    ...                   (2, 2), np.array([[2.0, 2.0]]))
    >>> x.tolist()
    [[1.0, 0.5]]
    """
    n = shape[0]
    nt = vals.shape[0]
    if n == 0:
        return np.zeros_like(rhs)
    vec = rhs.ndim == 2
    b = rhs[..., None] if vec else rhs
    if n <= DENSE_LIMIT:
        A = np.zeros((nt, n * n))
        lin = rows * n + cols
        # Duplicate-summing scatter of the same pattern for every step.
        order = np.argsort(lin, kind="stable")
        uniq, start = np.unique(lin[order], return_index=True)
        A[:, uniq] = np.add.reduceat(vals[:, order], start, axis=1)
        A = A.reshape(nt, n, n)
        if check:
            check_singular(A)
        try:
            x = np.linalg.solve(A, b)
        except np.linalg.LinAlgError:
            check_singular(A)
            raise
        return x[..., 0] if vec else x
    # Sparse, block-diagonal over chunks of steps (the pivots are always checked).
    out = np.empty_like(b)
    chunk = max(1, 200_000 // max(n, 1))
    for k0 in range(0, nt, chunk):
        k1 = min(nt, k0 + chunk)
        nk = k1 - k0
        off = (np.arange(nk) * n)[:, None]
        R = (rows[None, :] + off).ravel()
        C = (cols[None, :] + off).ravel()
        A = sp.csc_matrix((vals[k0:k1].ravel(), (R, C)), shape=(nk * n, nk * n))
        f = _step_factor(A, np.abs(vals[k0:k1]).max())
        if f is None or f.is_singular:
            # The failing pivot's column lies in the block of the singular step.
            col = None if f is None else f.smallest_pivot_column
            raise SingularStep(k0 + (0 if col is None else col // n))
        rr = b[k0:k1].reshape(nk * n, -1)
        out[k0:k1] = f.solve(rr, refine=False).reshape(nk, n, -1)
    return out[..., 0] if vec else out


def _step_factor(A: sp.csc_matrix, scale: float) -> Factor | None:
    """SuperLU factor of a compatibility matrix (or of a block-diagonal stack of them),
    marked singular under this module's configuration rule: a pivot at most
    :data:`SINGULAR_RCOND` times the largest entry ``scale``.  None when SuperLU finds the
    matrix exactly singular (it then names no pivot)."""
    f = factor(A, "general", backend="superlu", singular="flag")
    if f.smallest_pivot_column is None and f.is_singular:
        return None
    if f.smallest_pivot <= SINGULAR_RCOND * max(scale, 1e-300):
        f.is_singular = True
    return f


def check_singular(A: np.ndarray) -> None:
    """Raise :class:`SingularStep` at the first matrix of the stack ``A`` (nt, n, n) whose
    reciprocal condition number is below :data:`SINGULAR_RCOND`.

    The singular values come from the eigenvalues of AᵀA (cheaper than an SVD; the square
    root halves the attainable precision, ample for a 1e-5 threshold).
    """
    lam = np.linalg.eigvalsh(np.einsum("tji,tjk->tik", A, A))
    rc = np.sqrt(np.clip(lam[:, 0], 0.0, None) / np.maximum(lam[:, -1], 1e-300))
    bad = np.flatnonzero(~(rc >= SINGULAR_RCOND))
    if bad.size:
        raise SingularStep(int(bad[0]))


@dataclass
class BlockTriangularForm:
    """Block lower-triangular form of a square sparsity pattern (solve order).

    Attributes
    ----------
    rows, cols : list of ndarray
        Equations (rows) and unknowns (columns) of each diagonal block, in solve order: the
        equations of block k involve only its own unknowns and those of earlier blocks.
    diag : list of tuple of ndarray
        Per block, (local row, local column, index into the pattern's entries) of the
        diagonal block.
    coupling : list of tuple of ndarray
        Per block, (coupled unknowns of earlier blocks, local row, position among them, entry
        index) of the off-diagonal part.
    """

    rows: list
    cols: list
    diag: list
    coupling: list

    @property
    def n_blocks(self) -> int:
        """Number of diagonal blocks."""
        return len(self.rows)

    @property
    def max_size(self) -> int:
        """Size of the largest diagonal block."""
        return max((r.size for r in self.rows), default=0)


def block_triangular_form(rows: np.ndarray, cols: np.ndarray, n: int
                          ) -> BlockTriangularForm | None:
    """Block lower-triangular form of the n × n pattern ``(rows, cols)``, or ``None`` when the
    pattern is structurally singular (no perfect matching).

    Examples
    --------
    A lower-triangular 3 × 3 pattern splits into three 1 × 1 blocks, solved top to bottom:

    >>> f = block_triangular_form(np.array([0, 1, 1, 2, 2]), np.array([0, 0, 1, 1, 2]), 3)
    >>> [r.tolist() for r in f.rows]
    [[0], [1], [2]]
    """
    rows = np.asarray(rows, dtype=np.int64)
    cols = np.asarray(cols, dtype=np.int64)
    pat = sp.csr_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n))
    match = maximum_bipartite_matching(pat, perm_type="column")     # row i ↔ column match[i]
    if n == 0 or np.any(match < 0):
        return None
    row_of = np.empty(n, dtype=np.int64)
    row_of[match] = np.arange(n)
    # Equation i depends on unknown j, which is pinned by equation row_of[j].
    dep = sp.csr_matrix((np.ones(rows.size), (rows, row_of[cols])), shape=(n, n))
    nb, label = connected_components(dep, directed=True, connection="strong")
    # Topological order of the components: a block after every block it depends on.
    src, dst = label[rows], label[row_of[cols]]
    cross = src != dst
    edges = np.unique(np.stack([src[cross], dst[cross]], axis=1), axis=0)
    needs = [set() for _ in range(nb)]
    users = [[] for _ in range(nb)]
    for a, b in edges:
        needs[a].add(int(b))
        users[b].append(int(a))
    ready = [k for k in range(nb) if not needs[k]]
    order = []
    while ready:
        k = ready.pop()
        order.append(k)
        for a in users[k]:
            needs[a].discard(k)
            if not needs[a]:
                ready.append(a)
    position = np.empty(nb, dtype=np.int64)
    position[np.array(order, dtype=np.int64)] = np.arange(nb)
    entry_block = position[label[rows]]
    col_block = position[label[row_of[cols]]]
    by_block = np.argsort(entry_block, kind="stable")
    starts = np.searchsorted(entry_block[by_block], np.arange(nb + 1))
    block_rows, block_cols, diag, coupling = [], [], [], []
    local = np.empty(n, dtype=np.int64)
    for b in range(nb):
        er = np.sort(np.flatnonzero(position[label] == b))
        ec = match[er]
        local[er] = np.arange(er.size)
        lc = np.empty(n, dtype=np.int64)
        lc[ec] = np.arange(ec.size)
        idx = by_block[starts[b]:starts[b + 1]]
        own = col_block[idx] == b
        d = idx[own]
        diag.append((local[rows[d]], lc[cols[d]], d))
        o = idx[~own]
        ucols, pos = np.unique(cols[o], return_inverse=True)
        coupling.append((ucols, local[rows[o]], pos.reshape(-1), o))
        block_rows.append(er)
        block_cols.append(ec)
    return BlockTriangularForm(rows=block_rows, cols=block_cols, diag=diag, coupling=coupling)


#: Steps per thread below which a block substitution is not split between threads.
PARALLEL_SOLVE_MIN_STEPS = 100
#: Stacks of at least this many small matrices are inverted in worker threads (4,000 9 × 9
#: inverses take about 6 ms on one thread; a map over ready threads costs about 0.1 ms).
PARALLEL_INVERSE_MIN = 4_000


def _stacked_inverse(D: np.ndarray) -> np.ndarray:
    """``numpy.linalg.inv`` of a stack (blocks, steps, n, n), split over the steps between
    worker threads when large (LAPACK releases the GIL; results bit-identical)."""
    spans = _step_pieces(D.shape[1], D.shape[0])
    if len(spans) == 1:
        return np.linalg.inv(D)
    parts = parallel_map(np.linalg.inv, [D[:, a:b] for a, b in spans])
    return np.concatenate(parts, axis=1)


def _step_pieces(nt: int, count: int) -> list[tuple[int, int]]:
    """Contiguous pieces of ``nt`` steps, one per worker thread when the stack of ``count``
    matrices per step is large (:data:`PARALLEL_INVERSE_MIN`), else the whole range."""
    workers = worker_count()
    if workers < 2 or nt < 2 or count * nt < PARALLEL_INVERSE_MIN:
        return [(0, nt)]
    return contiguous_spans(nt, min(workers, nt))


def _rcond(A: np.ndarray, inv: np.ndarray) -> np.ndarray:
    """Reciprocal condition numbers from Frobenius norms of a stack and its inverses."""
    with np.errstate(over="ignore", invalid="ignore"):
        return 1.0 / np.sqrt(np.einsum("...ij,...ij->...", A, A)
                             * np.einsum("...ij,...ij->...", inv, inv))


class _BlockInverses:
    """Stacked inverses of the diagonal blocks of a :class:`BlockTriangularForm`, every step.

    Blocks of one size are inverted by batched LAPACK calls (a large stack split between
    worker threads: a contiguous group of whole blocks each, or a piece of the steps each when
    the blocks are fewer than the threads); a step is singular when any of its diagonal
    blocks has a reciprocal condition number (Frobenius norms) below :data:`SINGULAR_RCOND` —
    B is singular exactly when one of its diagonal blocks is.
    """

    def __init__(self, form: BlockTriangularForm, vals: np.ndarray):
        nt = vals.shape[0]
        self.form = form
        self.inv: list = [None] * form.n_blocks
        self.off: list = [None] * form.n_blocks
        sizes = np.array([r.size for r in form.rows])
        worst = np.full(nt, np.inf)
        # The stacks are filled, and their condition numbers taken, over the same pieces of
        # the steps as their inversion (in worker threads for a large stack; every step
        # is filled and tested the same in any piece).
        spans = _step_pieces(nt, form.n_blocks)
        for size in np.unique(sizes):
            ids = np.flatnonzero(sizes == size)
            D = np.empty((ids.size, nt, size * size))

            def fill(span, ids=ids, D=D, size=size):
                a, b = span
                D[:, a:b] = 0.0                     # zeroed here, in the worker threads
                for g, blk in enumerate(ids):
                    r, c, e = form.diag[blk]
                    D[g, a:b][:, r * size + c] = vals[a:b, e]
            parallel_map(fill, spans)
            D = D.reshape(ids.size, nt, size, size)
            # Many blocks of one size (a chain's): each worker thread inverts a contiguous
            # group of whole blocks and takes their condition numbers while they are in its
            # cache; the groups' inverses are kept as they are (no copy into one stack).
            groups = contiguous_spans(ids.size, len(spans)) if 1 < len(spans) <= ids.size \
                else None

            def invert(group, D=D):
                a, b = group
                inv = np.linalg.inv(D[a:b])
                return inv, np.nan_to_num(_rcond(D[a:b], inv), nan=0.0).min(axis=0)
            try:
                if groups is not None:
                    parts = parallel_map(invert, groups)
                else:
                    inv = _stacked_inverse(D)
            except np.linalg.LinAlgError:
                lam = np.linalg.eigvalsh(np.einsum("btji,btjk->btik", D, D))
                rc = np.sqrt(np.clip(lam[..., 0], 0.0, None) / np.maximum(lam[..., -1], 1e-300))
                raise SingularStep(int(np.flatnonzero((~(rc >= SINGULAR_RCOND)).any(axis=0))[0])
                                   ) from None
            if groups is not None:
                for (a, _), (part, rc) in zip(groups, parts):
                    np.fmin(worst, rc, out=worst)
                    for g, blk in enumerate(ids[a:a + part.shape[0]]):
                        self.inv[blk] = part[g]
            else:
                def condition(span, D=D, inv=inv):
                    a, b = span
                    worst[a:b] = np.fmin(worst[a:b], np.nan_to_num(
                        _rcond(D[:, a:b], inv[:, a:b]), nan=0.0).min(axis=0))
                parallel_map(condition, spans)
                for g, b in enumerate(ids):
                    self.inv[b] = inv[g]
        bad = np.flatnonzero(~(worst >= SINGULAR_RCOND))
        if bad.size:
            raise SingularStep(int(bad[0]))
        for b, (ucols, _, _, _) in enumerate(form.coupling):
            if ucols.size:
                self.off[b] = np.empty((nt, form.rows[b].size, ucols.size))

        def fill_off(span):
            a, z = span
            for b, (ucols, lr, pos, e) in enumerate(form.coupling):
                if ucols.size:
                    self.off[b][a:z] = 0.0
                    # the block's entries by their flat index in its rows (a view)
                    self.off[b].reshape(nt, -1)[a:z, lr * ucols.size + pos] = vals[a:z, e]
        parallel_map(fill_off, spans)

    def solve(self, rhs: np.ndarray, transpose: bool, steps: np.ndarray | None,
              out: np.ndarray | None = None) -> np.ndarray:
        """Forward (B x = rhs) or backward (Bᵀ x = rhs) block substitution, every step at
        once; ``steps`` maps each right-hand side to its factorised step; ``out``: an array
        shaped like ``rhs`` to write the solution into."""
        out = np.empty_like(rhs) if out is None else out
        if transpose and rhs.ndim == 3 and rhs.shape[2] > 1:
            # one right-hand side at a time: numpy's einsum is several times slower with a
            # trailing axis, and the columns' arithmetic is the same; each column's
            # contiguous copy is the backward substitution's scratch array
            for c in range(rhs.shape[2]):
                self._backward(np.ascontiguousarray(rhs[..., c]), steps, out[..., c])
            return out
        if transpose:
            self._backward(rhs.copy(), steps, out)
            return out
        f = self.form

        def pick(a):
            return a if steps is None else a[steps]

        for b in range(f.n_blocks):
            r = rhs[:, f.rows[b]]
            if self.off[b] is not None:
                r = r - np.einsum("tij,tj...->ti...", pick(self.off[b]),
                                  out[:, f.coupling[b][0]])
            out[:, f.cols[b]] = np.einsum("tij,tj...->ti...", pick(self.inv[b]), r)
        return out

    def _backward(self, c: np.ndarray, steps: np.ndarray | None, out: np.ndarray) -> None:
        """Backward block substitution Bᵀ x = c into ``out``; ``c`` is overwritten."""
        f = self.form

        def pick(a):
            return a if steps is None else a[steps]

        for b in range(f.n_blocks - 1, -1, -1):
            y = np.einsum("tji,tj...->ti...", pick(self.inv[b]), c[:, f.cols[b]])
            out[:, f.rows[b]] = y
            if self.off[b] is not None:
                c[:, f.coupling[b][0]] -= np.einsum("tij,ti...->tj...", pick(self.off[b]), y)


def _form(rows: np.ndarray, cols: np.ndarray, n: int,
          form: BlockTriangularForm | None) -> BlockTriangularForm | None:
    """``form``, or when it is not given the pattern's block-triangular form (none is needed
    when no block could be small enough)."""
    if form is not None:
        return form
    return block_triangular_form(rows, cols, n) if DENSE_LIMIT > 0 else None


def _blocks_pay(form: BlockTriangularForm | None) -> bool:
    """Whether block substitution applies: several diagonal blocks, all dense-sized."""
    return form is not None and form.n_blocks > 1 and form.max_size <= DENSE_LIMIT


def is_direct(rows: np.ndarray, cols: np.ndarray, n: int,
              form: BlockTriangularForm | None = None) -> bool:
    """Whether :class:`CompatSolver` keeps stacked inverses (no refinement) for this pattern;
    ``form``: its :func:`block_triangular_form`, when the caller keeps it."""
    return n <= DENSE_LIMIT or _blocks_pay(_form(rows, cols, n, form))


class CompatSolver:
    """Factorised compatibility matrices B_k of every step, for ``B x = b`` and ``Bᵀ y = c``.

    A pattern with a block-triangular form of more than one block, all of at most
    :data:`DENSE_LIMIT` rows, keeps the stacked inverses of its diagonal blocks (block
    substitution, :func:`block_triangular_form`).  Other small systems keep the stacked
    inverses (one batched LAPACK call; every later solve is a batched matrix–vector product);
    large ones keep SuperLU factorisations at anchor steps with refinement, used for both B
    and Bᵀ (``trans="T"``).  The velocities, the accelerations and the dynamic and static
    member forces of a motion all reuse the same factorisation.

    Parameters
    ----------
    rows, cols : ndarray of int, shape (nnz,)
        Pattern of B (no duplicates).
    vals : ndarray, shape (nt, nnz)
    n : int
        Size of each square B_k.
    form : BlockTriangularForm or None, optional
        The pattern's :func:`block_triangular_form` when the caller keeps it (a model's
        pattern does); found here when not given.

    Raises
    ------
    SingularStep
        At the first step whose reciprocal condition number (dense: Frobenius norms, which
        bound the spectral one within a factor n) or relative pivot (sparse) is below
        :data:`SINGULAR_RCOND`.
    """

    def __init__(self, rows: np.ndarray, cols: np.ndarray, vals: np.ndarray, n: int,
                 form: BlockTriangularForm | None = None):
        self.n = n
        self.nt = vals.shape[0]
        self.inverse = None
        self.block_inverses: _BlockInverses | None = None
        # whether a direct solve of many steps splits them between worker threads
        self.split = True
        if n == 0:
            return
        form = _form(rows, cols, n, form)
        if _blocks_pay(form):
            self.block_inverses = _BlockInverses(form, vals)
            return
        if n <= DENSE_LIMIT:
            A = np.zeros((self.nt, n * n))
            A[:, rows * n + cols] = vals
            A = A.reshape(self.nt, n, n)
            try:
                inv = np.linalg.inv(A)
            except np.linalg.LinAlgError:
                check_singular(A)
                raise SingularStep(0) from None          # pragma: no cover
            with np.errstate(over="ignore", invalid="ignore"):
                rc = 1.0 / (np.linalg.norm(A, axis=(1, 2)) * np.linalg.norm(inv, axis=(1, 2)))
            bad = np.flatnonzero(~(rc >= SINGULAR_RCOND))
            if bad.size:
                raise SingularStep(int(bad[0]))
            self.inverse = inv
            return
        # Large systems: SuperLU factorisations of B at anchor steps only; every step is
        # solved by refinement against its own B with the nearest anchor's factors.  B changes
        # little between neighbouring steps, so a few refinement sweeps reach round-off, at a
        # fraction of the cost of one factorisation per step.
        self.rows, self.cols, self.vals = rows, cols, vals
        self.anchors = np.unique(np.linspace(0, self.nt - 1,
                                             max(1, -(-self.nt // ANCHOR_SPACING))).round()
                                 .astype(int))
        mids = (self.anchors[1:] + self.anchors[:-1]) / 2.0
        self.owner = np.searchsorted(mids, np.arange(self.nt))
        scale = np.abs(vals).max()
        self.lus = []
        for k in self.anchors:
            f = _step_factor(sp.csc_matrix((vals[k], (rows, cols)), shape=(n, n)), scale)
            if f is None or f.is_singular:
                raise SingularStep(int(k))
            self.lus.append(f)
        # All steps' B_k as one block-diagonal CSR matrix, for the residuals.
        off = (np.arange(self.nt) * n)[:, None]
        self._block = sp.csr_matrix((vals.ravel(), ((rows[None, :] + off).ravel(),
                                                    (cols[None, :] + off).ravel())),
                                    shape=(self.nt * n, self.nt * n))
        self._block_t = self._block.T.tocsr()

    def _matvec(self, x: np.ndarray, transpose: bool) -> np.ndarray:
        """B_k x_k (or B_kᵀ x_k) for every step, vectorised over steps."""
        A = self._block_t if transpose else self._block
        return (A @ x.ravel()).reshape(x.shape)

    def _anchor_solve(self, r: np.ndarray, transpose: bool) -> np.ndarray:
        dx = np.empty_like(r)
        for j, lu in enumerate(self.lus):
            idx = np.flatnonzero(self.owner == j)
            if idx.size:
                dx[idx] = lu.solve(np.ascontiguousarray(r[idx].T), refine=False,
                                   transpose=transpose).T
        return dx

    def subset(self, k0: int, k1: int) -> "CompatSolver | None":
        """The factorisations of steps ``k0:k1`` (views, no copy); ``None`` on the anchored
        SuperLU path, whose anchors belong to the whole motion."""
        if not self.direct:
            return None
        return self._select(slice(k0, k1), len(range(k0, min(k1, self.nt))), self.split)

    def gather(self, steps: np.ndarray) -> "CompatSolver":
        """The factorisations of the steps ``steps`` (one per right-hand side of the later
        solves, gathered once): ``gather(steps).solve(rhs)`` is ``solve(rhs, steps=steps)``
        with the same numbers, for an iteration that solves with one step map many times.
        Direct paths only; its solves run in the calling thread (it is made for work
        already split between threads)."""
        if not self.direct:
            raise ValueError("gather needs a direct (stacked-inverse) solver")
        return self._select(steps, len(steps), False)

    def _select(self, index, nt: int, split: bool) -> "CompatSolver":
        """A direct solver holding the stacked factorisations ``[index]`` of ``nt`` steps."""
        out = object.__new__(CompatSolver)
        out.__dict__.update(self.__dict__)
        out.nt, out.split = nt, split
        if self.inverse is not None:
            out.inverse = self.inverse[index]
        if self.block_inverses is not None:
            bi = object.__new__(_BlockInverses)
            bi.form = self.block_inverses.form
            bi.inv = [a[index] for a in self.block_inverses.inv]
            bi.off = [None if a is None else a[index] for a in self.block_inverses.off]
            out.block_inverses = bi
        return out

    @property
    def direct(self) -> bool:
        """Whether solves are direct (stacked inverses), not anchored refinement."""
        return self.n == 0 or self.inverse is not None or self.block_inverses is not None

    def solve(self, rhs: np.ndarray, transpose: bool = False,
              approximate: bool = False, steps: np.ndarray | None = None) -> np.ndarray:
        """x with B_k x_k = rhs_k (or B_kᵀ x_k = rhs_k), rhs of shape (nt, n), or (nt, n, r)
        on the direct paths.

        ``approximate=True`` (anchored SuperLU path) returns the nearest anchor's solution
        without refinement — enough for an outer iteration that corrects itself (chord
        Newton).  ``steps`` (direct paths only) maps each row of ``rhs`` to the factorised
        step whose matrix it uses.
        """
        if self.inverse is not None:
            sub = "tji,tj...->ti..." if transpose else "tij,tj...->ti..."
            return np.einsum(sub, self.inverse if steps is None else self.inverse[steps], rhs)
        if self.block_inverses is not None:
            rhs = np.asarray(rhs, dtype=float)
            workers = (min(worker_count(), self.nt // PARALLEL_SOLVE_MIN_STEPS)
                       if self.split else 1)
            if steps is not None or workers < 2 or rhs.shape[0] != self.nt:
                return self.block_inverses.solve(rhs, transpose, steps)
            # independent steps: contiguous chunks of them in worker threads, each writing
            # its rows of the solution
            out = np.empty_like(rhs)
            parallel_map(
                lambda ab: self.subset(ab[0], ab[1]).block_inverses.solve(
                    rhs[ab[0]:ab[1]], transpose, None, out[ab[0]:ab[1]]),
                contiguous_spans(self.nt, workers))
            return out
        if self.n == 0:
            return np.zeros_like(rhs, dtype=float)
        if steps is not None:
            raise ValueError("steps needs a direct (stacked-inverse) solver")
        rhs = np.asarray(rhs, dtype=float)
        if approximate:
            return self._anchor_solve(rhs, transpose)
        x = np.zeros_like(rhs)
        r = rhs.copy()
        prev = np.full(self.nt, np.inf)
        bmax = np.abs(self.vals).max(axis=1)
        for _ in range(REFINEMENT_SWEEPS):
            x += self._anchor_solve(r, transpose)
            r = rhs - self._matvec(x, transpose)
            err = np.abs(r).max(axis=1)
            # Round-off floor of the residual: a few ulps of |B| |x| and of |rhs|.
            tol = 1e-13 * (np.abs(rhs).max(axis=1) + 4.0 * bmax * np.abs(x).max(axis=1)) + 1e-300
            if np.all(err <= tol):
                return x
            stalled = (err > tol) & (err >= 0.95 * prev)
            if np.any(stalled):
                # No contraction: B_k is (nearly) singular or far from its anchor.
                raise SingularStep(int(np.flatnonzero(stalled)[0]))
            prev = err
        raise SingularStep(int(np.flatnonzero(err > tol)[0]))
