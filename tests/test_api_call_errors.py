"""A call that does not match a function of the Python API (docs/python.md): an unknown
option, an option given by position, a missing required option, a model, motion or file
argument of the wrong type.  Each is a ``trussfe.InputError`` naming the argument (as the
command line refuses the same mistakes, exit status 2), and a ``TypeError`` as Python raises
for such a call; the functions keep their signatures and docstrings."""
import inspect
import math
from pathlib import Path

import pytest

import trussfe
from trussfe import api
from trussfe.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"
MODEL = MESHES / "triangular_truss_static.toml"
MOVING = MESHES / "triangular_truss_motion_active.toml"

#: Every function of the API that takes a model, with the arguments it needs besides it.
CALLS = {
    "static": {}, "modes": {}, "buckling": {}, "simulate": {}, "actuators": {},
    "elastic": {}, "transient": {"motion": "triangular_truss_motion_3s.toml"},
    "mechanism": {}, "trace": {"drive": "A:x", "step": 0.1, "steps": 1}, "topology": {},
    "postcritical": {}, "show": {}, "as_structure": {},
}


def _call(name, model, tmp_path, **kwargs):
    func = getattr(trussfe.api, name)
    if name == "show":
        return func(model, tmp_path / "m.png", **kwargs)
    return func(model, **kwargs)


@pytest.mark.parametrize("name", sorted(CALLS))
def test_an_unknown_option_is_an_input_error_naming_it(name, tmp_path):
    with pytest.raises(InputError) as err:
        _call(name, MODEL, tmp_path, **CALLS[name], mas="lumped")
    assert isinstance(err.value, TypeError)
    assert err.value.item == "mas"
    assert f"{name}() got an unexpected keyword argument 'mas'" in str(err.value)


def test_the_unknown_option_message_suggests_the_option_meant():
    with pytest.raises(InputError, match=r"^mas: modes\(\) got an unexpected keyword "
                                         r"argument 'mas'; did you mean 'mass'\?$"):
        trussfe.modes(MODEL, mas="lumped")
    with pytest.raises(InputError, match=r"topology\(\) takes no options"):
        trussfe.topology(MODEL, count=2)


def test_model_from_dict_and_read_model_refuse_unknown_keywords():
    with pytest.raises(InputError, match="base_dri: .*did you mean 'base_dir'"):
        trussfe.model_from_dict({"model": {"dimension": 2}}, base_dri=".")
    with pytest.raises(InputError, match="unexpected keyword argument 'strict'"):
        trussfe.read_model(MODEL, strict=True)


def test_an_option_given_by_position_is_refused():
    with pytest.raises(InputError, match=r"^static\(\): takes 1 positional argument\(s\) "
                                         r"\(model\) but 2 were given; give the options by "
                                         "keyword$") as err:
        trussfe.static(MODEL, "pinned-beam")
    assert isinstance(err.value, TypeError)


def test_a_missing_required_option_is_named():
    """The command line: ``the following arguments are required: --step``."""
    with pytest.raises(InputError, match=r"^step: trace\(\) is missing the required "
                                         r"argument 'step'$") as err:
        trussfe.trace(MESHES / "mech_fourbar.toml", drive="2:y", steps=2)
    assert isinstance(err.value, TypeError)
    with pytest.raises(InputError, match="^motion: transient"):
        trussfe.transient(MOVING)
    with pytest.raises(InputError, match="^model: "):
        trussfe.static()


@pytest.mark.parametrize("model", [42, None, [1, 2], 3.5, b"model.toml"])
@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_model_of_the_wrong_type_is_refused(name, model, tmp_path):
    with pytest.raises(InputError) as err:
        _call(name, model, tmp_path, **CALLS[name])
    assert isinstance(err.value, TypeError)
    assert err.value.item == "model"
    assert str(err.value) == (f"model: the model must be a Structure, a model file path or "
                              f"a dict of tables, not {type(model).__name__}")


@pytest.mark.parametrize("name", ["simulate", "actuators", "elastic", "transient"])
@pytest.mark.parametrize("motion", [5, math.nan, ["m.toml"]])
def test_a_motion_of_the_wrong_type_is_refused(name, motion):
    with pytest.raises(InputError, match="^motion: the motion must be a motion file path, "
                                         "a Motion or None, not ") as err:
        api.ANALYSES[name](MOVING, motion=motion)
    assert isinstance(err.value, TypeError)


