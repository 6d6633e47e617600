# SPDX-License-Identifier: MIT
"""Linear finite-element analyses: :func:`static`, :func:`modes`, :func:`buckling`."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Any, ClassVar

import numpy as np

from ..linalg.pardiso import available as pardiso_available
from ..fem.load_cases import load_cases_json, solve_load_cases
from ..fem.static import solve_static
from .model import ModelLike, as_structure
from .options import choice, flag, positive_int, progress_callback
from .numerics import numerics_checked
from .results import Result

#: Sparse linear solvers of :func:`static`.
SOLVERS = ("auto", "superlu", "pardiso")


def solves_one_case(structure, *, case: str | None = None, combination: str | None = None,
                    all_cases: bool = False) -> bool:
    """Whether :func:`static` gives one result (a :class:`StaticResult`: the chosen case or
    combination, or the loads of a model without ``[load_cases]``) rather than every case and
    combination (a :class:`LoadCasesResult`)."""
    if case is not None or combination is not None:
        return True
    return not all_cases and "load_cases" not in structure.extensions


@numerics_checked
def static(model: ModelLike, *, bar_model: str = "truss", subdivisions: int | None = None,
           solver: str = "auto", case: str | None = None, combination: str | None = None,
           all_cases: bool = False) -> StaticResult | LoadCasesResult:
    """Linear static analysis under the model's loads, member loads and gravity, or its load
    cases and combinations (``trussfe static``).

    Parameters
    ----------
    model : Structure, path or dict
        The model (see :func:`trussfe.model_from_dict` for a dict).
    bar_model : {"truss", "pinned-beam"}
        Bars as axial-only truss elements or as pinned beams.
    subdivisions : int, optional
        Elements per frame member (default 4).
    solver : {"auto", "superlu", "pardiso"}
        Sparse linear solver; ``auto`` takes PARDISO for large models when installed.
    case : str, optional
        Analyse this load case alone (``[load_cases.NAME]``; ``"default"`` for the loads of
        a model without load cases).
    combination : str, optional
        Analyse this combination alone (``[combinations]``).
    all_cases : bool
        Every case and combination with their envelope.  The default for a model with
        ``[load_cases]`` when neither ``case`` nor ``combination`` is given.

    Returns
    -------
    StaticResult or LoadCasesResult
        One case or combination: a :class:`StaticResult` (``displacement`` and ``reaction``
        (node, dim), ``axial_force`` (member,), …).  All cases: a :class:`LoadCasesResult`
        (``cases``, ``combinations``: name → :class:`StaticResult`; ``envelope``).

    Raises
    ------
    InputError
        A bad model or option, an unknown case or combination.
    MechanismError
        The structure is a mechanism.
    """
    subdivisions = positive_int("--subdivisions", subdivisions)
    all_cases = flag("--all", all_cases)
    choice("--solver", solver, SOLVERS)
    chosen = [o for o, v in (("--case", case), ("--combination", combination),
                             ("--all", all_cases)) if v not in (None, False)]
    if len(chosen) > 1:
        from ..errors import InputError
        raise InputError(chosen[1], f"give one of --case, --combination and --all, not "
                                    f"{' and '.join(chosen)}")
    structure = as_structure(model)
    if solver == "pardiso" and not pardiso_available():
        from ..errors import InputError
        raise InputError("--solver", "PARDISO is not available (pip install pypardiso); "
                         "use --solver superlu")
    if not chosen and solves_one_case(structure):
        # the model's [loads] and gravity: the one implicit case, solved as always
        return StaticResult(structure, solve_static(structure, bar_model=bar_model,
                                                    subdivisions=subdivisions,
                                                    backend=solver))
    for option, value in (("--case", case), ("--combination", combination)):
        if value is not None and not isinstance(value, str):
            from ..errors import InputError
            raise InputError(option, f"expected a name, got {value!r}")
    solution = solve_load_cases(
        structure, cases=None if case is None and combination is None else
        ([case] if case is not None else []),
        combinations=None if case is None and combination is None else
        ([combination] if combination is not None else []),
        bar_model=bar_model, subdivisions=subdivisions, backend=solver)
    if case is not None:
        return StaticResult(structure, solution.cases[case], selected=("case", case))
    if combination is not None:
        return StaticResult(structure, solution.combinations[combination],
                            selected=("combination", combination),
                            factors=solution.factors[combination])
    return LoadCasesResult(structure, solution)


@numerics_checked
def modes(model: ModelLike, *, count: int | None = None, mass: str = "consistent",
          bar_model: str = "truss", subdivisions: int | None = None,
          mass_from: str | None = None,
          progress: Callable[[int, int], None] | None = None) -> ModesResult:
    """Natural frequencies and mass-normalised mode shapes (``trussfe modes``).

    Parameters
    ----------
    model : Structure, path or dict
    count : int, optional
        Number of modes (default 6, or every mode of a model with fewer free DOFs that carry
        mass).
    mass : {"consistent", "lumped"}
        Member mass matrix.
    bar_model : {"truss", "pinned-beam"}
        Pinned beams add the members' own bending modes.
    subdivisions : int, optional
        Elements per frame member (default 4).
    mass_from : str, optional
        A load case whose nodal loads along gravity add their mass, F·ĝ/``|g|``, at their nodes
        (:mod:`trussfe.mechanics.mass_source`): the payload of a case in the modes.
    progress : callable, optional
        Called as ``progress(done, total)`` between the stages of the solution (a progress
        bar; the command line draws one on a terminal).

    Returns
    -------
    ModesResult
        ``frequencies_hz`` (mode,), ``shapes`` (mode, node, dim), ``effective_mass``, …
    """
    count = positive_int("--count", count)
    subdivisions = positive_int("--subdivisions", subdivisions)
    progress = progress_callback(progress)
    structure = as_structure(model)
    if mass_from is not None:
        structure = _with_case_masses(structure, mass_from)
    from ..fem.modal import solve_modes         # imported on first use: start-up

    return ModesResult(structure, solve_modes(structure, count=count, mass=mass,
                                              bar_model=bar_model, subdivisions=subdivisions,
                                              progress=progress), mass_from=mass_from)


def _with_case_masses(structure, name: str):
    """The structure with the masses of load case ``name``'s loads along gravity added."""
    from ..errors import InputError
    from ..io.suggest import suggest as _suggest
    from ..mechanics.mass_source import masses_from_loads
    from ..model.load_cases import model_load_cases

    cases = model_load_cases(structure)
    try:
        case = cases.case(name)
    except KeyError:
        raise InputError("--mass-from", f"no load case '{name}'"
                         f"{_suggest(name, cases.case_names)}") from None
    if len(case.member_loads):
        raise InputError("--mass-from", f"load case '{name}' has member loads; only nodal "
                                        "loads are turned into masses")
    where = f"load_cases.{name}.loads" if "load_cases" in structure.extensions else "loads"
    if structure.source:
        where = f"{structure.source}: {where}"
    added = masses_from_loads(case.loads, structure.gravity, where, structure.node_ids)
    return structure.with_masses(structure.masses + added)


