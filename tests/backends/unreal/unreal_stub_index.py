"""An index of the real Unreal Engine 5.6 Python API, read from PyPI's ``unreal-stub``.

The stub (one 26 MB ``unreal/unreal.py`` generated from UE 5.6.0) cannot be
imported or ``ast.parse``-d: it starts with a byte-order mark and one default
value near line 118336 is not valid Python. Every ``class`` and ``def`` in it
sits on a single line, though, so it is indexed with line patterns:

- ``class Name(Bases):`` at column 0 opens a class; any other column-0 statement closes it;
- ``    @classmethod`` / ``@staticmethod`` / ``@property`` / ``@x.setter`` decorate
  the next 4-space-indented ``def``;
- ``    NAME: Type = ...`` is a class attribute (enum values);
- ``    - ``name`` (type):  [Read-Write]`` lines of a class docstring are its
  editor properties (``get_editor_property``/``set_editor_property`` names);
- ``def name(...)`` at column 0 is a module function.

Parameter lists are split on top-level commas (brackets and string literals in
default values are skipped), so each method is known with its parameter names,
which of them have defaults, and its return annotation. Lookups follow the base
classes, so inherited methods are found.
"""

from __future__ import annotations

import functools
import importlib.metadata
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

__all__ = [
    "Member",
    "Param",
    "StubClass",
    "StubIndex",
    "load_stub_index",
    "split_top_level",
    "stub_path",
]

MemberKind = Literal["method", "classmethod", "staticmethod", "property", "attribute"]

_CLASS = re.compile(r"^class ([A-Za-z_]\w*)\((.*)\):\s*$")
_MEMBER_DEF = re.compile(r"^    def ([A-Za-z_]\w*)\((.*)\)\s*(?:->\s*(.*?))?:\s*$")
_FUNCTION_DEF = re.compile(r"^def ([A-Za-z_]\w*)\((.*)\)\s*(?:->\s*(.*?))?:\s*$")
_DECORATOR = re.compile(r"^    @([\w.]+)\s*$")
_ATTRIBUTE = re.compile(r"^    ([A-Za-z_]\w*)\s*:\s*([^=]+?)\s*=")
_EDITOR_PROPERTY = re.compile(r"^    - ``(\w+)`` \((.*?)\):\s+\[(Read-Write|Read-Only)\]")


@dataclass(frozen=True, slots=True)
class Param:
    """One parameter of a stub signature (``self``/``cls`` excluded)."""

    name: str
    has_default: bool
    kind: Literal["positional", "var_positional", "var_keyword", "keyword_only"] = "positional"


@dataclass(frozen=True, slots=True)
class Member:
    """A method, property or class attribute of a stub class (or a module function)."""

    name: str
    kind: MemberKind
    params: tuple[Param, ...] = ()
    returns: str = ""
    writable: bool = False

    @property
    def positional(self) -> tuple[Param, ...]:
        """Parameters that may be passed by position."""
        return tuple(p for p in self.params if p.kind == "positional")

    @property
    def keyword_names(self) -> frozenset[str]:
        """Parameter names that may be passed by keyword."""
        return frozenset(p.name for p in self.params if p.kind in ("positional", "keyword_only"))

    @property
    def accepts_var_positional(self) -> bool:
        """True when the signature has ``*args``."""
        return any(p.kind == "var_positional" for p in self.params)

    @property
    def accepts_var_keyword(self) -> bool:
        """True when the signature has ``**kwargs``."""
        return any(p.kind == "var_keyword" for p in self.params)

    def check_call(self, positional_count: int, keywords: tuple[str, ...]) -> list[str]:
        """Problems with calling this member with that many positional args and these keywords."""
        problems: list[str] = []
        positional = self.positional
        if positional_count > len(positional) and not self.accepts_var_positional:
            problems.append(
                f"{self.name}() takes at most {len(positional)} positional argument(s), "
                f"got {positional_count}"
            )
        for keyword in keywords:
            if keyword not in self.keyword_names and not self.accepts_var_keyword:
                problems.append(
                    f"{self.name}() has no parameter {keyword!r} "
                    f"(parameters: {', '.join(p.name for p in self.params) or 'none'})"
                )
        bound = {p.name for p in positional[:positional_count]} | set(keywords)
        for param in self.params:
            required = param.kind in ("positional", "keyword_only") and not param.has_default
            if required and param.name not in bound:
                problems.append(f"{self.name}() misses required argument {param.name!r}")
        for param in positional[:positional_count]:
            if param.name in keywords:
                problems.append(f"{self.name}() got {param.name!r} both by position and keyword")
        return problems


