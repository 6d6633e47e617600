"""Transient elastic response along a prescribed motion (trussfe.response.transient).

Sources of the expected values: closed forms (rigid-body fields, the single-DOF Duhamel
solution, polynomial interpolation), the discrete energy identity of Newmark's average
acceleration rule, the rigid-body model of :mod:`trussfe.rigid` (Lacy eqs. 2.13–2.14) and the
single-model FE assembly of :mod:`trussfe.fem`.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.response import transient as tr
from trussfe.response.transient import motion_on_grid, rayleigh, transient_response
from trussfe.response.transient_fe import assemble_block, massless_active, rigid_field
from trussfe.studies.transient_slews import (
    cycloidal_motion,
    sdof_bar,
    sdof_check,
    sdof_closed_form,
    triangle_slew,
)
from trussfe.errors import AnalysisError, InputError
from trussfe.fem.discretisation import discretise
from trussfe.fem.modal import mass_matrix
from trussfe.rigid.forces import member_bodies
from trussfe.rigid.motion import Motion, third_order_motion
from trussfe.studies.lacy_rigid import L2, L3MIN, triangular_truss
from trussfe.rigid.simulate import simulate


@pytest.fixture(scope="module")
def tri():
    return triangular_truss()


def _kin_slice(kin, sl):
    return tr._slice_kin(kin, sl)


# ---------------------------------------------------------------------- FE ingredients
def test_rigid_field_is_linear_along_members(tri):
    """A rigid rotation ω × x (closed form) gives the exact station displacements of every
    member, and a uniform translation strains nothing."""
    fe = discretise(tri, "pinned-beam", 4)
    x = tri.coords
    rot = np.c_[-x[:, 1], x[:, 0]]                     # ω = 1 rad/s about z through O2
    u = rigid_field(fe, rot)
    st = fe.station_displacements(u)                   # (m, k + 1, 2)
    conn = tri.connectivity
    s = np.linspace(0.0, 1.0, 5)
    pts = x[conn[:, 0], None] + s[None, :, None] * (x[conn[:, 1]] - x[conn[:, 0]])[:, None]
    assert_allclose(st, np.stack([-pts[..., 1], pts[..., 0]], axis=-1), atol=1e-12)
    K = fe.stiffness()
    for field in (rot, np.tile([0.3, -0.7], (3, 1))):
        assert np.abs(K @ rigid_field(fe, field)).max() < 1e-8 * abs(K).max()


def test_batch_assembly_equals_single_models(tri):
    """Per-step K and M of a batch of steps equal the single-model assembly in the same
    geometry (fem.discretise + fem.modal.mass_matrix, an independent path)."""
    m = third_order_motion(tri, [L3MIN + L2], [L3MIN + 1.2 + L2], 1.0, 20, include_end=True)
    r = simulate(tri, m)
    single = discretise(massless_active(tri), "pinned-beam", 4)
    sl = slice(5, 12)
    B = assemble_block(tri, single, r.kinematics.coords[sl], _kin_slice(r.kinematics, sl),
                       member_bodies(tri), bar_model="pinned-beam", subdivisions=4)
    alld = np.arange(single.n_dof)
    Ks, Ms = B.sparse("K", alld), B.sparse("M", alld)
    Kd = B.dense("K", alld)
    for c, step in enumerate(range(5, 12)):
        fe = discretise(tri.with_coords(r.kinematics.coords[step]), "pinned-beam", 4)
        K, M = fe.stiffness(), mass_matrix(fe)
        assert abs(Ks[c] - K).max() <= 1e-12 * abs(K).max()
        assert abs(Ms[c] - M).max() <= 1e-12 * abs(M).max()
        assert_allclose(Kd[c], K.toarray(), atol=1e-12 * abs(K).max())


# ---------------------------------------------------------------------- closed forms
def test_single_dof_against_duhamel_and_order_two():
    """One active bar pushing 10 kg with a cycloidal stroke: closed-form Duhamel solution;
    Newmark's phase error (ω dt)²/12 makes the error second order in dt."""
    a, b = sdof_check(dt=4.0e-4), sdof_check(dt=2.0e-4)
    assert b["max_error"] < 4.0e-4                    # relative to the peak force
    assert_allclose(math.log2(a["max_error"] / b["max_error"]), 2.0, atol=0.02)
    assert_allclose(b["frequency_hz"], math.sqrt(1.0e5 / 10.0) / (2 * math.pi), rtol=1e-12)
    assert_allclose(b["peak"], b["peak_exact"], rtol=2e-5)
    # T·f1 = 3.2: the dynamic peak exceeds the quasi-static m·max L̈ = 78.54 N by 45 %
    assert_allclose(b["peak_qs"], 10.0 * 0.05 * 2 * math.pi / 0.2 ** 2, rtol=1e-12)
    assert b["peak"] / b["peak_qs"] > 1.4
    assert b["energy_residual"] < 1e-12


