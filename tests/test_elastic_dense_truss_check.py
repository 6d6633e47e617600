# SPDX-License-Identifier: MIT
"""``trussfe elastic`` at frozen instants of a motion against a dense direct-stiffness solve
of the pin-jointed truss written here: node positions from the actuator lengths, velocities
and accelerations from the compatibility equations, the loads of docs/elastic.md (tube,
rotary inertia, active base at min(cg, L − L_t) with its transfer couple, nodal masses and
loads) taken to the joints as the statically exact end loads of a pin-ended member (linear
bar shape functions axially, simple-beam reactions across), and the joint displacements,
reactions and tube-midpoint axial forces of that truss.  Also: a model with ``[load_cases]``
is refused."""
import json
import tomllib

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy import signal

from trussfe import api
from trussfe._resources import mesh_path
from trussfe.api.model import as_structure
from trussfe.cli import main
from trussfe.errors import InputError

_GX, _GW = np.polynomial.legendre.leggauss(4)      # exact for the quadratic integrands here


def _third_order(t, duration):
    """Lacy's actuator model (section 2.2, docs/rigid-body.md): unit-step response of
    2ωn³ / ((s² + 2ζωn s + ωn²)(s + 2ωn)), ζ = 0.8, ωn = 6 / (ζ 0.9 T), and its two time
    derivatives, from scipy.signal."""
    z = 0.8
    wn = 6.0 / (z * 0.9 * duration)
    den = np.polymul([1.0, 2 * z * wn, wn ** 2], [1.0, 2 * wn])
    _, y = signal.step(signal.lti([2 * wn ** 3], den), T=t)
    _, yd = signal.impulse(signal.lti([2 * wn ** 3], den), T=t)
    _, ydd = signal.impulse(signal.lti([2 * wn ** 3, 0.0], den), T=t)
    return y, yd, ydd


def _integrate(segs, x_hi, weight):
    """∫ weight(x) q(x) dx over the parts of the segments (x0, x1, q0, q1) below x_hi."""
    out = np.zeros(3)
    for x0, x1, q0, q1 in segs:
        hi = min(x1, x_hi)
        if hi <= x0:
            continue
        for xg, wg in zip(0.5 * (hi - x0) * (_GX + 1) + x0, 0.5 * (hi - x0) * _GW):
            out = out + wg * weight(xg) * (q0 + q1 * xg)
    return out


