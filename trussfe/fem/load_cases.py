# SPDX-License-Identifier: MIT
"""Load cases, combinations and their envelope: one factorisation, many right-hand sides.

Every case of a model (:mod:`trussfe.model.load_cases`) becomes a load vector and, where it
moves supports, a vector of prescribed displacements (:func:`case_load`); the stiffness is
factorised once and all cases are solved together (:func:`solve_load_cases`).  The analysis is
linear, so a combination's displacements, reactions and section forces are the factored sums
of its cases' (its von Mises stresses are those of the summed section forces), and the
envelope is the largest and smallest value of each member force, stress and reaction over the
combinations, with the combination that gives it (:class:`Envelope`).

Imposed strains (temperature, initial strain, length error) enter as the axial fixed-end
forces of :func:`trussfe.mechanics.imposed_strain.axial_fixed_end_force`: their equivalent
joint loads go into the load vector, and the fixed-end force itself into the member forces
recovered from the displacements (:meth:`FEModel.element_forces` subtracts the loads carried
by the elements).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

from ..errors import InputError
from ..mechanics.imposed_strain import axial_fixed_end_force, imposed_strain
from ..model.load_cases import Combination, LoadCase, LoadCases, model_load_cases
from ..model.structure import DOF_NAMES, Structure
from .discretisation import FEModel, discretise
from .member_loads import MemberLoadVectors, member_load_vector
from .static import (SECTION_FORCE_NAMES, LinearSystem, StaticResult, active_member_weight,
                     reacting_nodes, static_json)


@dataclass
class CaseLoad:
    """What one load case applies to a discretisation.

    Attributes
    ----------
    f : ndarray, shape (n_dof,)
        Global load vector: nodal loads, self-weight, the joint loads equivalent to the
        fixed-end forces of imposed strains and member loads.
    f_local : list of ndarray
        Per element group, the loads carried by the elements in the local field space
        (:meth:`FEModel.element_forces` subtracts them from ``K_local u``).
    u_prescribed : ndarray, shape (n_dof,), optional
        Prescribed displacements of the fixed DOFs (None: the supports do not move).
    member_loads : MemberLoadVectors, optional
        The case's loads along members (None: none), included in ``f`` and ``f_local``.
    applied : tuple of MemberLoad
        Those loads as given: the case's own and, with gravity, the weight of its active
        frame members (:func:`~trussfe.fem.static.active_member_weight`).
    """

    f: np.ndarray
    f_local: list[np.ndarray]
    u_prescribed: np.ndarray | None = None
    member_loads: MemberLoadVectors | None = None
    applied: tuple = ()


def imposed_strain_local(fe: FEModel, case: LoadCase) -> list[np.ndarray] | None:
    """Per element group, the local load vectors of the axial fixed-end forces of the case's
    imposed strains (None when the case imposes none).

    On every element of a member the axial field carries ``N0`` of
    :func:`~trussfe.mechanics.imposed_strain.axial_fixed_end_force`: the element's load vector
    is ``[N0, −N0]`` on its two axial DOFs, so that its end forces ``K u − f`` are ``−N`` at
    the start and ``+N`` at the end with ``N = EA (ε − ε0)``.
    """
    if not case.has_imposed_strain:
        return None
    s = fe.structure
    eps0 = imposed_strain(s.lengths(), thermal_expansion=s.member_properties.thermal_expansion,
                          delta_T=case.delta_T, initial_strain=case.initial_strain,
                          length_error=case.length_error)
    N0 = axial_fixed_end_force(s.E, s.area, eps0)
    out = []
    for g in fe.groups:
        fl = np.zeros(g.n_local)
        n0 = N0[fe.element_member[g.elements]]
        if np.any(n0):
            u = g.field("u")
            dofs = u.basis.element_dofs                      # (2, n_el): start, end
            np.add.at(fl, u.offset + dofs[0], n0)
            np.add.at(fl, u.offset + dofs[1], -n0)
        out.append(fl)
    return out


def member_load_vectors(fe: FEModel, member_loads) -> MemberLoadVectors | None:
    """The equivalent nodal loads and fixed-end forces of loads along members
    (:func:`trussfe.fem.member_loads.member_load_vector`); None when there are none."""
    return member_load_vector(fe, member_loads) if len(member_loads) else None


def prescribed_vector(fe: FEModel, case: LoadCase) -> np.ndarray | None:
    """The case's prescribed displacements as a global vector on the fixed DOFs (None when
    no support moves).

    Raises
    ------
    InputError
        A prescribed rotation at a node without rotational freedom.
    """
    if not case.has_prescribed:
        return None
    s = fe.structure
    dofs = fe.node_dofs
    P = case.prescribed[:, :dofs.shape[1]]
    lost = (P != 0.0) & (dofs < 0)
    if np.any(lost):
        i, c = np.argwhere(lost)[0]
        raise _in_file(s, InputError(f"load_cases.{case.name}.prescribed.{s.node_ids[i]}",
                                     f"rotation {DOF_NAMES[s.dim][c]} is prescribed at a pin "
                                     "joint that has no rotational freedom; attach a beam "
                                     "without a release or remove it"))
    up = np.zeros(fe.n_dof)
    ok = (P != 0.0) & (dofs >= 0)
    up[dofs[ok]] = P[ok]
    if np.any(up[~fe.fixed] != 0.0):
        i = int(np.flatnonzero(np.any((P != 0.0) & ~fe.fixed[np.maximum(dofs, 0)], axis=1))[0])
        raise _in_file(s, InputError(f"load_cases.{case.name}.prescribed.{s.node_ids[i]}",
                                     "a displacement is prescribed on a free DOF; add it to "
                                     "[supports]"))
    return up


def _in_file(structure: Structure, err: InputError) -> InputError:
    """``err`` naming the model file before its item (docs/bad-input.md), when the
    structure was read from one."""
    return err.in_file(structure.source)


def case_load(fe: FEModel, case: LoadCase) -> CaseLoad:
    """The load vector, element loads and prescribed displacements of one case."""
    item = (f"load_cases.{case.name}.loads" if "load_cases" in fe.structure.extensions
            else "loads")
    f = fe.load_vector(self_weight=case.gravity, loads=case.loads, item=item)
    f_local = (fe.element_self_weight_local() if case.gravity
               else [np.zeros(g.n_local) for g in fe.groups])
    strained = imposed_strain_local(fe, case)
    if strained is not None:
        for k, (g, fl) in enumerate(zip(fe.groups, strained)):
            if np.any(fl):
                f_local[k] = f_local[k] + fl
                f += g.T.T @ fl                  # the joint loads equivalent to them
    # with gravity, active members weigh their base and leadscrew tube, not ρAL
    applied = tuple(case.member_loads)
    if case.gravity:
        joints, along = active_member_weight(fe)
        f = f + joints
        applied = applied + along
    mlv = member_load_vectors(fe, applied)
    if mlv is not None:
        f = f + mlv.global_vector
        f_local = [a + b for a, b in zip(f_local, mlv.local)]
    return CaseLoad(f=f, f_local=f_local, u_prescribed=prescribed_vector(fe, case),
                    member_loads=mlv, applied=applied)


# ---------------------------------------------------------------------------- envelope
#: Member quantities of the envelope: name → (StaticResult attribute, unit).
ENVELOPE_MEMBER_FIELDS = ("axial_force", "axial_stress", "max_von_mises")


@dataclass
class Envelope:
    """Largest and smallest value of every member force, stress and reaction over a set of
    results (the combinations, or the cases of a model without combinations).

    Attributes
    ----------
    over : str
        ``"combinations"`` or ``"cases"``.
    names : tuple of str
        The results enveloped, in order.
    fields : dict
        Name → ``(max, max_index, min, min_index)``; arrays of the quantity's shape, the
        indices into ``names``.  Names: ``axial_force``, ``axial_stress``, ``max_von_mises``
        (member,), ``end_forces`` (member, 2, 6), ``reactions`` (node, ndof_node).
    """

    over: str
    names: tuple[str, ...]
    fields: dict = field(default_factory=dict)

    def governing(self, quantity: str, which: str = "max") -> np.ndarray:
        """Name of the governing result of each entry of ``quantity`` (``which``: max or
        min), an array of str of the quantity's shape."""
        mx, imx, mn, imn = self.fields[quantity]
        return np.asarray(self.names, dtype=object)[imx if which == "max" else imn]