def test_single_dof_slow_stroke_is_quasi_static():
    """T·f1 = 32: the closed form's amplification is 1/(1 − r²) + residual vibration,
    r = 1/(T f1); the FE peak follows it and stays within 4 % of the quasi-static force."""
    d = sdof_check(dt=5.0e-4, duration=2.0, t_end=2.4)
    assert_allclose(d["peak"], d["peak_exact"], rtol=1e-4)
    assert abs(d["peak"] / d["peak_qs"] - 1.0) < 0.04


def test_motion_on_grid_quintic_is_exact_for_quintics():
    """C² quintic Hermite interpolation reproduces a degree-5 polynomial and its rates."""
    t = np.linspace(0.0, 1.0, 4)
    c = np.array([1.0, 0.2, -0.3, 0.5, 0.1, -0.2])      # L = Σ c_k t^k

    def poly(x, d):
        p = np.polynomial.Polynomial(c).deriv(d)
        return p(x)[:, None]

    m = Motion(t, [0], poly(t, 0), poly(t, 1), poly(t, 2))
    g = motion_on_grid(m, 0.01)
    assert_allclose(g.length, poly(g.time, 0), rtol=1e-12)
    assert_allclose(g.velocity, poly(g.time, 1), rtol=1e-11, atol=1e-12)
    assert_allclose(g.acceleration, poly(g.time, 2), rtol=1e-10, atol=1e-12)


# ---------------------------------------------------------------------- triangle
@pytest.fixture(scope="module")
def fast_frozen():
    return triangle_slew(0.3, 1.0e-3, update="frozen")


@pytest.fixture(scope="module")
def fast_updated():
    return triangle_slew(0.3, 1.0e-3)


def test_quasi_static_equals_rigid_body_forces(fast_updated):
    """Statically determinate truss, same loads: the quasi-static FE member forces are the
    rigid-body ones (Lacy eqs. 2.13–2.14) at every step; only the tube's cross-section
    rotary inertia (r²/L² ≈ 4e-5 of its transverse inertia) differs."""
    r = fast_updated
    peak = np.abs(r.axial_force_rigid).max(axis=0)
    assert np.all(np.abs(r.axial_force_qs - r.axial_force_rigid).max(axis=0) < 1e-5 * peak)
    assert_allclose(r.moment_qs[:, 0], r.moment_rigid[:, 0], rtol=1e-8,
                    atol=1e-8 * r.moment_rigid[:, 0].max())
    # starting at rest in the quasi-static state
    assert_allclose(r.axial_force[0], r.axial_force_qs[0], rtol=1e-12)


def test_energy_balance_exact_with_frozen_matrices(fast_frozen):
    """Average acceleration: E_{n+1} − E_n = Δuᵀ(f_n + f_{n+1})/2 exactly (LTI model)."""
    e = fast_frozen.energy
    assert fast_frozen.energy_residual() < 1e-12
    assert np.all(e["parametric"] == 0.0)
    # not a trivial balance: the vibration carries a fifth of the work done at T f1 = 5
    assert e["kinetic"].max() > 0.1 * e["work"].max()


def test_energy_balance_with_damping():
    """Rayleigh damping: the dissipated energy closes the balance exactly (frozen)."""
    a, b = rayleigh(0.05, 17.0, 70.0)
    r = triangle_slew(0.3, 1.0e-3, update="frozen", damping=(a, b))
    assert r.energy["dissipated"][-1] > 0.0
    assert r.energy_residual() < 1e-12
    assert np.all(np.diff(r.energy["dissipated"]) >= -1e-15)


def test_energy_residual_updated_matrices_is_second_order(fast_updated):
    """Updated K(t), M(t): with the parametric energy the residual is O(dt²)."""
    half = triangle_slew(0.3, 5.0e-4)
    ratio = fast_updated.energy_residual() / half.energy_residual()
    assert_allclose(ratio, 4.0, rtol=0.05)