def _independent(model, motion, steps):
    """Joint displacements, reactions and tube-midpoint tensions at the given steps."""
    s = as_structure(model)
    cfg = tomllib.loads(open(model, encoding="utf-8").read())
    mot = tomllib.loads(open(motion, encoding="utf-8").read())["motion"]
    T, ns = mot["duration"], mot["steps"]
    t = np.arange(ns + (1 if mot.get("include_end", False) else 0)) * T / ns
    y, yd, ydd = _third_order(t, T)
    n, m, d = s.n_nodes, s.n_members, s.dim
    conn = np.asarray(s.connectivity)
    X = np.array(s.coords, dtype=float)
    L_model = np.linalg.norm(X[conn[:, 1]] - X[conn[:, 0]], axis=1)
    act = {s.member_ids.index(k): v for k, v in cfg["active_members"].items()}
    free = ~np.asarray(s.supports)[:, :d].reshape(-1).astype(bool)
    EA = np.asarray(s.E) * np.asarray(s.area)
    mu = np.asarray(s.density) * np.asarray(s.area)
    sec = next(iter(cfg["sections"].values()))
    r2 = (sec["outer_diameter"] ** 2 + sec["inner_diameter"] ** 2) / 16.0     # I/A of a tube
    g = np.zeros(3)
    g[:d] = s.gravity
    pad = (lambda v: np.r_[v, 0.0]) if d == 2 else (lambda v: np.asarray(v))
    out = {}
    for i in steps:
        L, Ld, Ldd = L_model.copy(), np.zeros(m), np.zeros(m)
        for j, a in act.items():
            l0, l1 = mot["start"][s.member_ids[j]], mot["end"][s.member_ids[j]]
            L[j], Ld[j], Ldd[j] = l0 + (l1 - l0) * y[i], (l1 - l0) * yd[i], (l1 - l0) * ydd[i]
        for _ in range(60):                       # positions: Newton on |x_b − x_a|² = L²
            R = X[conn[:, 1]] - X[conn[:, 0]]
            J = np.zeros((m, n * d))
            for j, (a, b) in enumerate(conn):
                J[j, a * d:a * d + d], J[j, b * d:b * d + d] = -2 * R[j], 2 * R[j]
            dx = np.linalg.lstsq(J[:, free], L ** 2 - (R ** 2).sum(1), rcond=None)[0]
            X.reshape(-1)[free] += dx
            if np.abs(dx).max() < 1e-15:
                break
        R = X[conn[:, 1]] - X[conn[:, 0]]
        B = np.zeros((m, n * d))
        for j, (a, b) in enumerate(conn):
            B[j, a * d:a * d + d], B[j, b * d:b * d + d] = -R[j], R[j]
        V = np.zeros(n * d)
        V[free] = np.linalg.lstsq(B[:, free], L * Ld, rcond=None)[0]
        V = V.reshape(n, d)
        Vr = V[conn[:, 1]] - V[conn[:, 0]]
        Acc = np.zeros(n * d)
        Acc[free] = np.linalg.lstsq(B[:, free], L * Ldd + Ld ** 2 - (Vr ** 2).sum(1),
                                    rcond=None)[0]
        Acc = Acc.reshape(n, d)
        F = np.zeros((n, 3))
        K = np.zeros((n * d, n * d))
        members = []
        for j, (a, b) in enumerate(conn):
            e = pad(R[j]) / L[j]
            aa, ab = pad(Acc[a]), pad(Acc[b])
            ed = (pad(Vr[j]) - Ld[j] * e) / L[j]
            edd = (ab - aa - Ldd[j] * e - 2 * Ld[j] * ed) / L[j]
            alpha = np.cross(e, edd)
            if j in act:     # tube at fixed distance from the end node; base fixed to the start
                ac = act[j]
                xt, cg, mb = L[j] - ac["tube_length"], ac["base_cg"], ac["base_mass"]
                segs = [(xt, L[j], -mu[j] * (ab - L[j] * edd - g), -mu[j] * edd)]
                Fb = -mb * (aa + cg * edd - g)
                xp = min(cg, xt)
                Cb = -(mb * ac["base_length"] ** 2 / 12) * alpha + np.cross((cg - xp) * e, Fb)
                point, xm = [(xp, Fb)], L[j] - ac["tube_length"] / 2
            else:
                xt = 0.0
                segs = [(0.0, L[j], -mu[j] * (aa - g), -mu[j] * (ab - aa) / L[j])]
                Cb, point, xm = np.zeros(3), [], L[j] / 2
            C = Cb - mu[j] * r2 * alpha * (L[j] - xt)            # all couples on the member
            fa = _integrate(segs, L[j], lambda x: 1 - x / L[j]) + np.cross(e, C) / L[j]
            fb = _integrate(segs, L[j], lambda x: x / L[j]) - np.cross(e, C) / L[j]
            for xq, Fq in point:
                fa, fb = fa + Fq * (1 - xq / L[j]), fb + Fq * xq / L[j]
            F[a] += fa
            F[b] += fb
            k = EA[j] / L[j] * np.outer(e[:d], e[:d])
            ia, ib = slice(a * d, a * d + d), slice(b * d, b * d + d)
            K[ia, ia] += k
            K[ib, ib] += k
            K[ia, ib] -= k
            K[ib, ia] -= k
            below = _integrate(segs, xm, lambda x: 1.0) + sum(
                (Fq for xq, Fq in point if xq < xm), np.zeros(3))
            members.append((a, b, e, fa @ e - below @ e))
        F += np.asarray(s.masses)[:, None] * (g - np.c_[Acc, np.zeros((n, 3 - d))])
        F[:, :d] += np.asarray(s.loads)[:, :d]
        f = F[:, :d].reshape(-1)
        u = np.zeros(n * d)
        u[free] = np.linalg.solve(K[np.ix_(free, free)], f[free])
        react = np.where(free, 0.0, K @ u - f).reshape(n, d)
        u = u.reshape(n, d)
        tension = np.array([EA[j] / L[j] * ((u[b] - u[a]) @ e[:d]) + rest
                            for j, (a, b, e, rest) in enumerate(members)])
        out[i] = dict(time=t[i], coords=X.copy(), u=u, reaction=react, tension=tension,
                      load_sum=F[:, :d].sum(0))
    return out, t


