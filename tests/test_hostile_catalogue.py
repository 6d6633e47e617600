"""Every hostile or careless input of the catalogue (``hostile_cases.py``) is answered per the
command-line contract: exit status 2, exactly one line ``trussfe: error: <item>: <what>`` on
stderr (warning lines of the model reader aside), no traceback, no Python or numpy warning
line, no non-finite number on stdout, and no file left behind — neither a result nor a
hidden temporary.

The commands run in-process (``trussfe.cli.main``), so the whole catalogue takes seconds.
"""
from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

from trussfe.cli import main

import hostile_cases as hc

PLACEHOLDER_FILES = {"m": ("m.toml", hc.GOOD), "mech": ("mech.toml", hc.MECH),
                     "act": ("act.toml", hc.ACT), "mot": ("mot.toml", hc.MOTION)}


def _setup(folder: Path) -> dict:
    """Write the base inputs into ``folder``; return the placeholder values."""
    values = {}
    for key, (name, text) in PLACEHOLDER_FILES.items():
        (folder / name).write_text(text, encoding="utf-8")
        values[key] = str(folder / name)
    out = folder / "out"
    out.mkdir()
    (out / "empty").mkdir()
    (folder / "plain.txt").write_text("not a folder\n")
    for name in ("notes.vtu", "notes.msh", "notes.txt"):
        (folder / name).write_text("these are my notes, not a mesh\n")
    os.mkfifo(folder / "pipe.toml")
    os.symlink(folder / "gone.toml", folder / "dangling.toml")
    os.symlink(folder / "loop.toml", folder / "loop.toml")
    values.update(out=str(out), file=str(folder / "plain.txt"), fifo=str(folder / "pipe.toml"),
                  link=str(folder / "dangling.toml"), loop=str(folder / "loop.toml"),
                  model=values["m"])
    return values


def _fill(argv: list[str], values: dict) -> list[str]:
    out = []
    for a in argv:
        for key, v in values.items():
            a = a.replace("{" + key + "}", v)
        out.append(a)
    return out


def _snapshot(folder: Path) -> dict:
    return {str(p.relative_to(folder)): (p.stat().st_size if p.is_file() else -1)
            for p in folder.rglob("*") if not p.is_symlink() and not p.is_fifo()}


NON_FINITE = re.compile(r"(?<![A-Za-z])(nan|inf|infinity)(?![A-Za-z])", re.IGNORECASE)


def assert_refused(argv: list[str], folder: Path, capsys, words: str = "") -> str:
    """Run ``trussfe argv``; check the contract for a refused input; return the error line."""
    capsys.readouterr()
    before = _snapshot(folder)
    rc = main(argv)
    out, err = capsys.readouterr()
    lines = err.splitlines()
    assert "Traceback" not in err, err
    assert "Warning" not in err and "warnings.warn" not in err, err
    assert rc == 2, (rc, err)
    others = [ln for ln in lines[:-1] if not ln.startswith("trussfe: warning: ")]
    assert lines and not others, err
    last = lines[-1]
    assert last.startswith("trussfe: error: "), err
    assert "internal error" not in last, err
    assert words in last, (words, last)
    assert not NON_FINITE.search(out), out
    assert _snapshot(folder) == before, "files left behind"
    return last


# ----------------------------------------------------------------------------- cases
def _model_edit_cases():
    for name, old, new in hc.MODEL_EDITS:
        assert old in hc.GOOD, name
        yield pytest.param(hc.GOOD.replace(old, new, 1).encode("utf-8"), id=f"model: {name}")
    for name, data in hc.MODEL_FILES:
        yield pytest.param(data, id=f"model file: {name}")


@pytest.mark.parametrize("command", ["static"])
@pytest.mark.parametrize("data", list(_model_edit_cases()))
def test_bad_model(data, command, tmp_path, capsys):
    _setup(tmp_path)
    bad = tmp_path / "bad.toml"
    bad.write_bytes(data)
    assert_refused([command, str(bad), "--json", str(tmp_path / "out" / "r.json")],
                   tmp_path, capsys)


def _motion_cases():
    for name, old, new in hc.MOTION_EDITS:
        assert old in hc.MOTION, name
        yield pytest.param("mbad.toml", hc.MOTION.replace(old, new, 1).encode("utf-8"),
                           id=f"motion: {name}")
    for name, fname, data in hc.MOTION_FILES:
        yield pytest.param(fname, data, id=f"motion file: {name}")


@pytest.mark.parametrize("fname, data", list(_motion_cases()))
def test_bad_motion(fname, data, tmp_path, capsys):
    v = _setup(tmp_path)
    bad = tmp_path / fname
    bad.write_bytes(data)
    assert_refused(["simulate", v["act"], "--motion", str(bad), "--json",
                    str(tmp_path / "out" / "r.json")], tmp_path, capsys)


def _option_cases():
    for prefix, option, values in hc.OPTION_CASES:
        for name, value in values:
            yield pytest.param(prefix, option, value, id=f"{prefix[0]} {option} {name}")


@pytest.mark.parametrize("prefix, option, value", list(_option_cases()))
def test_bad_option_value(prefix, option, value, tmp_path, capsys):
    v = _setup(tmp_path)
    line = assert_refused(_fill(prefix, v) + [option, value, "--json",
                                               str(tmp_path / "out" / "r.json")],
                          tmp_path, capsys, option)
    assert line.startswith(f"trussfe: error: {option}")


@pytest.mark.parametrize("name, argv, words", [pytest.param(*c, id=c[0])
                                               for c in hc.ARGV_CASES])
def test_bad_argv(name, argv, words, tmp_path, capsys):
    v = _setup(tmp_path)
    assert_refused(_fill(argv, v), tmp_path, capsys, words)


def _output_cases():
    for prefix, option, kind in hc.OUTPUTS:
        for name, path, kinds in hc.BAD_OUTPUT_PATHS:
            if kind in kinds:
                yield pytest.param(prefix, option, path, id=f"{prefix[0]} {option} {name}")


@pytest.mark.parametrize("prefix, option, path", list(_output_cases()))
def test_bad_output_path(prefix, option, path, tmp_path, capsys):
    """Refused before any analysis, naming the option."""
    v = _setup(tmp_path)
    v["model"] = _fill(prefix, v)[1]
    line = assert_refused(_fill(prefix, v) + [option, _fill([path], v)[0]], tmp_path, capsys,
                          option)
    assert ".tmp" not in line


def test_catalogue_size():
    """The catalogue holds at least 300 hostile inputs."""
    n = (len(list(_model_edit_cases())) + len(list(_motion_cases()))
         + len(list(_option_cases())) + len(hc.ARGV_CASES) + len(list(_output_cases())))
    assert n >= 300, n