@pytest.mark.parametrize("call, item", [
    (lambda tmp: trussfe.read_model(5), "path"),
    (lambda tmp: trussfe.read_model(None), "path"),
    (lambda tmp: trussfe.model_from_dict({"model": {"dimension": 2}}, base_dir=5),
     "base_dir"),
    (lambda tmp: trussfe.show(MODEL, 5), "png"),
    (lambda tmp: trussfe.show(MODEL, tmp / "m.png", results=5), "results"),
])
def test_file_arguments_of_the_wrong_type_are_refused(call, item, tmp_path):
    with pytest.raises(InputError) as err:
        call(tmp_path)
    assert isinstance(err.value, TypeError) and err.value.item == item


def test_good_calls_still_run():
    """Paths, path-likes, dicts and structures; a motion file, a Motion object or None."""
    s = trussfe.read_model(str(MODEL))
    assert trussfe.static(s).axial_force.shape == (2,)
    assert trussfe.static(model=MODEL).axial_force.shape == (2,)
    r = trussfe.simulate(MOVING, motion=None)
    assert r.time.shape == (1,)


@pytest.mark.parametrize("name", [*api.ANALYSIS_NAMES, "show", "model_from_dict",
                                  "read_model", "as_structure"])
def test_signatures_and_docstrings_are_the_functions_own(name):
    """``help(trussfe.static)`` shows the analysis' own signature and docstring."""
    func = getattr(trussfe.api, name)
    own = inspect.unwrap(func)
    assert own is not func
    assert inspect.signature(func) == inspect.signature(own)
    assert func.__doc__ == own.__doc__ and func.__doc__
    assert func.__name__ == own.__name__ == name
    assert getattr(trussfe, name, func) is func


def test_the_option_names_of_the_validation_suite_are_unchanged():
    assert api.option_names("modes") == ("count", "mass", "bar_model", "subdivisions",
                                         "mass_from", "progress")
    assert api.option_names("topology") == ()


def test_option_names_of_an_unknown_analysis_is_an_input_error():
    with pytest.raises(InputError, match=r"^analysis: unknown analysis 'modez'; did you "
                                         r"mean 'modes'\?$"):
        api.option_names("modez")
    with pytest.raises(InputError, match="^analysis: unknown analysis 'statics'"):
        api.check_options("statics", {"count": 1})


@pytest.mark.parametrize("name", [*api.ANALYSIS_NAMES, "show", "model_from_dict",
                                  "read_model", "as_structure"])
def test_the_functions_pickle_by_name(name):
    """A function of the API can be sent to another process (multiprocessing, Dask)."""
    import pickle
    func = getattr(api, name)
    assert pickle.loads(pickle.dumps(func)) is func


def test_picture_labels_and_actuator_quantity_are_checked(tmp_path):
    """``show(labels="no")`` is refused (a yes/no option takes True or False; "no" would
    draw the labels), and an unknown actuator quantity names the argument and suggests the
    nearest one."""
    root = Path(__file__).resolve().parents[1]
    with pytest.raises(trussfe.InputError, match="labels"):
        trussfe.show(root / "meshes" / "triangular_truss_static.toml", tmp_path / "m.png",
                     labels="no")
    assert not (tmp_path / "m.png").exists()
    r = trussfe.actuators(root / "meshes" / "double_octahedron_actuators.toml")
    with pytest.raises(trussfe.InputError, match="did you mean 'force'"):
        r.history("forse")


@pytest.mark.parametrize("kwargs, item", [({"case": 5}, "case"), ({"cases": 5}, "cases"),
                                          ({"case": ["fem", 3]}, "case"),
                                          ({"progress": "no"}, "progress")])
def test_validate_checks_its_arguments(kwargs, item):
    """``trussfe.validate`` refuses arguments of the wrong type before any case runs, naming
    the argument."""
    with pytest.raises(InputError, match=rf"^{item}: "):
        trussfe.validate(**kwargs)
