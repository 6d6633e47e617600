# SPDX-License-Identifier: MIT
"""Linear finite-element analyses: :func:`static`, :func:`modes`, :func:`buckling`."""
from __future__ import annotations

from ..fem.buckling import solve_buckling
from ..fem.linsolve import pardiso_available
from ..fem.modal import solve_modes
from ..fem.static import solve_static
from .model import ModelLike, as_structure
from .options import choice, positive_int
from .results import BucklingResult, ModesResult, StaticResult

#: Sparse linear solvers of :func:`static`.
SOLVERS = ("auto", "superlu", "pardiso")


def static(model: ModelLike, *, bar_model: str = "truss", subdivisions: int | None = None,
           solver: str = "auto") -> StaticResult:
    """Linear static analysis under the model's loads and gravity (``trussfe static``).

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

    Returns
    -------
    StaticResult
        ``displacement`` and ``reaction`` (node, dim), ``axial_force`` (member,), …

    Raises
    ------
    InputError
        A bad model or option.
    MechanismError
        The structure is a mechanism.
    """
    positive_int("--subdivisions", subdivisions)
    choice("--solver", solver, SOLVERS)
    structure = as_structure(model)
    if solver == "pardiso" and not pardiso_available():
        from ..errors import InputError
        raise InputError("--solver", "PARDISO is not available (pip install pypardiso); "
                         "use --solver superlu")
    return StaticResult(structure, solve_static(structure, bar_model=bar_model,
                                                subdivisions=subdivisions, backend=solver))


def modes(model: ModelLike, *, count: int = 6, mass: str = "consistent",
          bar_model: str = "truss", subdivisions: int | None = None) -> ModesResult:
    """Natural frequencies and mass-normalised mode shapes (``trussfe modes``).

    Parameters
    ----------
    model : Structure, path or dict
    count : int
        Number of modes.
    mass : {"consistent", "lumped"}
        Member mass matrix.
    bar_model : {"truss", "pinned-beam"}
        Pinned beams add the members' own bending modes.
    subdivisions : int, optional
        Elements per frame member (default 4).

    Returns
    -------
    ModesResult
        ``frequencies_hz`` (mode,), ``shapes`` (mode, node, dim), ``effective_mass``, …
    """
    structure = as_structure(model)
    return ModesResult(structure, solve_modes(structure, count=count, mass=mass,
                                              bar_model=bar_model, subdivisions=subdivisions))


def buckling(model: ModelLike, *, count: int = 4, bar_model: str = "pinned-beam",
             subdivisions: int | None = None) -> BucklingResult:
    """Linear (eigen) buckling about the static state under the model's loads and gravity
    (``trussfe buckling``).

    Parameters
    ----------
    model : Structure, path or dict
    count : int
        Number of load factors.
    bar_model : {"pinned-beam", "truss"}
        Pinned beams buckle between joints; truss bars show joint instability only.
    subdivisions : int, optional
        Elements per frame member (default 4).

    Returns
    -------
    BucklingResult
        ``load_factors`` (mode,), ``shapes`` (mode, node, dim), ``euler_load`` (member,), …
    """
    structure = as_structure(model)
    return BucklingResult(structure, solve_buckling(structure, count=count,
                                                    bar_model=bar_model,
                                                    subdivisions=subdivisions))
