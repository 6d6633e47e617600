# SPDX-License-Identifier: MIT
"""The explained values of Slewing Experiment 1's documented deviations, computed without
trussfe's solvers.

Cases actuator_slew1, elastic_m6_strains, lacy_fig_5_12_m6_components and lacy_slew1_members
explain their deviations from the thesis with values of the hanging double-octahedral bay
along the synthetic slew.  Here each is recomputed from the model file
(meshes/double_octahedron_actuators.toml, read with trussfe's reader) and the motion file
(meshes/slew1_motion.csv, parsed here) by a plain numpy computation:

* positions by Newton's method on the squared member lengths, node velocities and
  accelerations from the once and twice differentiated length constraints
  (d·ḋ = L L̇, ḋ·ḋ + d·d̈ = L̇² + L L̈) with the motion file's rates;
* every member a rigid body (Newton–Euler): a passive member a uniform tube, an active member
  its base (mass, centre of gravity, inertia) riding with its start node plus its leadscrew
  tube riding with its end node, the loads m (a − g) integrated in closed form, the rotary
  inertia ρ I α of the tube's sections; each member's moment equation gives the transverse
  parts of its pin forces, the joint equilibrium of the pin-jointed truss (one square system
  of the axial parts and the reactions) the rest;
* section forces by the Newton–Euler equations of the piece between the section and the end
  node; stresses by the formulas the cases name (σ_T = N/A, |M| c/I, τ = 2 V/A, Lacy eqs.
  2.24/2.25 and 4.75/4.76, Appendix C's cantilever equations for M8).

At rest (the slew's first and last samples, whose rates are zero) this is the statics of the
pin-jointed truss under its members' weights and the 46.0 N loads.  Each test reads the
explained value and its tolerance from the case file and asserts the independent value lies
within it.
"""
from __future__ import annotations

import functools
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import trussfe

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "meshes" / "double_octahedron_actuators.toml"
MOTION = ROOT / "meshes" / "slew1_motion.csv"
CASES = ROOT / "validation" / "cases"

#: Peak shear stress of a thin round tube over V/A (Lacy eq. 2.23 at the neutral axis).
KAPPA = 2.0


# ---------------------------------------------------------------------------------------
# the recorded explained values
# ---------------------------------------------------------------------------------------

def _explained(case: str, path: str) -> tuple[float, float, float]:
    """Explained value, rtol and atol of the documented deviation ``path`` of ``case``."""
    with open(CASES / f"{case}.toml", "rb") as f:
        data = tomllib.load(f)
    found = [q for q in data["quantities"] if q["path"] == path and "explained" in q]
    assert len(found) == 1, f"{case}: {len(found)} documented deviations at {path}"
    q = found[0]
    return (float(q["explained"]), float(q.get("explained_rtol", 0.0)),
            float(q.get("explained_atol", 0.0)))


def _assert_explained(value: float, case: str, path: str) -> None:
    recorded, rtol, atol = _explained(case, path)
    assert abs(value - recorded) <= atol + rtol * abs(recorded), (
        f"{case} {path}: independent {value!r}, recorded {recorded!r} "
        f"(rtol {rtol:g}, atol {atol:g})")


# ---------------------------------------------------------------------------------------
# the bay and the motion
# ---------------------------------------------------------------------------------------