@dataclass(slots=True)
class StubClass:
    """One class of the stub: its bases, members and editor properties."""

    name: str
    bases: tuple[str, ...]
    members: dict[str, Member] = field(default_factory=dict)
    editor_properties: dict[str, str] = field(default_factory=dict)


class StubIndex:
    """Classes and module functions of the ``unreal`` module, with inheritance lookups."""

    def __init__(self, classes: dict[str, StubClass], functions: dict[str, Member]) -> None:
        self.classes = classes
        self.functions = functions
        self._method_names: frozenset[str] | None = None

    def __contains__(self, name: str) -> bool:
        return name in self.classes or name in self.functions

    def mro(self, class_name: str) -> Iterator[StubClass]:
        """The class and its bases, depth first in declaration order, each once."""
        seen: set[str] = set()
        pending = [class_name]
        while pending:
            name = pending.pop(0)
            if name in seen or name not in self.classes:
                continue
            seen.add(name)
            stub_class = self.classes[name]
            yield stub_class
            pending[0:0] = list(stub_class.bases)

    def member(self, class_name: str, name: str) -> Member | None:
        """The member ``name`` of ``class_name`` or of its nearest base that defines it."""
        for stub_class in self.mro(class_name):
            found = stub_class.members.get(name)
            if found is not None:
                return found
        return None

    def editor_property(self, class_name: str, name: str) -> str | None:
        """The type of editor property ``name`` on ``class_name`` (or a base), else None."""
        for stub_class in self.mro(class_name):
            if name in stub_class.editor_properties:
                return stub_class.editor_properties[name]
        return None

    def is_subclass(self, class_name: str, base_name: str) -> bool:
        """True when ``class_name`` is ``base_name`` or derives from it."""
        return any(c.name == base_name for c in self.mro(class_name))

    @property
    def method_names(self) -> frozenset[str]:
        """Every member name defined on any class (used to spot untracked API calls)."""
        if self._method_names is None:
            names: set[str] = set()
            for stub_class in self.classes.values():
                names.update(
                    name
                    for name, member in stub_class.members.items()
                    if member.kind != "attribute"
                )
            self._method_names = frozenset(names)
        return self._method_names


def split_top_level(text: str, separator: str = ",") -> list[str]:
    """Split ``text`` on ``separator`` outside brackets and string literals."""
    parts: list[str] = []
    depth = 0
    quote: str | None = None
    start = 0
    index = 0
    while index < len(text):
        char = text[index]
        if quote is not None:
            if char == "\\":
                index += 2
                continue
            if char == quote:
                quote = None
        elif char in "\"'":
            quote = char
        elif char in "([{":
            depth += 1
        elif char in ")]}":
            depth -= 1
        elif char == separator and depth == 0:
            parts.append(text[start:index])
            start = index + 1
        index += 1
    tail = text[start:]
    if tail.strip():
        parts.append(tail)
    return [part.strip() for part in parts]