@numerics_checked
def buckling(model: ModelLike, *, count: int | None = None, bar_model: str = "pinned-beam",
             subdivisions: int | None = None, case: str | None = None,
             combination: str | None = None) -> BucklingResult:
    """Linear (eigen) buckling about the static state under the model's loads and gravity,
    or under one load case or combination (``trussfe buckling``).

    Parameters
    ----------
    model : Structure, path or dict
    count : int, optional
        Number of load factors (default 4, or every finite one when there are fewer).
    bar_model : {"pinned-beam", "truss"}
        Pinned beams buckle between joints; truss bars show joint instability only.
    subdivisions : int, optional
        Elements per frame member (default 4).
    case, combination : str, optional
        The state to buckle about: a load case or a combination (one of them is needed for
        a model with ``[load_cases]``).  The load factor scales the whole state, imposed
        strains and support settlements included.

    Returns
    -------
    BucklingResult
        ``load_factors`` (mode,), ``shapes`` (mode, node, dim), ``euler_load`` (member,), …
    """
    from ..errors import InputError
    count = positive_int("--count", count)
    subdivisions = positive_int("--subdivisions", subdivisions)
    structure = as_structure(model)
    from ..fem.buckling import solve_buckling   # imported on first use: start-up

    if case is not None and combination is not None:
        raise InputError("--combination", "give one of --case and --combination, not both")
    if case is None and combination is None:
        if "load_cases" in structure.extensions:
            raise InputError("--case", "the model has load cases: choose the state to buckle "
                             "about with --case NAME or --combination NAME")
        return BucklingResult(structure, solve_buckling(structure, count=count,
                                                        bar_model=bar_model,
                                                        subdivisions=subdivisions))
    for option, value in (("--case", case), ("--combination", combination)):
        if value is not None and not isinstance(value, str):
            raise InputError(option, f"expected a name, got {value!r}")
    solution = solve_load_cases(structure, cases=[case] if case is not None else [],
                                combinations=[combination] if combination is not None else [],
                                bar_model=bar_model, subdivisions=subdivisions)
    state = (solution.cases[case] if case is not None
             else solution.combinations[combination])
    return BucklingResult(structure, solve_buckling(structure, count=count, static=state),
                          selected=("case", case) if case is not None
                          else ("combination", combination))