class _Bay:
    """The model file's data as plain arrays (nothing of trussfe's analyses)."""

    def __init__(self, path: Path = MODEL):
        s = trussfe.read_model(path)
        self.ids = list(s.member_ids)
        self.nodes = list(s.node_ids)
        self.conn = np.asarray(s.connectivity, dtype=int)
        self.coords = np.asarray(s.coords, dtype=float)
        self.n, self.m = self.coords.shape[0], self.conn.shape[0]
        self.fixed = np.asarray(s.translation_supports, dtype=bool)
        self.free = np.flatnonzero(~self.fixed.ravel())
        self.g = np.asarray(s.gravity, dtype=float)
        self.loads = np.asarray(s.loads, dtype=float)[:, :3]
        self.masses = np.asarray(s.masses, dtype=float)
        sections = {(sec.outer_diameter, sec.inner_diameter) for sec in s.sections}
        materials = {(mat.E, mat.density) for mat in s.materials}
        assert len(sections) == 1 and len(materials) == 1       # one tube, one aluminium
        (od, idd), (self.E, rho) = sections.pop(), materials.pop()
        self.od, self.id = od, idd
        self.A = math.pi / 4 * (od ** 2 - idd ** 2)
        self.I = math.pi / 64 * (od ** 4 - idd ** 4)
        self.c = od / 2
        self.r2 = (od ** 2 + idd ** 2) / 16                    # I / A of a round tube
        self.rho = rho
        self.mu = rho * self.A                                   # kg/m
        self.active = {a.member: a for a in s.extensions["active_members"]}
        d = self.coords[self.conn[:, 1]] - self.coords[self.conn[:, 0]]
        self.L0 = np.linalg.norm(d, axis=1)

    def member(self, name: str) -> int:
        return self.ids.index(name)

    def node(self, name: str) -> int:
        return self.nodes.index(name)


def _read_motion(bay: _Bay, path: Path = MOTION):
    """Time, member indices and lengths, rates and accelerations of a motion CSV."""
    lines = [ln for ln in path.read_text(encoding="utf-8").splitlines()
             if ln.strip() and not ln.startswith("#")]
    head = lines[0].split(",")
    data = np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])
    col = {h: data[:, i] for i, h in enumerate(head)}
    names = [h for h in head[1:] if "." not in h]
    stack = lambda suffix: np.stack([col[k + suffix] for k in names], axis=1)
    return (col["time"], [bay.member(k) for k in names], stack(""), stack(".velocity"),
            stack(".acceleration"))


class _State:
    """Positions and rates of the bay at one instant."""

    def __init__(self, bay: _Bay, x, L, Ld, Ldd):
        conn, free = bay.conn, bay.free
        d = x[conn[:, 1]] - x[conn[:, 0]]
        J = np.zeros((bay.m, bay.n, 3))
        J[np.arange(bay.m), conn[:, 1]] += d
        J[np.arange(bay.m), conn[:, 0]] -= d
        J = J.reshape(bay.m, -1)[:, free]
        v = np.zeros(3 * bay.n)
        v[free] = np.linalg.solve(J, L * Ld)                  # d·ḋ = L L̇
        v = v.reshape(bay.n, 3)
        dd = v[conn[:, 1]] - v[conn[:, 0]]
        a = np.zeros(3 * bay.n)
        a[free] = np.linalg.solve(J, Ld ** 2 + L * Ldd - (dd * dd).sum(1))
        a = a.reshape(bay.n, 3)
        ddd = a[conn[:, 1]] - a[conn[:, 0]]
        e = d / L[:, None]
        ed = (dd - Ld[:, None] * e) / L[:, None]
        edd = (ddd - 2 * Ld[:, None] * ed - Ldd[:, None] * e) / L[:, None]
        self.x, self.v, self.a, self.L = x, v, a, L
        self.e, self.ed, self.edd = e, ed, edd
        self.omega = np.cross(e, ed)                           # no spin about the axis
        self.alpha = np.cross(e, edd)


def _positions(bay: _Bay, x0: np.ndarray, L: np.ndarray) -> np.ndarray:
    """Node positions with member lengths ``L``, Newton's method from ``x0``."""
    x = x0.copy()
    conn = bay.conn
    for _ in range(50):
        d = x[conn[:, 1]] - x[conn[:, 0]]
        r = (d * d).sum(1) - L * L
        if np.abs(r).max() < 1e-14 * (L * L).max():
            return x
        J = np.zeros((bay.m, bay.n, 3))
        J[np.arange(bay.m), conn[:, 1]] += 2 * d
        J[np.arange(bay.m), conn[:, 0]] -= 2 * d
        x.reshape(-1)[bay.free] -= np.linalg.solve(J.reshape(bay.m, -1)[:, bay.free], r)
    raise AssertionError("no assembly")


