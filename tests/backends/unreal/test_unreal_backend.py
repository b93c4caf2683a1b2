"""The Unreal backend's script: valid, deterministic, small, and safe with any recipe text."""

from __future__ import annotations

import ast
import builtins
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from fake_unreal import run_script
from unreal_recipes import mixed_crops, packed_recipe, two_field_recipe

import agrirecipe.layout
from agrirecipe import AgrirecipeError, Scene
from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe.backends import get_backend
from agrirecipe.backends.unreal import (
    SCRIPT_NAME,
    UnrealBackend,
    unreal_location_cm,
    unreal_sun_rotation,
    unreal_yaw_deg,
)
from agrirecipe.recipe import Sun

# Text built to break out of every kind of Python literal and comment.
HOSTILE = (
    "x'''\"\"\"\\'\\\"\\\\\n"
    "__import__('builtins').AGRIRECIPE_PWNED = 1 # \r\n"
    '"); __import__("builtins").AGRIRECIPE_PWNED = 2; ("\n'
    "''') ; AGRIRECIPE_PWNED = 3 ; (''' \u2028 \x00 {scene} %s {{}}"
)


def _scene_json_constant(tree: ast.Module) -> ast.Constant:
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "SCENE_JSON":
            assert isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)
            return node.value
    raise AssertionError("no SCENE_JSON assignment")


def test_script_is_valid_python_3_11_with_the_kernel_and_runtime_inlined() -> None:
    script = UnrealBackend().script(Scene(two_field_recipe()))
    ast.parse(script, feature_version=(3, 11))
    assert agrirecipe.layout.kernel_source().rstrip("\n") in script
    assert "import unreal\n" in script
    assert script.rstrip().endswith(
        "ASSETS_ROOT = None\n\nAGRIRECIPE_RESULT = run(SCENE_JSON, iter_field_plants, ASSETS_ROOT)"
    )
    header = script.split("\n\n", 1)[0]
    assert "-run=pythonscript -script=unreal_build.py -unattended -nullrhi" in header
    assert all(line.startswith("#") for line in header.splitlines())


def test_scene_json_holds_the_kernel_parameters_of_every_field() -> None:
    scene = Scene(two_field_recipe())
    document = json.loads(_scene_json_constant(ast.parse(scene.script("unreal"))).value)
    assert [field["kernel"] for field in document["fields"]] == (
        agrirecipe.layout.field_parameters(scene.recipe)
    )
    assert document["scene"]["prompt"] == scene.recipe.prompt
    assert document["format"] == 1


def test_same_recipe_same_bytes_even_across_processes() -> None:
    recipe = two_field_recipe()
    script = UnrealBackend().script(Scene(recipe))
    assert UnrealBackend().script(Scene(recipe)) == script
    code = (
        "import sys; sys.path.insert(0, sys.argv[1]); from unreal_recipes import "
        "two_field_recipe; from agrirecipe import Scene; "
        "sys.stdout.write(Scene(two_field_recipe()).script('unreal'))"
    )
    environment = {**os.environ, "PYTHONHASHSEED": "12345"}
    other = subprocess.run(
        [sys.executable, "-c", code, str(Path(__file__).parent)],
        capture_output=True,
        text=True,
        check=True,
        env=environment,
    ).stdout
    assert other == script


def test_different_seed_changes_only_the_data() -> None:
    first = ast.parse(UnrealBackend(scene_name="Farm").script(Scene(two_field_recipe(seed=1))))
    second = ast.parse(UnrealBackend(scene_name="Farm").script(Scene(two_field_recipe(seed=2))))
    assert _scene_json_constant(first).value != _scene_json_constant(second).value
    _scene_json_constant(first).value = _scene_json_constant(second).value = ""
    assert ast.dump(first) == ast.dump(second)


def test_hostile_prompt_and_labels_stay_data() -> None:
    benign = two_field_recipe()
    hostile = two_field_recipe(prompt=HOSTILE * 3, apple_label=HOSTILE, carrot_label=HOSTILE[:150])
    backend = UnrealBackend(scene_name="Farm")
    benign_script, hostile_script = backend.script(Scene(benign)), backend.script(Scene(hostile))
    # Identical code: the only difference is the value of the SCENE_JSON string.
    benign_tree, hostile_tree = ast.parse(benign_script), ast.parse(hostile_script)
    document = json.loads(_scene_json_constant(hostile_tree).value)
    assert document["scene"]["prompt"] == HOSTILE * 3
    assert [field["label"] for field in document["fields"]] == [HOSTILE, HOSTILE[:150]]
    _scene_json_constant(benign_tree).value = _scene_json_constant(hostile_tree).value = ""
    assert ast.dump(benign_tree) == ast.dump(hostile_tree)
    # No recipe text in comments or code: before SCENE_JSON there is none, and
    # each line of SCENE_JSON is one complete string literal on its own.
    code, _, rest = hostile_script.partition("SCENE_JSON = (\n")
    literal_lines, _, tail = rest.partition("\n)\n")
    assert "PWNED" not in code and "PWNED" not in tail
    for line in literal_lines.splitlines():
        piece = ast.parse(line.strip(), mode="eval").body
        assert isinstance(piece, ast.Constant) and isinstance(piece.value, str)
    assert hostile_script.isascii()
    # Running it does what the benign script does, with the text as labels.
    namespace, recording = run_script(hostile_script)
    assert not hasattr(builtins, "AGRIRECIPE_PWNED")
    assert "AGRIRECIPE_PWNED" not in namespace
    labels = [actor._label for actor in recording.actors_of("Actor")]
    assert labels == [HOSTILE, HOSTILE[:150]]
    # The log quotes the (shortened) request with repr: readable, one line.
    quoted = repr((HOSTILE * 3)[:297] + "...")
    assert any(quoted in message for _, message in recording.logs)