def envelope(results: dict[str, StaticResult], over: str) -> Envelope:
    """The :class:`Envelope` of ``results`` (name → result), vectorised over the results."""
    names = tuple(results)
    env = Envelope(over=over, names=names)
    stacks = {key: np.stack([getattr(r, key) for r in results.values()])
              for key in ENVELOPE_MEMBER_FIELDS + ("end_forces", "reactions")}
    for key, a in stacks.items():
        imx, imn = np.argmax(a, axis=0), np.argmin(a, axis=0)
        env.fields[key] = (np.take_along_axis(a, imx[None], 0)[0], imx,
                           np.take_along_axis(a, imn[None], 0)[0], imn)
    return env


# ---------------------------------------------------------------------------- solution
@dataclass
class LoadCaseSolution:
    """Results of :func:`solve_load_cases`.

    Attributes
    ----------
    fe : FEModel
    load_cases : LoadCases
    cases : dict
        Case name → :class:`~trussfe.fem.static.StaticResult`, for every case solved.
    combinations : dict
        Combination name → :class:`~trussfe.fem.static.StaticResult`, the factored sum.
    factors : dict
        Combination name → {case: factor}.
    """

    fe: FEModel
    load_cases: LoadCases
    cases: dict[str, StaticResult]
    combinations: dict[str, StaticResult]
    factors: dict[str, dict[str, float]]

    @property
    def structure(self) -> Structure:
        """The analysed structure."""
        return self.fe.structure

    @property
    def envelope(self) -> Envelope:
        """Over the combinations, or over the cases when none is combined."""
        if self.combinations:
            return envelope(self.combinations, "combinations")
        return envelope(self.cases, "cases")


