"""Every public name of ``trussfe`` and ``trussfe.api`` (their ``__all__``) exists and is
documented in the API reference (docs/api/*.rst), and every name the reference documents
exists."""
import importlib
import re
from pathlib import Path

import pytest

import trussfe
from trussfe import api

ROOT = Path(__file__).resolve().parents[1]
API_DOCS = sorted((ROOT / "docs" / "api").glob("*.rst"))

_DIRECTIVE = re.compile(r"^\.\. (?:py:)?(auto\w+|data|function|class|exception)::\s*(\S+)",
                        re.M)
_MEMBERS = re.compile(r"^\.\. automodule::\s*(\S+)\n((?:[ \t]+:.*\n?|[ \t]+\S.*\n?)*)", re.M)


def _resolve(dotted: str):
    """The object a dotted name documents: the longest importable module, then attributes."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr)
        return obj
    raise ImportError(dotted)


def documented() -> set[str]:
    """Full dotted names documented by the reference: directives, automodule ``:members:``
    lists and autosummary entries (relative to ``.. currentmodule::``)."""
    names: set[str] = set()
    for page in API_DOCS:
        text = page.read_text()
        for kind, name in _DIRECTIVE.findall(text):
            if kind != "autosummary":
                names.add(name)
        for module, options in _MEMBERS.findall(text):
            m = re.search(r":members:(.*?)(?=\n\s*:|\Z)", options, re.S)
            if m:
                names |= {f"{module}.{n.strip()}" for n in m.group(1).split(",") if n.strip()}
        current = re.search(r"^\.\. currentmodule::\s*(\S+)", text, re.M)
        for block in re.findall(r"^\.\. autosummary::\n((?:\n|[ \t]+.*\n)*)", text, re.M):
            for entry in block.split():
                if not entry.startswith(":"):
                    names.add(f"{current.group(1)}.{entry}" if current else entry)
    return names


def _is_documented(module: str, name: str, names: set[str]) -> bool:
    obj = getattr(importlib.import_module(module), name)
    if f"{module}.{name}" in names:
        return True
    # the same object documented under another name (trussfe.static is trussfe.api.static)
    return any(_resolve(n) is obj for n in names if n.rsplit(".", 1)[-1] == name)


@pytest.mark.parametrize("module", ["trussfe", "trussfe.api"])
def test_every_public_name_exists_and_is_documented(module):
    mod = importlib.import_module(module)
    names = documented()
    missing = [n for n in mod.__all__ if not hasattr(mod, n)]
    assert not missing, missing
    undocumented = [n for n in mod.__all__ if not _is_documented(module, n, names)]
    assert not undocumented, undocumented


def test_every_documented_name_exists():
    names = documented()
    assert {"trussfe.api.static", "trussfe.api.LoadCasesResult",
            "trussfe.api.ANALYSES"} <= names
    broken = []
    for name in sorted(names):
        try:
            _resolve(name)
        except (ImportError, AttributeError):
            broken.append(name)
    assert not broken, broken


def test_dir_lists_the_lazy_names():
    assert set(trussfe.__all__) <= set(dir(trussfe))
    assert set(api.__all__) <= set(dir(api))
