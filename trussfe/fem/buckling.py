# SPDX-License-Identifier: MIT
"""Linear (eigen) buckling about the static state, and the thesis' member Euler check.

With the element axial forces ``N`` of a linear static solution under the model's loads,
the load factors λ solve

.. math:: (K + \\lambda K_g(N))\\,\\varphi = 0 ,

so ``λ`` times the applied loads is a bifurcation load.  The problem is solved as
``K_g φ = θ K φ`` with ``θ = −1/λ`` (``K`` positive definite on the free DOFs), keeping the
eigenvalues of largest ``|θ|``: the smallest ``|λ|``.  The sign is kept: ``λ < 0`` means the
structure buckles only if the loads are *reversed* (a member that is in tension under the
given loads and would be compressed by the reversed ones); it is reported as negative and
never as a buckling factor of the given loads.

``bar_model="truss"`` finds the instability of the joints only (axial bars with the string
stiffness of their axial force); ``"pinned-beam"`` (default here) subdivides every bar into
beam elements so that each member's own Euler buckling between its joints appears.

Member Euler loads (Lacy eq. 2.26 / 4.77, pinned ends) are those of
:func:`trussfe.mechanics.euler.member_euler_loads`.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError, InputError
from ..io.json_document import result_json
from ..mechanics.euler import member_euler_loads
from ..linalg.eigen import DENSE_BUCKLING_LIMIT, EigenNotConverged, buckling_pairs
from ..model.structure import Structure
from .discretisation import FEModel
from .solver import factorise
from .static import StaticResult, _largest_per_row, solve_static

log = logging.getLogger(__name__)


#: Axial forces below this fraction of the largest applied load count as "unloaded".
UNLOADED_TOLERANCE = 1e-12


@dataclass
class BucklingResult:
    """Result of :func:`solve_buckling`.

    Attributes
    ----------
    static : StaticResult
        The pre-buckling state.
    load_factors : ndarray, shape (k,)
        λ, ascending by absolute value, sign kept.
    shapes : ndarray, shape (n_dof, k)
        Buckling modes, scaled so that the largest translation component over the joints
        and the stations along the members is +1
        (:meth:`~trussfe.fem.discretisation.FEModel.largest_translations`).
    euler_load : ndarray, shape (m,)
        Member Euler loads (Lacy eq. 2.26), N.
    utilisation : ndarray, shape (m,)
        Largest compression along the member / Euler load (0 for members in tension
        everywhere): :func:`largest_compression`.
    """

    static: StaticResult
    load_factors: np.ndarray
    shapes: np.ndarray
    euler_load: np.ndarray
    utilisation: np.ndarray

    @property
    def fe(self) -> FEModel:
        """The discretisation."""
        return self.static.fe

    @property
    def structure(self) -> Structure:
        """The analysed structure."""
        return self.static.fe.structure

    @property
    def critical_load_factor(self) -> float:
        """Smallest positive load factor (``nan`` if none was found)."""
        pos = self.load_factors[self.load_factors > 0]
        return float(pos.min()) if pos.size else float("nan")

    def node_shapes(self) -> np.ndarray:
        """Buckling modes at the nodes, shape (k, n_nodes, ndof_node)."""
        return np.stack([self.fe.node_values(self.shapes[:, i])
                         for i in range(self.shapes.shape[1])])


#: Load factors computed when no count is given (fewer where fewer exist).
DEFAULT_BUCKLING_COUNT = 4


def solve_buckling(structure: Structure, count: int | None = None,
                   bar_model: str = "pinned-beam",
                   subdivisions: int | None = None, self_weight: bool = True,
                   static: StaticResult | None = None) -> BucklingResult:
    """Linear buckling load factors and modes about the static state under the model's loads.

    Parameters
    ----------
    structure : Structure
    count : int, optional
        Number of load factors (smallest |λ| first).  Default
        :data:`DEFAULT_BUCKLING_COUNT`, or every finite one when there are fewer (logged);
        an explicit count above them is refused.
    bar_model : {"pinned-beam", "truss"}
    subdivisions : int, optional
        Sub-elements per frame member (≥ 4 recommended for member buckling).
    self_weight : bool
        Include gravity in the pre-buckling state (it is then scaled by λ as well).
    static : StaticResult, optional
        A pre-computed static state to reuse.

    Returns
    -------
    BucklingResult

    Raises
    ------
    AnalysisError
        Unloaded structure (no axial force anywhere); more load factors asked for than the
        geometric stiffness has non-zero eigenvalues.
    MechanismError
        The structure cannot carry the loads.

    Examples
    --------
    A pinned–pinned column under 1 N: λ is its Euler load π²EI/L² (error 5e-4 with 4
    elements, 3e-5 with 8: Hermite elements converge as h⁴).

    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [0, 2]], [(0, 1)],
    ...                     section=Section.tube("t", 0.0254, 0.022225),
    ...                     material=Material("al", E=71e9, G=26.2e9, density=2711.5),
    ...                     supports={0: "xy", 1: "x"}, loads={1: [0.0, -1.0]})
    >>> r = solve_buckling(s, count=1, subdivisions=8)
    >>> round(float(r.load_factors[0]), 1)
    1481.2
    """
    item = structure.source or structure.name
    every = count is None                     # the default count, or every factor there is
    if every:
        count = DEFAULT_BUCKLING_COUNT
    if isinstance(count, bool) or int(count) != count or count < 1:
        raise InputError("--count", f"must be a positive integer, got {count!r}")
    count = int(count)
    if static is None:
        static = solve_static(structure, bar_model=bar_model, subdivisions=subdivisions,
                              self_weight=self_weight)
    fe = static.fe
    # the element forces of the static state as recovered, with the forces the elements carry
    # themselves subtracted (self-weight, the fixed-end forces of member loads and of imposed
    # strains)
    N = static.element_axial_force
    fscale = np.abs(static.f).max() if static.f.size else 0.0
    if fscale == 0.0 and static.reactions.size:
        # a state of moved supports alone: its reactions give the scale of its forces
        fscale = np.abs(static.reactions).max()
    if fscale == 0.0:
        raise AnalysisError(item, "the structure is unloaded: linear buckling needs [loads], "
                            "gravity or a load case to scale")
    if np.abs(N).max() <= UNLOADED_TOLERANCE * fscale:
        raise AnalysisError(item, "no member carries an axial force under the loads (they "
                            "bend the members only): linear buckling scales the axial "
                            "forces, and without them there is no buckling load")
    K = fe.stiffness()
    Kg = fe.geometric_stiffness(N)
    free = fe.free
    n = free.size
    Kff = K[free][:, free].tocsr()
    Kgff = Kg[free][:, free].tocsr()
    solve = None
    if n > DENSE_BUCKLING_LIMIT and count < n - 1:
        solve = factorise(K, free, fe=fe, item=item).solve
    try:
        mu, V = buckling_pairs(Kff, Kgff, count, solve=solve)
    except EigenNotConverged as err:
        raise AnalysisError(item, str(err)) from None
    tiny = np.abs(mu) <= 1e-12 * np.abs(mu).max()
    if np.any(tiny) or mu.size < count:
        found = int(np.sum(~tiny))
        if not every or found == 0:
            raise AnalysisError(item, f"asked for {count} load factors but only {found} "
                                f"finite ones exist (the geometric stiffness has rank {found} "
                                "on the free DOFs); use a smaller --count")
        log.info("%s: only %d finite load factors exist: all of them computed", item, found)
        mu, V = mu[~tiny], V[:, ~tiny]
    lam = 1.0 / mu
    shapes = np.zeros((fe.n_dof, V.shape[1]))
    shapes[free] = V
    shapes /= fe.largest_translations(shapes)
    pe = member_euler_loads(structure)
    util = largest_compression(static) / pe
    log.info("buckling: λ1 = %.6g (%d free DOFs)", lam[0], n)
    return BucklingResult(static=static, load_factors=lam, shapes=shapes, euler_load=pe,
                          utilisation=util)


def largest_compression(static: StaticResult) -> np.ndarray:
    """Largest compressive axial force along every member, N (0 where none), shape (m,).

    Taken over the member's stations: its ends, the nodes of its sub-elements and, for a
    member carrying member loads, the positions of its point loads (where the axial force
    jumps; the value there is the one just past the load).  Under self-weight or a load along
    a member the compression is not the midpoint force ``axial_force``: a pinned bar with an
    axial point load below its middle is compressed under the load and carries nothing at
    mid-length.  This is the compression of Lacy's check (Appendix A:
    ``max(abs(min(tension)))`` over the sections), as along a motion
    (:func:`trussfe.rigid.buckling.buckling_check`).
    """
    comp = _largest_per_row(-static.section_forces[..., 0])
    if static.loaded_stations is not None:
        members, _, forces = static.loaded_stations
        if members.size:
            comp[members] = np.fmax(comp[members],
                                    np.fmax.reduce(-forces[..., 0], axis=1))
    return np.maximum(comp, 0.0)


def buckling_json(result: BucklingResult, command: str = "buckling") -> dict:
    """The ``buckling`` JSON document (docs/json.md, ``buckling``).

    ``load_factors`` ascending by absolute value (sign kept), ``critical_load_factor`` (the
    smallest positive one, ``null`` if none), ``modes[i]`` with ``load_factor`` and ``shape``
    (node id → translations, largest component 1), and per member the static
    ``axial_force`` (at mid-length), ``euler_load`` (Lacy eq. 2.26, C = 1) and
    ``buckling_utilisation`` (largest compression along the member / Euler load).
    """
    s = result.structure
    fe = result.fe
    dim = s.dim
    shapes = result.node_shapes()
    modes = [{"load_factor": float(lam),
              "shape": {nid: shapes[i, j, :dim].tolist() for j, nid in enumerate(s.node_ids)}}
             for i, lam in enumerate(result.load_factors)]
    members = {mid: {"axial_force": float(result.static.axial_force[i]),
                     "euler_load": float(result.euler_load[i]),
                     "buckling_utilisation": float(result.utilisation[i])}
               for i, mid in enumerate(s.member_ids)}
    crit = result.critical_load_factor
    return result_json(
        command, s.name,
        bar_model=fe.bar_model,
        subdivisions=fe.subdivisions,
        n_dof=fe.n_dof,
        load_factors=result.load_factors.tolist(),
        critical_load_factor=crit if np.isfinite(crit) else None,
        modes=modes,
        members=members,
    )
