"""docs/cli.md lists every option of every command, in the command's synopsis and in its
table, with the default the parser uses; and it lists no option the parser does not have."""
from __future__ import annotations

import argparse
import re
from pathlib import Path

import pytest

from trussfe.cli import build_parser, command_names

ROOT = Path(__file__).resolve().parents[1]
DOC = (ROOT / "docs" / "cli.md").read_text(encoding="utf-8")


def _section(name: str) -> str:
    m = re.search(rf"^### {name}\n(.*?)(?=^### |^## |\Z)", DOC, re.S | re.M)
    assert m, f"docs/cli.md has no section for '{name}'"
    return m.group(1)


def _command_parsers() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(sub.choices)


PARSERS = _command_parsers()


def _options(name: str) -> dict[str, argparse.Action]:
    return {o: a for a in PARSERS[name]._actions for o in a.option_strings
            if o not in ("-h", "--help")}


def _table(section: str) -> dict[str, str]:
    """Option → its default cell, from the section's option table."""
    rows = {}
    for line in section.splitlines():
        m = re.match(r"^\| `(--[a-z-]+)[^`]*` \|\s*([^|]*?)\s*\|", line)
        if m:
            rows[m.group(1)] = m.group(2).strip()
    return rows


@pytest.mark.parametrize("name", command_names())
def test_every_option_is_documented_and_every_documented_option_exists(name):
    sec = _section(name)
    synopsis = re.search(r"```\n(.*?)```", sec, re.S).group(1)
    in_synopsis = set(re.findall(r"(--[a-z-]+)", synopsis))
    in_table = set(_table(sec))
    options = set(_options(name))
    assert options - in_table == set(), f"{name}: options missing from the table"
    assert options - in_synopsis == set(), f"{name}: options missing from the synopsis"
    assert (in_table | in_synopsis) - options == set(), f"{name}: documented, not options"


@pytest.mark.parametrize("name", command_names())
def test_literal_defaults_agree(name):
    """A default the parser holds itself (a number or a choice) is the one the table gives."""
    rows = _table(_section(name))
    for opt, action in _options(name).items():
        default = action.default
        if isinstance(default, bool) or default is None or opt not in rows:
            continue
        cell = rows[opt]
        if isinstance(default, tuple):                  # --size (1000, 800)
            default = "x".join(str(v) for v in default)
        text = re.sub(r"[`./]", "", cell)
        want = re.sub(r"[`./]", "", str(default))
        assert text.startswith(want), f"{name} {opt}: parser default {default!r}, docs {cell!r}"