# ---------------------------------------------------------------------------------------
# Newton–Euler of the members, joint equilibrium of the truss
# ---------------------------------------------------------------------------------------

def _end_forces(bay: _Bay, st: _State, *, loads: bool = True):
    """Pin forces on every member from its start and end nodes, (m, 3) each, under gravity
    and (``loads``) the model's loads."""
    g = bay.g
    mu, r2 = bay.mu, bay.r2
    R = np.zeros((bay.m, 3))            # ∫ dm (a − g): the pins' resultant on the member
    Ma = np.zeros((bay.m, 3))           # its moment about the start node (with ρ I α)
    for k, (ia, ib) in enumerate(bay.conn):
        e, edd, al, L = st.e[k], st.edd[k], st.alpha[k], st.L[k]
        aa, ab = st.a[ia] - g, st.a[ib] - g
        if k in bay.active:
            act = bay.active[k]
            lt, cg, mb = act.tube_length, act.base_cg, act.base_mass
            base = mb * (aa + cg * edd)                        # base rides with the start node
            R[k] = base + mu * (lt * ab - lt ** 2 / 2 * edd)   # tube: x_b − u e, 0 ≤ u ≤ lt
            Ma[k] = (cg * np.cross(e, base) + (act.base_inertia - mb * cg ** 2) * al
                     + mu * ((L * lt - lt ** 2 / 2) * np.cross(e, ab)
                             - (L * lt ** 2 / 2 - lt ** 3 / 3) * np.cross(e, edd))
                     + mu * r2 * lt * al)
        else:                                                  # x_a + s e, 0 ≤ s ≤ L
            R[k] = mu * (L * aa + L ** 2 / 2 * edd)
            Ma[k] = (mu * (L ** 2 / 2 * np.cross(e, aa) + L ** 3 / 3 * np.cross(e, edd))
                     + mu * r2 * L * al)
    # L e × F_b = M_a: the transverse part of F_b; its axial part f_b is unknown
    Fb_t = np.cross(Ma, st.e) / st.L[:, None]
    nr = int(bay.fixed.sum())
    # joint i: −Σ (pin forces on the members at i) + P_i + m_i (g − a_i) + r_i = 0
    K = np.zeros((3 * bay.n, bay.m + nr))
    rhs = -((bay.loads if loads else 0.0) + bay.masses[:, None] * (g - st.a)).ravel()
    for k, (ia, ib) in enumerate(bay.conn):
        K[3 * ib:3 * ib + 3, k] -= st.e[k]
        rhs[3 * ib:3 * ib + 3] += Fb_t[k]
        K[3 * ia:3 * ia + 3, k] += st.e[k]
        rhs[3 * ia:3 * ia + 3] += R[k] - Fb_t[k]
    K[np.flatnonzero(bay.fixed.ravel()), bay.m + np.arange(nr)] = 1.0
    sol = np.linalg.solve(K, rhs)
    Fb = Fb_t + sol[:bay.m, None] * st.e
    return R - Fb, Fb


def _section(bay: _Bay, st: _State, Fb: np.ndarray, k: int, u: float):
    """Tension, shear and moment at ``u`` from member k's end node: the start side's force
    and moment on the piece between the section and the end node (Newton–Euler of that piece,
    which rides with the end node), under gravity."""
    e, al = st.e[k], st.alpha[k]
    ab = st.a[bay.conn[k, 1]] - bay.g
    N = bay.mu * (u * ab - u ** 2 / 2 * st.edd[k]) - Fb[k]
    M = (bay.mu * (u ** 2 / 2 * np.cross(e, ab) - u ** 3 / 6 * al + bay.r2 * u * al)
         - u * np.cross(e, Fb[k]))
    return float(-N @ e), N - (N @ e) * e, M


