"""Result arrays of the Python API are read-only (docs/python.md, *Running an analysis and
reading its arrays*): writing into one raises instead of changing the result, its other
arrays and ``to_dict()``; dicts and lists a result hands out are new at every access."""
import inspect
from pathlib import Path

import numpy as np
import pytest

import trussfe

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"

RUNS = {
    "static": lambda: trussfe.static(MESHES / "triangular_truss_static.toml"),
    "static-case": lambda: trussfe.static(MESHES / "loads_closed_forms.toml", case="tip"),
    "modes": lambda: trussfe.modes(MESHES / "triangular_truss_static.toml", count=2),
    "buckling": lambda: trussfe.buckling(MESHES / "postcritical_euler_column.toml", count=2),
    "simulate": lambda: trussfe.simulate(MESHES / "triangular_truss_motion_active.toml",
                                         motion="triangular_truss_motion_3s.toml", steps=4),
    "actuators": lambda: trussfe.actuators(MESHES / "double_octahedron_actuators.toml",
                                           motion="double_octahedron_tilt_rotation.toml",
                                           steps=3),
    "elastic": lambda: trussfe.elastic(MESHES / "triangular_truss_motion_active.toml",
                                       motion="triangular_truss_motion_3s.toml", steps=3),
    "transient": lambda: trussfe.transient(MESHES / "triangular_truss_motion_active.toml",
                                           motion="triangular_truss_motion_3s.toml", dt=0.3),
    "mechanism": lambda: trussfe.mechanism(MESHES / "mech_fourbar.toml"),
    "trace": lambda: trussfe.trace(MESHES / "mech_fourbar.toml", drive="2:y", step=0.02,
                                   steps=2),
    "topology": lambda: trussfe.topology(MESHES / "mech_fourbar.toml"),
    "postcritical": lambda: trussfe.postcritical(MESHES / "postcritical_von_mises.toml",
                                                 steps=4),
}


def _array_properties(result) -> dict[str, np.ndarray]:
    out = {}
    for name, attr in inspect.getmembers(type(result)):
        if isinstance(attr, property) and not name.startswith("_"):
            value = getattr(result, name)
            if isinstance(value, np.ndarray) and value.size:
                out[name] = value
    return out


@pytest.mark.parametrize("run", sorted(RUNS))
def test_writing_into_a_result_array_raises_and_changes_nothing(run):
    result = RUNS[run]()
    before = result.to_dict()
    arrays = _array_properties(result)
    assert arrays
    for name, value in arrays.items():
        assert not value.flags.writeable, name
        with pytest.raises(ValueError, match="read-only"):
            value.flat[0] = value.flat[0] + 1
        with pytest.raises(ValueError, match="read-only"):
            value *= 2
    assert result.to_dict() == before
    for name, value in _array_properties(result).items():
        np.testing.assert_array_equal(value, arrays[name], err_msg=name)
        copy = np.array(value)            # a copy to change, as docs/python.md says
        copy.flat[0] = (not copy.flat[0]) if copy.dtype == bool else copy.flat[0] + 1
        assert getattr(result, name).flat[0] == arrays[name].flat[0] != copy.flat[0]


def test_the_static_arrays_share_no_writable_view():
    """``displacement`` and ``rotation`` are views of one solver array; neither opens it."""
    r = RUNS["static"]()
    u = r.to_dict()["nodes"]
    with pytest.raises(ValueError):
        r.displacement[:] = 0.0
    with pytest.raises(ValueError):
        r.rotation[:] = 0.0
    assert r.to_dict()["nodes"] == u


def test_dicts_and_lists_are_new_at_every_access():
    t = RUNS["transient"]()
    before = t.to_dict()
    energy = t.energy
    energy["kinetic"] = np.zeros(1)
    energy.clear()
    assert set(t.energy) == set(before["energy"])
    assert not t.energy["kinetic"].flags.writeable
    assert t.to_dict() == before

    p = RUNS["postcritical"]()
    before = p.to_dict()
    p.events.clear()
    assert len(p.events) == len(before["events"])
    assert p.to_dict() == before


def test_path_events_handed_out_are_copies():
    p = trussfe.postcritical(MESHES / "postcritical_von_mises.toml", steps=80)
    before = p.to_dict()
    assert p.events
    event = p.events[0]
    event.load_factor, event.kind = 1.0e9, "changed"
    assert p.events[0].load_factor != 1.0e9 and p.events[0].kind != "changed"
    assert p.to_dict() == before

    t = trussfe.trace(MESHES / "mech_fourbar.toml", drive="2:y", step=0.05, steps=40)
    before = t.to_dict()
    for e in t.events:
        e["kind"] = "changed"
    assert t.to_dict() == before


def test_arrays_computed_on_access_are_read_only_too():
    p = RUNS["postcritical"]()
    assert not p.displacement.flags.writeable and not p.axial_force.flags.writeable
    a = RUNS["actuators"]()
    assert not a.force.flags.writeable