def _parse_params(text: str, *, drop_first: bool) -> tuple[Param, ...]:
    params: list[Param] = []
    keyword_only = False
    for index, raw in enumerate(split_top_level(text)):
        if index == 0 and drop_first:
            continue  # self / cls
        if raw == "*":
            keyword_only = True
            continue
        if raw == "/":
            continue
        head = split_top_level(raw, "=")[0]
        name = split_top_level(head, ":")[0].strip()
        has_default = len(split_top_level(raw, "=")) > 1
        if name.startswith("**"):
            params.append(Param(name[2:], True, "var_keyword"))
        elif name.startswith("*"):
            params.append(Param(name[1:], True, "var_positional"))
            keyword_only = True
        else:
            params.append(
                Param(name, has_default, "keyword_only" if keyword_only else "positional")
            )
    return tuple(params)


def parse_stub(lines: Iterator[str]) -> StubIndex:
    """Index the stub's text (already decoded, BOM removed)."""
    classes: dict[str, StubClass] = {}
    functions: dict[str, Member] = {}
    current: StubClass | None = None
    decorator: str | None = None
    for line in lines:
        if not line.strip():
            continue
        if not line.startswith(" "):
            decorator = None
            class_match = _CLASS.match(line)
            if class_match:
                bases = tuple(
                    base.split("[", 1)[0].strip()
                    for base in split_top_level(class_match.group(2))
                    if base.strip()
                )
                current = StubClass(class_match.group(1), bases)
                classes[current.name] = current
                continue
            current = None
            function_match = _FUNCTION_DEF.match(line)
            if function_match:
                name = function_match.group(1)
                functions[name] = Member(
                    name,
                    "method",
                    _parse_params(function_match.group(2), drop_first=False),
                    (function_match.group(3) or "").strip(),
                )
            continue
        if current is None:
            continue
        decorator_match = _DECORATOR.match(line)
        if decorator_match:
            decorator = decorator_match.group(1)
            continue
        def_match = _MEMBER_DEF.match(line)
        if def_match:
            name = def_match.group(1)
            returns = (def_match.group(3) or "").strip()
            if decorator is not None and decorator.endswith(".setter"):
                existing = current.members.get(name)
                if existing is not None and existing.kind == "property":
                    current.members[name] = Member(
                        name, "property", returns=existing.returns, writable=True
                    )
            elif decorator == "property":
                current.members[name] = Member(name, "property", returns=returns)
            else:
                kind: MemberKind = "method"
                if decorator == "classmethod":
                    kind = "classmethod"
                elif decorator == "staticmethod":
                    kind = "staticmethod"
                current.members[name] = Member(
                    name,
                    kind,
                    _parse_params(def_match.group(2), drop_first=kind != "staticmethod"),
                    returns,
                )
            decorator = None
            continue
        property_match = _EDITOR_PROPERTY.match(line)
        if property_match:
            current.editor_properties.setdefault(property_match.group(1), property_match.group(2))
            continue
        attribute_match = _ATTRIBUTE.match(line)
        if attribute_match and not line.startswith("     "):
            name = attribute_match.group(1)
            current.members.setdefault(
                name, Member(name, "attribute", returns=attribute_match.group(2).strip())
            )
    return StubIndex(classes, functions)


def stub_path() -> Path:
    """The installed ``unreal/unreal.py`` of the ``unreal-stub`` distribution.

    Located through the distribution's metadata rather than ``import unreal``:
    the stub cannot be imported, and a test folder named ``unreal`` could
    shadow it on ``sys.path``.
    """
    distribution = importlib.metadata.distribution("unreal-stub")
    path = Path(str(distribution.locate_file("unreal/unreal.py")))
    if not path.is_file():
        raise FileNotFoundError(f"unreal-stub is installed but {path} is missing")
    return path


@functools.cache
def load_stub_index(path: Path | None = None) -> StubIndex:
    """Index the stub once per process (about a second for the 26 MB file)."""
    source = path if path is not None else stub_path()
    with source.open(encoding="utf-8-sig") as stream:
        return parse_stub(line.rstrip("\n") for line in stream)
