# SPDX-License-Identifier: MIT
"""``simulate --method bay-by-bay`` (Lacy chapter 6 on a model file) against the direct
analysis of the whole chain, the chain detection, and the top-plane rotation split over the
bays (``meshes/chain3_motion_rotation.toml``)."""
import json
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.rigid.bays import chain_layout
from trussfe.rigid.motion_file import load_motion
from trussfe.rigid.slew import plane_normal

MESHES = Path(__file__).resolve().parents[1] / "meshes"
CHAIN3 = MESHES / "chain3_motion_active.toml"
ROTATION = "chain3_motion_rotation.toml"


@pytest.fixture(scope="module")
def both():
    d = trussfe.simulate(CHAIN3, motion=ROTATION, steps=12, method="direct")
    b = trussfe.simulate(CHAIN3, motion=ROTATION, steps=12, method="bay-by-bay")
    return d.solution, b.solution


def test_bay_by_bay_equals_direct_on_the_shipped_chain(both):
    """Reference: the direct analysis (the whole chain as one truss).  Every field of the
    bay-by-bay analysis (kinematics up the chain, forces down, Lacy §6.1–6.2) agrees to
    1e-10 of its largest value (round-off and the 1e-12 position solve), and the chain
    really moves."""
    d, b = both
    for name in ("coords", "velocity", "acceleration"):
        x, y = getattr(d.kinematics, name), getattr(b.kinematics, name)
        assert_allclose(y, x, rtol=0, atol=1e-10 * np.abs(x).max(), err_msg=name)
    for x, y in ((d.forces.tension_end, b.forces.tension_end),
                 (d.static_forces.tension_end, b.static_forces.tension_end),
                 (d.forces.reactions, b.forces.reactions),
                 (d.stresses.von_mises, b.stresses.von_mises),
                 (d.actuator_force, b.actuator_force)):
        assert_allclose(y, x, rtol=0, atol=1e-10 * np.abs(x).max())
    assert np.abs(d.kinematics.acceleration).max() > 0.05
    assert b.options["method"] == "bay-by-bay" and d.options["method"] == "direct"


def test_ground_reactions_balance_the_chain_at_rest(both):
    """Global statics at the first step (the third-order motion starts at rest): the
    bay-by-bay ground reactions carry the weight of the tubes and active bases, and the
    46 N on each of the three top nodes (equilibrium)."""
    _, b = both
    bodies = b.bodies
    weight = (bodies.tube_mass.sum() + bodies.base_mass.sum()) * 9.81
    total = b.forces.reactions[0].sum(axis=0)
    assert_allclose(total, [0.0, 0.0, weight + 3 * 46.0], rtol=1e-12, atol=1e-9)


def test_the_layout_of_the_shipped_chains():
    """Three bays found in the 3-bay file, ten in the catalogue-written 10-bay file; at the
    equilibrium position each next-base node stands straight above the base node it
    corresponds to (the top plane is the base translated by the bay's height, 1.12183 m)."""
    for path, nb in ((CHAIN3, 3), (MESHES / "double_octahedral_chain_10.toml", 10)):
        lay = chain_layout(trussfe.read_model(path))
        x = lay.template.coords
        assert lay.n_bays == nb and lay.members.shape == (nb, 18)
        assert_allclose(x[list(lay.next_base)] - x[:3], [[0, 0, 1.1218253458835143]] * 3,
                        atol=1e-12)
    assert chain_layout(trussfe.read_model(CHAIN3)).ground_members.size == 3


def test_rotation_split_over_the_bays():
    """Lacy §6.1's example: every bay's active members take the same lengths, and the
    chain's top plane ends tilted by three times the single-bay tilt (the bays' relative
    rotations compose about one axis): 3 × 14.142° × y(T), y(T) = 1.0028226 the third-order
    profile at the end (Lacy §2.2)."""
    s = trussfe.read_model(CHAIN3)
    m = load_motion(MESHES / ROTATION, s, steps=20)
    L = m.length.reshape(m.n_steps, 3, 3)
    assert_allclose(L, L[:, :1].repeat(3, axis=1), rtol=0, atol=0)
    assert np.ptp(L) > 0.1
    r = trussfe.simulate(s, motion=m, method="bay-by-bay")
    top = [s.node_index(n) for n in ("N19", "N20", "N21")]
    n = plane_normal(r.position[-1, top])
    tilt = math.degrees(math.acos(abs(n[2])))
    from trussfe.rigid.motion import third_order_response
    y_end = third_order_response(np.array([4.0]), 4.0)[0][0]
    assert tilt == pytest.approx(3 * 14.142135623730951 * y_end, rel=1e-8)
    # the tilt is about (n1 + n2)/√2: the normal leans along (1, −1, 0)
    assert abs(n[0] + n[1]) < 1e-9