def _von_mises(bay: _Bay, T: float, V: np.ndarray, M: np.ndarray) -> float:
    """Lacy eqs. 2.24/2.25 on the round tube: max of the neutral axis' sqrt(σ² + 3 τ²) and
    the outer fibre's |σ| + |M| c / I (resultant moment)."""
    sig, tau = T / bay.A, KAPPA * np.linalg.norm(V) / bay.A
    return max(math.sqrt(sig ** 2 + 3 * tau ** 2), abs(sig) + np.linalg.norm(M) * bay.c / bay.I)


@functools.cache
def _slew():
    """The bay along the motion file: states and pin forces at every sample."""
    bay = _Bay()
    t, members, L, Ld, Ldd = _read_motion(bay)
    x = bay.coords.copy()
    states, forces = [], []
    for i in range(t.size):
        Li, Ldi, Lddi = bay.L0.copy(), np.zeros(bay.m), np.zeros(bay.m)
        Li[members], Ldi[members], Lddi[members] = L[i], Ld[i], Ldd[i]
        x = _positions(bay, x, Li)
        st = _State(bay, x, Li, Ldi, Lddi)
        states.append(st)
        forces.append(_end_forces(bay, st))
    return bay, t, (Ld, Ldd), states, forces


def _m8_force(bay, st, Fb) -> float:
    """Actuator force on M8 (N, compressing the leadscrew tube): the axial force of the whole
    tube where it meets the active base."""
    k = bay.member("M7_8")
    return -_section(bay, st, Fb, k, bay.active[k].tube_length)[0]


# ---------------------------------------------------------------------------------------
# actuator_slew1
# ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("path, sample", [("thesis.M8_force_start", 0),
                                          ("thesis.M8_force_end", -1)])
def test_m8_force_at_rest_at_the_slewed_positions(path, sample):
    """The M8 force at section 5.1's first (second) slewed position, where the slew starts
    (ends) at rest, by the joint equilibrium of the pin-jointed truss: positions by Newton's
    method on the member lengths, each member's weight carried to its pins by its own moment
    equation, the axial forces and reactions from the equilibrium of the nine joints under
    gravity and 46.0 N on N7–N9."""
    bay, _, (Ld, Ldd), states, _ = _slew()
    assert not Ld[sample].any() and not Ldd[sample].any()       # at rest
    st = states[sample]
    _, Fb = _end_forces(bay, _State(bay, st.x, st.L, np.zeros(bay.m), np.zeros(bay.m)))
    _assert_explained(_m8_force(bay, st, Fb), "actuator_slew1", path)


def test_m8_largest_force_along_the_slew():
    """The largest M8 force over the slew, by Newton–Euler of the members as rigid bodies at
    every sample of the motion file (the ramps' inertia included): at the start, the force at
    rest at section 5.1's first slewed position."""
    bay, _, _, states, forces = _slew()
    f = np.array([_m8_force(bay, st, Fb) for st, (_, Fb) in zip(states, forces)])
    assert int(np.argmax(f)) == 0
    _assert_explained(float(f.max()), "actuator_slew1", "thesis.M8_force_max")


# ---------------------------------------------------------------------------------------
# elastic_m6_strains
# ---------------------------------------------------------------------------------------

