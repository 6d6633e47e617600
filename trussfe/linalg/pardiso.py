# SPDX-License-Identifier: MIT
"""Intel MKL PARDISO through :mod:`pypardiso` (optional, x86-64 Linux).

An order of magnitude faster than SuperLU on large 3-D lattices (195k DOF: 0.2 s against 26 s
on this kind of machine).  Symmetric matrices are factorised as ``LDLᵀ`` with Bunch–Kaufman
pivoting (PARDISO matrix type −2) on their upper triangle, about half the work of the general
LU (195k-DOF space grid: 2.6 s against 4.5 s); PARDISO then reports the inertia.  Pivots it
had to perturb say the matrix is numerically singular.

``pypardiso`` looks for the MKL library every time a solver is made (0.7 s per factorisation
on this kind of machine when it walks the Python prefix).  Here the library is located once,
in the prefix's ``lib`` directory first, and new solvers share the loaded library: nothing is
written to the process environment.

Two factorisations:

* :func:`cholesky` — ``LLᵀ`` of a matrix expected positive definite (matrix type 2), with
  the settings given explicitly (``iparm(1) = 1``: without it PARDISO ignores every other
  setting and uses its defaults): MKL's parallel nested-dissection ordering (``iparm(2) =
  3``, both cores for METIS), its two-level parallel factorisation (``iparm(24) = 1``: 2.9 s
  against 3.2 s on a 10^6-DOF grid), no PARDISO refinement (:class:`~trussfe.linalg.factor.Factor`
  refines and records the residual), and the pivots returned (``iparm(56) = 1``,
  ``pardiso_getdiag``) so that the one singularity policy of
  :mod:`trussfe.linalg.tolerance` applies.  On a 195k-DOF space grid it factorises in
  about the time of the ``LDLᵀ`` below (0.9 s in a quiet minute: ordering 0.57 s, numerical
  factorisation 0.35 s; 22.6 million entries in L, 8 GFlop), and its solves take 0.025 s
  against 0.13 s.  A pivot that is not positive stops it: the caller then takes
  :func:`factorise`.
  Given the points of the unknowns, it factorises in their geometric nested-dissection
  order (:mod:`trussfe.linalg.ordering`, ``iparm(5) = 1``): 0.06 s of ordering and 0.15 s of
  analysis instead of 0.6 s for MKL's ordering and analysis at 180 × 180.
* :func:`factorise` — Bunch–Kaufman ``LDLᵀ`` (matrix type −2) or LU (type 11) with
  PARDISO's default settings, which reports the inertia and the pivots it had to perturb.

The memory PARDISO holds for a factorisation is released when its solve function is
garbage-collected (the factor of a 10^6-DOF grid is ~1.5 GB).
"""
from __future__ import annotations

import copy
import ctypes
import glob
import importlib.util
import os
import sys
import weakref
from functools import lru_cache

import numpy as np
import scipy.sparse as sp

from .ordering import nested_dissection


@lru_cache(maxsize=1)
def _solver_class():
    """pypardiso's ``PyPardisoSolver`` class, or None when pypardiso is not installed.

    Its module is loaded on its own: importing the package would make a solver at import
    time, and so search the whole prefix for MKL (0.7–3 s) unless the environment names the
    library, which library code does not set.
    """
    try:
        spec = importlib.util.find_spec("pypardiso")
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    path = os.path.join(list(spec.submodule_search_locations)[0], "pardiso_wrapper.py")
    try:
        mspec = importlib.util.spec_from_file_location("_trussfe_pypardiso_wrapper", path)
        module = importlib.util.module_from_spec(mspec)
        mspec.loader.exec_module(module)
        return module.PyPardisoSolver
    except Exception:          # not this layout of pypardiso, or its imports failing
        return None


@lru_cache(maxsize=1)
def _template():
    """A PyPardisoSolver bound to MKL, made once; None when PARDISO cannot be loaded."""
    cls = _solver_class()
    if cls is None:
        return None
    path = os.environ.get("PYPARDISO_MKL_RT")          # a library the user names
    if not path:
        # pip puts MKL directly in <prefix>/lib: look there before walking the whole tree
        direct = sorted(glob.glob(f"{sys.prefix}/lib/libmkl_rt.so*"), key=len)
        path = direct[0] if direct else None
    try:
        if path is None:
            return cls()                                # pypardiso's own (slow) search
        # the constructor would search again: set the solver up around the located library
        solver = object.__new__(cls)
        solver.__dict__.update(_fresh_state(ctypes.CDLL(path)))
        return solver
    except Exception:          # MKL failing to load
        return None


