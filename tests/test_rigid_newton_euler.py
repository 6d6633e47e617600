# SPDX-License-Identifier: MIT
"""The rigid-body force model (Lacy chapters 2–4) against references computed here from first
principles: positions by Newton's method on the bar lengths, node and body accelerations by
finite differences of those positions in time, every tube cut into slices that each carry
m (a − g) and their own rotary inertia, and the Newton–Euler equations of every member and
node solved as one system; beam statics in closed form; the motor formulas of Lacy
section 2.9.  Plus the refusal of a motion no assembly can follow."""
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.errors import TrussfeError
from trussfe.mechanics.mass import gyration_squared
from trussfe.rigid.active import active_members
from trussfe.rigid.motion import Motion
from trussfe.rigid.simulate import simulate

MESHES = Path(__file__).resolve().parents[1] / "meshes"


# ---------------------------------------------------------------------------------------
# independent reference
# ---------------------------------------------------------------------------------------

def _positions(x0, conn, lengths, fixed):
    """Node positions with the given bar lengths, Newton's method from ``x0``."""
    x = np.array(x0, dtype=float)
    free = np.flatnonzero(~fixed.ravel())
    for _ in range(60):
        d = x[conn[:, 1]] - x[conn[:, 0]]
        ln = np.linalg.norm(d, axis=1)
        r = ln - lengths
        if np.abs(r).max() < 1e-14 * lengths.max():
            return x
        e = d / ln[:, None]
        J = np.zeros((len(conn),) + x.shape)
        J[np.arange(len(conn)), conn[:, 0]] -= e
        J[np.arange(len(conn)), conn[:, 1]] += e
        x.reshape(-1)[free] += np.linalg.solve(J.reshape(len(conn), -1)[:, free], -r)
    raise AssertionError("no assembly")


def _rates(f, t, h=1e-3):
    """f(t), f'(t), f''(t) by five-point stencils."""
    v = [f(t + k * h) for k in (-2, -1, 0, 1, 2)]
    return (v[2], (v[0] - 8 * v[1] + 8 * v[3] - v[4]) / (12 * h),
            (-v[0] + 16 * v[1] - 30 * v[2] + 16 * v[3] - v[4]) / (12 * h * h))


