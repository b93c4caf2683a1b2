"""The UE 5.6 API stub index: it reads the real stub, and reads it right."""

from __future__ import annotations

import ast

import pytest
from unreal_stub_index import StubIndex, parse_stub, split_top_level, stub_path


def test_stub_is_the_real_unreal_stub_and_cannot_be_parsed_by_ast() -> None:
    path = stub_path()
    raw = path.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf"), "unreal-stub 0.3 starts with a byte-order mark"
    assert len(raw) > 20_000_000
    # The reason the index uses line patterns: one default value is not Python.
    with pytest.raises(SyntaxError):
        ast.parse(raw.decode("utf-8-sig"))


def test_index_holds_every_class_and_the_module_functions(stub_index: StubIndex) -> None:
    assert len(stub_index.classes) == 8581
    for name in ("log", "log_warning", "log_error", "load_asset", "get_editor_subsystem"):
        assert name in stub_index.functions
    assert stub_index.functions["get_engine_subsystem"].returns.startswith("Optional[")


def test_line_with_the_unparseable_default_is_still_indexed(stub_index: StubIndex) -> None:
    # ToolBarStyle.__init__ (around line 118336) holds "(Left=0.000000, ...)" defaults.
    init = stub_index.member("ToolBarStyle", "__init__")
    assert init is not None
    names = [param.name for param in init.params]
    assert names[0] == "background_brush"
    assert names[-1] == "raised_children_right_padding"
    assert "vertical_alignment_override" in names
    assert all(param.has_default for param in init.params)


def test_inherited_members_are_found_through_the_bases(stub_index: StubIndex) -> None:
    mro = [c.name for c in stub_index.mro("InstancedStaticMeshComponent")]
    assert mro[:5] == [
        "InstancedStaticMeshComponent",
        "StaticMeshComponent",
        "MeshComponent",
        "PrimitiveComponent",
        "SceneComponent",
    ]
    assert stub_index.member("InstancedStaticMeshComponent", "set_static_mesh") is not None
    assert stub_index.member("InstancedStaticMeshComponent", "set_collision_enabled") is not None
    cast = stub_index.member("DirectionalLightComponent", "cast")
    assert cast is not None and cast.kind == "classmethod"
    assert stub_index.is_subclass("DirectionalLight", "Actor")
    assert not stub_index.is_subclass("Actor", "DirectionalLight")


def test_add_instances_has_the_5_6_signature(stub_index: StubIndex) -> None:
    member = stub_index.member("InstancedStaticMeshComponent", "add_instances")
    assert member is not None
    assert [(p.name, p.has_default) for p in member.params] == [
        ("instance_transforms", False),
        ("should_return_indices", False),
        ("world_space", True),
        ("update_navigation", True),
    ]
    assert member.returns == "Array[int]"


def test_rotator_takes_roll_first(stub_index: StubIndex) -> None:
    init = stub_index.member("Rotator", "__init__")
    assert init is not None
    assert [p.name for p in init.params] == ["roll", "pitch", "yaw"]


def test_properties_enum_values_and_editor_properties(stub_index: StubIndex) -> None:
    root = stub_index.member("Actor", "root_component")
    assert root is not None and root.kind == "property" and root.returns == "SceneComponent"
    light = stub_index.member("DirectionalLight", "light_component")
    assert light is not None and light.returns == "LightComponent"
    value = stub_index.member("CollisionEnabled", "NO_COLLISION")
    assert value is not None and value.kind == "attribute"
    assert stub_index.editor_property("SkyLightComponent", "real_time_capture") == "bool"
    assert stub_index.editor_property("StaticMeshActor", "root_component") == "SceneComponent"
    assert stub_index.editor_property("Actor", "no_such_property") is None


@pytest.mark.parametrize(
    ("class_name", "member"),
    [
        ("Actor", "add_component_by_class"),
        ("Actor", "add_instance_component"),
        ("ActorComponent", "register_component"),
        ("Actor", "get_root_component"),
    ],
)
def test_names_public_scripts_use_do_not_exist_in_5_6(
    stub_index: StubIndex, class_name: str, member: str
) -> None:
    assert stub_index.member(class_name, member) is None


def test_classes_public_scripts_use_do_not_exist_in_5_6(stub_index: StubIndex) -> None:
    assert "InstancedStaticMeshActor" not in stub_index
    assert "LandscapeEditorSubsystem" not in stub_index
    # Deprecated rather than missing: it still exists, the generator must not use it.
    assert "EditorLevelLibrary" in stub_index


def test_call_checks_on_a_member() -> None:
    index = parse_stub(
        iter(
            [
                "class Base(object):",
                "    def go(self, a: int, b: str = 'x, y', *, c: float = (1, 2)) -> None:",
                "        ...",
                "class Child(Base):",
                "    @classmethod",
                "    def make(cls, thing: Dict[str, int] = {'a': 1}) -> Child:",
                "        ...",
                "def free(*args: Any, **kwargs: Any) -> None:",
                "    ...",
            ]
        )
    )
    go = index.member("Child", "go")
    assert go is not None
    assert [(p.name, p.has_default, p.kind) for p in go.params] == [
        ("a", False, "positional"),
        ("b", True, "positional"),
        ("c", True, "keyword_only"),
    ]
    assert go.check_call(1, ("c",)) == []
    assert go.check_call(0, ()) == ["go() misses required argument 'a'"]
    assert go.check_call(3, ()) == ["go() takes at most 2 positional argument(s), got 3"]
    assert "has no parameter 'd'" in go.check_call(1, ("d",))[0]
    make = index.member("Child", "make")
    assert make is not None and make.kind == "classmethod" and len(make.params) == 1
    free = index.functions["free"]
    assert free.check_call(5, ("anything",)) == []


def test_split_top_level_skips_brackets_and_strings() -> None:
    assert split_top_level("a, b=[1, 2], c='x,y', d=f(1, (2, 3))") == [
        "a",
        "b=[1, 2]",
        "c='x,y'",
        "d=f(1, (2, 3))",
    ]
