"""An FE model that cannot be solved at some step of a motion (``elastic``, ``transient``) is
refused in one line that names the model file, the step and its time, and the nodes by the
model's ids; the copies of the structure that solve many steps at once (``B@0``, ``B@1``, …)
never appear, and the mechanisms counted are those of that step."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import MechanismError
from trussfe.fem.discretisation import discretise
from trussfe.io.model_file import read_model
from trussfe.response.along_motion import stacked_structure

MODEL = mesh_path("triangular_truss_motion_active.toml")
MOTION = str(mesh_path("triangular_truss_motion_3s.toml"))


@pytest.fixture
def soft_model(tmp_path):
    """The triangular truss with a modulus below what its stiffness can resolve."""
    text = MODEL.read_text()
    assert "E = 71.0e9" in text
    p = tmp_path / "soft.toml"
    p.write_text(text.replace("E = 71.0e9", "E = 1e-320"))
    return p


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    assert "Traceback" not in err
    return lines[0]


@pytest.mark.parametrize("command", ["elastic", "transient"])
def test_error_names_step_time_and_model_nodes(soft_model, capsys, tmp_path, command):
    out = tmp_path / "r.json"
    rc = main([command, str(soft_model), "--motion", MOTION, "--json", str(out)])
    line = _one_line(capsys)
    assert rc == 2 and not out.exists()
    assert line.startswith(f"trussfe: error: {soft_model}: step 0 (t = 0 s): "), line
    assert "moving nodes: B;" in line
    assert "@" not in line
    assert "1800" not in line          # the copies' mechanisms summed over the steps


def test_one_copy_keeps_the_model_ids():
    from trussfe.response.along_motion import copy_ids
    s = read_model(MODEL)
    assert copy_ids(s.node_ids, 1) == list(s.node_ids)
    assert copy_ids(s.node_ids, 2)[s.n_nodes] == f"{s.node_ids[0]}@1"
    one = stacked_structure(s, s.coords[None])
    assert list(one.member_ids) == list(s.member_ids)


def test_transient_names_the_first_singular_step_of_a_block():
    """A block whose second step is a collinear (singular) position: the error names step
    k0 + 1 and its time, diagnosed on the single model."""
    from trussfe.response.transient import _singular_step_error
    s = read_model(MODEL)
    single = discretise(s, bar_model="pinned-beam", subdivisions=2)
    B = s.node_index("B")
    flat = s.coords.copy()
    flat[B] = [4.0, 0.0]                     # O2-B along O2-O1: B moves freely across
    Ks = [discretise(s.with_coords(x), bar_model="pinned-beam", subdivisions=2).stiffness()
          for x in (s.coords, flat)]
    block = SimpleNamespace(sparse=lambda which, dofs: [K[dofs][:, dofs] for K in Ks])
    time = np.array([0.0, 0.06, 0.12, 0.18, 0.24])
    err = _singular_step_error(block, single, s, 3, time)
    assert isinstance(err, MechanismError)
    assert err.item == f"{s.source}: step 4 (t = 0.24 s)"
    assert "B" in err.moving_nodes and "@" not in str(err)


def test_property_refused_on_the_copies_names_the_model_member():
    """A modulus refused while the steps are discretised together names the member as the
    model does (``follower``, not ``follower@0``)."""
    import dataclasses

    import trussfe
    from trussfe.errors import InputError

    s = read_model(MODEL)
    no_e = s.with_materials({0: dataclasses.replace(s.materials[0], E=0.0)})
    with pytest.raises(InputError) as info:
        trussfe.elastic(no_e, motion=MOTION)
    assert f"(member {s.member_ids[0]})" in str(info.value)
    assert "@" not in str(info.value)