class _Reference:
    """A 3-D pin-jointed truss as rigid bodies: a passive member a uniform tube of slices, an
    active member its base (mass, centre of gravity, inertia about it) plus slices of its
    tube, which rides with the end node (docs/rigid-body.md, *Model file*)."""

    def __init__(self, s, lengths, nslice=200):
        self.s, self.lengths, self.n = s, lengths, nslice
        self.conn = s.connectivity
        self.mu = s.density * s.area
        self.r2 = gyration_squared(s.Iy, s.Iz, s.area)
        self.act = {a.member: a for a in active_members(s)}
        self._x = s.coords

    def x(self, t):
        self._x = _positions(self._x, self.conn, self.lengths(t), self.s.translation_supports)
        return self._x

    def unit(self, k, t):
        x = self.x(t)
        d = x[self.conn[k, 1]] - x[self.conn[k, 0]]
        return d / np.linalg.norm(d)

    def slices(self, k, t, u_end):
        """Centres of the ``n`` slices of member k's tube from its end node to ``u_end``."""
        x = self.x(t)
        u = (np.arange(self.n) + 0.5) * u_end / self.n
        return x[self.conn[k, 1]] - u[:, None] * self.unit(k, t)

    def tube(self, k):
        return self.act[k].tube_length if k in self.act else None

    def solve(self, t):
        s, conn = self.s, self.conn
        g = np.asarray(s.gravity, dtype=float)
        x, _, acc = _rates(self.x, t)
        n, m = s.n_nodes, s.n_members
        fixed = s.translation_supports
        nr = int(fixed.sum())
        rows, rhs, self.alpha = [], [], {}
        for k, (a, b) in enumerate(conn):
            lt = self.tube(k) or np.linalg.norm(x[b] - x[a])
            p, _, pa = _rates(lambda tt: self.slices(k, tt, lt), t)
            ms = np.full(self.n, self.mu[k] * lt / self.n)
            js = ms * (self.r2[k] + (lt / self.n) ** 2 / 12)
            e, _, edd = _rates(lambda tt: self.unit(k, tt), t)
            alpha = np.cross(e, edd)
            self.alpha[k] = alpha
            f = ms[:, None] * (pa - g)
            R = f.sum(0)
            Ma = np.cross(p - x[a], f).sum(0) + js.sum() * alpha
            if k in self.act:
                A = self.act[k]
                pb, _, ab = _rates(lambda tt: self.x(tt)[conn[k, 0]]
                                   + A.base_cg * self.unit(k, tt), t)
                fb = A.base_mass * (ab - g)
                R = R + fb
                Ma = Ma + np.cross(pb - x[a], fb) + A.base_inertia_cg * alpha
            d = x[b] - x[a]
            for c in range(3):                        # F_a + F_b = R
                row = np.zeros(6 * m + nr)
                row[6 * k + c] = row[6 * k + 3 + c] = 1.0
                rows.append(row)
                rhs.append(R[c])
            S = np.array([[0, -d[2], d[1]], [d[2], 0, -d[0]], [-d[1], d[0], 0]])
            for c in range(3):                        # d × F_b = M_a
                row = np.zeros(6 * m + nr)
                row[6 * k + 3:6 * k + 6] = S[c]
                rows.append(row)
                rhs.append(Ma[c])
        ridx = -np.ones((n, 3), dtype=int)
        ridx[fixed] = np.arange(nr)
        for i in range(n):                            # −Σ F + P + M (g − a) + r = 0
            for c in range(3):
                row = np.zeros(6 * m + nr)
                for k, (a, b) in enumerate(conn):
                    row[6 * k + c] -= a == i
                    row[6 * k + 3 + c] -= b == i
                if ridx[i, c] >= 0:
                    row[6 * m + ridx[i, c]] = 1.0
                rows.append(row)
                rhs.append(-(s.loads[i, c] + s.masses[i] * (g[c] - acc[i, c])))
        Mx, rhs = np.array(rows), np.array(rhs)
        sol = np.linalg.lstsq(Mx, rhs, rcond=None)[0]
        assert np.abs(Mx @ sol - rhs).max() < 1e-9 * np.abs(rhs).max()
        react = np.zeros((n, 3))
        react[fixed] = sol[6 * m:]
        self.fb = sol[:6 * m].reshape(m, 2, 3)[:, 1]
        return x, acc, sol[:6 * m].reshape(m, 2, 3), react

    def cut(self, k, t, u):
        """Tension, shear and moment at the cut ``u`` from member k's end node: the piece
        between the cut and the end node in Newton–Euler equilibrium (after :meth:`solve`)."""
        g = np.asarray(self.s.gravity, dtype=float)
        x = self.x(t)
        e = self.unit(k, t)
        p, _, pa = _rates(lambda tt: self.slices(k, tt, u), t)
        ms = self.mu[k] * u / self.n
        f = ms * (pa - g)
        xc = x[self.conn[k, 1]] - u * e
        N = f.sum(0) - self.fb[k]
        M = (np.cross(p - xc, f).sum(0) + self.n * ms * (self.r2[k] + (u / self.n) ** 2 / 12)
             * self.alpha[k] - np.cross(u * e, self.fb[k]))
        return -N @ e, N - (N @ e) * e, M


def _tetrahedron():
    """A tripod on three pinned base nodes, every leg active, one with its base at the apex
    (its leadscrew tube pinned to a support), a lumped mass and a load at the apex, gravity
    oblique to every axis."""
    return trussfe.model_from_dict({
        "model": {"dimension": 3, "gravity": [1.0, -2.0, -9.81]},
        "materials": {"al": {"E": 70e9, "G": 26e9, "density": 2700.0}},
        "sections": {"tube": {"outer_diameter": 0.03, "inner_diameter": 0.025}},
        "nodes": {"A": [0, 0, 0], "B": [1.2, 0, 0], "C": [0.4, 1.0, 0], "D": [0.5, 0.4, 1.1]},
        "members": {"AD": {"nodes": ["A", "D"], "section": "tube", "material": "al"},
                    "BD": {"nodes": ["D", "B"], "section": "tube", "material": "al"},
                    "CD": {"nodes": ["C", "D"], "section": "tube", "material": "al"}},
        "supports": {n: ["x", "y", "z"] for n in "ABC"},
        "masses": {"D": 3.0}, "loads": {"D": [1.0, 2.0, -3.0]},
        "active_members": {k: {"base_mass": 1.1, "base_length": 0.6, "base_cg": 0.25,
                               "tube_length": 0.7} for k in ("AD", "BD", "CD")}})


