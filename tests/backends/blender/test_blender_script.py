"""The generated bpy script as text: structure, safety, size, settings (no bpy needed)."""

from __future__ import annotations

import ast
import io
import math
import tokenize
from importlib import resources
from pathlib import Path
from typing import Any

import pytest
from blender_recipes import HOSTILE, mixed_recipe, single_field_recipe

from agrirecipe import ConfigurationError, Scene, get_backend
from agrirecipe.backends.blender import (
    SCRIPT_NAME,
    BlenderBackend,
    RenderSettings,
    blender_script,
    render,
)
from agrirecipe.layout import field_parameters, kernel_source


def builder_source() -> str:
    return (
        resources.files("agrirecipe.backends._blender")
        .joinpath("scene_builder.py")
        .read_text(encoding="utf-8")
    )


def scene_literal(script: str) -> Any:
    """The value of ``SCENE = ...`` read with ``ast.literal_eval`` (never executed)."""
    for node in ast.parse(script).body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", None) == "SCENE":
            return ast.literal_eval(node.value)
    raise AssertionError("no SCENE literal in the script")


def shape(script: str) -> str:
    """The script's syntax tree with every string and number replaced by a placeholder."""

    class Blank(ast.NodeTransformer):
        def visit_Constant(self, node: ast.Constant) -> ast.Constant:
            return ast.Constant(value=type(node.value).__name__)

    return ast.dump(Blank().visit(ast.parse(script)))


def test_script_compiles_and_inlines_kernel_and_builder_verbatim() -> None:
    script = blender_script(mixed_recipe())
    compile(script, SCRIPT_NAME, "exec")
    assert kernel_source().strip() in script
    assert builder_source().strip() in script
    assert script.index("RESOLUTION =") < script.index(kernel_source().strip()[:60])
    assert "bpy.ops.wm.read_factory_settings(use_empty=True)" in script


def test_scene_literal_carries_the_kernel_parameters_of_every_field() -> None:
    recipe = mixed_recipe()
    data = scene_literal(blender_script(recipe))
    assert [f["params"] for f in data["fields"]] == field_parameters(recipe)
    assert [f["id"] for f in data["fields"]] == [f.id for f in recipe.fields]
    assert data["environment"]["sun"] == recipe.environment.sun.model_dump()


def test_same_recipe_gives_the_same_bytes() -> None:
    assert blender_script(mixed_recipe()) == blender_script(mixed_recipe())


def test_script_size_follows_fields_not_plants() -> None:
    small = single_field_recipe("Wheat", size_m=(4.0, 4.0))
    huge = single_field_recipe("Wheat", size_m=(150.0, 150.0))
    assert huge.nominal_plant_count > 1000 * small.nominal_plant_count
    assert abs(len(blender_script(huge)) - len(blender_script(small))) < 200
    assert len(blender_script(mixed_recipe())) < 120_000


def test_kernel_and_builder_define_no_name_twice() -> None:
    def top_level_names(source: str) -> set[str]:
        names = set()
        for node in ast.parse(source).body:
            if isinstance(node, ast.FunctionDef | ast.ClassDef):
                names.add(node.name)
            elif isinstance(node, ast.Assign):
                names.update(t.id for t in node.targets if isinstance(t, ast.Name))
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                names.add(node.target.id)
        return names

    shared = top_level_names(kernel_source()) & top_level_names(builder_source())
    assert not shared


def test_builder_keeps_the_inlining_rules() -> None:
    tree = ast.parse(builder_source())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            assert node.module != "__future__"
            assert not (node.module or "").startswith("agrirecipe")
        if isinstance(node, ast.Import):
            assert not any(alias.name.startswith("agrirecipe") for alias in node.names)
    assert "def main(" in builder_source()


def test_hostile_label_stays_data_and_prompt_never_appears() -> None:
    plain = single_field_recipe(label="plain label", prompt="plain prompt")
    hostile = single_field_recipe(label=HOSTILE, prompt="PROMPT-MARKER " + HOSTILE)
    plain_script, hostile_script = blender_script(plain), blender_script(hostile)
    # Same code, only constants differ: the label cannot add or change a statement.
    assert shape(plain_script) == shape(hostile_script)
    assert scene_literal(hostile_script)["fields"][0]["label"] == HOSTILE
    assert "PROMPT-MARKER" not in hostile_script
    tokens = tokenize.generate_tokens(io.StringIO(hostile_script).readline)
    carriers = {token.type for token in tokens if "PWNED" in token.string}
    assert carriers == {tokenize.STRING}
    assert hostile_script.isascii()


