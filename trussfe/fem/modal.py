# SPDX-License-Identifier: MIT
"""Modal analysis: natural frequencies, mass-normalised mode shapes, participation factors.

The generalized eigenproblem on the free DOFs

.. math:: K \\varphi = \\omega^2 M \\varphi, \\qquad \\varphi^T M \\varphi = 1

is solved by shift-invert Lanczos (:mod:`trussfe.linalg.eigen`; ARPACK through
``scipy.sparse.linalg.eigsh`` when that does not converge without restarts) with the
factorisation of ``K − σM`` from :func:`trussfe.linalg.factor`, or densely for small models.

Mass
----
* member mass: consistent (``ρA`` with the element shape functions; a truss bar gives
  ``ρAL/6 [[2, 1], [1, 2]]`` on every translation, docs/cli.md) or lumped (``ρAL/2`` at the
  ends of every element);
* lumped nodal masses ``[masses]``;
* active members (Lacy section 2.1, 4.7; ``[active_members]``): the active base (mass
  ``m_b``, first moment ``m_b c_b`` and second moment ``I_b`` about the start node) and the
  leadscrew tube (the member's section over ``tube_length`` at the end node) are rigid
  bodies on the member's line.  Transversely they follow the rigid rotation of the member,
  ``u(s) = (1 − s/L) u_a + (s/L) u_b``, which gives the exact rigid-body mass matrix

  .. math:: M_\\perp = \\begin{bmatrix} m - 2S/L + I/L^2 & S/L - I/L^2 \\\\
            S/L - I/L^2 & I/L^2 \\end{bmatrix} \\otimes (\\mathbf 1 - e e^T)

  with ``m, S, I`` the total mass and first and second moments about the start node (the
  tube's with the rotary inertia of its sections, as in the rigid-body force model); axially
  the base moves with the start node and the tube with the end node (the member telescopes;
  :func:`trussfe.mechanics.mass.rigid_line_mass`).
  The member's own distributed FE mass is then left out so the tube is not counted twice.

Rigid-body and mechanism modes
------------------------------
When the free stiffness is singular (an unsupported structure or a mechanism) its null space
is computed first (:func:`trussfe.linalg.stiffness_null_space`, scaled tolerance 1e-10); its
dimension ``r`` is the number of zero-frequency modes.  They are reported as exactly 0 Hz with
``kind = "rigid"`` — never as tiny, meaningless frequencies — and the shift becomes
``σ = −10⁻⁶ λ_ref`` (``λ_ref`` the median of ``K_ii / M_ii``) so ``K − σM`` can be factorised.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import AnalysisError, InputError
from ..io.json_document import result_json
from ..mechanics.geometry import member_vectors, unit_vectors
from ..mechanics.active_bodies import massless_active
from ..mechanics.mass import gyration_squared, mass_per_length, rigid_line_mass, tube_moments
from ..model.structure import Structure
from .discretisation import FEModel, discretise
from .. import linalg
from ..linalg import FreeBlock, free_submatrix, stiffness_null_space
from ..linalg.eigen import shift_invert_lanczos
from ..threads import parallel_map

log = logging.getLogger(__name__)

#: Number of modes computed when none is asked for (fewer when the model has fewer
#: mass-carrying free DOFs: then all of them).
DEFAULT_MODE_COUNT = 6

#: Free-DOF count up to which the eigenproblem is solved densely.
DENSE_MODAL_LIMIT = 600

MASS_KINDS = ("consistent", "lumped")

#: Largest relative eigen-residual ‖K φ − ω² M φ‖ / (ω² ‖M φ‖) of a mode taken as resolved.
#: Chains measured (see :func:`solve_modes`): residual 4e-3 → frequencies right to ~2e-5;
#: 0.39 → the two equal bending frequencies split by 1.3 %; 36–116 → f₁ set by round-off.
RESOLVED_RESIDUAL = 0.1

# ---------------------------------------------------------------------- mass
def _active_members(structure: Structure) -> list:
    return list(structure.extensions.get("active_members", []) or [])


def active_member_mass(fe: FEModel) -> sp.csr_matrix:
    """Mass matrix of the active members' rigid bodies (base and leadscrew tube).

    See the module docstring for the model.  Returns an ``(n_dof, n_dof)`` matrix acting on
    the translations of the active members' end nodes (zero without active members).
    """
    s = fe.structure
    acts = _active_members(s)
    dim = s.dim
    if not acts:
        return sp.csr_matrix((fe.n_dof, fe.n_dof))
    idx = np.array([a.member for a in acts], dtype=np.int64)
    e, L = unit_vectors(member_vectors(s.coords, s.connectivity[idx]))   # (act, dim), (act,)
    mb = np.array([a.base_mass for a in acts])
    Sb = mb * np.array([a.base_cg for a in acts])
    Ib = np.array([a.base_inertia for a in acts])
    lt = np.array([a.tube_length for a in acts])
    # the leadscrew tube, from L − l_t to L, with its sections' rotary inertia
    mt, St, It = tube_moments(mass_per_length(s.density, s.area)[idx], L - lt, L,
                              gyration_squared(s.Iy, s.Iz, s.area)[idx])
    blk = rigid_line_mass(L, e, mb + mt, Sb + St, Ib + It, mb, mt)   # (act, end, dim, end, dim)
    nodes = s.connectivity[idx]                                  # (act, 2)
    dofs = fe.node_dofs[nodes][:, :, :dim]                       # (act, end, dim)
    rows = np.broadcast_to(dofs[:, :, :, None, None], blk.shape)
    cols = np.broadcast_to(dofs[:, None, None, :, :], blk.shape)
    return sp.csr_matrix((blk.ravel(), (rows.ravel(), cols.ravel())),
                         shape=(fe.n_dof, fe.n_dof))


def mass_matrix(fe: FEModel, kind: str = "consistent", include_nodal_masses: bool = True,
                include_active_members: bool = True) -> sp.csr_matrix:
    """Global mass matrix: members, nodal masses and active members.

    Parameters
    ----------
    fe : FEModel
    kind : {"consistent", "lumped"}
        Member mass (see :meth:`FEModel.mass`).
    include_nodal_masses : bool
    include_active_members : bool
        Replace the distributed mass of active members by their base-and-tube rigid bodies
        (:func:`active_member_mass`).

    Returns
    -------
    scipy.sparse.csr_matrix, shape (n_dof, n_dof)
    """
    if kind not in MASS_KINDS:
        raise InputError("--mass", f"unknown mass kind {kind!r}; use consistent or lumped")
    acts = _active_members(fe.structure) if include_active_members else []
    if not acts:
        return fe.mass(kind=kind, include_nodal_masses=include_nodal_masses)
    # The same topology with massless active members: DOF numbering is identical.
    fe0 = discretise(massless_active(fe.structure), bar_model=fe.bar_model, subdivisions=fe.subdivisions)
    return (fe0.mass(kind=kind, include_nodal_masses=include_nodal_masses)
            + active_member_mass(fe)).tocsr()


def rigid_translations(fe: FEModel) -> np.ndarray:
    """Influence vectors of a unit rigid translation along each global axis.

    Returns
    -------
    ndarray, shape (n_dof, dim)
        Column ``d``: 1 on the node translations along axis ``d``, the components
        ``R[member, :, d]`` on interior-point translations (they are in member axes), 0 on
        rotations.  ``K @ r = 0`` for every column (a rigid translation strains nothing).
    """
    dim = fe.ndim
    r = np.zeros((fe.n_dof, dim))
    for d in range(dim):
        r[fe.node_dofs[:, d], d] = 1.0
    if fe.interior_dofs.size:
        R = fe.rotation[fe.interior_member]                       # (pt, dim_local, dim)
        for i in range(dim):
            dofs = fe.interior_dofs[:, i]
            ok = dofs >= 0
            r[dofs[ok], :] = R[ok, i, :]
    return r


# ---------------------------------------------------------------------- result
@dataclass
class ModalResult:
    """Result of :func:`solve_modes`.

    Attributes
    ----------
    fe : FEModel
    mass_kind : str
    eigenvalues : ndarray, shape (k,)
        ω² in rad²/s² (exactly 0 for rigid-body / mechanism modes).
    frequencies_hz : ndarray, shape (k,)
        ω / 2π, ascending.
    shapes : ndarray, shape (n_dof, k)
        Mass-normalised mode shapes (φᵀ M φ = 1), global DOF vector, 0 on fixed DOFs.
    rigid_modes : int
        Number of zero-frequency (rigid-body or mechanism) modes of the free structure; the
        first ``min(rigid_modes, k)`` modes are of that kind.
    participation : ndarray, shape (k, dim)
        Γ_id = φ_iᵀ M r_d (kg^½).
    effective_mass : ndarray, shape (k, dim)
        Γ_id², kg.
    total_mass : ndarray, shape (dim,)
        r_dᵀ M r_d over the free DOFs: the sum of the effective masses over all modes.
    residuals : ndarray, shape (k,)
        Relative eigen-residual ‖K φ − ω² M φ‖ / (ω² ‖M φ‖) of each elastic mode, computed in
        double precision (0 for rigid modes); above :data:`RESOLVED_RESIDUAL` the mode is not
        resolved (see :func:`solve_modes`).
    """

    fe: FEModel
    mass_kind: str
    eigenvalues: np.ndarray
    frequencies_hz: np.ndarray
    shapes: np.ndarray
    rigid_modes: int
    participation: np.ndarray
    effective_mass: np.ndarray
    total_mass: np.ndarray
    residuals: np.ndarray | None = None

    @property
    def structure(self) -> Structure:
        """The analysed structure."""
        return self.fe.structure

    @property
    def count(self) -> int:
        """Number of modes computed."""
        return self.frequencies_hz.size

    @property
    def kinds(self) -> list[str]:
        """``"rigid"`` (zero frequency) or ``"elastic"`` for each mode."""
        return ["rigid" if i < self.rigid_modes else "elastic" for i in range(self.count)]

    def node_shapes(self) -> np.ndarray:
        """Mode shapes at the nodes, shape (k, n_nodes, ndof_node) (translations then
        rotations, 0 where a node has no rotation DOF)."""
        return np.stack([self.fe.node_values(self.shapes[:, i]) for i in range(self.count)]) \
            if self.count else np.zeros((0,) + self.fe.node_dofs.shape)


# ---------------------------------------------------------------------- eigen-solver
def generalized_eigen(Kff: sp.spmatrix, Mff: sp.spmatrix, count: int, sigma: float = 0.0,
                      factor=None, item: str = "structure") -> tuple[np.ndarray, np.ndarray]:
    """The ``count`` eigenpairs of ``K φ = λ M φ`` nearest ``sigma`` (from above).

    Parameters
    ----------
    Kff, Mff : sparse matrices, shape (n, n)
        Symmetric; ``K − σM`` must be non-singular; ``M`` positive semi-definite.
    count : int
    sigma : float
        Shift (≤ the lowest eigenvalue wanted).
    factor : trussfe.linalg.Factor, optional
        A factorisation of ``K − σM`` to reuse.

    Returns
    -------
    eigenvalues : ndarray, shape (count,)
        Ascending.
    vectors : ndarray, shape (n, count)
        M-orthonormal.

    Notes
    -----
    Dense path (n ≤ :data:`DENSE_MODAL_LIMIT`): ``M φ = μ (K − σM) φ`` with ``K − σM``
    positive definite, so massless DOFs (μ = 0, infinite λ) are harmless; λ = σ + 1/μ.

    Examples
    --------
    Two unit masses on springs 2, −1 (fixed–free–free chain of stiffness 1):

    >>> import scipy.sparse as sp
    >>> K = sp.csr_matrix([[2.0, -1.0], [-1.0, 1.0]])
    >>> lam, V = generalized_eigen(K, sp.identity(2, format="csr"), 2)
    >>> np.round(lam, 6).tolist()          # (3 ∓ √5)/2
    [0.381966, 2.618034]
    """
    n = Kff.shape[0]

    def shifted():
        # K_ff may be a FreeBlock (products only): its sparse matrix is formed when needed
        return (Kff.tocsr() - sigma * Mff).tocsr() if sigma else Kff.tocsr()

    if n <= DENSE_MODAL_LIMIT or count >= n - 1:
        A = shifted()
        Ad, Md = A.toarray(), Mff.toarray()
        try:
            mu, V = sla.eigh(Md, Ad, subset_by_index=[n - count, n - 1])
        except np.linalg.LinAlgError:
            raise AnalysisError(item, "K − σM is not positive definite; the model has "
                                "massless mechanisms (a DOF with neither stiffness nor mass)") \
                from None
        mu, V = mu[::-1], V[:, ::-1]
        if np.any(mu <= 1e-14 * max(mu.max(), 1e-300)):
            # 1/ω² of the higher modes below the round-off of the lowest's: their frequencies
            # lie more than 1e7 times above it (a DOF without mass, or a nearly flat truss
            # whose one stiffness is nearly zero beside the others)
            ok = int(np.sum(mu > 1e-14 * mu.max()))
            raise AnalysisError(item, f"only the lowest {ok} of {count} modes are resolved: "
                                "the others are massless or lie more than 1e7 times above "
                                "them in frequency, beyond what double precision resolves "
                                f"beside them (a nearly flat or nearly mechanism geometry); "
                                f"use --count {ok}")
        lam = sigma + 1.0 / mu
    else:
        if factor is None:
            factor = linalg.factor(shifted(), "spd")
        fac = factor

        def solve(b):
            # the Lanczos iteration needs no refined solves: the factor's plain solve
            return fac.solve(b, refine=False)

        found = shift_invert_lanczos(solve, Mff, count, sigma=sigma)
        if found is not None:
            lam, V = found
        else:                       # not converged without restarts: ARPACK restarts
            op = spla.LinearOperator((n, n), matvec=solve, dtype=float)
            ncv = min(n - 1, max(2 * count + 1, count + 20))
            # ARPACK's shift-invert mode needs only M products and the solves
            lam, V = spla.eigsh(Kff.tocsr(), k=count, M=Mff, sigma=sigma, which="LM",
                                OPinv=op, ncv=ncv)
            order = np.argsort(lam)
            lam, V = lam[order], V[:, order]
    # M-normalise (eigsh returns M-orthonormal vectors already; dense returns A-normalised)
    mnorm = np.sqrt(np.einsum("ik,ik->k", V, Mff @ V))
    V = V / mnorm
    # a reproducible sign: the largest component positive
    big = np.argmax(np.abs(V), axis=0)
    V = V * np.sign(V[big, np.arange(V.shape[1])])
    return lam, V


#: Stages of :func:`solve_modes` reported to a progress callback.
MODAL_STAGES = 5


def _stage(progress, k: int) -> None:
    if progress is not None:
        progress(k, MODAL_STAGES)


def solve_modes(structure: Structure, count: int | None = None, mass: str = "consistent",
                bar_model: str = "truss", subdivisions: int | None = None,
                fe: FEModel | None = None, include_nodal_masses: bool = True,
                check_resolution: bool = True,
                progress: Callable[[int, int], None] | None = None) -> ModalResult:
    """Natural frequencies and mass-normalised mode shapes of a structure.

    Parameters
    ----------
    structure : Structure
    count : int, optional
        Number of modes (lowest first).  Default :data:`DEFAULT_MODE_COUNT`, or every mode
        when the model has fewer free DOFs that carry mass (logged); an explicit count larger
        than that is an error.
    mass : {"consistent", "lumped"}
        Member mass model.
    bar_model : {"truss", "pinned-beam"}
        ``pinned-beam`` subdivides every bar so its own bending modes appear.
    subdivisions : int, optional
        Sub-elements per frame member.
    fe : FEModel, optional
        A discretisation to reuse.
    include_nodal_masses : bool
    check_resolution : bool
        Refuse modes that double precision cannot resolve (default); with False they are
        returned with their residuals for inspection.
    progress : callable, optional
        Called as ``progress(done, total)`` between the stages (discretisation, matrices and
        factorisation, zero-frequency modes, eigen-solution, residuals).

    Returns
    -------
    ModalResult

    Raises
    ------
    InputError
        ``count`` not a positive integer, unknown mass kind.
    AnalysisError
        More modes asked for than the model has mass-carrying free DOFs; no free DOF; a mode
        whose eigen-residual exceeds :data:`RESOLVED_RESIDUAL` (``check_resolution``).

    Notes
    -----
    Resolution.  For an extremely slender structure the lowest ω² can be 10⁻¹⁸ of the
    largest ``K_ii / M_ii``: rounding the stiffness entries to double precision then changes
    it by more than its own size, and no solver can recover it.  The check computes each mode's
    residual ``‖K φ − ω² M φ‖ / (ω² ‖M φ‖)``; in double precision it cannot be smaller than
    about ε·max(K_ii/M_ii)/ω², so a large residual says the matrices do not determine the
    mode.  Measured on chains of double-octahedral bays (benchmarks/bench_modal.py): residual
    5e-7 at 100 bays, 4e-3 at 1,000 (frequencies agree with OpenSeesPy to 2e-5 and follow the
    cantilever's f ∝ L⁻² to 1e-4), 0.39 at 3,000 (the two equal bending frequencies split by
    1.3 %), 36–116 at 10,000 (f₁ from 35 % below to 2.5 % above the L⁻² extrapolation as the
    rounding of the member unit vectors changes: f₁ follows round-off).

    Examples
    --------
    A fixed–fixed steel bar in 1-D tension–compression, one element per half (two bars):
    the truss model with lumped mass gives ω² = 2EA/(m_node L) exactly.

    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [1, 0], [2, 0]], [(0, 1), (1, 2)],
    ...                     section=Section("a", 1e-4),
    ...                     material=Material("s", E=2e11, G=8e10, density=7850.0),
    ...                     supports={0: "xy", 1: "y", 2: "xy"})
    >>> r = solve_modes(s, count=1, mass="lumped")
    >>> bool(np.isclose(r.eigenvalues[0], 2 * 2e11 * 1e-4 / (7850.0 * 1e-4 * 1.0)))
    True
    """
    item = structure.source or structure.name
    every = count is None               # the default count, or every mode there is
    if every:
        count = DEFAULT_MODE_COUNT
    if isinstance(count, bool) or int(count) != count or count < 1:
        raise InputError("--count", f"must be a positive integer, got {count!r}")
    count = int(count)
    if fe is None:
        fe = discretise(structure, bar_model=bar_model, subdivisions=subdivisions)
    n = fe.free.size
    if n == 0:
        raise AnalysisError(item, "every DOF is supported: there is nothing to vibrate")
    dense = n <= DENSE_MODAL_LIMIT or count >= n - 1
    _stage(progress, 1)
    Kff, fac, Mff = _free_matrices(fe, mass, include_nodal_masses, dense)
    _stage(progress, 2)
    count = _check_mass(Mff, count, fe, mass, item, every)
    rigid, sigma, factor, keep = _zero_frequency_modes(Kff, Mff, fac, item)
    _stage(progress, 3)
    if keep is None:
        lam, V = generalized_eigen(Kff, Mff, count, sigma=sigma, factor=factor, item=item)
    else:
        # massless mechanisms: one DOF of each held, which fixes only their arbitrary part
        lam, Vk = generalized_eigen(_restrict(Kff, keep), _restrict(Mff, keep), count,
                                    sigma=sigma, item=item)
        V = np.zeros((n, Vk.shape[1]))
        V[keep] = Vk
    _stage(progress, 4)
    lam = _clean_eigenvalues(lam, min(rigid, count), Kff, Mff, item)
    residuals = eigen_residuals(Kff, Mff, lam, V, min(rigid, count))
    _stage(progress, 5)
    if check_resolution:
        _check_resolution(residuals, lam, Kff, Mff, item)
    shapes = np.zeros((fe.n_dof, count))
    shapes[fe.free] = V
    gamma, total = _participation(fe, Mff, V)
    freq = np.sqrt(lam) / (2.0 * np.pi)
    log.info("modes: %d of %d free DOFs, f1 = %.6g Hz", count, n, freq[0])
    return ModalResult(fe=fe, mass_kind=mass, eigenvalues=lam, frequencies_hz=freq,
                       shapes=shapes, rigid_modes=rigid, participation=gamma,
                       effective_mass=gamma**2, total_mass=total, residuals=residuals)


def _free_matrices(fe: FEModel, mass: str, include_nodal_masses: bool, dense: bool):
    """K_ff, its factor and M_ff, the first two made while M is assembled (two worker
    threads, :mod:`trussfe.threads`).

    The factor is None on the dense path and when a DOF has no stiffness (a mechanism: its
    null space comes next, :func:`_zero_frequency_modes`).  A long, narrow structure gets the
    banded factor of K_ff straight from K's free rows and columns, and K_ff stays an operator
    (:class:`~trussfe.linalg.FreeBlock`) formed only if a later step needs it.
    """
    free = fe.free
    n = free.size

    def stiffness_and_factor():
        K = fe.stiffness(copy=False)                 # read only
        block = FreeBlock(K, free)
        if dense or np.any(block.diagonal() <= 0):
            return (free_submatrix(K, free) if n < fe.n_dof else K.copy()), None
        fac = linalg.factor(block, "spd", singular="flag")
        if fac.backend in ("banded", "banded-lu"):
            return block, fac
        return (block.tocsr() if n < fe.n_dof else K.copy()), fac

    def mass_ff():
        return free_submatrix(mass_matrix(fe, mass, include_nodal_masses=include_nodal_masses),
                              free)

    (Kff, fac), Mff = parallel_map(lambda task: task(), [stiffness_and_factor, mass_ff])
    return Kff, fac, Mff


def _check_mass(Mff, count: int, fe: FEModel, mass: str, item: str, every: bool = False) -> int:
    """The number of modes to compute: ``count``, or every mode there is when the default
    count (``every``) exceeds the mass-carrying DOFs; refuse a model without mass, or an
    explicit count above the mass-carrying DOFs."""
    n_mass = int(np.count_nonzero(Mff.diagonal() > 0))
    if n_mass == 0:
        raise AnalysisError(item, "the structure has no mass: give members a density or "
                            "nodes a [masses] entry")
    if count > n_mass and every:
        log.info("%s: the model has only %d free DOFs that carry mass: all %d modes computed",
                 item, n_mass, n_mass)
        count = n_mass
    if count > n_mass:
        raise AnalysisError(item, f"asked for {count} modes but the model has only {n_mass} "
                            f"free DOFs that carry mass ({fe.free.size} free DOFs in all, "
                            f"{mass} mass, {fe.bar_model} bar model); use --count {n_mass} "
                            "or fewer")
    return count


#: Mass of a unit null-space vector, relative to the largest diagonal mass, below which the
#: mechanism carries no mass (:func:`_zero_frequency_modes`).
MASSLESS_TOLERANCE = 1e-10


def _restrict(A, keep: np.ndarray) -> sp.csr_matrix:
    """The rows and columns ``keep`` of a free-DOF matrix (sparse or FreeBlock)."""
    A = A if sp.issparse(A) else A.tocsr()
    return A.tocsr()[keep][:, keep].tocsr()


def _zero_frequency_modes(Kff, Mff, fac, item: str):
    """Number of zero-frequency (rigid-body and mechanism) modes, the shift and the factor for
    the eigen-solution, and the free DOFs to keep.

    A regular K_ff has none: shift 0 and its factor.  Otherwise the null space of K_ff
    (:func:`trussfe.linalg.stiffness_null_space`) is split by the mass it carries.  Its
    directions with mass are the zero-frequency modes (``r`` of them).  Its massless
    directions (in the null spaces of K and M both: the twist of a beam between ball joints
    under lumped mass, which puts no mass on rotations) are no modes at all: they make
    ``K − σM`` singular for every σ, and counting them as zero-frequency modes would report
    the lowest elastic modes as 0 Hz.  An eigenvector is determined only up to such a
    direction, so one DOF of each (pivoted QR of the massless basis) is held: the finite
    eigenpairs are unchanged and their vectors come out with zero there.  The shift
    ``σ = −10⁻⁶ λ_ref`` (``λ_ref`` the median of ``K_ii / M_ii``) then makes ``K − σM``
    factorisable (see the module notes).

    Returns
    -------
    rigid : int
    sigma : float
    factor : Factor or None
        The factor of K_ff to reuse (None: :func:`generalized_eigen` factorises ``K − σM``).
    keep : ndarray of bool, shape (n,), or None
        The free DOFs to solve on (None: all of them).
    """
    if fac is not None and not fac.is_singular:    # regular: no mechanism
        return 0, 0.0, fac, None
    null = stiffness_null_space(Kff)
    if not null.shape[1]:
        return 0, 0.0, None, None
    basis = sla.qr(null, mode="economic")[0]                  # orthonormal
    w, W = sla.eigh(basis.T @ (Mff @ basis))
    massive = w > MASSLESS_TOLERANCE * max(float(Mff.diagonal().max()), 1e-300)
    rigid = int(massive.sum())
    keep = None
    if not massive.all():
        massless = basis @ W[:, ~massive]
        pivots = sla.qr(massless.T, pivoting=True, mode="r")[1][: massless.shape[1]]
        keep = np.ones(null.shape[0], dtype=bool)
        keep[pivots] = False
        log.info("%s: %d massless mechanism(s) (no mass in the null space of the "
                 "stiffness): not modes; a DOF of each held", item, int((~massive).sum()))
        Kff, Mff = _restrict(Kff, keep), _restrict(Mff, keep)
    if not rigid:
        return 0, 0.0, None, keep
    kd, md = Kff.diagonal(), Mff.diagonal()
    ok = (kd > 0) & (md > 0)
    lam_ref = float(np.median(kd[ok] / md[ok])) if np.any(ok) else 1.0
    # the command's table says so too: a note for --verbose, not a warning
    log.info("%s: %d zero-frequency (rigid-body or mechanism) mode%s", item, rigid,
                "s" if rigid != 1 else "")
    return rigid, -1e-6 * lam_ref, None, keep


def _clean_eigenvalues(lam: np.ndarray, nz: int, Kff, Mff, item: str) -> np.ndarray:
    """The ``nz`` zero-frequency modes exactly 0; a negative eigenvalue of the elastic modes
    refused (K is positive semi-definite, so it is round-off: the lowest eigenvalues are below
    what double precision resolves for this stiffness)."""
    lam[:nz] = 0.0
    lam = np.maximum(lam, 0.0) if nz else lam
    if np.any(lam < 0):
        kd_max = float(Kff.diagonal().max())
        raise AnalysisError(item, f"the lowest eigenvalue came out negative (ω² = "
                            f"{lam.min():.3g} rad²/s², against a largest K_ii/M_ii of "
                            f"{kd_max / max(float(Mff.diagonal().max()), 1e-300):.3g}): the "
                            "stiffness is too ill-conditioned for double precision (an "
                            "extremely slender structure or a near-mechanism), so its lowest "
                            "frequencies cannot be resolved; shorten the model or add supports")
    return lam


def eigen_residuals(Kff, Mff, lam: np.ndarray, V: np.ndarray, nz: int = 0) -> np.ndarray:
    """Relative eigen-residuals ``‖K φ − ω² M φ‖ / (ω² ‖M φ‖)`` of the modes (the first ``nz``,
    zero-frequency modes: 0; a mode with ``ω² ‖M φ‖ = 0``: inf) — see :func:`solve_modes`,
    Notes."""
    count = lam.size
    MV = Mff @ V
    R = Kff @ V - MV * lam
    denom = lam * np.linalg.norm(MV, axis=0)
    residuals = np.zeros(count)
    el = np.arange(count) >= nz
    residuals[el] = np.linalg.norm(R[:, el], axis=0) / np.where(denom[el] > 0, denom[el], np.inf)
    if el.any() and not np.all(denom[el] > 0):
        residuals[el & ~(denom > 0)] = np.inf
    return residuals


def _check_resolution(residuals: np.ndarray, lam: np.ndarray, Kff, Mff, item: str) -> None:
    """Refuse modes whose eigen-residual exceeds :data:`RESOLVED_RESIDUAL`."""
    bad = residuals > RESOLVED_RESIDUAL
    if not np.any(bad):
        return
    md = Mff.diagonal()
    kmax = float(np.max(Kff.diagonal() / np.where(md > 0, md, np.inf)))
    raise AnalysisError(item, f"{int(bad.sum())} of the {lam.size} lowest modes cannot be "
                        "resolved in double precision (eigen-residual up to "
                        f"{residuals.max():.3g}; ω² = {lam[bad].min():.3g} rad²/s² is "
                        f"{lam[bad].min() / kmax:.1e} of the largest K_ii/M_ii): the "
                        "structure is too slender or too close to a mechanism for its "
                        "lowest frequencies to be computed; shorten the model or add supports")


def _participation(fe: FEModel, Mff, V: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Participation factors ``Γ = Vᵀ M r`` (mode, axis) of the mass-normalised modes and the
    total mass ``rᵀ M r`` per axis, ``r`` the rigid translations of the free DOFs."""
    r = rigid_translations(fe)[fe.free]                             # (n_free, dim)
    Mr = Mff @ r
    return V.T @ Mr, np.einsum("id,id->d", r, Mr)