def test_tripod_against_sliced_newton_euler_reference():
    """Three actuators moving at once (sines of different frequencies, exact rates), against
    the sliced-body reference above (finite differences of the positions, the full
    Newton–Euler system of Lacy eq. 2.13 solved at once): pin forces, reactions, section
    tension, shear and moment, actuator force, to 1e-7 of their scale."""
    s = _tetrahedron()
    L0 = s.lengths()
    amp, w = np.array([0.1, -0.08, 0.05]), np.array([2.0, 3.0, 1.3])
    time = np.array([0.0, 0.55])
    mot = Motion(time, [0, 1, 2], L0 + amp * np.sin(np.outer(time, w)),
                 amp * w * np.cos(np.outer(time, w)), -amp * w * w * np.sin(np.outer(time, w)))
    r = simulate(s, mot, n_sections=4)
    ref = _Reference(s, lambda t: L0 + amp * np.sin(w * t))
    for i, t in enumerate(time):
        x, acc, ends, react = ref.solve(t)
        scale = np.abs(ends).max()
        assert_allclose(r.kinematics.acceleration[i], acc, rtol=0, atol=1e-8)
        assert_allclose(r.forces.end_force[i], ends, rtol=0, atol=1e-9 * scale)
        assert_allclose(r.forces.reactions[i], react, rtol=0, atol=1e-9 * scale)
        for k in range(3):
            for j, u in enumerate(r.sections.position[k]):
                T, V, M = ref.cut(k, t, u)
                assert r.sections.tension[i, k, j] == pytest.approx(T, abs=1e-7 * scale)
                assert_allclose(r.sections.shear[i, k, j], V, rtol=0, atol=1e-7 * scale)
                assert_allclose(r.sections.moment[i, k, j], M, rtol=0, atol=1e-7 * scale)
            # the actuator force: the axial force on the whole leadscrew tube, pushing out
            assert r.actuator_force[i, k] == pytest.approx(-ref.cut(k, t, 0.7)[0],
                                                           abs=1e-7 * scale)


# ---------------------------------------------------------------------------------------
# beam statics in closed form
# ---------------------------------------------------------------------------------------

def _triangle(gravity, mass=0.0):
    """Lacy's triangular truss, the follower (O1 → B) 2 m long, the active member O2 → B."""
    return trussfe.model_from_dict({
        "model": {"dimension": 2, "gravity": list(gravity)},
        "materials": {"al": {"E": 71e9, "G": 26.2e9, "density": 2711.5}},
        "sections": {"tube": {"outer_diameter": 0.0254, "inner_diameter": 0.022225}},
        "nodes": {"O2": [0, 0], "O1": [2, 0], "B": [1.5625, 1.9515618744994994]},
        "members": {"follower": {"nodes": ["O1", "B"], "section": "tube", "material": "al"},
                    "active": {"nodes": ["O2", "B"], "section": "tube", "material": "al"}},
        "supports": {"O2": ["x", "y"], "O1": ["x", "y"]},
        "masses": {"B": mass},
        "active_members": {"active": {"base_mass": 2.4, "base_length": 2.1, "base_cg": 1.05,
                                      "tube_length": 2.0}}})


def test_follower_under_its_weight_is_a_simply_supported_beam():
    """At rest the follower carries its weight's transverse part q = ρ A g⊥ as a simply
    supported beam: M(x) = q x (L − x)/2 (ρ A g⊥ L²/8 at midspan) and V(x) = q (L/2 − x)."""
    s = _triangle((0.0, -9.81), mass=10.0)
    r = simulate(s, n_sections=9)
    k = s.member_index("follower")
    e = r.kinematics.unit[0, k, :2]
    q = s.density[k] * s.area[k] * 9.81 * abs(e[0])       # g⊥ = |e × g| for g along −y
    L = 2.0
    x = L - r.sections.position[k]                       # from the start node O1
    assert_allclose(np.abs(r.sections.moment[0, k, :, 2]), q * x * (L - x) / 2,
                    rtol=1e-12, atol=1e-12 * q * L * L)
    assert abs(r.sections.moment[0, k, 4, 2]) == pytest.approx(q * L * L / 8, rel=1e-12)
    assert_allclose(np.linalg.norm(r.sections.shear[0, k], axis=-1),
                    q * np.abs(L / 2 - x), rtol=1e-12, atol=1e-12 * q * L)


def test_rotating_follower_carries_a_triangular_inertia_load():
    """Without gravity the follower turns about its pinned start node O1, so its points
    accelerate transversely by x α (x from O1): the load ρ A x α is triangular and the
    simply supported beam's moment is M(x) = q₀ x (L² − x²)/(6 L), q₀ = ρ A L α (a uniform
    couple of the sections' rotary inertia adds no moment to a simply supported beam)."""
    s = _triangle((0.0, 0.0))
    k, ka = s.member_index("follower"), s.member_index("active")
    time = np.array([0.0, 0.37, 0.81])
    mot = Motion(time, [ka], (2.5 + 0.3 * (1 - np.cos(np.pi * time)))[:, None],
                 (0.3 * np.pi * np.sin(np.pi * time))[:, None],
                 (0.3 * np.pi ** 2 * np.cos(np.pi * time))[:, None])
    r = simulate(s, mot, n_sections=9)
    L = 2.0
    x = L - r.sections.position[k]
    for i in range(time.size):
        q0 = s.density[k] * s.area[k] * L * r.kinematics.alpha[i, k, 2]
        assert abs(q0) > 0.1
        assert_allclose(np.abs(r.sections.moment[i, k, :, 2]),
                        np.abs(q0 * x * (L * L - x * x) / (6 * L)), rtol=1e-10,
                        atol=1e-12 * abs(q0) * L * L)