def test_m6_largest_zeroed_strain_along_the_slew():
    """Slew 1's largest zeroed M6 strain (Lacy section 5.6: a gauge zeroed at the equilibrium
    position under gravity without the loads): N/(EA) at M6's midpoint along the slew, with
    gravity, 46.0 N and the inertia loads, less the same at rest at the equilibrium position
    (the model file's) under gravity alone, by Newton–Euler of the members as rigid bodies and
    the joint equilibrium of the truss.  The bay is statically determinate, so the pinned-beam
    FE model's midpoint axial force is this one."""
    bay, _, _, states, forces = _slew()
    k = bay.member("M6")
    N = np.array([_section(bay, st, Fb, k, st.L[k] / 2)[0]
                  for st, (_, Fb) in zip(states, forces)])
    act = list(bay.active)
    assert np.allclose(bay.L0[act], 1.1684, rtol=0, atol=1e-12)     # equilibrium position
    eq = _State(bay, bay.coords, bay.L0, np.zeros(bay.m), np.zeros(bay.m))
    _, Fb_eq = _end_forces(bay, eq, loads=False)
    N_eq = _section(bay, eq, Fb_eq, k, bay.L0[k] / 2)[0]
    strain = 1e6 * (N - N_eq) / (bay.E * bay.A)
    _assert_explained(float(strain.max()), "elastic_m6_strains", "slew1.max")


# ---------------------------------------------------------------------------------------
# lacy_fig_5_12_m6_components
# ---------------------------------------------------------------------------------------

@functools.cache
def _m6_components() -> dict:
    """Maxima over the slew of M6's midpoint stresses in the hinge-axis frame (Lacy eqs.
    4.2–4.4: b̂1 = unit(x̂ × b̂3), x̂ along N2 → N3, b̂2 = b̂3 × b̂1)."""
    bay, _, _, states, forces = _slew()
    k, n2, n3 = bay.member("M6"), bay.node("N2"), bay.node("N3")
    rows = []
    for st, (_, Fb) in zip(states, forces):
        T, V, M = _section(bay, st, Fb, k, st.L[k] / 2)
        e = st.e[k]
        b1 = np.cross(st.x[n3] - st.x[n2], e)
        b1 /= np.linalg.norm(b1)
        b2 = np.cross(e, b1)
        sig = T / bay.A
        m1, m2 = abs(M @ b1) * bay.c / bay.I, abs(M @ b2) * bay.c / bay.I
        t1, t2 = KAPPA * abs(V @ b1) / bay.A, KAPPA * abs(V @ b2) / bay.A
        per_axis = max(math.sqrt((abs(sig) + m1) ** 2 + 3 * t1 ** 2),      # eqs. 4.75/4.76
                       math.sqrt((abs(sig) + m2) ** 2 + 3 * t2 ** 2),
                       math.sqrt(sig ** 2 + 3 * (t1 ** 2 + t2 ** 2)))
        rows.append((sig, m1, m2, math.hypot(m1, m2), t2, per_axis))
    mx = np.array(rows).max(axis=0)
    return dict(zip(("tension", "bending_b1", "bending_b2", "bending_resultant", "shear_b2",
                     "von_mises_per_axis"), map(float, mx)))


@pytest.mark.parametrize("name", ["tension", "bending_b1", "bending_b2", "bending_resultant",
                                  "shear_b2", "von_mises_per_axis"])
def test_m6_stress_components_in_the_hinge_axis_frame(name):
    """M6's largest midpoint stress components along the slew in the thesis' hinge-axis
    frame (σ_T = N/A, |M·b̂i| c/I, their resultant, τ = 2 |V·b̂2|/A, eqs. 4.75/4.76), from
    the section forces of the Newton–Euler computation of the members as rigid bodies: the
    piece from M6's midpoint to its end node in equilibrium with its pin force and its
    inertia."""
    _assert_explained(_m6_components()[name], "lacy_fig_5_12_m6_components", f"ours.{name}")


# ---------------------------------------------------------------------------------------
# lacy_slew1_members
# ---------------------------------------------------------------------------------------

def _physical(path: str) -> float:
    bay, _, _, states, forces = _slew()
    pairs = list(zip(states, forces))
    if path == "physical.M8.max":         # the tube's seven sections, N5 to the cantilever
        k = bay.member("M7_8")
        u = bay.active[k].tube_length * np.linspace(0.0, 1.0, 7)
        return max(_von_mises(bay, *_section(bay, st, Fb, k, w)) for st, (_, Fb) in pairs
                   for w in u)
    k = bay.member(path.split(".")[-1 if path.startswith("physical.compression.") else -2])
    mid = [_section(bay, st, Fb, k, st.L[k] / 2) for st, (_, Fb) in pairs]
    if path.startswith("physical.compression."):
        return -min(T for T, _, _ in mid)
    return max(_von_mises(bay, *s) for s in mid)