@pytest.mark.parametrize("model,motion,steps", [
    ("triangular_truss_motion_active.toml", "triangular_truss_motion_3s.toml", (0, 9, 25, 49)),
    ("double_octahedron_motion_active.toml", "double_octahedron_motion_slew.toml",
     (0, 37, 120, 200)),
])
def test_frozen_instants_against_dense_truss(model, motion, steps):
    """At frozen instants of the Base Simulation (Lacy section 3.3) and of the hanging bay's
    slew, the FE joint displacements, support reactions, tube-midpoint axial forces and
    strains equal those of the dense pin-jointed truss solve of this file (1e-9 of the
    largest), the reactions balance the applied and d'Alembert loads, and the time grid is
    t_i = i T / steps (docs/rigid-body.md)."""
    model, motion = str(mesh_path(model)), str(mesh_path(motion))
    ref, t = _independent(model, motion, steps)
    r = api.elastic(model, motion=motion)
    assert_allclose(r.time, t, rtol=0, atol=1e-12)
    EA = r.structure.E * r.structure.area
    for i in steps:
        x = ref[i]
        assert_allclose(r.position[i], x["coords"], rtol=0, atol=1e-12)
        assert_allclose(r.displacement[i], x["u"], rtol=0, atol=1e-9 * np.abs(x["u"]).max())
        scale = np.abs(x["reaction"]).max()
        assert_allclose(r.reaction[i], x["reaction"], rtol=0, atol=1e-9 * scale)
        assert_allclose(r.reaction[i].sum(0), -x["load_sum"], rtol=0, atol=1e-12 * scale)
        assert_allclose(r.axial_force[i], x["tension"], rtol=0,
                        atol=1e-9 * np.abs(x["tension"]).max())
        assert_allclose(r.strain[i], x["tension"] / EA, rtol=0,
                        atol=1e-9 * np.abs(x["tension"] / EA).max())


def test_json_matches_the_dense_truss(tmp_path):
    """The ``elastic`` JSON of the Base Simulation holds, step by step, the displacements,
    reactions and midpoint axial forces of the dense truss solve of this file."""
    model = str(mesh_path("triangular_truss_motion_active.toml"))
    motion = str(mesh_path("triangular_truss_motion_3s.toml"))
    out = tmp_path / "e.json"
    assert main(["elastic", model, "--motion", motion, "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    ref, t = _independent(model, motion, (5, 30))
    assert_allclose(doc["time"], t, rtol=0, atol=1e-12)
    for i, x in ref.items():
        assert_allclose(doc["nodes"]["B"]["displacement"][i], x["u"][2], rtol=1e-9)
        assert_allclose([doc["nodes"]["O2"]["reaction"][i], doc["nodes"]["O1"]["reaction"][i]],
                        x["reaction"][:2], rtol=0, atol=1e-9 * np.abs(x["reaction"]).max())
        assert_allclose([doc["members"]["follower"]["axial_force"][i],
                         doc["members"]["active"]["axial_force"][i]], x["tension"], rtol=1e-9)


def _with_load_cases(tmp_path):
    text = mesh_path("triangular_truss_motion_active.toml").read_text(encoding="utf-8")
    text = text.replace("[supports]", "[load_cases.live]\nloads = { B = [100.0, 0.0] }\n\n"
                        "[load_cases.dead]\ngravity = true\n\n[supports]")
    p = tmp_path / "cases.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_load_cases_are_refused(tmp_path, capsys):
    """A model with ``[load_cases]`` gives every action in a case and no ``[loads]``
    (docs/model-format.md, *Load cases*): the response along a motion, which applies
    ``[loads]`` and ``[model] gravity``, refuses it in one line with exit status 2 instead of
    leaving out the 100 N of case ``live``."""
    p = _with_load_cases(tmp_path)
    with pytest.raises(InputError, match="load cases"):
        api.elastic(str(p), motion=str(mesh_path("triangular_truss_motion_3s.toml")))
    rc = main(["elastic", str(p), "--motion", str(mesh_path("triangular_truss_motion_3s.toml"))])
    err = capsys.readouterr().err
    assert rc == 2
    assert err.startswith("trussfe: error:") and err.count("\n") == 1