def test_settings_become_the_variables_at_the_top() -> None:
    settings = RenderSettings(resolution=(320, 180), samples=4, engine="workbench", denoise=False)
    script = blender_script(single_field_recipe(), settings, render_png="out dir/it's.png")
    namespace: dict[str, Any] = {}
    header = script[: script.index("# --- placement kernel")]
    exec(compile(header, "header", "exec"), namespace)
    assert namespace["RESOLUTION"] == (320, 180)
    assert namespace["SAMPLES"] == 4
    assert namespace["ENGINE"] == "workbench"
    assert namespace["DENOISE"] is False
    assert namespace["RENDER_PNG"] == "out dir/it's.png"
    assert namespace["SAVE_BLEND"] is None


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"resolution": (0, 540)}, "resolution"),
        ({"resolution": (960.0, 540)}, "resolution"),
        ({"resolution": (960, 540, 1)}, "resolution"),
        ({"samples": 0}, "samples"),
        ({"samples": True}, "samples"),
        ({"engine": "octane"}, "unknown render engine 'octane'"),
    ],
)
def test_bad_render_settings_are_configuration_errors(
    changes: dict[str, Any], message: str
) -> None:
    with pytest.raises(ConfigurationError, match=message) as caught:
        RenderSettings(**changes)
    assert caught.value.hint


def test_render_refuses_a_non_png_output_before_starting_blender(tmp_path: Path) -> None:
    with pytest.raises(ConfigurationError, match=r"not a \.png file"):
        render(single_field_recipe(), tmp_path / "scene.jpg")
    with pytest.raises(ConfigurationError, match=r"not a \.blend file"):
        render(single_field_recipe(), tmp_path / "scene.png", save_blend=tmp_path / "x.txt")
    assert list(tmp_path.iterdir()) == []


def test_backend_is_registered_and_writes_its_script(tmp_path: Path) -> None:
    backend = get_backend("blender")
    assert isinstance(backend, BlenderBackend)
    assert backend.outputs == (SCRIPT_NAME,)
    scene = Scene(mixed_recipe())
    written = backend.write(scene, tmp_path / "out")
    assert written == [tmp_path / "out" / SCRIPT_NAME]
    assert written[0].read_text(encoding="utf-8") == scene.script("blender")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["assets", SCRIPT_NAME]


def test_scene_write_includes_the_blender_script(tmp_path: Path) -> None:
    written = Scene(single_field_recipe()).write(tmp_path, backends=["blender"])
    assert {p.name for p in written} == {"recipe.json", SCRIPT_NAME}


@pytest.mark.parametrize("rotation", [0.0, 30.0, 90.0])
def test_ground_view_stands_between_the_first_rows_looking_along_them(rotation: float) -> None:
    from agrirecipe import generate
    from agrirecipe.backends.blender import ground_view
    from agrirecipe.layout import field_parameters

    recipe = generate("10 rows of maize, 80 m long, 76 cm apart", resolver="hybrid").recipe
    params = dict(field_parameters(recipe)[0], rotation_deg=rotation)
    view = ground_view(params, tallest_m=2.5)
    x, y, z = view["location_m"]
    assert view["bearing_deg"] == pytest.approx((-rotation) % 360.0)
    assert z == pytest.approx(max(1.4, 0.6 * 2.5))
    # back in field-local metres: half a row spacing past the first row, before the plants
    turn = math.radians(rotation)
    dx, dy = x - params["origin_m"][0], y - params["origin_m"][1]
    local_x = dx * math.cos(turn) + dy * math.sin(turn)
    local_y = -dx * math.sin(turn) + dy * math.cos(turn)
    spec = recipe.fields[0]
    first_row = (spec.geometry.size_m[0] - 9 * 0.76) / 2.0
    assert local_x == pytest.approx(first_row + 0.38, abs=1e-6)
    assert -1e-6 <= local_y < spec.geometry.headland_m + 0.01