def solve_load_cases(structure: Structure, cases: Sequence[str] | None = None,
                     combinations: Sequence[str] | None = None, *, bar_model: str = "truss",
                     subdivisions: int | None = None, backend: str = "auto",
                     fe: FEModel | None = None) -> LoadCaseSolution:
    """Solve load cases on one factorisation and sum them into combinations.

    Parameters
    ----------
    structure : Structure
        Its ``load_cases`` table, or the one implicit case of its loads
        (:func:`~trussfe.model.load_cases.model_load_cases`).
    cases : sequence of str, optional
        Cases to solve (default: all).  The cases of the combinations asked for are solved
        as well.
    combinations : sequence of str, optional
        Combinations to form (default: all when ``cases`` is None too, else none).
    bar_model, subdivisions, backend
        As :func:`~trussfe.fem.static.solve_static`.
    fe : FEModel, optional
        A discretisation to reuse.

    Returns
    -------
    LoadCaseSolution

    Raises
    ------
    InputError
        An unknown case or combination name.
    MechanismError
        The structure cannot carry load.

    Examples
    --------
    Two cases on a bar fixed at both ends: a load at its middle and a warming by 10 K
    (N = −EAαΔT = −2400 N in both halves); their sum is the combination.

    >>> from trussfe.api import model_from_dict
    >>> s = model_from_dict({"model": {"dimension": 2},
    ...     "materials": {"st": {"E": 2e11, "thermal_expansion": 1.2e-5}},
    ...     "sections": {"s": {"area": 1e-4}},
    ...     "nodes": {"A": [0, 0], "B": [1, 0], "C": [2, 0]},
    ...     "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st"},
    ...                 "BC": {"nodes": ["B", "C"], "section": "s", "material": "st"}},
    ...     "supports": {"A": ["x", "y"], "B": ["y"], "C": ["x", "y"]},
    ...     "load_cases": {"push": {"loads": {"B": [1000.0, 0.0]}},
    ...                    "hot": {"temperature": [{"members": ["AB", "BC"], "delta_T": 10}]}},
    ...     "combinations": {"both": {"push": 1.0, "hot": 1.0}}})
    >>> sol = solve_load_cases(s)
    >>> sol.cases["hot"].axial_force.round(6).tolist()
    [-2400.0, -2400.0]
    >>> sol.combinations["both"].axial_force.round(6).tolist()
    [-1900.0, -2900.0]
    """
    t0 = time.perf_counter()
    table = model_load_cases(structure)
    want_cases = list(table.case_names) if cases is None else [str(c) for c in cases]
    if combinations is None:
        combinations = table.combination_names if cases is None else ()
    combos: list[Combination] = []
    for name in combinations:
        try:
            combos.append(table.combination(str(name)))
        except KeyError:
            raise InputError("--combination", _unknown("combination", name,
                                                       table.combination_names)) from None
    for name in want_cases:
        if name not in table.case_names:
            raise InputError("--case", _unknown("load case", name, table.case_names))
    for combo in combos:
        want_cases += [c for c, _ in combo.factors if c not in want_cases]
    order = [n for n in table.case_names if n in want_cases]
    if fe is None:
        fe = discretise(structure, bar_model=bar_model, subdivisions=subdivisions)
    loads = [case_load(fe, table.case(n)) for n in order]
    F = np.stack([c.f for c in loads], axis=1)
    moved = any(c.u_prescribed is not None for c in loads)
    UP = (np.stack([np.zeros(fe.n_dof) if c.u_prescribed is None else c.u_prescribed
                    for c in loads], axis=1) if moved else None)
    system = LinearSystem(fe, backend, started=t0)
    U, residual = system.solve(F, UP)
    R = system._reactions
    results = {n: system.recover(U[:, j], F[:, j], float(residual[j]), loads[j].f_local,
                                 R[:, j], loads[j].member_loads)
               for j, n in enumerate(order)}
    # combinations: factored sums of the cases (linear), never solved again
    factors = {c.name: dict(c.factors) for c in combos}
    A = LoadCases(cases=tuple(table.case(n) for n in order),
                  combinations=tuple(combos)).factor_matrix() if combos else np.zeros((0, 0))
    combined = {}
    for k, combo in enumerate(combos):
        a = A[k]
        u, f = U @ a, F @ a
        f_local = [sum(a[j] * loads[j].f_local[g] for j in range(len(order)))
                   for g in range(len(fe.groups))]
        rhs = f if UP is None else f - system.stiffness() @ (UP @ a)
        r = system.internal_forces(u) - f
        nf, nr = np.linalg.norm(rhs[fe.free]), np.linalg.norm(r[fe.free])
        # the member loads of the combination (for the section forces along loaded members)
        scaled = [ml.scaled(a[j]) for j, n in enumerate(order) if a[j] != 0.0
                  for ml in loads[j].applied]
        combined[combo.name] = system.recover(u, f, float(nr / nf) if nf > 0 else float(nr),
                                              f_local, R @ a, member_load_vectors(fe, scaled))
    return LoadCaseSolution(fe=fe, load_cases=table, cases=results, combinations=combined,
                            factors=factors)


