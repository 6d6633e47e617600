"""Hypothesis fuzzing beyond the model reader: motion tables, motion CSV histories and random
command-line option values.  Whatever the input, the answer is a result or one
``InputError``/one error line with exit status 2 — never a traceback, an internal error
(exit 3), a warning line or a file left behind by a refused run."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hostile_cases as hc
from trussfe.cli import main
from trussfe.errors import TrussfeError
from trussfe.io.model_file import parse_model
from trussfe.io.toml_text import loads
from trussfe.rigid.motion import Motion
from trussfe.rigid.motion_file import motion_from_spec

STRUCTURE = parse_model(loads(hc.ACT), source="act.toml")

scalars = st.one_of(
    st.none(), st.booleans(), st.integers(-10**15, 10**15),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, 1, 2, 3, 6, 50, -1, 2.5, 3.7, 1e-300, 1e308, "abc", "no", "", "3"]),
    st.text(max_size=8))
values = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=3), st.dictionaries(st.text(max_size=6), inner, max_size=3)),
    max_leaves=6)
keys = st.sampled_from(["type", "duration", "steps", "start", "end", "damping_ratio",
                        "settling_fraction", "settling_constant", "real_root_factor",
                        "first_sample", "include_end", "file", "top_nodes", "axis",
                        "profile", "ramp_time", "grid", "time", "angle", "height", "junk"])
lengths = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 10),
                    st.text(max_size=3), st.booleans())
specs = st.fixed_dictionaries(
    {"duration": st.one_of(st.floats(0.01, 10), scalars),
     "steps": st.one_of(st.integers(1, 30), scalars),
     "start": st.one_of(st.fixed_dictionaries({"active": lengths}), values),
     "end": st.one_of(st.fixed_dictionaries({"active": lengths}), values)},
    optional={"type": st.one_of(st.sampled_from(["third-order", "rotation", "csv"]), scalars),
              "first_sample": scalars, "include_end": scalars, "damping_ratio": scalars,
              "settling_fraction": scalars})


def _check_motion(spec, tmp: Path) -> None:
    try:
        with np.errstate(all="raise"):
            m = motion_from_spec(spec, STRUCTURE, tmp, "fuzz.toml")
    except TrussfeError as err:
        assert str(err) and "\n" not in str(err)
        return
    assert isinstance(m, Motion)
    assert m.time.size >= 1 and np.all(np.isfinite(m.length))
    assert np.all(np.diff(m.time) > 0)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(spec=specs)
def test_fuzz_motion_tables(spec, tmp_path):
    """Fuzzed ``[motion]`` tables near the valid one: a Motion or one InputError."""
    _check_motion(spec, tmp_path)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(spec=st.dictionaries(keys, values, max_size=6))
def test_fuzz_motion_arbitrary(spec, tmp_path):
    """Arbitrary tables of the motion keys: a Motion or one InputError."""
    _check_motion(spec, tmp_path)


cells = st.one_of(st.floats(allow_nan=True, allow_infinity=True).map(repr),
                  st.integers(-10, 10).map(str), st.sampled_from(["", "a", "1e400", " 2",
                                                                  "2.5", "nan", "-0"]))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(header=st.lists(st.sampled_from(["time", "active", "active.velocity",
                                        "active.acceleration", "follower", "x", ""]),
                       min_size=1, max_size=4),
       rows=st.lists(st.lists(cells, min_size=0, max_size=5), max_size=8))
def test_fuzz_motion_csv(header, rows, tmp_path):
    """Fuzzed CSV histories: a Motion or one InputError."""
    from trussfe.rigid.motion_csv import read_motion_csv

    p = tmp_path / "m.csv"
    p.write_text(",".join(header) + "\n" + "\n".join(",".join(r) for r in rows) + "\n")
    try:
        with np.errstate(all="raise"):
            m = read_motion_csv(p, STRUCTURE)
    except TrussfeError as err:
        assert str(err) and "\n" not in str(err)
        return
    assert np.all(np.isfinite(m.length)) and np.all(np.isfinite(m.acceleration))


# ----------------------------------------------------------------------------- options
option_values = st.one_of(
    st.sampled_from(["0", "1", "2", "-1", "nan", "inf", "-inf", "1e400", "1e-300", "",
                     " ", "abc", "1.5", "0x10", "1_000", "٣", "1e3", "+2", "- 1", "\n2"]),
    st.integers(-3, 6).map(str), st.floats(allow_nan=True).map(repr), st.text(max_size=6))

#: (argv prefix, options that take a value); kept to quick analyses of the small models.
COMMANDS = [
    (["static", "{m}"], ["--subdivisions"]),
    (["modes", "{m}", "--count", "1"], ["--subdivisions"]),
    (["buckling", "{m}", "--count", "1"], ["--subdivisions"]),
    (["mechanism", "{mech}"], ["--tolerance"]),
    (["trace", "{mech}", "--drive", "2:y", "--step", "0.05"], ["--steps", "--tolerance",
                                                               "--branch"]),
    (["simulate", "{act}", "--motion", "{mot}"], ["--steps", "--sections"]),
    (["transient", "{act}", "--motion", "{mot}", "--bar-model", "truss"],
     ["--dt", "--t-end", "--vtk-every"]),
]


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    d = tmp_path_factory.mktemp("fuzzcli")
    files = {"m": hc.GOOD, "mech": hc.MECH, "act": hc.ACT, "mot": hc.MOTION}
    for k, text in files.items():
        (d / f"{k}.toml").write_text(text)
    return d


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_fuzz_command_line_options(inputs, data, capsys):
    """Random values for the numeric options of every command: exit 0 with a finite result,
    or exit 2 with one error line; never exit 3, a traceback or a warning line."""
    prefix, options = data.draw(st.sampled_from(COMMANDS))
    argv = [a.replace("{m}", str(inputs / "m.toml")).replace("{mech}", str(inputs / "mech.toml"))
            .replace("{act}", str(inputs / "act.toml")).replace("{mot}", str(inputs / "mot.toml"))
            for a in prefix]
    chosen = data.draw(st.lists(st.sampled_from(options), min_size=1, max_size=len(options),
                                unique=True))
    for opt in chosen:
        argv += [opt, data.draw(option_values)]
    if prefix[0] == "trace" and "--steps" not in chosen:
        argv += ["--steps", "2"]
    capsys.readouterr()
    rc = main(argv)
    out, err = capsys.readouterr()
    assert "Traceback" not in err and "Warning" not in err, err
    assert rc in (0, 2), (argv, rc, err)
    if rc == 2:
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    else:
        assert not any(w in out.lower().split() for w in ("nan", "inf")), out
    assert sorted(p.name for p in inputs.iterdir()) == ["act.toml", "m.toml", "mech.toml",
                                                          "mot.toml"]


# ----------------------------------------------------------------------------- extension tables
ext_keys = {
    "active_members": ["base_mass", "base_length", "base_cg", "base_inertia", "tube_length",
                       "min_length", "max_length", "junk"],
    "actuators": ["leadscrew_gain", "mean_diameter", "thread", "thread_angle", "friction",
                  "gearhead_gain", "armature_inertia", "resistance", "torque_constant",
                  "back_emf_constant", "max_speed", "max_voltage", "require_self_locking",
                  "convention", "junk"],
    "failure": ["buckling", "effective_length_factor", "critical_load", "residual",
                "softening_strain", "yield", "yield_strength", "fracture_strain", "junk"],
    "postcritical": ["control", "steps", "step", "max_load_factor", "max_displacement",
                     "monitor", "bar_model", "subdivisions", "imperfection", "branch", "junk"],
}
member_names = st.sampled_from(["active", "follower", "nobody", "", "active\n"])


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_fuzz_extension_tables(data):
    """Fuzzed ``[active_members]``, ``[actuators]``, ``[failure]``, ``[postcritical]``
    tables on the triangular truss: a Structure or one InputError."""
    doc = loads(hc.ACT)
    table = data.draw(st.sampled_from(sorted(ext_keys)))
    keys = st.sampled_from(ext_keys[table])
    if table in ("postcritical",):
        doc[table] = data.draw(st.dictionaries(keys, values, max_size=5))
    elif table == "failure":
        doc[table] = data.draw(st.one_of(st.dictionaries(keys, values, max_size=5),
                                         st.dictionaries(member_names, st.dictionaries(
                                             keys, values, max_size=4), max_size=2)))
    else:
        base = dict(doc.get(table, {}))
        extra = data.draw(st.dictionaries(member_names, st.one_of(
            values, st.dictionaries(keys, values, max_size=5)), max_size=2))
        base.update(extra)
        doc[table] = base
    try:
        with np.errstate(all="raise"):
            s = parse_model(doc, source="fuzz.toml")
    except TrussfeError as err:
        assert str(err) and "\n" not in str(err)
        return
    assert s.n_members == 2


def test_a_lightly_damped_short_motion_underflows_harmlessly(tmp_path):
    """A damping ratio of 1/64 makes the real pole so fast that its term underflows to zero
    (its exact limit) within a 1 s motion: a motion, not a numerical failure (found by the
    fuzzer above)."""
    spec = {"duration": 1.0, "steps": 6, "start": {"active": 1.0}, "end": {"active": 1.0},
            "damping_ratio": 0.015625}
    with np.errstate(all="raise"):
        m = motion_from_spec(spec, STRUCTURE, tmp_path, "fuzz.toml")
    assert np.all(np.isfinite(m.length)) and np.all(m.length == 1.0)