def _fresh_state(lib) -> dict:
    """The attributes of a new PyPardisoSolver around the loaded MKL library ``lib`` (as its
    constructor sets them)."""
    fn = lib.pardiso
    pt = (ctypes.c_int64, np.int64) if ctypes.sizeof(ctypes.c_void_p) == 8 else \
        (ctypes.c_int32, np.int32)
    i32 = ctypes.POINTER(ctypes.c_int32)
    fn.argtypes = [ctypes.POINTER(pt[0]), i32, i32, i32, i32, i32, ctypes.POINTER(None), i32,
                   i32, i32, i32, i32, i32, ctypes.POINTER(None), ctypes.POINTER(None), i32]
    fn.restype = None
    return {"libmkl": lib, "_mkl_pardiso": fn, "_pt_type": pt,
            "pt": np.zeros(64, dtype=pt[1]), "iparm": np.zeros(64, dtype=np.int32),
            "perm": np.zeros(0, dtype=np.int32), "mtype": 11, "phase": 13, "msglvl": False,
            "factorized_A": sp.csr_matrix((0, 0)), "size_limit_storage": 5e7,
            "_solve_transposed": False}


def available() -> bool:
    """True when :mod:`pypardiso` can be imported and finds MKL."""
    return _template() is not None


def new_solver(mtype: int):
    """A fresh PyPardisoSolver of matrix type ``mtype`` sharing the located MKL library."""
    t = _template()
    if t is None:
        raise RuntimeError("PARDISO is not available")
    s = copy.copy(t)
    s.pt = np.zeros_like(t.pt)
    s.iparm = np.zeros_like(t.iparm)
    s.perm = np.zeros(0, dtype=np.int32)
    s.factorized_A = sp.csr_matrix((0, 0))
    s.mtype = mtype
    return s


def factorise(A: sp.csr_matrix, symmetric: bool):
    """PARDISO factorisation of ``A``.

    Returns
    -------
    solve : callable
        ``solve(b)`` for ``b`` of shape (n,) or (n, k).
    negative : int or None
        Number of negative pivots (symmetric matrices only; None otherwise).
    perturbed : int
        Number of perturbed pivots: > 0 means numerically singular.

    Raises
    ------
    ValueError
        pypardiso refuses the matrix (an empty row or column: singular).
    """
    A = A.sorted_indices() if not A.has_sorted_indices else A
    if symmetric:
        M = sp.triu(A, format="csr")
        M.sort_indices()
        solver = new_solver(-2)                 # real symmetric indefinite, LDLᵀ
    else:
        M = A
        solver = new_solver(11)
    # iparm(1) = 0: PARDISO's default settings (METIS ordering, Bunch–Kaufman pivoting with
    # perturbation of pivots below 1e-8 for −2, 1e-13 for 11), which the inertia counts of
    # trussfe.linalg.rank rely on
    solver.factorize(M)
    perturbed = int(solver.get_iparm(14))       # iparm(14), 1-based: perturbed pivots
    negative = None
    if symmetric and perturbed == 0:
        pos, neg = int(solver.get_iparm(22)), int(solver.get_iparm(23))
        negative = neg if pos + neg == A.shape[0] else None
    if perturbed:
        solver.free_memory(everything=True)
        return None, negative, perturbed
    handle = _Handle(solver)

    def solve(b):
        return handle.solver.solve(M, b)

    return solve, negative, perturbed


class _Handle:
    """A PARDISO solver whose internal memory is released with the handle."""

    def __init__(self, solver):
        self.solver = solver
        weakref.finalize(self, _release, solver)


def _release(solver) -> None:
    try:
        solver.free_memory(everything=True)
    except Exception:          # interpreter shutting down, MKL already unloaded
        pass


def _getdiag(solver, n: int) -> np.ndarray | None:
    """The pivots of the factorisation (``pardiso_getdiag``; needs ``iparm(56) = 1``), or
    None when this MKL does not provide them."""
    fn = getattr(solver.libmkl, "pardiso_getdiag", None)
    if fn is None:
        return None
    df = np.zeros(n)
    da = np.zeros(n)
    err = ctypes.c_int32(0)
    fn(solver.pt.ctypes.data_as(ctypes.c_void_p), df.ctypes.data_as(ctypes.c_void_p),
       da.ctypes.data_as(ctypes.c_void_p), ctypes.byref(ctypes.c_int32(1)), ctypes.byref(err))
    return df if err.value == 0 else None


class NotPositiveDefinite(ValueError):
    """PARDISO's Cholesky factorisation met a pivot that is not positive."""