# ---------------------------------------------------------------------------------------
# motions no assembly can follow; actuators the motion does not name
# ---------------------------------------------------------------------------------------

def _grounded_active():
    """A triangle whose base member, between the two pinned supports, is declared active."""
    return trussfe.model_from_dict({
        "model": {"dimension": 2, "gravity": [0.0, -9.81]},
        "materials": {"al": {"E": 71e9, "density": 2711.5}},
        "sections": {"tube": {"outer_diameter": 0.0254, "inner_diameter": 0.022225}},
        "nodes": {"O2": [0, 0], "O1": [2.6, 0], "B": [1.1, 1.7]},
        "members": {"ground": {"nodes": ["O2", "O1"], "section": "tube", "material": "al"},
                    "right": {"nodes": ["O1", "B"], "section": "tube", "material": "al"},
                    "left": {"nodes": ["O2", "B"], "section": "tube", "material": "al"}},
        "supports": {"O2": ["x", "y"], "O1": ["x", "y"]},
        "active_members": {"ground": {"base_mass": 1.4, "base_length": 1.0,
                                      "tube_length": 1.9}}})


def test_motion_of_a_member_between_supports_is_refused():
    """The two pinned supports stay 2.6 m apart, so no assembly has the 2.7 m the motion asks
    of the member between them (docs/rigid-body.md, *Motion files*: lengths for which no
    assembly exists are refused, the step and the member named).  Before, the motion was
    run: the member kept 2.6 m with the motion's 0.2 m/s in its inertia loads."""
    s = _grounded_active()
    k = s.member_index("ground")
    time = np.array([0.0, 0.5, 1.0])
    mot = Motion(time, [k], (2.6 + 0.2 * time)[:, None], np.full((3, 1), 0.2),
                 np.zeros((3, 1)))
    with pytest.raises(TrussfeError, match=r"step 1 \(t = 0.5 s\).*'ground'.*2\.7 m"):
        simulate(s, mot)
    # held at the supports' distance it is a motion like any other (the rest of the truss
    # at rest: the static forces)
    held = Motion(time, [k], np.full((3, 1), 2.6), np.zeros((3, 1)), np.zeros((3, 1)))
    r = simulate(s, held)
    assert_allclose(r.forces.tension_end, r.static_forces.tension_end, rtol=0, atol=1e-12)


def test_actuators_the_motion_does_not_name_hold_their_load(tmp_path):
    """A CSV history of M7_8 alone: M9_10 and M11_12 keep their model length
    (docs/actuators.md, *Measured motions*), so their motors hold the load at rest.  Every
    actuator has its histories (as in an analysis at rest); a held one's, thesis convention
    (square thread, Lacy eqs. 2.37, 2.40, 2.44 with θ̇ = θ̈ = 0):
    T_m = |F| (d_m/2) (l + π μ d_m)/(π d_m − μ l), V_m = T_m R_a/K_t."""
    s = trussfe.read_model(MESHES / "double_octahedron_actuators.toml")
    k = s.member_index("M7_8")
    L0 = s.lengths()[k]
    t = np.linspace(0.0, 2.0, 41)
    csv = tmp_path / "m7_8.csv"
    csv.write_text("time,M7_8\n" + "".join(f"{a:.17g},{L0 + 0.02 * np.sin(a):.17g}\n" for a in t))
    res = trussfe.actuators(s, motion=csv)
    assert res.actuator_ids == ("M7_8", "M9_10", "M11_12")
    sol = res.solution
    order = [a.member for a in active_members(s)]
    for act in s.extensions["actuators"]:
        if act.name == "M7_8":
            continue
        h = sol.actuators[act.name]
        F = sol.actuator_force[:, order.index(act.member)]
        d, mu, lead = act.mean_diameter, act.friction, 2 * math.pi * act.leadscrew_gain
        torque = np.abs(F) * d / 2 * (lead + math.pi * mu * d) / (math.pi * d - mu * lead)
        assert_allclose(h["motor_speed"], 0.0, atol=0)
        assert_allclose(h["motor_torque"], torque, rtol=1e-12)
        assert_allclose(h["motor_voltage"], torque * act.resistance / act.torque_constant,
                        rtol=1e-12)
    assert sol.actuators["M7_8"]["motor_speed"].max() > 0
