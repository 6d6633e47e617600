# SPDX-License-Identifier: MIT
"""The Python API's checks of option values (docs/python.md, docs/bad-input.md).

docs/python.md: "a bad value raises ``trussfe.InputError`` naming the option"; docs/bad-input.md,
*Options*, lists the accepted values (counts are integers >= 1, ``--branch`` an integer >= 0,
``--tolerance`` a relative tolerance 0 < tol < 1, ``--step`` of ``trace`` a finite non-zero
number, ``--dt``/``--t-end``/``--scale`` finite numbers > 0, ``--size`` 200 to 8000 pixels).  A
wrong value given from Python must be refused the same way: one :class:`InputError` naming
the option -- never a bare ``ValueError``/``TypeError``/``OverflowError`` from the solver, a
numpy warning, or a silently wrong result.  Integer options take numpy integers too (the
dict given to ``model_from_dict`` does, docs/python.md *Building a model in Python*).
"""
from __future__ import annotations

import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import trussfe
from trussfe.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"
STATIC = MESHES / "triangular_truss_static.toml"
COLUMN = MESHES / "postcritical_euler_column.toml"
ACTIVE = MESHES / "triangular_truss_motion_active.toml"
MOTION = "triangular_truss_motion_3s.toml"
FOURBAR = MESHES / "mech_fourbar.toml"
VON_MISES = MESHES / "postcritical_von_mises.toml"

NAN, INF = math.nan, math.inf


def _refused(option: str, call) -> InputError:
    """``call()`` raises one InputError naming ``option``, and no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(InputError) as err:
            call()
    assert str(err.value).startswith(f"{option}: "), str(err.value)
    return err.value


# ------------------------------------------------------------- integer options
#: (option as the command line spells it, the call with the value) for every integer option.
INTEGER_OPTIONS = [
    ("--count", lambda v: trussfe.modes(STATIC, count=v)),
    ("--subdivisions", lambda v: trussfe.modes(COLUMN, bar_model="pinned-beam", subdivisions=v)),
    ("--count", lambda v: trussfe.buckling(COLUMN, count=v)),
    ("--subdivisions", lambda v: trussfe.buckling(COLUMN, subdivisions=v)),
    ("--sections", lambda v: trussfe.simulate(ACTIVE, motion=MOTION, steps=3, sections=v)),
    ("--sections", lambda v: trussfe.elastic(ACTIVE, motion=MOTION, steps=3, sections=v)),
    ("--subdivisions", lambda v: trussfe.elastic(ACTIVE, motion=MOTION, steps=3,
                                                 subdivisions=v)),
    ("--subdivisions", lambda v: trussfe.transient(ACTIVE, motion=MOTION, dt=0.5,
                                                   subdivisions=v)),
]
BAD_COUNTS = [NAN, INF, 2.5, "3", True, 0]


@pytest.mark.parametrize("value", BAD_COUNTS, ids=repr)
@pytest.mark.parametrize("option, call", INTEGER_OPTIONS,
                         ids=["modes-count", "modes-subdivisions", "buckling-count",
                              "buckling-subdivisions", "simulate-sections", "elastic-sections",
                              "elastic-subdivisions", "transient-subdivisions"])
def test_integer_options_refuse_bad_values_naming_the_option(option, call, value):
    """docs/bad-input.md: counts are "integers >= 1"; ``nan``, ``inf``, ``1.5`` are refused
    naming the option (was: ValueError 'cannot convert float NaN to integer',
    OverflowError, TypeError "'<' not supported", or ``True`` taken as 1)."""
    _refused(option, lambda: call(value))


def test_required_counts_refuse_none():
    """``simulate(sections=None)`` names the option (was: TypeError from int() / '<');
    ``buckling(count=None)`` is the default count (4, or the finite load factors there are)."""
    _refused("--sections", lambda: trussfe.simulate(ACTIVE, sections=None))
    assert trussfe.buckling(COLUMN, count=None).load_factors.size == 4


@pytest.mark.parametrize("call", [
    lambda: trussfe.static(COLUMN, bar_model="pinned-beam", subdivisions=np.int64(3)),
    lambda: trussfe.simulate(ACTIVE, motion=MOTION, steps=np.int64(4)),
    lambda: trussfe.elastic(ACTIVE, motion=MOTION, steps=np.int32(3)),
    lambda: trussfe.transient(ACTIVE, motion=MOTION, steps=np.int64(4), dt=0.5),
    lambda: trussfe.postcritical(VON_MISES, steps=np.int64(5)),
    lambda: trussfe.modes(STATIC, count=np.int64(2)),
], ids=["static", "simulate", "elastic", "transient", "postcritical", "modes"])
def test_numpy_integers_are_integers(call):
    """An integer option given a numpy integer (a value from an array) is accepted, as
    ``count``, ``max_order`` and trace's ``steps`` already were (was: '--steps: must be a
    positive integer, got np.int64(4)')."""
    assert call().to_dict()["units"] == "SI"