@dataclass(frozen=True, eq=False, repr=False)
class StaticResult(Result):
    """Linear static analysis (:func:`trussfe.static`); ``solution`` is a
    :class:`trussfe.fem.static.StaticResult`.  Global equilibrium holds: the reactions balance
    the applied loads and gravity."""

    command: ClassVar[str] = "static"
    #: ``("case", NAME)`` or ``("combination", NAME)`` when one was chosen, else None.
    selected: tuple[str, str] | None = None
    #: The factors of a chosen combination, case → factor.
    factors: dict[str, float] | None = None

    @property
    def displacement(self) -> np.ndarray:
        """Node translations, shape (node, dim), m."""
        return self.solution.displacements[:, :self.dim]

    @property
    def rotation(self) -> np.ndarray:
        """Node rotations, shape (node, 1) in 2-D or (node, 3) in 3-D, rad (zero at nodes
        without rotational freedom)."""
        return self.solution.displacements[:, self.dim:]

    @property
    def reaction(self) -> np.ndarray:
        """Support reaction forces, shape (node, dim), N (zero where not supported)."""
        return self.solution.reactions[:, :self.dim]

    @property
    def reaction_moment(self) -> np.ndarray:
        """Support reaction moments, shape (node, 1 or 3), N·m."""
        return self.solution.reactions[:, self.dim:]

    @property
    def axial_force(self) -> np.ndarray:
        """Member axial force, shape (member,), N (tension positive)."""
        return self.solution.axial_force

    @property
    def axial_stress(self) -> np.ndarray:
        """Axial stress N/A, shape (member,), Pa."""
        return self.solution.axial_stress

    @property
    def strain(self) -> np.ndarray:
        """Axial strain N/(EA), shape (member,)."""
        return self.solution.strain

    @property
    def max_von_mises(self) -> np.ndarray:
        """Largest von Mises stress along each member, shape (member,), Pa."""
        return self.solution.max_von_mises

    @property
    def end_forces(self) -> np.ndarray:
        """Section forces at the member ends, shape (member, 2, 6): start and end;
        N, Vy, Vz, T, My, Mz in member axes."""
        return self.solution.end_forces

    @property
    def section_forces(self) -> np.ndarray:
        """Section forces at the stations, shape (member, station, 6)."""
        return self.solution.section_forces

    @property
    def station_x(self) -> np.ndarray:
        """Station positions along each member, shape (member, station), m."""
        return self.solution.station_x

    @property
    def residual(self) -> float:
        """Relative residual of the linear solve."""
        return float(self.solution.residual)

    def _document(self) -> dict:
        from ..fem.static import static_json
        doc = static_json(self.solution)
        if self.selected is not None:
            doc[self.selected[0]] = self.selected[1]
            if self.factors is not None:
                doc["factors"] = dict(self.factors)
        return doc


@dataclass(frozen=True, eq=False, repr=False)
class LoadCasesResult(Result):
    """Every load case and combination of a model with their envelope
    (:func:`trussfe.static` with ``all_cases``, or a model with ``[load_cases]``);
    ``solution`` is a :class:`trussfe.fem.load_cases.LoadCaseSolution`.  Each case and
    combination is in global equilibrium."""

    command: ClassVar[str] = "static"

    @property
    def cases(self) -> dict[str, StaticResult]:
        """Case name → its :class:`StaticResult`, in the order of the model."""
        return {n: StaticResult(self.structure, r, selected=("case", n))
                for n, r in self.solution.cases.items()}

    @property
    def combinations(self) -> dict[str, StaticResult]:
        """Combination name → its :class:`StaticResult` (the factored sum of its cases)."""
        return {n: StaticResult(self.structure, r, selected=("combination", n),
                                factors=self.solution.factors[n])
                for n, r in self.solution.combinations.items()}

    @property
    def envelope(self) -> Any:
        """Largest and smallest member forces, stresses and reactions over the combinations
        (over the cases when there are none), with the governing one
        (:class:`trussfe.fem.load_cases.Envelope`)."""
        return self.solution.envelope

    def _document(self) -> dict:
        return load_cases_json(self.solution)