def modes_json(result: ModalResult, command: str = "modes") -> dict:
    """The ``modes`` JSON document (docs/json.md, ``modes``).

    Besides ``frequencies_hz`` and ``modes[i].frequency_hz`` / ``shape`` (node id →
    mass-normalised translations, m·kg^-½), it gives ``rigid_modes`` (number of zero-frequency
    modes), each mode's ``kind`` ("rigid" or "elastic"), ``participation`` and
    ``effective_mass`` per axis, and ``total_mass`` per axis.
    """
    fe = result.fe
    s = fe.structure
    dim = s.dim
    axes = ("x", "y", "z")[:dim]
    shapes = result.node_shapes()
    modes = []
    for i in range(result.count):
        modes.append({
            "frequency_hz": float(result.frequencies_hz[i]),
            "kind": result.kinds[i],
            "participation": dict(zip(axes, result.participation[i].tolist())),
            "effective_mass": dict(zip(axes, result.effective_mass[i].tolist())),
            "shape": {nid: shapes[i, j, :dim].tolist() for j, nid in enumerate(s.node_ids)},
        })
    return result_json(
        command, s.name,
        bar_model=fe.bar_model,
        subdivisions=fe.subdivisions,
        mass=result.mass_kind,
        n_dof=fe.n_dof,
        n_free_dof=int(fe.free.size),
        rigid_modes=int(result.rigid_modes),
        frequencies_hz=result.frequencies_hz.tolist(),
        total_mass=dict(zip(axes, result.total_mass.tolist())),
        modes=modes,
    )