def _unknown(what: str, name, valid: Sequence[str]) -> str:
    from ..io.suggest import suggest as _suggest
    if not valid:
        return f"the model has no {what}s"
    return f"the model has no {what} '{name}'{_suggest(str(name), list(valid))}"


# ---------------------------------------------------------------------------- JSON
def envelope_json(env: Envelope, structure: Structure, fe: FEModel) -> dict:
    """The ``envelope`` of the ``static`` JSON document (docs/json.md)."""
    s = structure
    dim = s.dim
    names = np.asarray(env.names, dtype=object)

    def entry(key, index):
        mx, imx, mn, imn = env.fields[key]
        by = lambda i: np.asarray(names[i], dtype=object).tolist()
        return {"max": np.asarray(mx[index]).tolist(), "max_by": by(imx[index]),
                "min": np.asarray(mn[index]).tolist(), "min_by": by(imn[index])}

    members = {}
    for i, mid in enumerate(s.member_ids):
        d = {key: entry(key, i) for key in ENVELOPE_MEMBER_FIELDS}
        d["end_forces"] = {end: {nm: entry("end_forces", (i, e, c))
                                 for c, nm in enumerate(SECTION_FORCE_NAMES)}
                           for e, end in enumerate(("start", "end"))}
        members[mid] = d
    nodes = {}
    held = reacting_nodes(fe)
    for i in np.flatnonzero(held.any(axis=1)):
        d = {}
        if held[i, :dim].any():
            d["reaction"] = entry("reactions", (i, slice(0, dim)))
        if fe.has_rotation[i] and held[i, dim:].any():
            d["reaction_moment"] = entry("reactions", (i, slice(dim, None)))
        nodes[s.node_ids[i]] = d
    return {"over": env.over, "names": list(env.names), "nodes": nodes, "members": members}


def load_cases_json(solution: LoadCaseSolution, cases: Sequence[str] | None = None,
                    combinations: Sequence[str] | None = None) -> dict:
    """The ``static`` JSON document of several cases and combinations with their envelope
    (docs/json.md, ``static`` with load cases)."""
    fe = solution.fe
    s = fe.structure
    case_names = list(solution.cases) if cases is None else list(cases)
    combo_names = list(solution.combinations) if combinations is None else list(combinations)

    def body(result):
        doc = static_json(result)
        return {k: doc[k] for k in ("residual", "nodes", "members")}

    doc = static_json(next(iter(solution.cases.values())))
    head = {k: doc[k] for k in ("units", "command", "model", "bar_model", "subdivisions",
                                "dof_names", "n_dof")}
    picked = {n: solution.combinations[n] for n in combo_names}
    env = (envelope(picked, "combinations") if picked
           else envelope({n: solution.cases[n] for n in case_names}, "cases"))
    return {
        **head,
        "cases": {n: body(solution.cases[n]) for n in case_names},
        "combinations": {n: {"factors": solution.factors[n], **body(solution.combinations[n])}
                         for n in combo_names},
        "envelope": envelope_json(env, s, fe),
    }