@dataclass(frozen=True, eq=False, repr=False)
class ModesResult(Result):
    """Modal analysis (:func:`trussfe.modes`); ``solution`` is a
    :class:`trussfe.fem.modal.ModalResult`."""

    command: ClassVar[str] = "modes"
    #: The load case whose loads along gravity added masses (``--mass-from``), if any.
    mass_from: str | None = None

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies, shape (mode,), Hz, ascending."""
        return self.solution.frequencies_hz

    @property
    def shapes(self) -> np.ndarray:
        """Mass-normalised mode shapes at the nodes, shape (mode, node, dim), m·kg^-½."""
        return self.solution.node_shapes()[:, :, :self.dim]

    @property
    def participation(self) -> np.ndarray:
        """Participation factors, shape (mode, dim)."""
        return self.solution.participation

    @property
    def effective_mass(self) -> np.ndarray:
        """Effective modal masses, shape (mode, dim), kg."""
        return self.solution.effective_mass

    @property
    def total_mass(self) -> np.ndarray:
        """Total mass per axis, shape (dim,), kg."""
        return self.solution.total_mass

    @property
    def kinds(self) -> tuple[str, ...]:
        """``"rigid"`` (zero frequency) or ``"elastic"`` per mode."""
        return tuple(self.solution.kinds)

    @property
    def rigid_modes(self) -> int:
        """Number of zero-frequency (rigid-body or mechanism) modes."""
        return int(self.solution.rigid_modes)

    def _document(self) -> dict:
        from ..fem.modal import modes_json
        doc = modes_json(self.solution)
        # beside "mass": the masses of the run are the model's plus this case's payload
        out = {}
        for key, value in doc.items():
            out[key] = value
            if key == "mass":
                out["mass_from"] = self.mass_from
        out.setdefault("mass_from", self.mass_from)
        return out


@dataclass(frozen=True, eq=False, repr=False)
class BucklingResult(Result):
    """Linear buckling analysis (:func:`trussfe.buckling`); ``solution`` is a
    :class:`trussfe.fem.buckling.BucklingResult`."""

    command: ClassVar[str] = "buckling"
    #: ``("case", NAME)`` or ``("combination", NAME)``: the state buckled about, if chosen.
    selected: tuple[str, str] | None = None

    @property
    def load_factors(self) -> np.ndarray:
        """Load factors, shape (mode,), ascending by magnitude (negative = reversed loads)."""
        return self.solution.load_factors

    @property
    def critical_load_factor(self) -> float:
        """Smallest positive load factor (``nan`` if none among the modes computed)."""
        return float(self.solution.critical_load_factor)

    @property
    def shapes(self) -> np.ndarray:
        """Buckling mode shapes at the nodes, shape (mode, node, dim); each mode is scaled to
        a largest translation of 1 over the joints and the stations along the members, so at
        the nodes it may be smaller (zero where members buckle between fixed joints)."""
        return self.solution.node_shapes()[:, :, :self.dim]

    @property
    def axial_force(self) -> np.ndarray:
        """Static member axial force under the reference loads, shape (member,), N."""
        return self.solution.static.axial_force

    @property
    def euler_load(self) -> np.ndarray:
        """Member Euler load (Lacy eq. 2.26, C = 1), shape (member,), N."""
        return self.solution.euler_load

    @property
    def buckling_utilisation(self) -> np.ndarray:
        """Compression over Euler load, shape (member,)."""
        return self.solution.utilisation

    def _document(self) -> dict:
        from ..fem.buckling import buckling_json
        doc = buckling_json(self.solution)
        if self.selected is not None:
            doc[self.selected[0]] = self.selected[1]
        return doc
