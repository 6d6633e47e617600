# SPDX-License-Identifier: MIT
"""docs/architecture.md names real code: every ``module:function`` and ``trussfe.…`` name it
cites in backticks is imported and looked up, so the page cannot go stale silently.

Source of the expected values: the page itself (each cited name must resolve in the package).
"""
from __future__ import annotations

import importlib
import importlib.util
import re
from pathlib import Path

import pytest

PAGE = Path(__file__).resolve().parents[1] / "docs" / "architecture.md"

# `module:attr.attr` relative to trussfe (or starting with trussfe.), optionally followed by a
# call's arguments; or a dotted `trussfe.module.attr`.
_COLON = re.compile(r"^(?P<mod>[a-z_][\w]*(?:\.[a-z_]\w*)*):(?P<attr>[A-Za-z_]\w*(?:\.\w+)*)"
                    r"(?:\(.*\))?$")
_DOTTED = re.compile(r"^trussfe(?:\.\w+)+$")


def cited_names() -> list[str]:
    """The names in backticks on the page that point into the package."""
    text = re.sub(r"^```.*?^```", "", PAGE.read_text(encoding="utf-8"), flags=re.S | re.M)
    names = []
    for token in re.findall(r"`([^`]+)`", text):
        token = " ".join(token.split())      # a name may be wrapped across lines
        if _COLON.match(token) or _DOTTED.match(token):
            names.append(token)
    return sorted(set(names))


def _module_exists(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except ModuleNotFoundError:
        return False


#: The member-mechanics modules of the page's section 4.  Where none of them is in the tree,
#: their names are skipped; once one is, every name the page cites must resolve.
MECHANICS_MODULES = ("trussfe.mechanics.stress", "trussfe.mechanics.euler",
                     "trussfe.mechanics.mass", "trussfe.mechanics.geometry")


def _owning_module(token: str) -> str:
    """The module a cited name points into (the longest importable prefix for a dotted one)."""
    m = _COLON.match(token)
    if m:
        mod = m["mod"] if m["mod"].startswith("trussfe") else f"trussfe.{m['mod']}"
        return "trussfe" if mod == "trussfe.trussfe" else mod
    return token


def _lookup(obj, attrs: list[str], where: str):
    for a in attrs:
        if hasattr(obj, a):
            obj = getattr(obj, a)
            continue
        # a dataclass field without a default is no class attribute
        fields = getattr(obj, "__dataclass_fields__", {})
        assert a in fields, f"{where}: no attribute '{a}' on {obj!r}"
        obj = fields[a]
    return obj


def resolve(token: str):
    """Import the module a cited name points into and look the rest up."""
    m = _COLON.match(token)
    if m:
        mod = m["mod"] if m["mod"].startswith("trussfe") else f"trussfe.{m['mod']}"
        if mod == "trussfe.trussfe":
            mod = "trussfe"
        return _lookup(importlib.import_module(mod), m["attr"].split("."), token)
    parts = token.split(".")
    # the longest importable prefix is the module; the rest are attributes
    for k in range(len(parts), 0, -1):
        mod = ".".join(parts[:k])
        if _module_exists(mod):
            return _lookup(importlib.import_module(mod), parts[k:], token)
    raise AssertionError(f"{token}: no such module")


def test_page_cites_the_code():
    # the parser found the page's names: the traces of section 5 alone cite several dozen
    names = cited_names()
    assert len(names) > 60, names
    for must in ("mechanics.stress:von_mises", "model.structure:Structure.area",
                 "linalg.factor:factor", "api:ANALYSES"):
        assert must in names


@pytest.mark.parametrize("token", cited_names())
def test_cited_name_exists(token):
    mod = _owning_module(token)
    if (any(mod == p or mod.startswith(p + ".") for p in MECHANICS_MODULES)
            and not any(_module_exists(p) for p in MECHANICS_MODULES)):
        pytest.skip(f"{mod} is not in this tree")
    assert resolve(token) is not None


def test_resolver_rejects_a_missing_name():
    # the check can fail: a name that is not in the package is refused
    with pytest.raises(AssertionError):
        resolve("model.structure:Structure.no_such_property")
    with pytest.raises((AssertionError, ModuleNotFoundError)):
        resolve("no_such_module:thing")