def _upper(A: sp.csr_matrix):
    """The upper triangle of a CSR matrix with sorted indices as zero-based int32 CSR arrays
    (``indptr``, ``indices``, ``data``), in one vectorised pass (scipy's ``triu`` goes through
    COO and back: with pypardiso's one-based copies 0.13 s against 0.09 s for the 14 million
    entries of a 10^6-DOF grid, and pypardiso copies the indices again at every solve)."""
    n = A.shape[0]
    counts = np.diff(A.indptr)
    row = np.repeat(np.arange(n, dtype=A.indices.dtype), counts)
    keep = A.indices >= row
    del row
    kept = np.zeros(A.nnz + 1, dtype=np.int64)
    np.cumsum(keep, out=kept[1:])
    indptr = kept[A.indptr].astype(np.int32)
    return indptr, A.indices[keep].astype(np.int32, copy=False), A.data[keep]


def _call(solver, phase: int, n: int, data, ia, ja, b: np.ndarray) -> np.ndarray:
    """One PARDISO call on zero-based int32 CSR arrays (``iparm(35) = 1``), without
    pypardiso's per-call copies of the index arrays; ``b`` Fortran-ordered (n, k)."""
    x = np.zeros_like(b)
    err = ctypes.c_int32(0)
    i32 = ctypes.POINTER(ctypes.c_int32)
    f64 = ctypes.POINTER(ctypes.c_double)
    one = ctypes.c_int32(1)
    solver._mkl_pardiso(
        solver.pt.ctypes.data_as(ctypes.POINTER(solver._pt_type[0])), ctypes.byref(one),
        ctypes.byref(one), ctypes.byref(ctypes.c_int32(solver.mtype)),
        ctypes.byref(ctypes.c_int32(phase)), ctypes.byref(ctypes.c_int32(n)),
        data.ctypes.data_as(f64), ia.ctypes.data_as(i32), ja.ctypes.data_as(i32),
        solver.perm.ctypes.data_as(i32), ctypes.byref(ctypes.c_int32(b.shape[1])),
        solver.iparm.ctypes.data_as(i32), ctypes.byref(ctypes.c_int32(0)),
        b.ctypes.data_as(f64), x.ctypes.data_as(f64), ctypes.byref(err))
    if err.value == -4:
        raise NotPositiveDefinite("a pivot that is not positive")
    if err.value != 0:
        raise RuntimeError(f"PARDISO error {err.value}")
    return x


def cholesky(A: sp.csr_matrix, points=None):
    """PARDISO ``LLᵀ`` (matrix type 2) of a symmetric matrix expected positive definite.

    Parameters
    ----------
    A : scipy.sparse.csr_matrix
    points : trussfe.linalg.ordering.Points, optional
        Where the unknowns sit: PARDISO then factorises in the geometric nested-dissection
        order of :func:`trussfe.linalg.ordering.nested_dissection` (``iparm(5) = 1``)
        instead of ordering the matrix itself, unless that ordering declines.

    Returns
    -------
    solve : callable
        ``solve(b)`` for ``b`` of shape (n,) or (n, k).
    pivots : ndarray or None
        The ``LDLᵀ`` pivots (squares of the Cholesky factor's diagonal), None when MKL does
        not return them.
    ordering : str
        ``"geometric"`` (the nested dissection of ``points``) or ``"pardiso"`` (PARDISO's
        own).

    Raises
    ------
    NotPositiveDefinite
        A pivot is zero or negative (PARDISO error −4): singular or indefinite.
    ValueError
        An empty row or column.
    """
    A = A.sorted_indices() if not A.has_sorted_indices else A
    n = A.shape[0]
    if not np.diff(A.indptr).all():
        raise ValueError("Matrix A is singular, because it contains empty row(s)")
    ia, ja, data = _upper(A)
    data = np.ascontiguousarray(data, dtype=float)
    perm = None
    if points is not None:
        perm = nested_dissection(ia, ja, points)
    solver = new_solver(2)
    solver.set_iparm(1, 1)          # the settings below are used (else all defaults)
    solver.set_iparm(2, 3)          # MKL's parallel nested dissection (METIS)
    if perm is not None:            # the geometric order instead
        solver.perm = perm.astype(np.int32)
        solver.set_iparm(5, 1)
    solver.set_iparm(8, 0)          # no PARDISO refinement: Factor.solve refines
    solver.set_iparm(24, 1)         # two-level parallel factorisation (−8 % on the grids)
    solver.set_iparm(35, 1)         # zero-based indices: the arrays go in as they are
    solver.set_iparm(56, 1)         # keep the pivots for pardiso_getdiag
    handle = _Handle(solver)
    _call(solver, 12, n, data, ia, ja, np.zeros((n, 1), order="F"))   # analyse, factorise
    pivots = _getdiag(solver, n)

    def solve(b):
        b = np.asarray(b, dtype=float)
        rhs = np.asfortranarray(b.reshape(n, -1))
        x = _call(handle.solver, 33, n, data, ia, ja, rhs)
        return x.reshape(b.shape)

    return solve, pivots, "pardiso" if perm is None else "geometric"
