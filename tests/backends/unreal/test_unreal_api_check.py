"""Generated Unreal scripts use only real UE 5.6 API, allow-listed, called compatibly."""

from __future__ import annotations

import ast
import functools
import textwrap

import pytest
from unreal_api_check import ApiReport, check_script, policy_problems
from unreal_recipes import growth_form_recipe, two_field_recipe
from unreal_stub_index import StubIndex
from unreal_surface import ALLOWED_NAMES, ALLOWED_UNTRACKED_MEMBERS, BANNED_NAMES

from agrirecipe import Scene
from agrirecipe.backends.unreal import UnrealBackend


@functools.cache
def _scripts() -> dict[str, str]:
    two_fields = Scene(two_field_recipe())
    return {
        "default": UnrealBackend().script(two_fields),
        "every growth form": UnrealBackend().script(Scene(growth_form_recipe("Winter"))),
        "no sky, saves level": UnrealBackend(sky=False, save_level=True).script(two_fields),
    }


def _check(source: str, index: StubIndex) -> ApiReport:
    return check_script(
        source,
        index,
        allowed_names=ALLOWED_NAMES,
        allowed_untracked=ALLOWED_UNTRACKED_MEMBERS,
        banned_names=BANNED_NAMES,
    )


@pytest.mark.parametrize("variant", ["default", "every growth form", "no sky, saves level"])
def test_generated_script_passes_the_api_check(stub_index: StubIndex, variant: str) -> None:
    source = _scripts()[variant]
    report = _check(source, stub_index)
    assert report.problems == []
    assert policy_problems(source) == []
    # Every unreal value's type was followed: nothing was accepted on trust.
    assert report.untracked == set()
    # The check saw the API calls that matter (it is not vacuously empty).
    for used in [
        ("InstancedStaticMeshComponent", "add_instances"),
        ("EditorActorSubsystem", "spawn_actor_from_class"),
        ("SubobjectDataSubsystem", "add_new_subobject"),
        ("SubobjectDataSubsystem", "k2_gather_subobject_data_for_instance"),
        ("ScopedSlowTask", "should_cancel"),
        ("Actor", "set_folder_path"),
        ("Actor", "set_actor_label"),
        ("StaticMeshComponent", "set_static_mesh"),
        ("EditorAssetLibrary", "does_asset_exist"),
    ]:
        assert used in report.members
    assert {"ScopedEditorTransaction", "ScopedSlowTask", "Rotator", "Transform"} <= report.names


def test_generated_script_never_names_known_bad_api() -> None:
    for source in _scripts().values():
        for name in BANNED_NAMES:
            assert name not in source


def test_allow_list_names_exist_in_the_stub(stub_index: StubIndex) -> None:
    assert sorted(name for name in ALLOWED_NAMES if name not in stub_index) == []
    assert sorted(name for name in BANNED_NAMES & ALLOWED_NAMES) == []


def test_every_allow_listed_name_is_needed() -> None:
    used: set[str] = set()
    for source in _scripts().values():
        used |= _check_names(source)
    assert used == ALLOWED_NAMES


def _check_names(source: str) -> set[str]:
    return {
        node.attr
        for node in ast.walk(ast.parse(source))
        if isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "unreal"
    }


def _snippet_problems(body: str, index: StubIndex) -> list[str]:
    source = "import unreal\n\n\ndef build() -> None:\n" + textwrap.indent(
        textwrap.dedent(body), "    "
    )
    return _check(source, index).problems + policy_problems(source)


_PRELUDE = """
actors = unreal.get_editor_subsystem(unreal.EditorActorSubsystem)
actor = actors.spawn_actor_from_class(unreal.Actor, unreal.Vector(0.0, 0.0, 0.0))
"""


def test_a_correct_snippet_passes(stub_index: StubIndex) -> None:
    problems = _snippet_problems(
        _PRELUDE
        + """
actor.set_actor_label("field")
actor.set_actor_location(unreal.Vector(1.0, 2.0, 3.0), False, True)
ground = actors.spawn_actor_from_class(unreal.StaticMeshActor, unreal.Vector())
ground.static_mesh_component.set_collision_enabled(unreal.CollisionEnabled.NO_COLLISION)
""",
        stub_index,
    )
    assert problems == []


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ("root = actor.get_root_component()\n", "get_root_component"),
        (
            "actor.add_component_by_class(unreal.InstancedStaticMeshComponent)\n",
            "add_component_by_class",
        ),
        ("unreal.InstancedStaticMeshActor\n", "InstancedStaticMeshActor"),
        ("unreal.EditorLevelLibrary.get_all_level_actors()\n", "not on the allow-list"),
        ("unreal.SplineComponent\n", "not on the allow-list"),
        ("unreal.NoSuchThing\n", "does not exist in the UE 5.6 API"),
        ("actor.set_actor_location(unreal.Vector())\n", "misses required argument 'sweep'"),
        ("unreal.Vector(1.0, 2.0, 3.0, 4.0)\n", "at most 3 positional"),
        ("unreal.Transform(location=unreal.Vector(), rotaton=None)\n", "no parameter 'rotaton'"),
        ("unreal.Rotator(0.0, 0.0, 90.0)\n", "roll first"),
        ("actor.set_actor_label(text='x')\n", "no parameter 'text'"),
        ("unreal.Actor.set_actor_label('x')\n", "instance method called on the class"),
        ("actor.set_editor_property('not_a_property', 1)\n", "no editor property"),
        ("actor.root_component.add_instances([], False, True)\n", "no member 'add_instances'"),
        ("actor.set_folder_path\nactor.no_such_attribute\n", "no member 'no_such_attribute'"),
        ("mesh = unreal.load_asset('/Game/A.A')\nmesh.set_static_mesh(None)\n", "not followed"),
        (
            "c = unreal.InstancedStaticMeshComponent.cast(actor.root_component)\n"
            "c.add_instances([], False, True, False)\n",
            "add_instances must be",
        ),
    ],
)
def test_the_check_catches_bad_api_use(stub_index: StubIndex, body: str, expected: str) -> None:
    problems = _snippet_problems(_PRELUDE + body, stub_index)
    assert any(expected in problem for problem in problems), problems


def test_types_follow_function_annotations_and_tuples(stub_index: StubIndex) -> None:
    source = textwrap.dedent(
        """
        import unreal


        def make(subobjects: unreal.SubobjectDataSubsystem, actor: unreal.Actor) -> unreal.Actor:
            handle, failure = subobjects.add_new_subobject(unreal.AddNewSubobjectParams())
            failure.no_such_text_method()
            root = subobjects.k2_gather_subobject_data_for_instance(actor)[0]
            root.no_such_handle_method()
            return actor


        def use(subobjects: unreal.SubobjectDataSubsystem) -> None:
            made = make(subobjects, None)
            made.no_such_actor_method()
        """
    )
    problems = _check(source, stub_index).problems
    assert any("Text has no member 'no_such_text_method'" in p for p in problems), problems
    assert any("SubobjectDataHandle has no member 'no_such_handle_method'" in p for p in problems)
    assert any("Actor has no member 'no_such_actor_method'" in p for p in problems)