@pytest.mark.parametrize("path", ["physical.M8.max", "physical.M6.max", "physical.M19.max",
                                  "physical.compression.M19"])
def test_member_stresses_along_the_slew(path):
    """Largest von Mises stresses (Lacy eqs. 2.24/2.25, the round tube's resultant moment)
    of M6 and M19 at their midpoints and of M8, the leadscrew tube pinned at N5, at seven
    sections from N5 to where it meets the active base, and M19's largest midpoint
    compression, along the slew at 46.0 N: section forces of the Newton–Euler computation of
    the members as rigid bodies."""
    _assert_explained(_physical(path), "lacy_slew1_members", path)


@pytest.mark.parametrize("path, lever", [("m8_steps.pin_N4.max", "ls"),
                                         ("m8_steps.lever_l2.max", "l2")])
def test_appendix_c_cantilever_of_m8(path, lever):
    """M8's largest stress by Appendix C's cantilever equations (pin force of M7/8 at N4,
    the tube's centre-of-gravity acceleration reached from N4, lever ls/2 or the listing's
    l2/2 with l2 the length of M2, the per-axis von Mises of eqs. 4.75/4.76 in the code's
    frame of M7/8, Appendix D's tube), fed with the pin force, node acceleration and member
    rates of the Newton–Euler computation of the members as rigid bodies:

        F = m a_cg − f − m g,  M1 = I α1 + (ls/2) b̂2·(f − F),
        M2 = −I α1 + (ls/2) b̂1·f − lever b̂1·F,  I = m (3 OD² + 3 ID² + 4 ls²)/48.
    """
    bay, _, _, states, forces = _slew()
    k = bay.member("M7_8")
    n4, n5, n6 = bay.node("N4"), bay.node("N5"), bay.node("N6")
    ls = bay.active[k].tube_length
    arm = ls / 2 if lever == "ls" else bay.L0[bay.member("M2")] / 2
    half = ls / 2
    mass = bay.mu * ls
    inertia = mass / 48 * (3 * bay.od ** 2 + 3 * bay.id ** 2 + 4 * ls ** 2)
    unit = lambda v: v / np.linalg.norm(v)
    stress = []
    for st, (Fa, _) in zip(states, forces):
        b3 = unit(st.x[n5] - st.x[n4])
        b1 = unit(np.cross(unit(st.x[n6] - st.x[n4]), b3))
        b2 = np.cross(b3, b1)
        w1, w2 = b1 @ st.omega[k], b2 @ st.omega[k]
        a1, a2 = b1 @ st.alpha[k], b2 @ st.alpha[k]
        a4 = st.a[n4]
        acg = (b1 * (b1 @ a4 + a2 * half) + b2 * (b2 @ a4 - a1 * half)
               + b3 * (b3 @ a4 - (w1 ** 2 + w2 ** 2) * half))
        f = Fa[k]                                   # the pin force of M7/8 at N4
        F = mass * acg - f - mass * bay.g
        M1 = inertia * a1 + half * (b2 @ (f - F))
        M2 = -inertia * a1 + half * (b1 @ f) - arm * (b1 @ F)
        sig = abs(b3 @ F) / bay.A
        stress.append(max(
            math.sqrt((sig + abs(M1) * bay.c / bay.I) ** 2 + 3 * (KAPPA * (b1 @ F) / bay.A) ** 2),
            math.sqrt((sig + abs(M2) * bay.c / bay.I) ** 2 + 3 * (KAPPA * (b2 @ F) / bay.A) ** 2)))
    _assert_explained(max(stress), "lacy_slew1_members", path)