def test_block_size_and_sparse_path_do_not_change_results(monkeypatch):
    """Blocks of 7 steps, and the sparse per-step LU path, give the same history."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 0.3, 60, include_end=True)
    ref = transient_response(s, m)
    small = transient_response(s, m, block=7)
    assert_allclose(small.axial_force, ref.axial_force, rtol=1e-9, atol=1e-9)
    assert_allclose(small.energy["residual"], ref.energy["residual"], atol=1e-12)
    monkeypatch.setattr(tr, "DENSE_LIMIT", 0)
    sp_ = transient_response(s, m, block=16)
    assert_allclose(sp_.axial_force, ref.axial_force, rtol=1e-8, atol=1e-8)
    assert_allclose(sp_.energy["residual"], ref.energy["residual"], atol=1e-10)


def test_slow_slew_is_quasi_static_fast_one_amplified():
    """T·f1 = 51 (T = 3 s): the elastic force stays within 2 % of the quasi-static one;
    T·f1 = 5 (T = 0.3 s): a dynamic amplification of tens of per cent."""
    slow = triangle_slew(3.0, 1.0e-3).departure()["follower"]
    fast = triangle_slew(0.3, 2.5e-4).departure()["follower"]
    assert slow["relative"] < 0.02
    assert fast["relative"] > 0.3
    assert fast["amplification"] > 1.2


def test_truss_bar_model_runs_and_balances_energy():
    """Truss bars (no bending DOFs): the frozen energy identity holds to round-off and the
    quasi-static actuator force equals the rigid-body one (its loads are nodal)."""
    s = triangular_truss()
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 0.3, 100, include_end=True)
    r = transient_response(s, m, bar_model="truss", update="frozen")
    assert r.energy_residual() < 1e-12
    u = transient_response(s, m, bar_model="truss")
    peak = np.abs(u.axial_force_rigid[:, 1]).max()
    assert np.abs(u.axial_force_qs[:, 1] - u.axial_force_rigid[:, 1]).max() < 1e-5 * peak


# ---------------------------------------------------------------------- bad input
def _short_motion(s, T=0.3, steps=30):
    return third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], T, steps, include_end=True)


@pytest.mark.parametrize("kw,item", [
    ({"dt": 0.0}, "dt"), ({"dt": -1e-3}, "dt"), ({"dt": 1.0}, "dt"),
    ({"update": "sometimes"}, "update"), ({"bar_model": "rope"}, "bar_model"),
    ({"damping": (-1.0, 0.0)}, "damping"), ({"damping": "lots"}, "damping"),
    ({"t_end": 0.5, "dt": 1e-2}, "motion"), ({"block": 0}, "block"),
    ({"k": 0}, "subdivisions"),
])
def test_bad_options_give_one_line_errors(tri, kw, item):
    with pytest.raises(InputError) as exc:
        transient_response(tri, _short_motion(tri), **kw)
    msg = str(exc.value)
    assert item in msg and "\n" not in msg


def test_motion_too_short_or_single_sample(tri):
    one = Motion([0.0], [1], [[2.5]], [[0.0]], [[0.0]])
    with pytest.raises(InputError, match="single sample"):
        transient_response(tri, one)
    uneven = Motion([0.0, 0.1, 0.3], [1], [[2.5]] * 3, [[0.0]] * 3, [[0.0]] * 3)
    with pytest.raises(InputError, match="not sampled uniformly"):
        transient_response(tri, uneven)


def test_mechanism_is_refused(tri):
    """Without the follower, node B hangs on the active member alone: a mechanism."""
    s = tri.subset_members(np.array([False, True]))
    # the active member follows the subset: renumbered from 1 to 0
    assert [a.member for a in s.extensions["active_members"]] == [0]
    with pytest.raises(AnalysisError, match="mechanism") as exc:
        transient_response(s, _short_motion(s))
    assert "\n" not in str(exc.value)


def test_held_motion_continues_as_free_vibration():
    """After a stroke that ends at rest the lengths are held: the closed form's free
    vibration continues (single DOF)."""
    s = sdof_bar()
    m = cycloidal_motion(s, 0.05, 0.2, 1.0e-4)            # ends at T = 0.2 s
    r = transient_response(s, m, bar_model="truss", update="frozen", t_end=0.35)
    exact = sdof_closed_form(r.time, 0.05, 0.2, 10.0, 1.0e5)
    assert r.time[-1] == pytest.approx(0.35)
    assert np.abs(r.axial_force[:, 0] - exact).max() < 2e-4 * np.abs(exact).max()
    assert np.all(r.axial_force_qs[r.time > 0.2 + 1e-9, 0] == pytest.approx(0.0, abs=1e-9))


# ---------------------------------------------------------------------- command line
def test_cli_transient_json_plot_and_errors(tmp_path, capsys):
    """``trussfe transient``: JSON with one value per step, a PNG, one-line errors (exit 2)."""
    import json

    from trussfe._resources import mesh_path
    from trussfe.cli import main
    from trussfe import api

    model = str(mesh_path("triangular_truss_motion_active.toml"))
    out = tmp_path / "t.json"
    png = tmp_path / "t.png"
    assert main(["transient", model, "--motion", "triangular_truss_motion_3s.toml",
                 "--dt", "0.01", "--json", str(out), "--plot", str(png)]) == 0
    doc = json.loads(out.read_text())
    assert doc["command"] == "transient" and doc["units"] == "SI"
    n = len(doc["time"])
    assert n == 295                                      # 0 … 2.94 s every 0.01 s
    for mid in ("follower", "active"):
        assert len(doc["members"][mid]["axial_force"]) == n
    assert png.read_bytes()[:4] == b"\x89PNG"
    assert api.transient(model, motion="triangular_truss_motion_3s.toml",
                         dt=0.01).to_dict()["time"] == \
        doc["time"]
    capsys.readouterr()
    assert main(["transient", model, "--motion", "triangular_truss_motion_3s.toml",
                 "--dt", "0"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("trussfe: error: --dt:") and "\n" not in err


def test_cli_transient_vtk_series(tmp_path, capsys):
    """``--vtk``: a .pvd of .vtu steps (every K-th and the last) whose arrays, read back by
    meshio and by VTK's own reader, equal the JSON histories (docs/vtk.md)."""
    import json

    import meshio
    import pyvista as pv

    from trussfe._resources import mesh_path
    from trussfe.cli import main
    from trussfe.io.vtk import read_pvd

    model = str(mesh_path("triangular_truss_motion_active.toml"))
    out, vtk = tmp_path / "t.json", tmp_path / "vtk"
    assert main(["transient", model, "--motion", "triangular_truss_motion_3s.toml",
                 "--dt", "0.02", "--json", str(out), "--vtk", str(vtk),
                 "--vtk-every", "10"]) == 0
    doc = json.loads(out.read_text())
    n = len(doc["time"])
    entries = read_pvd(vtk / "triangular_truss_motion_active.pvd")
    steps = sorted(set(range(0, n, 10)) | {n - 1})
    assert [t for t, _ in entries] == pytest.approx([doc["time"][k] for k in steps])
    ids = list(doc["members"])
    nodes = list(doc["nodes"])
    for (t, path), k in zip(entries, steps):
        m = meshio.read(path)
        for name, key in (("axial_force", "axial_force"),
                          ("axial_force_rigid", "axial_force_rigid"),
                          ("moment", "moment")):
            np.testing.assert_allclose(m.cell_data[name][0],
                                       [doc["members"][i][key][k] for i in ids], rtol=1e-12)
        d = np.array([doc["nodes"][i]["displacement"][k] for i in nodes])
        np.testing.assert_allclose(m.point_data["displacement"][:, : d.shape[1]], d,
                                   rtol=1e-12, atol=1e-300)
    grid = pv.read(entries[-1][1])
    assert "axial_stress" in grid.cell_data and "displacement_quasi_static" in grid.point_data
    capsys.readouterr()
    assert main(["transient", model, "--motion", "triangular_truss_motion_3s.toml",
                 "--vtk", str(tmp_path / "v2"), "--vtk-every", "0"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("trussfe: error: --vtk-every:") and "\n" not in err
    assert not (tmp_path / "v2").exists()


def test_double_octahedron_quasi_static_equals_rigid_body():
    """3-D (both bending planes, sparse path): the quasi-static FE axial forces and midpoint
    moments of the slewing double-octahedral bay equal the rigid-body ones (Lacy eqs. 4.20,
    section forces), and the frozen energy identity holds."""
    from trussfe.studies.transient_slews import double_octahedron_slew

    r = double_octahedron_slew(0.5, 0.025)
    assert r.fe.free.size > tr.DENSE_LIMIT                 # exercises the sparse path
    peak = np.abs(r.axial_force_rigid).max()
    assert np.abs(r.axial_force_qs - r.axial_force_rigid).max() < 1e-5 * peak
    passive = ~np.isin(np.arange(r.structure.n_members),
                       [a.member for a in r.structure.extensions["active_members"]])
    mr = r.moment_rigid[:, passive]
    assert np.abs(r.moment_qs[:, passive] - mr).max() < 1e-5 * mr.max()
    f = double_octahedron_slew(0.5, 0.025, update="frozen")
    assert f.energy_residual() < 1e-11


def test_cli_summary_skips_members_without_a_quasi_static_force(capsys, monkeypatch):
    """The summary line names the member of the largest relative departure among those with
    a quasi-static force: a member without one has no ratio (NaN), which must not be picked
    because it comes first (Python's max keeps a NaN key it starts from)."""
    from trussfe._resources import mesh_path
    from trussfe.cli import main
    from trussfe.response.transient import TransientResult

    def departure(self):
        return {"follower": {"max_abs": 0.5, "relative": float("nan")},
                "active": {"max_abs": 0.2, "relative": 0.01}}
    monkeypatch.setattr(TransientResult, "departure", departure)
    model = str(mesh_path("triangular_truss_motion_active.toml"))
    assert main(["transient", model, "--motion", "triangular_truss_motion_3s.toml",
                 "--dt", "0.01"]) == 0
    out = capsys.readouterr().out
    assert "0.2 N (1 %) in member active" in out