def test_numpy_integer_gives_the_same_result():
    a = trussfe.simulate(ACTIVE, motion=MOTION, steps=np.int64(5)).to_dict()
    b = trussfe.simulate(ACTIVE, motion=MOTION, steps=5).to_dict()
    assert a == b


# ------------------------------------------------------------- tolerances
@pytest.mark.parametrize("value", [NAN, INF, 1.5, 1.0, 0.0, -1.0, "1e-6"], ids=repr)
def test_mechanism_tolerance_is_checked(value):
    """docs/bad-input.md: ``--tolerance`` (mechanism) is "a relative tolerance, 0 < tol < 1".
    Was: accepted from Python; ``nan``, ``inf`` or 1.5 gave the four-bar linkage rank 0, 4
    mechanisms and 3 states of self-stress instead of rank 3, 1 mechanism, 0 states."""
    _refused("--tolerance", lambda: trussfe.mechanism(FOURBAR, tolerance=value))


def test_mechanism_good_tolerance_still_works():
    k = trussfe.mechanism(FOURBAR, tolerance=1e-6)
    assert (k.rank, k.mechanisms, k.self_stress_states) == (3, 1, 0)


@pytest.mark.parametrize("value", [NAN, INF, 1.5, 0.0, -1.0, None, "x"], ids=repr)
def test_trace_tolerance_is_checked(value):
    """docs/bad-input.md: ``--tolerance`` (trace) 0 < tol < 1.  Was: -1 gave a numpy
    RuntimeWarning (sqrt of a negative), None or 'x' a TypeError, inf or 1.5 a path."""
    _refused("--tolerance", lambda: trussfe.trace(FOURBAR, drive="2:y", step=0.05, steps=2,
                                                  tolerance=value))


@pytest.mark.parametrize("value", [NAN, 1.5, None, "1", True, -1], ids=repr)
def test_trace_branch_is_checked(value):
    """docs/bad-input.md: ``--branch`` (trace) is an integer >= 0 (was: nan and 1.5 accepted,
    None and '1' a TypeError "'<' not supported")."""
    _refused("--branch", lambda: trussfe.trace(FOURBAR, drive="2:y", step=0.05, steps=2,
                                               branch=value))


@pytest.mark.parametrize("value", [None, "0.05", NAN, 0.0], ids=repr)
def test_trace_step_is_checked(value):
    """docs/bad-input.md: ``--step`` (trace) is a finite non-zero number (was: None a
    TypeError, the string '0.05' accepted)."""
    _refused("--step", lambda: trussfe.trace(FOURBAR, drive="2:y", step=value, steps=2))


@pytest.mark.parametrize("value", [3, None, b"2:y"], ids=repr)
def test_trace_drive_of_the_wrong_type(value):
    """``drive`` is NODE:AXIS or a list of them (was: TypeError "'int' object is not
    iterable")."""
    _refused("--drive", lambda: trussfe.trace(FOURBAR, drive=value, step=0.05, steps=2))


# ------------------------------------------------------------- real-valued options
@pytest.mark.parametrize("option, call", [
    ("--step", lambda: trussfe.postcritical(VON_MISES, step="1")),
    ("--max-load-factor", lambda: trussfe.postcritical(VON_MISES, max_load_factor="1")),
    ("--imperfection", lambda: trussfe.postcritical(VON_MISES, imperfection="0.1")),
    ("--monitor", lambda: trussfe.postcritical(VON_MISES, monitor=3)),
    ("--t-end", lambda: trussfe.transient(ACTIVE, motion=MOTION, dt=0.5, t_end="1")),
    ("--t-end", lambda: trussfe.transient(ACTIVE, motion=MOTION, dt=0.5, t_end=INF)),
    ("--dt", lambda: trussfe.transient(ACTIVE, motion=MOTION, dt=NAN)),
], ids=["pc-step", "pc-max-load-factor", "pc-imperfection", "pc-monitor", "tr-t-end-str",
        "tr-t-end-inf", "tr-dt-nan"])