def test_write_creates_the_script_atomically(tmp_path: Path) -> None:
    from agrirecipe.layout import field_parameters
    from agrirecipe.plants import has_relief

    scene = Scene(two_field_recipe())
    written = UnrealBackend().write(scene, tmp_path / "out")
    assert written == [tmp_path / "out" / SCRIPT_NAME]
    assert written[0].read_text(encoding="utf-8") == scene.script("unreal")
    # Beside it, only the plant meshes it imports (no temporary file left behind).
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["assets", SCRIPT_NAME]
    meshes = sorted((tmp_path / "out" / "assets").rglob("*.glb"))
    ground = [p for p in meshes if p.parent.name == "ground"]
    assert len(meshes) - len(ground) == 3 * len(scene.recipe.fields)
    parameters = {str(p["id"]): p for p in field_parameters(scene.recipe)}
    relief = [s.id for s in scene.recipe.fields if has_relief(s, parameters[s.id])]
    assert "carrots" in relief  # ridges (and the orchard's headland track)
    assert sorted(p.stem for p in ground) == sorted(relief)
    assert not [p for p in (tmp_path / "out").rglob(".*")]


def test_backend_is_registered_by_name() -> None:
    backend = get_backend("unreal")
    assert isinstance(backend, UnrealBackend)
    assert backend.outputs == ("unreal_build.py",)
    scene = Scene(two_field_recipe())
    assert scene.script("unreal") == backend.script(scene)


@pytest.mark.parametrize(
    "options",
    [
        {"chunk_size": 0},
        {"chunk_size": 2_000_000},
        {"chunk_size": True},
        {"chunk_size": 1.5},
        {"scene_name": "my farm"},
        {"scene_name": "../../Game"},
        {"scene_name": ""},
        {"scene_name": "9lives"},
    ],
)
def test_bad_options_raise_a_configuration_error(options: dict[str, Any]) -> None:
    with pytest.raises(ConfigurationError) as caught:
        UnrealBackend(**options)
    assert isinstance(caught.value, AgrirecipeError)
    assert caught.value.hint


def test_scene_name_names_the_folders() -> None:
    script = UnrealBackend(scene_name="North_Farm").script(Scene(two_field_recipe()))
    document = json.loads(_scene_json_constant(ast.parse(script)).value)
    assert [field["folder"] for field in document["fields"]] == [
        "Agrirecipe/North_Farm/apples",
        "Agrirecipe/North_Farm/carrots",
    ]


def test_a_kernel_that_clashes_with_the_runtime_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    source = agrirecipe.layout.kernel_source() + "\n\ndef build_scene(scene, plants):\n    pass\n"
    monkeypatch.setattr(agrirecipe.layout, "kernel_source", lambda: source)
    with pytest.raises(BackendError, match="build_scene"):
        UnrealBackend().script(Scene(two_field_recipe()))


def test_a_kernel_without_an_entry_point_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(agrirecipe.layout, "kernel_source", lambda: "import math\n")
    with pytest.raises(BackendError, match="place_field"):
        UnrealBackend().script(Scene(two_field_recipe()))


def test_ten_field_million_plant_scene_script_stays_under_64_kb() -> None:
    crops = mixed_crops(10)
    large = packed_recipe(crops, 1_000_000)
    small = packed_recipe(crops, 10_000)
    assert len(large.fields) == 10
    assert 900_000 <= large.nominal_plant_count <= 1_100_000
    large_size = len(UnrealBackend().script(Scene(large)).encode("utf-8"))
    small_size = len(UnrealBackend().script(Scene(small)).encode("utf-8"))
    assert large_size < 64 * 1024
    # Proportional to fields, not plants: 100x the plants changes a few digits.
    assert abs(large_size - small_size) < 512


def test_unit_and_handedness_conversions() -> None:
    assert unreal_location_cm(1.5, 2.0, -0.25) == (150.0, -200.0, -25.0)
    assert unreal_location_cm(0.0, 0.0, 0.0) == (0.0, 0.0, 0.0)
    assert str(unreal_location_cm(0.0, 0.0, 0.0)[1]) == "0.0", "no -0.0 in scripts"
    assert unreal_yaw_deg(0.5 * 3.141592653589793) == pytest.approx(-90.0)
    # Midday sun in the south, 30 degrees up: light travels north (Unreal -Y) and down.
    assert unreal_sun_rotation(Sun(elevation_deg=30.0, azimuth_deg=180.0)) == (-30.0, -90.0)
    # Sun in the east: light travels west (Unreal -X), yaw 180.
    assert unreal_sun_rotation(Sun(elevation_deg=10.0, azimuth_deg=90.0)) == (-10.0, 180.0)
    assert unreal_sun_rotation(Sun(elevation_deg=10.0, azimuth_deg=270.0)) == (-10.0, 0.0)
