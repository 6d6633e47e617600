# SPDX-License-Identifier: MIT
"""Default scales a new user meets: gravity in post-critical analysis, member buckling that
is not modelled, round-off in the elastic comparison, the default mode count, actuators
without data.  References: the linear static solution (small-deflection limit of the
dead-load state), the Euler load π²EI/L² (Lacy eq. 2.26), statics (the FE and rigid-body
section forces of a structure at rest are equal), the model's own DOF count."""
from __future__ import annotations

import json

import numpy as np
from numpy.testing import assert_allclose

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.mechanics.euler import member_euler_loads
from trussfe.fem.static import solve_static
from trussfe.io.model_file import read_model
from trussfe.nonlinear.analysis import run_postcritical, unmodelled_buckling


def _weighted_triangle(load=1.0):
    s = read_model(mesh_path("triangular_truss_weight.toml"))
    loads = np.array(s.loads)
    loads[s.node_index("B"), 1] = -load
    return s.with_loads(loads)


def test_gravity_is_a_constant_dead_load_in_postcritical(equilibrium):
    """The path starts from the equilibrium under the weight alone (λ = 0) and carries it at
    every λ: at λ = 0 the nonlinear state is the linear self-weight solution to the
    geometric nonlinearity (u/L ≈ 1e-5), and the load pattern adds to it."""
    s = _weighted_triangle()
    res = run_postcritical(s, control="load", steps=2, step=10.0, max_load_factor=20.0)
    m = res.model
    assert np.any(m.dead != 0)
    lin = solve_static(s, loads=np.zeros_like(s.loads))            # the weight alone
    equilibrium(lin, loads=np.zeros_like(s.loads))
    u0 = m.joint_displacements(res.path[0].u)
    assert_allclose(u0, lin.displacements[:, :2], rtol=0,
                    atol=1e-4 * np.abs(lin.displacements).max())
    assert np.abs(u0).max() > 0
    both = solve_static(s, loads=20.0 * s.loads)
    u1 = m.joint_displacements(res.path[-1].u)
    assert_allclose(res.path[-1].load_factor, 20.0)
    assert_allclose(u1, both.displacements[:, :2], rtol=0,
                    atol=1e-4 * np.abs(both.displacements).max())


def test_postcritical_summary_says_gravity_is_a_dead_load(tmp_path, capsys):
    p = tmp_path / "w.toml"
    p.write_text(mesh_path("triangular_truss_weight.toml").read_text()
                 + '\n[loads]\nB = [0.0, -1.0]\n')
    assert main(["postcritical", str(p), "--control", "load", "--steps", "1",
                 "--max-load-factor", "5", "--json", str(tmp_path / "o.json")]) == 0
    assert "constant dead load" in capsys.readouterr().out
    assert json.loads((tmp_path / "o.json").read_text())["gravity_dead_load"] is True


def test_member_passing_its_euler_load_is_named_once_on_stderr(capsys):
    """Without [failure] a bar is not allowed to buckle: the first one to pass π²EI/L² is
    named, with the load factor, in one stderr line."""
    path = mesh_path("triangular_truss_static.toml")
    assert main(["postcritical", str(path)]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "member buckling is not modelled" in err[0]
    s = read_model(path)
    res = run_postcritical(s)
    mem, lam, pe = unmodelled_buckling(res)
    assert_allclose(pe, member_euler_loads(s)[mem], rtol=1e-12)
    assert f"member {s.member_ids[mem]} exceeds its Euler load" in err[0]
    k = [p.load_factor for p in res.path].index(lam)
    assert -res.path[k].forces[mem] > pe and -res.path[k - 1].forces[mem] <= pe


def test_elastic_comparison_of_a_pin_jointed_structure_is_not_divided_by_zero(capsys):
    """The double octahedron at rest: FE and rigid forces agree to round-off, and so does
    the largest scaled difference (its moments are all round-off zeros)."""
    assert main(["elastic", str(mesh_path("double_octahedron_equilibrium.toml"))]) == 0
    out = capsys.readouterr().out
    diff = float(out.rsplit("largest scaled difference", 1)[1].split()[0])
    assert diff < 1e-6


def test_default_mode_count_on_a_model_with_fewer_free_dofs(capsys, tmp_path):
    """The README's triangular truss has 2 free DOFs: the default run computes both and
    says so; an explicit count above that is still refused."""
    path = str(mesh_path("triangular_truss_static.toml"))
    assert main(["modes", path, "--json", str(tmp_path / "m.json")]) == 0
    out = capsys.readouterr().out
    assert "all 2 modes computed" in out
    assert len(json.loads((tmp_path / "m.json").read_text())["modes"]) == 2
    assert main(["modes", path, "--count", "6"]) == 2


def test_actuators_without_an_actuators_table_is_refused(tmp_path, capsys):
    out = tmp_path / "a.json"
    rc = main(["actuators", str(mesh_path("triangular_truss_static.toml")),
               "--json", str(out)])
    assert rc == 2 and not out.exists()
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("trussfe: error:") and "[actuators]" in err[0]
