# SPDX-License-Identifier: MIT
"""Modal and buckling checks for the validation suite (``validation/cases/modal_*.toml``,
``buckling_*.toml``): each function returns a flat dict of named quantities that the case
files compare with their references.

Sources are named in the case files: closed-form frequencies and Euler loads, Lacy's Table 3.3
and section 5.8 allowables, and an independent dense assembly ``K = Bᵀ diag(EA/L) B`` from the
compatibility matrix (Hortobágyi eq. 2) for the double-octahedral bay.
"""
from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from .. import models
from ..kinematics.compatibility import compatibility_matrix
from ..model.sections import Material, Section
from ..model.structure import Structure, build_structure
from ..fem.buckling import solve_buckling
from ..fem.modal import solve_modes
from ..mechanics.euler import member_euler_loads
from ..io.output import working_folder

#: Lacy, Appendix A/C code: ``E = 71.0e9``, ``ro = 2711.5``, ``G = 26.2e9``.
ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
INCH = 0.0254
#: Triangular truss tubes (Appendix A: OD 1 in, ID 7/8 in).
TRIANGLE_TUBE = Section.tube("triangle", 0.0254, 0.022225)
#: Leadscrew tube of the double octahedron (Appendix C code: OD 0.75 in, ID 0.63 in).
LEADSCREW_TUBE = Section.tube("leadscrew", 0.75 * INCH, 0.63 * INCH)
#: Fixed members with Appendix D's area 9.0245e-5 m² (ID 0.62 in).
FIXED_TUBE = Section.tube("fixed", 0.75 * INCH, 0.62 * INCH)

#: Double-octahedral bay (catalogue values): base side, cross-longeron length (Appendix D
#: coordinates), active lengths at the equilibrium and the two slewed positions (1.1079 m is the
#: short length that reproduces Tables 5.2–5.4; the thesis prints 1.1077 m).
BASE_SIDE = models.octahedral.BASE_SIDE
LONGERON = models.octahedral.LONGERON
ACTIVE_EQUILIBRIUM = models.EQUILIBRIUM_LENGTH
ACTIVE_LONG, ACTIVE_SHORT = models.SLEW_LONG, models.SLEW_SHORT
TOP_MASS = 4.536            # kg: the 10 lb weights on the top nodes (44.498 N / 9.81)


def column(length: float, section: Section, load: float = -1.0,
           subdivisions_dim: int = 2) -> Structure:
    """A pinned–pinned column along y under an axial end load (N, negative = compression)."""
    return build_structure([[0.0, 0.0], [0.0, length]], [(0, 1)], section=section,
                           material=ALUMINIUM, supports={0: "xy", 1: "x"},
                           loads={1: [0.0, load]}, name=f"column {length} m")


def lacy_buckling_allowables(subdivisions: int = 8) -> dict:
    """Euler allowables of Lacy Table 3.3 and section 5.8 by eq. 2.26 and by FE buckling.

    Returns
    -------
    dict
        ``*_euler`` (eq. 2.26, C = 1) and ``*_fe`` (first load factor of the member as a
        pinned-beam column of ``subdivisions`` elements under 1 N) for: the triangular truss
        follower / leadscrew tube (2.0 m), the leadscrew tube M8 (0.254 m), the top-plane
        members with the 0.889 m length the thesis' code uses, and with their real length
        1.2192 m; plus ``top_plane_overstatement`` = 3055.2 N / real allowable.
    """
    cases = {"table33": (2.0, TRIANGLE_TUBE), "m8": (0.254, LEADSCREW_TUBE),
             "top_plane_code_length": (LONGERON, FIXED_TUBE),
             "top_plane_real_length": (BASE_SIDE, FIXED_TUBE)}
    out = {}
    for key, (L, sec) in cases.items():
        s = column(L, sec)
        out[f"{key}_euler"] = float(member_euler_loads(s)[0])
        out[f"{key}_fe"] = float(solve_buckling(s, count=1, subdivisions=subdivisions)
                                 .load_factors[0])
    out["top_plane_overstatement"] = 3055.2 / out["top_plane_real_length_euler"]
    return out


def _axial_modes_figure(x: np.ndarray, shapes: np.ndarray, L: float) -> dict:
    """The fixed–free bar's first axial modes against sin((2n − 1)πx/2L), as a PNG in a
    temporary folder."""

    from ..io.figures import subplots
    from ..io.output import atomic_path

    fig, ax = subplots(figsize=(6.4, 4.2))
    xx = np.linspace(0.0, L, 200)
    for i in range(shapes.shape[0]):
        u = shapes[i] / shapes[i][-1] * (-1) ** i       # free end: sin((2n − 1)π/2)
        ax.plot(xx, np.sin((2 * i + 1) * np.pi * xx / (2 * L)), color="0.6", lw=3,
                label="closed form sin((2n−1)πx/2L)" if i == 0 else None)
        ax.plot(x[::8], u[::8], "o", ms=3, label=f"trussfe mode {i + 1}")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("axial displacement (scaled)")
    ax.set_title("fixed–free bar, axial modes")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = working_folder("trussfe_modal_") / "axial_bar_modes.png"
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")
    return {"axial_bar_modes": str(path)}


