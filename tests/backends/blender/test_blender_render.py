"""Headless renders with real bpy: a PNG appears and shows sky, soil and plants."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from blender_recipes import field, single_field_recipe
from PIL import Image

from agrirecipe import BackendError, dump_recipe
from agrirecipe.backends import blender
from agrirecipe.enrich import build_environment
from agrirecipe.layout import layout_scene
from agrirecipe.recipe import FieldGeometry, SceneRecipe

pytestmark = pytest.mark.slow

RESOLUTION = (320, 180)


def orchard_and_wheat() -> SceneRecipe:
    """A summer orchard (green canopies) beside a ripe wheat plot (golden)."""
    apples = field(
        "apples",
        "Apple",
        FieldGeometry(origin_m=(0.0, 0.0), size_m=(24.0, 30.0), headland_m=3.0),
        stage="Maturation",
    )
    wheat = field(
        "wheat",
        "Wheat",
        FieldGeometry(origin_m=(30.0, 0.0), size_m=(8.0, 8.0), headland_m=0.5),
        stage="Maturation",
    )
    return SceneRecipe(
        prompt="an orchard beside ripe wheat",
        seed=1,
        environment=build_environment("Summer"),
        fields=(apples, wheat),
    )


def colour_shares(png: Path) -> dict[str, float]:
    """Shares of the image in sky blue, soil brown, ripe-wheat gold and leaf green."""
    with Image.open(png) as image:
        assert image.size == RESOLUTION
        hsv = np.asarray(image.convert("RGB").convert("HSV")).astype(np.float64)
    hue, saturation, value = hsv[..., 0] * 360 / 255, hsv[..., 1] / 255, hsv[..., 2] / 255
    return {
        "sky": float(((hue > 195) & (hue < 235) & (saturation > 0.1)).mean()),
        "soil": float(((hue > 5) & (hue < 32) & (saturation > 0.25) & (value < 0.6)).mean()),
        "gold": float(((hue > 32) & (hue < 60) & (saturation > 0.4) & (value > 0.35)).mean()),
        "canopy": float(((hue >= 97) & (hue < 150) & (saturation > 0.3)).mean()),
    }


def assert_not_blank(png: Path) -> None:
    with Image.open(png) as image:
        pixels = np.asarray(image.convert("RGB")).astype(np.float64)
    assert pixels.std() > 15.0  # a blank or single-colour frame has ~0
    shares = colour_shares(png)
    assert shares["sky"] > 0.02, shares
    assert shares["soil"] > 0.01, shares
    assert shares["gold"] > 0.005, shares  # the wheat plants
    assert shares["canopy"] > 0.03, shares  # the apple trees


def test_in_process_build_and_render(tmp_path: Path) -> None:
    """``build()`` then ``render()`` in one process with bpy (run in a child to isolate it)."""
    recipe = orchard_and_wheat()
    recipe_file = tmp_path / "recipe.json"
    recipe_file.write_text(dump_recipe(recipe), encoding="utf-8")
    png = tmp_path / "out" / "scene.png"
    child = textwrap.dedent(
        f"""
        import json, sys
        from agrirecipe import load_recipe
        from agrirecipe.backends.blender import build, render
        recipe = load_recipe({str(recipe_file)!r})
        report = build(recipe)
        path = render(recipe, {str(png)!r}, resolution={RESOLUTION!r}, samples=4)
        print("REPORT " + json.dumps({{"plants": dict(report.plants), "path": str(path)}}))
        """
    )
    completed = subprocess.run(
        [sys.executable, "-c", child], capture_output=True, text=True, timeout=600, check=False
    )
    assert completed.returncode == 0, completed.stdout[-3000:] + completed.stderr[-3000:]
    line = next(x for x in completed.stdout.splitlines() if x.startswith("REPORT "))
    report = json.loads(line.removeprefix("REPORT "))
    layout = layout_scene(recipe)
    assert report["plants"] == {f.field_id: f.plant_count for f in layout.fields}
    assert report["path"] == str(png.resolve())
    assert_not_blank(png)
    assert [p.name for p in png.parent.iterdir()] == ["scene.png"]  # no temporary left


def test_isolated_render_writes_png_and_blend(tmp_path: Path) -> None:
    png = tmp_path / "orchard.png"
    blend = tmp_path / "orchard.blend"
    result = blender.render(
        orchard_and_wheat(), png, resolution=RESOLUTION, samples=4, isolated=True, save_blend=blend
    )
    assert result == png.resolve()
    assert_not_blank(png)
    # A .blend file, plain or zstd-compressed (Blender 5's default).
    assert blend.read_bytes()[:7] == b"BLENDER" or blend.read_bytes()[:4] == b"\x28\xb5\x2f\xfd"
    assert blend.stat().st_size > 10_000


def test_workbench_renders_a_small_scene(tmp_path: Path) -> None:
    """Workbench goes through software OpenGL (EGL + Mesa) here: fine for small scenes."""
    png = blender.render(
        single_field_recipe("Lettuce"),
        tmp_path / "lettuce.png",
        resolution=(160, 90),
        samples=1,
        engine="workbench",
        isolated=True,
    )
    with Image.open(png) as image:
        assert image.size == (160, 90)
        pixels = np.asarray(image.convert("RGB")).astype(np.float64)
    assert pixels.std() > 10.0
    green = (pixels[..., 1] > pixels[..., 0] + 20) & (pixels[..., 1] > pixels[..., 2] + 20)
    assert green.mean() > 0.05  # lettuce heads


def test_isolated_failure_reports_blenders_output(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    source = blender._builder_source()
    monkeypatch.setattr(
        blender,
        "_builder_source",
        lambda: source + '\n\nraise RuntimeError("bpy refused the scene")\n',
    )
    with pytest.raises(BackendError, match="bpy refused the scene") as caught:
        blender.render(single_field_recipe(), tmp_path / "x.png", isolated=True)
    assert caught.value.stage == "render"
    assert not list(tmp_path.iterdir())


def test_in_process_failure_is_a_backend_error(tmp_path: Path) -> None:
    child = textwrap.dedent(
        f"""
        import sys
        sys.path.insert(0, {str(Path(__file__).parent)!r})
        from blender_recipes import single_field_recipe
        from agrirecipe import BackendError
        from agrirecipe.backends import blender
        source = blender._builder_source()
        # A builder whose main step is broken: main() ends up calling None.
        blender._builder_source = lambda: source + "\\nbuild_scene = None\\n"
        try:
            blender.build(single_field_recipe())
        except BackendError as error:
            print("CAUGHT", error.stage, type(error.__cause__).__name__)
        """
    )
    completed = subprocess.run(
        [sys.executable, "-c", child], capture_output=True, text=True, timeout=300, check=False
    )
    assert "CAUGHT render TypeError" in completed.stdout, completed.stdout + completed.stderr


def test_timeout_is_a_backend_error(tmp_path: Path) -> None:
    with pytest.raises(BackendError, match="did not finish within"):
        blender.render(single_field_recipe(), tmp_path / "x.png", isolated=True, timeout_s=0.05)
    assert not list(tmp_path.iterdir())