def test_real_options_of_the_wrong_type_name_the_option(option, call):
    """A string where a number is needed is refused naming the option (was: TypeError 'must
    be real number, not str', 'cannot unpack non-iterable int object', or the string taken)."""
    _refused(option, call)


# ------------------------------------------------------------- show
@pytest.mark.parametrize("size", [(0, 0), (-5, 100), (100,), (NAN, 300), "big", None,
                                  (100.5, 300), (10 ** 6, 10 ** 6)], ids=repr)
def test_show_size_is_checked(size, tmp_path):
    """docs/cli.md, *show*: ``--size WxH`` is 200 to 8000 pixels each; from Python the same
    (was: RuntimeWarning, ValueError, TypeError, a std::bad_alloc MemoryError, or 100.5
    silently cut to 100)."""
    _refused("--size", lambda: trussfe.show(STATIC, tmp_path / "a.png", size=size,
                                            backend="matplotlib"))
    assert not (tmp_path / "a.png").exists()


@pytest.mark.parametrize("scale", [0, -1.0, NAN, INF, "2"], ids=repr)
def test_show_scale_is_checked(scale, tmp_path):
    """docs/cli.md, *show*: ``--scale S`` is a finite number > 0 (docs/bad-input.md); was:
    0, -1 and nan drawn, inf a RuntimeWarning, '2' a TypeError."""
    r = trussfe.static(STATIC)
    _refused("--scale", lambda: trussfe.show(STATIC, tmp_path / "a.png", results=r,
                                             scale=scale, backend="matplotlib"))


def test_show_signature_in_python_md_lists_case():
    """docs/python.md gives the signature of ``trussfe.show``; it lists every option,
    ``case`` included."""
    import inspect
    text = (ROOT / "docs" / "python.md").read_text()
    start = text.index("`trussfe.show(model, png, *,")
    documented = text[start:text.index(")`", start)]
    for name in inspect.signature(trussfe.show).parameters:
        assert re.search(rf"\b{name}\b", documented), name


@pytest.mark.parametrize("call, option", [
    (lambda: trussfe.static(STATIC, all_cases="yes"), "--all"),
    (lambda: trussfe.static(STATIC, all_cases=1), "--all"),
    (lambda: trussfe.trace(FOURBAR, drive="2:y", step=0.01, steps=2, frozen="no"), "--frozen"),
    (lambda: trussfe.postcritical(VON_MISES, branch=3), "--branch"),
], ids=["all=yes", "all=1", "frozen=no", "branch=3"])
def test_yes_no_options_take_true_or_false_only(call, option):
    """docs/python.md: a bad value raises InputError naming the option.  A yes/no option
    given a string or a number is refused — ``frozen="no"`` would otherwise run frozen."""
    with pytest.raises(trussfe.InputError, match=rf"^{option}: expected True or False"):
        call()


def test_numpy_bools_are_yes_no_values():
    """A numpy bool is a yes/no value: ``all_cases=np.False_`` is a plain static run, the
    same forces as without the option."""
    assert np.array_equal(trussfe.static(STATIC, all_cases=np.False_).axial_force,
                          trussfe.static(STATIC).axial_force)


@pytest.mark.parametrize("call", [
    lambda: trussfe.modes(STATIC, progress=3),
    lambda: trussfe.trace(FOURBAR, drive="2:y", step=0.01, steps=2, progress="bar"),
    lambda: trussfe.postcritical(VON_MISES, progress=True),
], ids=["modes", "trace", "postcritical"])
def test_progress_that_cannot_be_called_is_refused_before_the_run(call):
    """docs/python.md: ``progress`` is a callable ``progress(done, total)``; anything else is
    refused up front (it failed with a TypeError at its first call, mid-run)."""
    with pytest.raises(trussfe.InputError, match=r"^progress: expected a callable"):
        call()