def modal_closed_form(figures: bool = True) -> dict:
    """Frequencies of an axial bar and a simply supported beam against closed form.

    Returns
    -------
    dict
        ``axial_bar_f{1,2}_ratio``: fixed–free bar of 200 consistent truss elements over
        (2n−1)c/(4L); ``ss_beam_f{1,2,3}_ratio``: one pinned-beam member of 32 elements over
        n²π/(2L²)·√(EI/ρA); ``ss_beam_rate``: observed order of convergence of f1 between
        k = 4 and 8 (Hermite cubics: 4).
    """
    L = 2.0
    n = 200
    x = np.c_[np.linspace(0, L, n + 1), np.zeros(n + 1)]
    sup = {i: "y" for i in range(n + 1)}
    sup[0] = "xy"
    bar = build_structure(x, np.c_[np.arange(n), np.arange(1, n + 1)], section=TRIANGLE_TUBE,
                          material=ALUMINIUM, supports=sup)
    c = np.sqrt(ALUMINIUM.E / ALUMINIUM.density)
    bar_modes = solve_modes(bar, count=2)
    fb = bar_modes.frequencies_hz
    out = {f"axial_bar_f{i + 1}_ratio": float(fb[i] / ((2 * i + 1) * c / (4 * L)))
           for i in range(2)}
    if figures:
        out["figures"] = _axial_modes_figure(x[:, 0], bar_modes.node_shapes()[:, :, 0], L)
    beam = build_structure([[0, 0], [L, 0]], [(0, 1)], section=TRIANGLE_TUBE,
                           material=ALUMINIUM, supports={0: "xy", 1: "y"})
    base = np.pi / (2 * L**2) * np.sqrt(ALUMINIUM.E * TRIANGLE_TUBE.Iz
                                        / (ALUMINIUM.density * TRIANGLE_TUBE.area))
    fs = solve_modes(beam, count=3, bar_model="pinned-beam", subdivisions=32).frequencies_hz
    out.update({f"ss_beam_f{i + 1}_ratio": float(fs[i] / ((i + 1) ** 2 * base))
                for i in range(3)})
    err = [solve_modes(beam, count=1, bar_model="pinned-beam", subdivisions=k)
           .frequencies_hz[0] / base - 1 for k in (4, 8)]
    out["ss_beam_rate"] = float(np.log2(err[0] / err[1]))
    return out


def double_octahedron(active: tuple[float, float, float] = (ACTIVE_EQUILIBRIUM,) * 3,
                      top_mass: float = TOP_MASS) -> Structure:
    """The double-octahedral bay of the catalogue (:func:`trussfe.models.double_octahedron`)
    at the active lengths ``active`` (M7/8, M9/10, M11/12) with ``top_mass`` on each top node
    and no load: the structure of the modal check."""
    return models.double_octahedron(active, 0.0, top_mass=top_mass, name="double-octahedral bay")


def independent_truss_modes(s: Structure, count: int) -> np.ndarray:
    """Frequencies (Hz) of a pin-jointed truss from ``K = Bᵀ diag(EA/L) B`` (compatibility
    matrix) and the consistent bar mass ρAL/6 [[2, 1], [1, 2]] on each translation plus nodal
    masses, dense generalized eigenproblem — no scikit-fem, no DOF transformation."""
    free = ~s.translation_supports
    B = compatibility_matrix(s.coords, s.connectivity, free=free).toarray()
    L = s.lengths()
    K = B.T @ np.diag(s.E * s.area / L) @ B
    n, dim = s.coords.shape
    M = np.zeros((n * dim, n * dim))
    mb = s.density * s.area * L / 6.0
    a, b = s.connectivity.T
    for d in range(dim):                       # per axis (3 at most), vectorised over bars
        ia, ib = a * dim + d, b * dim + d
        np.add.at(M, (ia, ia), 2 * mb)
        np.add.at(M, (ib, ib), 2 * mb)
        np.add.at(M, (ia, ib), mb)
        np.add.at(M, (ib, ia), mb)
    M[np.arange(n * dim), np.arange(n * dim)] += np.repeat(s.masses, dim)
    keep = free.ravel()
    M = M[keep][:, keep]
    lam = sla.eigh(K, M, eigvals_only=True, subset_by_index=[0, count - 1])
    return np.sqrt(lam) / (2 * np.pi)


def double_octahedron_modes(count: int = 3) -> dict:
    """First frequencies of the double-octahedral bay at its three static positions (truss
    model, consistent mass, 4.536 kg on each top node), by the FE core and by the independent
    dense assembly; and the lumped-mass frequencies for comparison.  The bay is symmetric under
    a third of a turn about z, so which active member is the long one does not change a
    frequency or the vertical effective mass.

    Returns
    -------
    dict
        ``{position}_f{i}`` (FE), ``{position}_f{i}_independent`` and ``{position}_f{i}_ratio``
        (FE / independent) for position ``equilibrium``, ``slewed_1`` (M7/8 long, M9/10 and
        M11/12 short) and ``slewed_2`` (M7/8 short, the others long); ``{position}_meff_z_fraction``: share of the
        free mass in the first ``count`` modes, vertically.
    """
    positions = {"equilibrium": (ACTIVE_EQUILIBRIUM,) * 3,
                 "slewed_1": (ACTIVE_LONG, ACTIVE_SHORT, ACTIVE_SHORT),
                 "slewed_2": (ACTIVE_SHORT, ACTIVE_LONG, ACTIVE_LONG)}
    out = {}
    for name, act in positions.items():
        s = double_octahedron(act)
        r = solve_modes(s, count=count)
        ref = independent_truss_modes(s, count)
        for i in range(count):
            out[f"{name}_f{i + 1}"] = float(r.frequencies_hz[i])
            out[f"{name}_f{i + 1}_independent"] = float(ref[i])
            out[f"{name}_f{i + 1}_ratio"] = float(r.frequencies_hz[i] / ref[i])
        out[f"{name}_meff_z_fraction"] = float(r.effective_mass[:, 2].sum() / r.total_mass[2])
        out[f"{name}_f1_lumped"] = float(solve_modes(s, count=1, mass="lumped")
                                         .frequencies_hz[0])
    return out
