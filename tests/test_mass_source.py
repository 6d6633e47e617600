"""Masses from a load case's loads along gravity (``modes --mass-from CASE``)."""
import math

import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main

E, A, L = 210e9, 1e-4, 2.0


def _bar(load, masses=None, gravity=(-9.81, 0.0)):
    """An axial bar along x fixed at A, B free along x only; the payload case 'payload'."""
    return trussfe.model_from_dict({
        "model": {"name": "bar", "dimension": 2, "gravity": list(gravity)},
        "materials": {"steel": {"E": E}},
        "sections": {"bar": {"area": A}},
        "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "bar", "material": "steel"}},
        "supports": {"A": ["x", "y"], "B": ["y"]},
        **({"masses": masses} if masses else {}),
        "load_cases": {"payload": {"loads": {"B": list(load)}}},
    })


def test_payload_case_gives_the_spring_mass_frequency():
    """Closed form: a massless bar with a tip mass m = W/g vibrates at √(EA/(L m))/2π; the
    same as giving the mass in [masses]."""
    W, g = 981.0, 9.81
    r = trussfe.modes(_bar((-W, 0.0)), count=1, mass_from="payload")
    m = W / g
    assert_allclose(r.frequencies_hz[0], math.sqrt(E * A / (L * m)) / (2 * math.pi),
                    rtol=1e-12)
    same = trussfe.modes(_bar((-W, 0.0), masses={"B": m}), count=1)
    assert_allclose(r.frequencies_hz, same.frequencies_hz, rtol=1e-14)


def test_only_the_component_along_gravity_is_mass():
    """A load across gravity carries no mass; the one along it does."""
    r = trussfe.modes(_bar((-981.0, 500.0)), count=1, mass_from="payload")
    assert_allclose(r.frequencies_hz[0],
                    math.sqrt(E * A / (L * 100.0)) / (2 * math.pi), rtol=1e-12)


@pytest.mark.parametrize("argv, words", [
    (["--mass-from", "paylod"], "no load case 'paylod'"),
])
def test_bad_mass_source_is_one_line(tmp_path, capsys, argv, words):
    from trussfe.io.model_writer import write_model
    path = tmp_path / "bar.toml"
    write_model(_bar((-981.0, 0.0)), path)
    assert main(["modes", str(path), *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0] and "did you mean" in err[0].lower()


def test_a_load_against_gravity_is_refused():
    with pytest.raises(trussfe.InputError, match="against gravity"):
        trussfe.modes(_bar((981.0, 0.0)), count=1, mass_from="payload")
    with pytest.raises(trussfe.InputError, match="gravity direction"):
        trussfe.modes(_bar((-981.0, 0.0), gravity=(0.0, 0.0)), count=1, mass_from="payload")


def test_load_against_gravity_names_file_case_and_node(tmp_path, capsys):
    """The refusal names the model file, the case's loads and the node by its id (the
    payload is at node B)."""
    from trussfe.io.model_writer import write_model
    s = _bar((981.0, 0.0))
    path = tmp_path / "bar.toml"
    write_model(s, path)
    assert main(["modes", str(path), "--mass-from", "payload"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "bar.toml: load_cases.payload.loads.B: a load against gravity" in err[0]
