"""The recording fake cannot drift from the real API: its surface is checked against the stub."""

from __future__ import annotations

import functools
import inspect
from typing import Any

from fake_unreal import SUPPORT_TYPES, make_fake_unreal
from unreal_api_check import check_script
from unreal_recipes import growth_form_recipe, two_field_recipe
from unreal_stub_index import Member, StubIndex
from unreal_surface import ALLOWED_NAMES, ALLOWED_UNTRACKED_MEMBERS

from agrirecipe import Scene
from agrirecipe.backends.unreal import UnrealBackend


def _public_names(module: Any) -> set[str]:
    return {name for name in vars(module) if not name.startswith("_")}


def _own_members(cls: type) -> dict[str, Any]:
    """Public members a fake class defines itself (plus ``__init__``/``__enter__``/``__exit__``)."""
    return {
        name: value
        for name, value in vars(cls).items()
        if (not name.startswith("_") or name in ("__init__", "__enter__", "__exit__"))
    }


def _fake_parameters(value: Any) -> list[tuple[str, bool]]:
    function = value.__func__ if isinstance(value, classmethod | staticmethod) else value
    parameters = list(inspect.signature(function).parameters.values())
    if not isinstance(value, staticmethod):
        parameters = parameters[1:]  # self / cls
    return [(p.name, p.default is not inspect.Parameter.empty) for p in parameters]


def _stub_parameters(member: Member) -> list[tuple[str, bool]]:
    return [(p.name, p.has_default) for p in member.params]


def test_fake_module_is_the_allow_list_plus_support_types() -> None:
    module, _ = make_fake_unreal()
    names = _public_names(module)
    assert names == ALLOWED_NAMES | SUPPORT_TYPES
    # Support types are only received from the API, never named by scripts.
    assert not ALLOWED_NAMES & SUPPORT_TYPES


def test_fake_classes_and_functions_exist_in_the_stub_with_the_same_signatures(
    stub_index: StubIndex,
) -> None:
    module, _ = make_fake_unreal()
    problems: list[str] = []
    for name in sorted(_public_names(module)):
        value = getattr(module, name)
        if not isinstance(value, type):
            stub_function = stub_index.functions.get(name)
            if stub_function is None:
                problems.append(f"function {name} is not in the stub")
            elif _fake_parameters_of_function(value) != _stub_parameters(stub_function):
                problems.append(
                    f"{name}{_fake_parameters_of_function(value)} != stub "
                    f"{_stub_parameters(stub_function)}"
                )
            continue
        if name not in stub_index.classes:
            problems.append(f"class {name} is not in the stub")
            continue
        for base in value.__mro__[1:]:
            if base is object:
                continue
            if not stub_index.is_subclass(name, base.__name__):
                problems.append(f"{name} derives from {base.__name__} in the fake, not the stub")
        for member_name, member_value in _own_members(value).items():
            stub_member = stub_index.member(name, member_name)
            if stub_member is None:
                problems.append(f"{name}.{member_name} is not in the stub")
                continue
            if isinstance(member_value, property):
                if stub_member.kind != "property":
                    problems.append(f"{name}.{member_name} is a {stub_member.kind} in the stub")
                continue
            if member_name.isupper():  # enum values
                if stub_member.kind != "attribute":
                    problems.append(f"{name}.{member_name} is not an enum value in the stub")
                continue
            expected_kind = (
                "classmethod"
                if isinstance(member_value, classmethod)
                else "staticmethod"
                if isinstance(member_value, staticmethod)
                else "method"
            )
            if stub_member.kind != expected_kind:
                problems.append(
                    f"{name}.{member_name} is a {stub_member.kind} in the stub, "
                    f"a {expected_kind} in the fake"
                )
            fake_params = _fake_parameters(member_value)
            if fake_params != _stub_parameters(stub_member):
                problems.append(
                    f"{name}.{member_name}{fake_params} != stub {_stub_parameters(stub_member)}"
                )
    assert problems == []


def _fake_parameters_of_function(function: Any) -> list[tuple[str, bool]]:
    return [
        (p.name, p.default is not inspect.Parameter.empty)
        for p in inspect.signature(function).parameters.values()
    ]


@functools.cache
def _used_members(index: StubIndex) -> set[tuple[str, str]]:
    used: set[tuple[str, str]] = set()
    for scene, backend in [
        (Scene(two_field_recipe()), UnrealBackend()),
        (Scene(two_field_recipe()), UnrealBackend(sky=False, save_level=True)),
        (Scene(growth_form_recipe()), UnrealBackend()),
    ]:
        report = check_script(
            backend.script(scene),
            index,
            allowed_names=ALLOWED_NAMES,
            allowed_untracked=ALLOWED_UNTRACKED_MEMBERS,
        )
        used |= report.members
    return used


def test_fake_implements_exactly_what_the_scripts_use(stub_index: StubIndex) -> None:
    module, _ = make_fake_unreal()
    implemented: set[tuple[str, str]] = set()
    for name in _public_names(module):
        value = getattr(module, name)
        if isinstance(value, type):
            implemented |= {
                (name, member)
                for member in _own_members(value)
                if not member.startswith("__") and member != "__init__"
            }
    served: set[tuple[str, str]] = set()
    missing: list[str] = []
    for class_name, member in sorted(_used_members(stub_index)):
        fake_class = getattr(module, class_name, None)
        owner = None
        if fake_class is not None:
            owner = next(
                (c.__name__ for c in fake_class.__mro__ if member in vars(c)),
                None,
            )
        if owner is None:
            missing.append(f"{class_name}.{member}")
        else:
            served.add((owner, member))
    assert missing == []
    assert implemented == served, "the fake implements API the scripts never use"
