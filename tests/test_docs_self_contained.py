# SPDX-License-Identifier: MIT
"""The project speaks of itself alone: no tracked file refers to documents outside the
repository or to issue numbers; the user contract lives in ``docs/`` (docs/index.md).

Patterns are assembled from pieces so that this file does not match itself.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: Where the rule applies (folders and single files, relative to the repository root).
SCOPE = ("trussfe", "tests", "docs", "validation", "meshes", "examples", "benchmarks", "README.md",
         "CHANGELOG.md")

_MD = r"\." + "md"
#: Outside documents and issue references, each with the reason it is refused.
FORBIDDEN = [
    (re.compile("CONT" + "RACT" + _MD), "a contract document outside the repository"),
    (re.compile("CONT" + r"RACT\s*§"), "a section of a contract document outside the repository"),
    (re.compile("DES" + "IGN" + _MD), "a design document outside the repository"),
    (re.compile("STY" + "LE" + _MD), "a style document outside the repository"),
    (re.compile(r"\.\./" + "sha" + "red"), "a path outside the repository"),
    (re.compile(r"\b[Ii]s" + r"sue\s+(?:#?\d+|item)"), "an issue number or item"),
    (re.compile(r"\b[Ii]s" + r"sue's\b|\(is" + r"sue[,:)]"), "a reference to an issue"),
    (re.compile(r"\bse" + r"ed\s+0\d\d\b"), "a source numbered outside the repository"),
]


def _tracked_files() -> list[Path]:
    """Tracked text files in scope (git ls-files; the working tree when git is unavailable)."""
    try:
        out = subprocess.run(["git", "ls-files", "-z", "--", *SCOPE], cwd=ROOT,
                             capture_output=True, check=True).stdout
        names = [n for n in out.decode("utf-8", "replace").split("\0") if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
    if not names:                      # not a git checkout (e.g. an unpacked sdist)
        names = [str(p.relative_to(ROOT)) for s in SCOPE for p in
                 ([ROOT / s] if (ROOT / s).is_file() else (ROOT / s).rglob("*"))
                 if p.is_file()]
    return [ROOT / n for n in names if (ROOT / n).is_file()]


def _offences(text: str) -> list[tuple[int, str, str]]:
    found = []
    for lineno, line in enumerate(text.splitlines(), 1):
        for pattern, why in FORBIDDEN:
            if pattern.search(line):
                found.append((lineno, why, line.strip()))
    return found


def test_patterns_catch_what_they_should():
    """The patterns match the references they are meant to refuse, and not ordinary text."""
    bad = ["see " + "CONT" + "RACT.md §3", "(" + "DES" + "IGN.md geometry)",
           "is" + "sue item 2b", "Is" + "sue 13", "the is" + "sue's minimum",
           "(is" + "sue: 1e-6)", "../" + "shared/x", "(se" + "ed 002, Fig. 4.1)",
           "STY" + "LE.md"]
    good = ["docs/json.md, `static`", "random seed 0", "seed: int = 0",
            "an issue with the mesh file is reported on one line"]
    assert all(_offences(t) for t in bad), [t for t in bad if not _offences(t)]
    assert not any(_offences(t) for t in good), [t for t in good if _offences(t)]


def test_scope_is_not_empty():
    files = {p.relative_to(ROOT).parts[0] for p in _tracked_files()}
    assert {"trussfe", "tests", "docs", "README.md"} <= files


@pytest.mark.parametrize("top", SCOPE)
def test_no_outside_references(top):
    """No file under ``top`` names an outside document or an issue."""
    problems = []
    for path in _tracked_files():
        rel = path.relative_to(ROOT)
        if rel.parts[0] != top:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue                  # binary files (meshes, images) hold no prose
        problems += [f"{rel}:{n}: {why}: {line}" for n, why, line in _offences(text)]
    assert not problems, "\n".join(problems)