def test_cli_json_of_both_methods_agree(tmp_path, capsys):
    """``--method bay-by-bay`` and the default give the same JSON numbers (1e-9 of the
    largest force) and record the method in ``options``."""
    out = {}
    for method in ("direct", "bay-by-bay"):
        f = tmp_path / f"{method}.json"
        assert main(["simulate", str(CHAIN3), "--motion", str(MESHES / ROTATION), "--steps", "4",
                     "--method", method, "--json", str(f)]) == 0
        out[method] = json.loads(f.read_text())
    capsys.readouterr()
    assert out["direct"]["options"].pop("method") == "direct"
    assert out["bay-by-bay"]["options"].pop("method") == "bay-by-bay"

    def numbers(doc, prefix=""):
        if isinstance(doc, dict):
            for k, v in doc.items():
                yield from numbers(v, f"{prefix}.{k}")
        elif isinstance(doc, list):
            for i, v in enumerate(doc):
                yield from numbers(v, f"{prefix}[{i}]")
        elif isinstance(doc, (int, float)) and not isinstance(doc, bool):
            yield prefix, float(doc)
        else:
            yield prefix, doc

    a, b = dict(numbers(out["direct"])), dict(numbers(out["bay-by-bay"]))
    assert a.keys() == b.keys()
    for k, v in a.items():
        if isinstance(v, float):
            assert b[k] == pytest.approx(v, rel=1e-9, abs=1e-9), k
        else:
            assert b[k] == v, k


@pytest.mark.parametrize("argv, message", [
    (["triangular_truss_static.toml", "--method", "bay-by-bay"], "the model is planar"),
    (["double_octahedron_equilibrium.toml", "--method", "bay-by-bay", "--scheme", "thesis"],
     "cannot be combined with --scheme thesis"),
    (["chain3_motion_active.toml", "--method", "bays"], "invalid choice: 'bays'"),
])
def test_bad_method_use_is_one_line_exit_2(argv, message, capsys):
    """Bad input: one line on stderr, exit status 2."""
    assert main(["simulate", str(MESHES / argv[0]), *argv[1:]]) == 2
    err = capsys.readouterr().err
    assert err.startswith("trussfe: error: ") and err.count("\n") == 1 and message in err


def test_api_method_is_checked():
    """The API refuses an unknown method with the command line's message."""
    with pytest.raises(InputError, match="--method"):
        trussfe.simulate(CHAIN3, method="bay_by_bay")


def test_a_chain_with_a_different_bay_is_refused():
    """A chain whose second bay is not a copy of the first (one node moved) is refused,
    saying which bay."""
    s = trussfe.read_model(CHAIN3)
    x = np.array(s.coords)
    x[s.node_index("N10")] += [0.0, 0.0, 0.01]
    with pytest.raises(InputError, match="bay 2 is not a copy of bay 1"):
        chain_layout(s.with_coords(x))


def test_bay_lengths_take_each_bay_active_member_from_its_motion_column():
    """Every bay's active lengths, rates and accelerations are those of its members in the
    motion (an active member the motion does not drive keeps its model length and zero
    rates; a member listed twice takes its last column), checked against the model's member
    lengths and the motion's columns member by member."""
    from trussfe.rigid.bays import bay_lengths
    from trussfe.rigid.motion import Motion
    from trussfe.studies.lacy_rigid import double_octahedral_chain
    chain = double_octahedral_chain(4)
    layout = chain_layout(chain)
    acts = np.array([a.member for a in chain.extensions["active_members"]])
    members = np.concatenate([acts[1:], acts[2:3]])          # acts[0] undriven, one twice
    rng = np.random.default_rng(2)
    nt = 6
    length, rate, acc = (rng.random((nt, members.size)) for _ in range(3))
    motion = Motion(time=np.arange(nt) * 0.1, members=members, length=length, velocity=rate,
                    acceleration=acc, source="test", first_step=0)
    L, Ld, Ldd = bay_lengths(chain, layout, motion)
    cols = layout.members[:, layout.active]
    model = chain.lengths()
    for (b, a), k in np.ndenumerate(cols):
        hits = np.flatnonzero(members == k)
        if hits.size:
            j = hits[-1]
            for got, want in ((L, length), (Ld, rate), (Ldd, acc)):
                np.testing.assert_array_equal(got[:, b, a], want[:, j])
        else:
            np.testing.assert_array_equal(L[:, b, a], model[k])
            assert not Ld[:, b, a].any() and not Ldd[:, b, a].any()
    assert np.isin(acts[0], cols) and not np.isin(acts[0], members)


def test_chain_layout_is_kept_with_the_model():
    """A model's layout is found once and kept while the model exists (read-only arrays); a
    changed model (another object) gets its own, and a non-chain is still refused."""
    import gc
    import weakref
    from trussfe.studies.lacy_rigid import double_octahedral_chain
    chain = double_octahedral_chain(3)
    first = chain_layout(chain)
    assert chain_layout(chain) is first
    assert not first.nodes.flags.writeable and not first.members.flags.writeable
    moved = chain.variant(coords=chain.coords * 2.0)
    other = chain_layout(moved)
    assert other is not first and np.array_equal(other.nodes, first.nodes)
    ref = weakref.ref(moved)
    del moved, other
    gc.collect()
    assert ref() is None                                   # the kept layout does not hold it
    bent = chain.coords.copy()
    bent[-1] += [0.1, 0.0, 0.0]                            # the last bay no longer a copy
    with pytest.raises(InputError, match="not a copy"):
        chain_layout(chain.variant(coords=bent))
